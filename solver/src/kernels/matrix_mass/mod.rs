//! Central difference with a non-diagonal mass (CMM, AMM: a factored tridiagonal solve; RMM: a
//! tridiagonal product with the assembled inverse).
//!
//! Files: `kernel` ([`MatrixMassStep`]: the step, its passes run in cache blocks),
//! `chunks` (the step of a long bar in two fixed chunks of nodes, on one thread or two, the same
//! bits), `pair` (the calling thread and one worker kept for the kernel's life, which runs the
//! second chunk on two threads), `passes` (the blocked passes; RMM broadcasting `M^-1` over blocks where it is constant),
//! `avx2` (the residual and velocity sweeps in AVX2 intrinsics, the same bits),
//! `placed_arrays` (the state in one allocation, each array at a measured page offset, so the
//! step's speed does not depend on where the allocator puts four arrays).

#[cfg(target_arch = "x86_64")]
mod avx2;
mod chunks;
pub(crate) mod kernel;
mod pair;
mod passes;
mod placed_arrays;

pub use kernel::{MatrixMassStep, StartState, TWO_THREADS_FROM_NODES};
