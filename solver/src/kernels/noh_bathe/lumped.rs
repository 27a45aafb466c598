//! [`LumpedNohBathe`]: one Noh-Bathe step with the lumped mass as a single sweep over the bar,
//! bit-identical to the step written pass by pass (each array swept once per stage,
//! `crate::schemes::noh_bathe`'s matrix-mass path) and reading each array once per step instead
//! of about a dozen times.
//!
//! With `f_e = k_e (u_e - u_{e-1})` the force of element `e` (nodes `e-1`, `e`; `f_0 = f_N = 0`
//! through the padded stiffnesses) and `r_i = f_{i+1} - f_i + F_i` the residual, a step is three
//! stages, each needing its neighbours' results of the one before:
//!
//! ```text
//!   1. predict  (node j):  u_j <- u_j + (c0 v_j + c1 a_j)                          (= u_p)
//!   2. middle   (node j):  am_j = r_j(u_p) / m_j;  v_j <- v_j + c2 (a_j + am_j);
//!                          u_j <- u_j + (c3 v_j + c4 am_j)                          (= u_n)
//!   3. end      (node i):  an_i = r_i(u_n) / m_i;  v_i <- v_i + ((c5 a_i + c6 am_i) + c7 an_i);
//!                          a_i <- an_i
//! ```
//!
//! Stage 2 at node `j` needs stage 1 at `j + 1`, stage 3 at `i` needs stage 2 at `i + 1`, so
//! over a chunk of [`CHUNK`] nodes the three stages run one and two nodes behind each other,
//! their intermediate forces and `am` in chunk-sized buffers (in the first-level cache), the
//! residual formed where it is used. Every operation and every sum is the pass-by-pass step's,
//! in its order: the strain sum `sum_e f_e du_e` in element order, `v M v` and `a M a` in four
//! partial sums by `i mod 4`, then `(s0 + s1) + (s2 + s3)`. The strain sum is one chain of N
//! dependent additions per step: its latency, not the arithmetic, is this step's floor (its
//! additions run inside the next chunk's prediction to overlap the rest).

/// Nodes per chunk: the six arrays and the buffers of a chunk stay in the first-level cache, and
/// the chain of strain additions of one chunk is short enough to overlap the next chunk's work
/// (128 measured against 64 and 512: benches/RESULTS.md, "2026-11-28").
pub const CHUNK: usize = 128;

/// The sums of a step, at `t + dt`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NohBatheSums {
    /// `sum_e f_e du_e = u K u` (element order).
    pub twice_strain: f64,
    /// `v M v`.
    pub twice_kinetic: f64,
    /// `a M a` as `sum_i a_i r_i`.
    pub impulse: f64,
}

/// The state arrays a step updates and the model's arrays it reads.
#[derive(Debug)]
pub struct NohBatheArrays<'a> {
    /// `u` (N + 1 nodes).
    pub u: &'a mut [f64],
    /// `v`.
    pub v: &'a mut [f64],
    /// `a`.
    pub a: &'a mut [f64],
    /// Element stiffnesses padded with a zero at both ends (N + 2).
    pub stiffness: &'a [f64],
    /// `1/m_i`, 0 at fixed nodes.
    pub inverse_mass: &'a [f64],
    /// `m_i`.
    pub mass: &'a [f64],
}

/// The step's coefficients and chunk buffers.
#[derive(Debug, Clone)]
pub struct LumpedNohBathe {
    c: [f64; 8],
    avx2: bool,
    forces: Vec<f64>,
    middle: Vec<f64>,
    /// The terms of `v M v` and `a M a` of a chunk, side by side.
    terms: Vec<f64>,
    /// The strain terms `f_e du_e` of the last chunk, not yet summed (`pending` of them).
    strain_terms: Vec<f64>,
    pending: usize,
}

impl LumpedNohBathe {
    /// The step with coefficients `c` (`h1, h1^2/2, h1/2, h2, h2^2/2, h2 w0, h2 w1, h2 w2`).
    pub fn new(c: [f64; 8]) -> Self {
        Self {
            c,
            avx2: crate::simd::has_avx2(),
            forces: vec![0.0; CHUNK + 3],
            middle: vec![0.0; CHUNK + 3],
            terms: vec![0.0; 2 * (CHUNK + 3)],
            strain_terms: vec![0.0; CHUNK + 3],
            pending: 0,
        }
    }

