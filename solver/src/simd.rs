//! What the vectorised sweeps share: the width of their partial sums and the CPU features that
//! select an intrinsics path at run time.
//!
//! Every intrinsics path computes the same bits as its portable twin (the same operations in
//! the same order, each rounding as the scalar code does), so the choice made here changes
//! speed only, never results.

/// Independent partial sums per energy term, node `i` adding to lane `i % LANES`: the lumped
/// step ([`crate::kernels::lumped`]), the matrix-mass step and Park's folded step all sum in
/// this fixed order, so their sums do not depend on the vector width the compiler picks. Eight
/// lanes fill two AVX2 registers, which is what the intrinsics paths are written for.
pub(crate) const LANES: usize = 8;

/// Whether the running CPU has AVX2 (the blocked sweeps' intrinsics and AVX2-compiled copies
/// are taken only then; elsewhere the portable path, with the same bits).
pub(crate) fn has_avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Whether the running CPU has fused multiply-add instructions (the windowed solve's
/// intrinsics use them; its portable path computes the same fused operations with `mul_add`).
pub(crate) fn has_fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}
