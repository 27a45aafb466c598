//! The lumped central-difference velocity sweep with its three energy sums, written with AVX2
//! intrinsics (used by [`crate::kernels::lumped::kernel`] where the CPU has AVX2).
//!
//! Same arithmetic as the portable sweep of `kernel.rs`, operation for operation (no FMA: each
//! `_mm256_mul_pd` and `_mm256_add_pd` rounds as the scalar `*` and `+` do), with node `i` of the
//! segment adding to lane `i % 8` (lanes 0-3 in one register, 4-7 in the other): the states and
//! the energy sums are bit-identical to the portable path. The compiler's own vectorisation of
//! the portable energy sweep shuffles lanes and spills its accumulators (measured here: the
//! energy step cost 1.5x the plain step at N = 1e5); written out, it streams.

use std::arch::x86_64::{
    __m256d, _mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_storeu_pd, _mm256_sub_pd,
};

use crate::simd::LANES;

/// Partial sums of one lane group: `[lanes 0-3, lanes 4-7]`.
type Pair = [__m256d; 2];

#[target_feature(enable = "avx2")]
#[inline]
fn load_pair(lanes: &[f64; LANES]) -> Pair {
    // SAFETY: `lanes` holds 8 values; unaligned loads of 4 at offsets 0 and 4.
    unsafe {
        [
            _mm256_loadu_pd(lanes.as_ptr()),
            _mm256_loadu_pd(lanes.as_ptr().add(4)),
        ]
    }
}

#[target_feature(enable = "avx2")]
#[inline]
fn store_pair(pair: Pair, lanes: &mut [f64; LANES]) {
    // SAFETY: `lanes` holds 8 values; unaligned stores of 4 at offsets 0 and 4.
    unsafe {
        _mm256_storeu_pd(lanes.as_mut_ptr(), pair[0]);
        _mm256_storeu_pd(lanes.as_mut_ptr().add(4), pair[1]);
    }
}

/// Update `v[i] += s[i] r_i`, `r_i = k[i+1] (u[i+2] - u[i+1]) - k[i] (u[i+1] - u[i])`, for the
/// whole groups of 8 nodes of the segment, and add node `i`'s `k[i+1] right^2`, `m[i] old new`
/// and `m[i] (old + new)^2` to lane `i % 8` of `strain`, `staggered`, `kinetic`. Returns the
/// number of nodes done (a multiple of 8); the caller does the rest.
///
/// Lengths: `u` = `v.len() + 2`, `k` = `v.len() + 1`, `s` and `m` = `v.len()` (asserted).
///
/// # Safety
/// The CPU must support AVX2.
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn sweep_with_energy(
    u: &[f64],
    k: &[f64],
    v: &mut [f64],
    s: &[f64],
    m: &[f64],
    strain: &mut [f64; LANES],
    staggered: &mut [f64; LANES],
    kinetic: &mut [f64; LANES],
) -> usize {
    let n = v.len();
    assert!(u.len() == n + 2 && k.len() == n + 1 && s.len() == n && m.len() == n);
    let whole = n / LANES * LANES;
    let (mut e_strain, mut e_staggered, mut e_kinetic) =
        (load_pair(strain), load_pair(staggered), load_pair(kinetic));
    let (up, kp, vp, sp, mp) = (
        u.as_ptr(),
        k.as_ptr(),
        v.as_mut_ptr(),
        s.as_ptr(),
        m.as_ptr(),
    );
    let mut base = 0;
    while base < whole {
        for (h, offset) in [0usize, 4].into_iter().enumerate() {
            let i = base + offset;
            // SAFETY: i + 4 <= whole <= n, so u[i..i+6], k[i..i+5], v, s, m [i..i+4] are in
            // bounds by the asserted lengths.
            unsafe {
                let u0 = _mm256_loadu_pd(up.add(i));
                let u1 = _mm256_loadu_pd(up.add(i + 1));
                let u2 = _mm256_loadu_pd(up.add(i + 2));
                let k0 = _mm256_loadu_pd(kp.add(i));
                let k1 = _mm256_loadu_pd(kp.add(i + 1));
                let right = _mm256_sub_pd(u2, u1);
                let k_right = _mm256_mul_pd(k1, right);
                let r = _mm256_sub_pd(k_right, _mm256_mul_pd(k0, _mm256_sub_pd(u1, u0)));
                let old = _mm256_loadu_pd(vp.add(i));
                let new = _mm256_add_pd(old, _mm256_mul_pd(_mm256_loadu_pd(sp.add(i)), r));
                _mm256_storeu_pd(vp.add(i), new);
                let mass = _mm256_loadu_pd(mp.add(i));
                let sum = _mm256_add_pd(old, new);
                e_strain[h] = _mm256_add_pd(e_strain[h], _mm256_mul_pd(k_right, right));
                e_staggered[h] =
                    _mm256_add_pd(e_staggered[h], _mm256_mul_pd(_mm256_mul_pd(mass, old), new));
                e_kinetic[h] =
                    _mm256_add_pd(e_kinetic[h], _mm256_mul_pd(_mm256_mul_pd(mass, sum), sum));
            }
        }
        base += LANES;
    }
    store_pair(e_strain, strain);
    store_pair(e_staggered, staggered);
    store_pair(e_kinetic, kinetic);
    whole
}