    /// One step: `mid` are the loads `F(t + p dt)`, `end` the loads `F(t + dt)`, each by node,
    /// sorted, each node once. Compiled for AVX2 where the CPU has it (the same operations:
    /// the same bits).
    pub fn step(
        &mut self,
        arrays: NohBatheArrays<'_>,
        mid: &[(usize, f64)],
        end: &[(usize, f64)],
    ) -> NohBatheSums {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only when the running CPU reports AVX2 support.
            return unsafe { self.step_avx2(arrays, mid, end) };
        }
        self.sweep::<false>(arrays, mid, end)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn step_avx2(
        &mut self,
        arrays: NohBatheArrays<'_>,
        mid: &[(usize, f64)],
        end: &[(usize, f64)],
    ) -> NohBatheSums {
        self.sweep::<true>(arrays, mid, end)
    }

    /// The step; `AVX2`: inlined into [`Self::step_avx2`], its prediction written with AVX2
    /// intrinsics.
    #[inline(always)]
    fn sweep<const AVX2: bool>(
        &mut self,
        arrays: NohBatheArrays<'_>,
        mid: &[(usize, f64)],
        end: &[(usize, f64)],
    ) -> NohBatheSums {
        let NohBatheArrays {
            u,
            v,
            a,
            stiffness: k,
            inverse_mass: inv,
            mass,
        } = arrays;
        let n = u.len();
        let [c0, c1, ..] = self.c;
        let (mut p1, mut p2, mut p3) = (0, 0, 0);
        // The force of the element left of the first node of stage 2 and of stage 3.
        let (mut left_mid, mut left_end) = (0.0, 0.0);
        // `self.middle[j - base]` holds am_j.
        let mut base = 0;
        let mut sums = Sums::default();
        let mut hi = 0;
        while p3 < n {
            hi += CHUNK;
            let h1 = (hi + 2).min(n);
            let (terms, strain) = (&self.strain_terms[..self.pending], sums.strain);
            let (up, vp, ap) = (&mut u[p1..h1], &v[p1..h1], &a[p1..h1]);
            sums.strain = if AVX2 {
                #[cfg(target_arch = "x86_64")]
                // SAFETY: `AVX2` is true only inside `step_avx2`, taken when the CPU has AVX2.
                unsafe {
                    predict_avx2(up, vp, ap, [c0, c1], terms, strain)
                }
                #[cfg(not(target_arch = "x86_64"))]
                predict(up, vp, ap, [c0, c1], terms, strain)
            } else {
                predict(up, vp, ap, [c0, c1], terms, strain)
            };
            self.pending = 0;
            p1 = h1;
            // am of [p3, p2) moves to the front of the buffer.
            self.middle.copy_within(p3 - base..p2 - base, 0);
            base = p3;
            let h2 = (hi + 1).min(n);
            left_mid = self.middle_stage(p2, h2, base, left_mid, u, v, a, k, inv, mid);
            p2 = h2;
            let h3 = hi.min(n);
            left_end = self.end_stage(
                p3, h3, base, left_end, u, v, a, k, inv, mass, end, &mut sums,
            );
            p3 = h3;
        }
        for t in &self.strain_terms[..self.pending] {
            sums.strain += t;
        }
        self.pending = 0;
        let lanes = |s: [f64; 4]| (s[0] + s[1]) + (s[2] + s[3]);
        NohBatheSums {
            twice_strain: sums.strain,
            twice_kinetic: lanes(sums.kinetic),
            impulse: lanes(sums.impulse),
        }
    }

    /// `self.forces[j - lo + 1] = f_{j+1}` of the current `u` for `j` in `[lo, hi)`, with
    /// `self.forces[0] = left` (`f_lo`); `f_N = 0`.
    #[inline(always)]
    fn element_forces(&mut self, lo: usize, hi: usize, left: f64, u: &[f64], k: &[f64]) {
        let n = u.len();
        let inner = hi.min(n - 1);
        let forces = &mut self.forces[..=hi - lo];
        forces[0] = left;
        if inner > lo {
            let (du_hi, du_lo) = (&u[lo + 1..=inner], &u[lo..inner]);
            for (((f, k), u1), u0) in forces[1..=inner - lo]
                .iter_mut()
                .zip(&k[lo + 1..=inner])
                .zip(du_hi)
                .zip(du_lo)
            {
                *f = k * (u1 - u0);
            }
        }
        if hi == n {
            forces[hi - lo] = 0.0;
        }
    }

