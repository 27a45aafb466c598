//! The group solve of [`crate::mass::windows`] in AVX2 intrinsics: twelve windows' recurrences
//! in three registers (lane `i` of register `q` is window `4q + i`).
//!
//! ```text
//!   forward   z_k = r_k - l_{k-1} z_{k-1}          (z_0 = r_0)       rows 0 .. window
//!   backward  x_k = (z_k (1/d_k)) - l_k x_{k+1}    (x_window = 0)    rows window - 1 .. lowest
//! ```
//!
//! The residual rows are read four at a time from each window and transposed (4 x 4, two
//! unpacks and two lane permutes per pair) into row-major group order; the solution is
//! transposed back four rows at a time. Same arithmetic as the portable loop, operation for
//! operation: each `a - l b` is one fused multiply-add (`_mm256_fnmadd_pd`, one rounding, as
//! the portable `(-l).mul_add(b, a)`), `z (1/d)` a product (`_mm256_mul_pd`, as `*`): the same
//! bits. A group's shared factors are broadcast to every lane (`_mm256_broadcast_sd`), its
//! per-window factors loaded four lanes at a time.

use std::arch::x86_64::{
    __m256d, _mm256_broadcast_sd, _mm256_fnmadd_pd, _mm256_loadu_pd, _mm256_mul_pd,
    _mm256_permute2f128_pd, _mm256_setzero_pd, _mm256_storeu_pd, _mm256_unpackhi_pd,
    _mm256_unpacklo_pd,
};

use super::group::WINDOWS_PER_GROUP;

/// Registers of four windows.
const QUADS: usize = WINDOWS_PER_GROUP / 4;

/// Rows `0..4` of `m` (four registers) become its columns.
#[inline(always)]
unsafe fn transpose(m: [__m256d; 4]) -> [__m256d; 4] {
    // SAFETY (of the intrinsics): the callers are compiled with AVX2.
    unsafe {
        let t0 = _mm256_unpacklo_pd(m[0], m[1]);
        let t1 = _mm256_unpackhi_pd(m[0], m[1]);
        let t2 = _mm256_unpacklo_pd(m[2], m[3]);
        let t3 = _mm256_unpackhi_pd(m[2], m[3]);
        [
            _mm256_permute2f128_pd::<0x20>(t0, t2),
            _mm256_permute2f128_pd::<0x20>(t1, t3),
            _mm256_permute2f128_pd::<0x31>(t0, t2),
            _mm256_permute2f128_pd::<0x31>(t1, t3),
        ]
    }
}

/// Solve the [`WINDOWS_PER_GROUP`] windows of a group with their `factors` (`SHARED`:
/// `[l_k, 1/d_k]` per row for every window; otherwise per row `k` the `l_k` of the windows, then
/// their `1/d_k`), window `c` reading `r[starts[c]..starts[c] + window]`; `rows` receives `z` in
/// group layout, `solution` the rows `lowest..window` of `x` in window layout
/// (`solution[c * window + k]`). `window` and `lowest` are multiples of 4.
///
/// # Safety
/// The CPU must support AVX2 and FMA.
#[target_feature(enable = "avx2,fma")]
pub(crate) unsafe fn solve_windows<const SHARED: bool>(
    (factors, starts, r): (&[f64], &[usize; WINDOWS_PER_GROUP], &[f64]),
    (window, lowest): (usize, usize),
    [rows, solution]: [&mut [f64]; 2],
) {
    let lanes = if SHARED { 1 } else { WINDOWS_PER_GROUP };
    assert!(window.is_multiple_of(4) && lowest.is_multiple_of(4) && lowest <= window);
    assert!(factors.len() >= 2 * window * lanes && rows.len() >= window * WINDOWS_PER_GROUP);
    assert!(solution.len() >= WINDOWS_PER_GROUP * window);
    assert!(starts.iter().all(|&s| s + window <= r.len()));
    let (fp, rp) = (factors.as_ptr(), r.as_ptr());
    let (zp, xp) = (rows.as_mut_ptr(), solution.as_mut_ptr());
    // SAFETY: row offsets below are < window and window offsets < WINDOWS_PER_GROUP, so every index
    // is within the lengths asserted above; loads and stores are unaligned.
    unsafe {
        let factor = |at: usize, q: usize| {
            if SHARED {
                _mm256_broadcast_sd(&*fp.add(at))
            } else {
                _mm256_loadu_pd(fp.add(at * WINDOWS_PER_GROUP + 4 * q))
            }
        };
        let lower = |k: usize, q: usize| factor(2 * k, q);
        let pivot = |k: usize, q: usize| factor(2 * k + 1, q);
        // Forward, four rows at a time per register (the registers' chains are independent:
        // the core overlaps them).
        let mut z = [_mm256_setzero_pd(); QUADS];
        let mut block = 0;
        while block < window {
            let mut columns = [[_mm256_setzero_pd(); 4]; QUADS];
            for (q, column) in columns.iter_mut().enumerate() {
                let read = |i: usize| _mm256_loadu_pd(rp.add(starts[4 * q + i] + block));
                *column = transpose([read(0), read(1), read(2), read(3)]);
            }
            for m in 0..4 {
                let k = block + m;
                for (q, (zq, column)) in z.iter_mut().zip(&columns).enumerate() {
                    *zq = if k == 0 {
                        column[m]
                    } else {
                        _mm256_fnmadd_pd(lower(k - 1, q), *zq, column[m])
                    };
                    _mm256_storeu_pd(zp.add(k * WINDOWS_PER_GROUP + 4 * q), *zq);
                }
            }
            block += 4;
        }
        // Backward, four rows at a time per register, transposed back to window order.
        let mut x = [_mm256_setzero_pd(); QUADS];
        let mut block = window;
        while block > lowest {
            block -= 4;
            let mut found = [[_mm256_setzero_pd(); 4]; QUADS];
            for m in (0..4).rev() {
                let k = block + m;
                for q in 0..QUADS {
                    let zk = _mm256_loadu_pd(zp.add(k * WINDOWS_PER_GROUP + 4 * q));
                    x[q] = _mm256_fnmadd_pd(lower(k, q), x[q], _mm256_mul_pd(zk, pivot(k, q)));
                    found[q][m] = x[q];
                }
            }
            for (q, rows_of_quad) in found.into_iter().enumerate() {
                for (i, column) in transpose(rows_of_quad).into_iter().enumerate() {
                    _mm256_storeu_pd(xp.add((4 * q + i) * window + block), column);
                }
            }
        }
    }
}
