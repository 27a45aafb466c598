//! The matrix-mass step's sweeps with their energy sums, written with AVX2 intrinsics (used by
//! [`crate::kernels::matrix_mass::passes`] where the CPU has AVX2): the residual rows with the
//! strain and increment lanes, and the velocity update with the impulse lanes.
//!
//! ```text
//!   r_i = k_{i+1} (u_{i+1} - u_i) - k_i (u_i - u_{i-1}),
//!   strain[i % 8] += k_{i+1} (u_{i+1} - u_i)^2,   increment[i % 8] += v_i (r^n_i + r^{n+1}_i),
//!   impulse[i % 8] += a_i r_i,   v_i += dt a_i
//! ```
//!
//! Same arithmetic as the portable loops, operation for operation (no FMA: each `_mm256_mul_pd`,
//! `_mm256_add_pd` and `_mm256_sub_pd` rounds as the scalar `*`, `+` and `-` do), node `i`
//! adding to lane `i % 8` (lanes 0-3 in one register, 4-7 in the other) in increasing `i`:
//! bit-identical. The compiler's own vectorisation of the portable loops spilled their
//! accumulators to the stack (measured here with `perf annotate`).

use std::arch::x86_64::{
    _mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_permute2f128_pd, _mm256_set1_pd,
    _mm256_shuffle_pd, _mm256_storeu_pd, _mm256_sub_pd,
};

use crate::simd::LANES;

/// The velocity update of the whole chunks of [`LANES`] nodes of `v` with the impulse lanes
/// (the slices start at a multiple of [`LANES`] of the whole arrays and `a`, `r` are at least as
/// long as `v`); returns the number of nodes done, the caller updates the rest.
///
/// # Safety
/// The CPU must support AVX2.
#[target_feature(enable = "avx2")]
pub(crate) unsafe fn velocity_lanes(
    v: &mut [f64],
    a: &[f64],
    r: &[f64],
    dt: f64,
    impulse: &mut [f64; LANES],
) -> usize {
    let whole = v.len() / LANES * LANES;
    assert!(a.len() >= whole && r.len() >= whole);
    let (vp, ap, rp) = (v.as_mut_ptr(), a.as_ptr(), r.as_ptr());
    // SAFETY: every offset below is < whole, within the three slices (asserted above); loads
    // and stores are unaligned; `impulse` holds 8 values.
    unsafe {
        let step = _mm256_set1_pd(dt);
        let mut product = [
            _mm256_loadu_pd(impulse.as_ptr()),
            _mm256_loadu_pd(impulse.as_ptr().add(4)),
        ];
        let mut i = 0;
        while i < whole {
            for (h, lane) in product.iter_mut().enumerate() {
                let o = i + 4 * h;
                let vi = _mm256_loadu_pd(vp.add(o));
                let ai = _mm256_loadu_pd(ap.add(o));
                *lane = _mm256_add_pd(*lane, _mm256_mul_pd(ai, _mm256_loadu_pd(rp.add(o))));
                _mm256_storeu_pd(vp.add(o), _mm256_add_pd(vi, _mm256_mul_pd(step, ai)));
            }
            i += LANES;
        }
        _mm256_storeu_pd(impulse.as_mut_ptr(), product[0]);
        _mm256_storeu_pd(impulse.as_mut_ptr().add(4), product[1]);
    }
    whole
}

/// The unloaded interior residual rows `chunks` (whole chunks of [`LANES`] rows from a multiple of
/// [`LANES`], `1 <= chunks.start`, `chunks.end <= n - 1`) of
/// [`crate::kernels::matrix_mass::passes::residual_rows`]:
/// `r_i = k[i+1] (u[i+1] - u[i]) - k[i] (u[i] - u[i-1])` overwriting `r^n_i`, with
/// `k[i+1] (u[i+1] - u[i])^2` added to `strain[i % 8]` and `v_i (r^n_i + r_i)` to
/// `increment[i % 8]`; returns `chunks.end`. Row `i`'s left force `k[i] (u[i] - u[i-1])` is row
/// `i - 1`'s right one, formed by the same operations: it is shifted in from the previous four rows
/// (one element force per row instead of two; 5-8 % faster CMM, AMM and RMM steps at N = 1e5,
/// measured), the same bits.
///
/// # Safety
/// The CPU must support AVX2.
#[target_feature(enable = "avx2")]
pub(crate) unsafe fn residual_rows(
    (k, u, v): (&[f64], &[f64], &[f64]),
    r: &mut [f64],
    chunks: std::ops::Range<usize>,
    [strain, increment]: [&mut [f64; LANES]; 2],
) -> usize {
    let n = u.len();
    assert!(chunks.start >= 1 && chunks.end < n);
    assert!(chunks.start.is_multiple_of(LANES) && chunks.end.is_multiple_of(LANES));
    assert!(k.len() >= n && v.len() >= n && r.len() >= n);
    let (kp, up, vp, rp) = (k.as_ptr(), u.as_ptr(), v.as_ptr(), r.as_mut_ptr());
    // SAFETY: rows i of the chunks read u[i..i+5], k[i+1..i+5] (i + 4 <= chunks.end <= n - 1),
    // v and r [i..i+4], and the first chunk's start - 4 >= 4 (a multiple of LANES >= 1) reads
    // u[start-4..start+1], k[start-3..start+1]: within the asserted lengths; unaligned loads
    // and stores; the lane arrays hold 8 values.
    unsafe {
        let load = |p: *const f64| [_mm256_loadu_pd(p), _mm256_loadu_pd(p.add(4))];
        let (mut strain_sum, mut increment_sum) = (load(strain.as_ptr()), load(increment.as_ptr()));
        // The element force right of rows i..i+4 (`k[i+1] (u[i+1] - u[i])`); the left one of a
        // row is the right one of the row before, the same operations: taken from the previous
        // four rows' by a lane shift (the first chunk's from rows start-4..start).
        let right_of = |i: usize| {
            let u1 = _mm256_loadu_pd(up.add(i));
            let du = _mm256_sub_pd(_mm256_loadu_pd(up.add(i + 1)), u1);
            (_mm256_mul_pd(_mm256_loadu_pd(kp.add(i + 1)), du), du)
        };
        let mut previous = right_of(chunks.start - 4).0;
        let mut base = chunks.start;
        while base < chunks.end {
            for h in 0..2 {
                let i = base + 4 * h;
                let (right, du) = right_of(i);
                // [previous[3], right[0], right[1], right[2]]
                let middle = _mm256_permute2f128_pd::<0x21>(previous, right);
                let left = _mm256_shuffle_pd::<0b0101>(middle, right);
                previous = right;
                let new = _mm256_sub_pd(right, left);
                let sum = _mm256_add_pd(_mm256_loadu_pd(rp.add(i)), new);
                strain_sum[h] = _mm256_add_pd(strain_sum[h], _mm256_mul_pd(right, du));
                increment_sum[h] = _mm256_add_pd(
                    increment_sum[h],
                    _mm256_mul_pd(_mm256_loadu_pd(vp.add(i)), sum),
                );
                _mm256_storeu_pd(rp.add(i), new);
            }
            base += LANES;
        }
        for h in 0..2 {
            _mm256_storeu_pd(strain.as_mut_ptr().add(4 * h), strain_sum[h]);
            _mm256_storeu_pd(increment.as_mut_ptr().add(4 * h), increment_sum[h]);
        }
    }
    chunks.end
}