    /// Stage 2 on nodes `[lo, hi)`; returns `f_hi` of `u_p` (the next chunk's left force).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn middle_stage(
        &mut self,
        lo: usize,
        hi: usize,
        base: usize,
        left: f64,
        u: &mut [f64],
        v: &mut [f64],
        a: &[f64],
        k: &[f64],
        inv: &[f64],
        loads: &[(usize, f64)],
    ) -> f64 {
        if hi <= lo {
            return left;
        }
        let [_, _, c2, c3, c4, ..] = self.c;
        let len = hi - lo;
        self.element_forces(lo, hi, left, u, k);
        let middle = &mut self.middle[lo - base..hi - base];
        let (u, v, a, inv) = (&mut u[lo..hi], &mut v[lo..hi], &a[lo..hi], &inv[lo..hi]);
        let forces = &self.forces[..=len];
        // Nodes [s, e) of the chunk, the load `F` added to the residual of the last when
        // given: r = (f_{i+1} - f_i) + F as the pass-by-pass step forms it.
        let segment = |s: usize,
                       e: usize,
                       load: Option<f64>,
                       u: &mut [f64],
                       v: &mut [f64],
                       am: &mut [f64]| {
            let (e0, last) = if load.is_some() {
                (e - 1, Some(e - 1))
            } else {
                (e, None)
            };
            for (((((u, v), a), inv), am), (f1, f0)) in u[s..e0]
                .iter_mut()
                .zip(&mut v[s..e0])
                .zip(&a[s..e0])
                .zip(&inv[s..e0])
                .zip(&mut am[s..e0])
                .zip(forces[s + 1..=e0].iter().zip(&forces[s..e0]))
            {
                let m = (f1 - f0) * inv;
                *am = m;
                *v += c2 * (a + m);
                *u += c3 * *v + c4 * m;
            }
            if let (Some(i), Some(f)) = (last, load) {
                let m = ((forces[i + 1] - forces[i]) + f) * inv[i];
                am[i] = m;
                v[i] += c2 * (a[i] + m);
                u[i] += c3 * v[i] + c4 * m;
            }
        };
        let mut start = 0;
        for (at, f) in loads_in(loads, lo, hi) {
            segment(start, at + 1, Some(f), u, v, middle);
            start = at + 1;
        }
        segment(start, len, None, u, v, middle);
        self.forces[len]
    }

    /// Stage 3 on nodes `[lo, hi)`, its sums into `sums`; returns `f_hi` of `u_n`.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn end_stage(
        &mut self,
        lo: usize,
        hi: usize,
        base: usize,
        left: f64,
        u: &[f64],
        v: &mut [f64],
        a: &mut [f64],
        k: &[f64],
        inv: &[f64],
        mass: &[f64],
        loads: &[(usize, f64)],
        sums: &mut Sums,
    ) -> f64 {
        if hi <= lo {
            return left;
        }
        let [.., c5, c6, c7] = self.c;
        let len = hi - lo;
        self.element_forces(lo, hi, left, u, k);
        // u K u in element order: the elements lo + 1 ..= min(hi, N - 1), their terms
        // f_e du_e formed side by side here, summed one after the other while the next chunk
        // is predicted (the chain of additions then overlaps that work).
        let inner = hi.min(u.len() - 1);
        if inner > lo {
            let terms = &mut self.strain_terms[..inner - lo];
            for (((t, f), u1), u0) in terms
                .iter_mut()
                .zip(&self.forces[1..=inner - lo])
                .zip(&u[lo + 1..=inner])
                .zip(&u[lo..inner])
            {
                *t = f * (u1 - u0);
            }
            self.pending = inner - lo;
        }
        let middle = &self.middle[lo - base..hi - base];
        let (v, a) = (&mut v[lo..hi], &mut a[lo..hi]);
        let (inv, mass) = (&inv[lo..hi], &mass[lo..hi]);
        let forces = &self.forces[..=len];
        let (kinetic_terms, impulse_terms) = self.terms.split_at_mut(CHUNK + 3);
        let (kinetic_terms, impulse_terms) = (&mut kinetic_terms[..len], &mut impulse_terms[..len]);
        let segment = |s: usize,
                       e: usize,
                       load: Option<f64>,
                       v: &mut [f64],
                       a: &mut [f64],
                       tk: &mut [f64],
                       ti: &mut [f64]| {
            let (e0, last) = if load.is_some() {
                (e - 1, Some(e - 1))
            } else {
                (e, None)
            };
            for (((((((v, a), inv), am), m), tk), ti), (f1, f0)) in v[s..e0]
                .iter_mut()
                .zip(&mut a[s..e0])
                .zip(&inv[s..e0])
                .zip(&middle[s..e0])
                .zip(&mass[s..e0])
                .zip(&mut tk[s..e0])
                .zip(&mut ti[s..e0])
                .zip(forces[s + 1..=e0].iter().zip(&forces[s..e0]))
            {
                let r = f1 - f0;
                let an = r * inv;
                *v += c5 * *a + c6 * am + c7 * an;
                *a = an;
                *tk = *v * m * *v;
                *ti = an * r;
            }
            if let (Some(i), Some(f)) = (last, load) {
                let r = (forces[i + 1] - forces[i]) + f;
                let an = r * inv[i];
                v[i] += c5 * a[i] + c6 * middle[i] + c7 * an;
                a[i] = an;
                tk[i] = v[i] * mass[i] * v[i];
                ti[i] = an * r;
            }
        };
        let mut start = 0;
        for (at, f) in loads_in(loads, lo, hi) {
            segment(start, at + 1, Some(f), v, a, kinetic_terms, impulse_terms);
            start = at + 1;
        }
        segment(start, len, None, v, a, kinetic_terms, impulse_terms);
        // Node lo + i adds to lane (lo + i) mod 4: chunks start at multiples of four.
        debug_assert_eq!(lo % 4, 0);
        let (mut kinetic, mut impulse) = (sums.kinetic, sums.impulse);
        let quads = len / 4;
        for (tk, ti) in kinetic_terms
            .chunks_exact(4)
            .zip(impulse_terms.chunks_exact(4))
        {
            for lane in 0..4 {
                kinetic[lane] += tk[lane];
                impulse[lane] += ti[lane];
            }
        }
        for i in 4 * quads..len {
            kinetic[i % 4] += kinetic_terms[i];
            impulse[i % 4] += impulse_terms[i];
        }
        sums.kinetic = kinetic;
        sums.impulse = impulse;
        self.forces[len]
    }
}

