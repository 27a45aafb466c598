//! The velocity update of the matrix-mass step with its two energy sums, and the energy
//! increment of the CMM/AMM force pass, written with AVX2 intrinsics (used by
//! [`crate::matrix_passes`] where the CPU has AVX2).
//!
//! ```text
//!   increment[i % 8] += v_i (r^n_i + r^{n+1}_i),   impulse[i % 8] += a_i r^{n+1}_i,
//!   v_i += dt a_i
//! ```
//!
//! Same arithmetic as the portable loop, operation for operation (no FMA: each `_mm256_mul_pd`
//! and `_mm256_add_pd` rounds as the scalar `*` and `+` do), node `i` adding to lane `i % 8`
//! (lanes 0-3 in one register, 4-7 in the other) in increasing `i`: bit-identical. The
//! compiler's own vectorisation of the portable loop spilled its accumulators to the stack
//! (measured here with `perf annotate`).

use std::arch::x86_64::{
    __m256d, _mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_storeu_pd,
};

use crate::kernel::LANES;

/// The velocity update of the whole chunks of [`LANES`] nodes of `v` (the slices start at a
/// multiple of [`LANES`] of the whole arrays and are at least as long as `v`), the increment
/// only with `INCREMENT` (`r_previous` unread without it); returns the number of nodes done,
/// the caller updates the rest.
///
/// # Safety
/// The CPU must support AVX2.
#[target_feature(enable = "avx2")]
pub(crate) unsafe fn velocity_lanes<const INCREMENT: bool>(
    v: &mut [f64],
    a: &[f64],
    r_previous: &[f64],
    r: &[f64],
    dt: f64,
    increment: &mut [f64; LANES],
    impulse: &mut [f64; LANES],
) -> usize {
    let whole = v.len() / LANES * LANES;
    assert!(a.len() >= whole && r_previous.len() >= whole && r.len() >= whole);
    let (vp, ap, pp, rp) = (v.as_mut_ptr(), a.as_ptr(), r_previous.as_ptr(), r.as_ptr());
    // SAFETY: every offset below is < whole, within all four slices (asserted above); loads and
    // stores are unaligned; `increment` and `impulse` hold 8 values each.
    unsafe {
        let step = _mm256_set1_pd(dt);
        let load =
            |p: *const f64| -> [__m256d; 2] { [_mm256_loadu_pd(p), _mm256_loadu_pd(p.add(4))] };
        let mut sum = load(increment.as_ptr());
        let mut product = load(impulse.as_ptr());
        let mut i = 0;
        while i < whole {
            for h in 0..2 {
                let o = i + 4 * h;
                let vi = _mm256_loadu_pd(vp.add(o));
                let ai = _mm256_loadu_pd(ap.add(o));
                let ri = _mm256_loadu_pd(rp.add(o));
                if INCREMENT {
                    let pi = _mm256_loadu_pd(pp.add(o));
                    sum[h] = _mm256_add_pd(sum[h], _mm256_mul_pd(vi, _mm256_add_pd(pi, ri)));
                }
                product[h] = _mm256_add_pd(product[h], _mm256_mul_pd(ai, ri));
                _mm256_storeu_pd(vp.add(o), _mm256_add_pd(vi, _mm256_mul_pd(step, ai)));
            }
            i += LANES;
        }
        for h in 0..2 {
            _mm256_storeu_pd(increment.as_mut_ptr().add(4 * h), sum[h]);
            _mm256_storeu_pd(impulse.as_mut_ptr().add(4 * h), product[h]);
        }
    }
    whole
}

/// The energy increment of the whole chunks of [`LANES`] nodes of `v`,
/// `increment[i % 8] += v_i (r^n_i + r^{n+1}_i)`, with `copy_i = r^{n+1}_i` when `COPY` (the
/// slices start at a multiple of [`LANES`] of the whole arrays and are at least as long as `v`;
/// `copy` unused without `COPY`); returns the number of nodes done, the caller does the rest.
///
/// # Safety
/// The CPU must support AVX2.
#[target_feature(enable = "avx2")]
pub(crate) unsafe fn increment_lanes<const COPY: bool>(
    v: &[f64],
    r_previous: &[f64],
    r: &[f64],
    copy: &mut [f64],
    increment: &mut [f64; LANES],
) -> usize {
    let whole = v.len() / LANES * LANES;
    assert!(r_previous.len() >= whole && r.len() >= whole && (!COPY || copy.len() >= whole));
    let (vp, pp, rp, cp) = (
        v.as_ptr(),
        r_previous.as_ptr(),
        r.as_ptr(),
        copy.as_mut_ptr(),
    );
    // SAFETY: every offset below is < whole, within all four slices (asserted above; `copy` is
    // written only with `COPY`); loads and stores are unaligned; `increment` holds 8 values.
    unsafe {
        let mut sum = [
            _mm256_loadu_pd(increment.as_ptr()),
            _mm256_loadu_pd(increment.as_ptr().add(4)),
        ];
        let mut i = 0;
        while i < whole {
            for (h, lane) in sum.iter_mut().enumerate() {
                let o = i + 4 * h;
                let ri = _mm256_loadu_pd(rp.add(o));
                let sum_r = _mm256_add_pd(_mm256_loadu_pd(pp.add(o)), ri);
                *lane = _mm256_add_pd(*lane, _mm256_mul_pd(_mm256_loadu_pd(vp.add(o)), sum_r));
                if COPY {
                    _mm256_storeu_pd(cp.add(o), ri);
                }
            }
            i += LANES;
        }
        _mm256_storeu_pd(increment.as_mut_ptr(), sum[0]);
        _mm256_storeu_pd(increment.as_mut_ptr().add(4), sum[1]);
    }
    whole
}