/// The interior rows `chunks` (whole chunks of [`LANES`] rows from a multiple of [`LANES`],
/// `1 <= chunks.start`, `chunks.end <= n - 1`) of
/// [`crate::kernels::matrix_mass::passes::reciprocal_velocity`]:
/// `a_i = (off_{i-1} r_{i-1} + diag_i r_i) + off_i r_{i+1}`, `impulse[i % 8] += a_i r_i`,
/// `v_i += dt a_i`; returns `chunks.end`. `CONSTANT`: every row's `diag_i`, `off_{i-1}` and
/// `off_i` are `constant` (`[diag, off]`, broadcast; the arrays are not read).
///
/// # Safety
/// The CPU must support AVX2.
#[target_feature(enable = "avx2")]
pub(crate) unsafe fn reciprocal_velocity<const CONSTANT: bool>(
    ((diag, off), constant): ((&[f64], &[f64]), [f64; 2]),
    r: &[f64],
    v: &mut [f64],
    (dt, chunks): (f64, std::ops::Range<usize>),
    impulse: &mut [f64; LANES],
) -> usize {
    let n = diag.len();
    assert!(chunks.start >= 1 && chunks.end < n);
    assert!(chunks.start.is_multiple_of(LANES) && chunks.end.is_multiple_of(LANES));
    assert!(off.len() + 1 >= n && r.len() >= n && v.len() >= n);
    let (dp, op, rp, vp) = (diag.as_ptr(), off.as_ptr(), r.as_ptr(), v.as_mut_ptr());
    // SAFETY: rows i of the chunks read off[i-1..i+4], r[i-1..i+5], diag and v [i..i+4]
    // (i + 4 <= chunks.end <= n - 1), within the asserted lengths; unaligned; `impulse` holds 8.
    unsafe {
        let step = _mm256_set1_pd(dt);
        let mut product = [
            _mm256_loadu_pd(impulse.as_ptr()),
            _mm256_loadu_pd(impulse.as_ptr().add(4)),
        ];
        let (constant_diag, constant_off) =
            (_mm256_set1_pd(constant[0]), _mm256_set1_pd(constant[1]));
        let coefficient = |p: *const f64, i: usize, value| {
            if CONSTANT {
                value
            } else {
                _mm256_loadu_pd(p.add(i))
            }
        };
        let mut base = chunks.start;
        while base < chunks.end {
            for (h, lane) in product.iter_mut().enumerate() {
                let i = base + 4 * h;
                let ri = _mm256_loadu_pd(rp.add(i));
                let left = _mm256_mul_pd(
                    coefficient(op, i - 1, constant_off),
                    _mm256_loadu_pd(rp.add(i - 1)),
                );
                let centre = _mm256_mul_pd(coefficient(dp, i, constant_diag), ri);
                let right = _mm256_mul_pd(
                    coefficient(op, i, constant_off),
                    _mm256_loadu_pd(rp.add(i + 1)),
                );
                let a = _mm256_add_pd(_mm256_add_pd(left, centre), right);
                *lane = _mm256_add_pd(*lane, _mm256_mul_pd(a, ri));
                let vi = _mm256_loadu_pd(vp.add(i));
                _mm256_storeu_pd(vp.add(i), _mm256_add_pd(vi, _mm256_mul_pd(step, a)));
            }
            base += LANES;
        }
        _mm256_storeu_pd(impulse.as_mut_ptr(), product[0]);
        _mm256_storeu_pd(impulse.as_mut_ptr().add(4), product[1]);
    }
    chunks.end
}