/// The running sums of a step.
#[derive(Debug, Default)]
struct Sums {
    strain: f64,
    kinetic: [f64; 4],
    impulse: [f64; 4],
}

/// Stage 1, `u_j <- u_j + (c0 v_j + c1 a_j)`, with the additions `strain += t` of `terms`, in
/// order, four of each per iteration (the chain of additions hides behind the predictions);
/// returns the strain sum.
#[inline(always)]
fn predict(
    u: &mut [f64],
    v: &[f64],
    a: &[f64],
    [c0, c1]: [f64; 2],
    terms: &[f64],
    strain: f64,
) -> f64 {
    let mut strain = strain;
    let quads = (u.len() / 4).min(terms.len() / 4);
    let (u_quads, u_rest) = u.split_at_mut(4 * quads);
    for (((u, v), a), t) in u_quads
        .chunks_exact_mut(4)
        .zip(v.chunks_exact(4))
        .zip(a.chunks_exact(4))
        .zip(terms.chunks_exact(4))
    {
        for lane in 0..4 {
            u[lane] += c0 * v[lane] + c1 * a[lane];
        }
        strain += t[0];
        strain += t[1];
        strain += t[2];
        strain += t[3];
    }
    for ((u, v), a) in u_rest.iter_mut().zip(&v[4 * quads..]).zip(&a[4 * quads..]) {
        *u += c0 * v + c1 * a;
    }
    for t in &terms[4 * quads..] {
        strain += t;
    }
    strain
}

/// [`predict`] with AVX2 intrinsics: the same operations (no FMA: each `_mm256_mul_pd` and
/// `_mm256_add_pd` rounds as the scalar `*` and `+` do), the same bits.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline]
fn predict_avx2(
    u: &mut [f64],
    v: &[f64],
    a: &[f64],
    [c0, c1]: [f64; 2],
    terms: &[f64],
    strain: f64,
) -> f64 {
    use std::arch::x86_64::{
        _mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_set1_pd, _mm256_storeu_pd,
    };
    let len = u.len().min(v.len()).min(a.len());
    let quads = (len / 4).min(terms.len() / 4);
    let (c0v, c1v) = (_mm256_set1_pd(c0), _mm256_set1_pd(c1));
    let mut strain = strain;
    for q in 0..quads {
        let i = 4 * q;
        // SAFETY: i + 4 <= len, the length of u, v and a.
        unsafe {
            let uq = _mm256_loadu_pd(u.as_ptr().add(i));
            let vq = _mm256_loadu_pd(v.as_ptr().add(i));
            let aq = _mm256_loadu_pd(a.as_ptr().add(i));
            let step = _mm256_add_pd(_mm256_mul_pd(c0v, vq), _mm256_mul_pd(c1v, aq));
            _mm256_storeu_pd(u.as_mut_ptr().add(i), _mm256_add_pd(uq, step));
        }
        strain += terms[i];
        strain += terms[i + 1];
        strain += terms[i + 2];
        strain += terms[i + 3];
    }
    for ((u, v), a) in u[4 * quads..len]
        .iter_mut()
        .zip(&v[4 * quads..len])
        .zip(&a[4 * quads..len])
    {
        *u += c0 * v + c1 * a;
    }
    for t in &terms[4 * quads..] {
        strain += t;
    }
    strain
}

/// The loads on nodes `[lo, hi)`, as `(node - lo, F)`, in node order.
#[inline(always)]
fn loads_in(loads: &[(usize, f64)], lo: usize, hi: usize) -> impl Iterator<Item = (usize, f64)> {
    loads
        .iter()
        .filter(move |(node, _)| (lo..hi).contains(node))
        .map(move |&(node, f)| (node - lo, f))
}
