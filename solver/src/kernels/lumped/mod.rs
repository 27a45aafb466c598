//! Central difference with the lumped (diagonal) mass: the step every lumped run takes, and
//! blocks of it.
//!
//! Files: `kernel` ([`LumpedStep`]: one step in cache blocks, O(N), no global
//! matrix), `avx2` (its energy sweep in AVX2 intrinsics, the same bits), `tiled` (temporal
//! blocking: [`DEPTH`] steps per pass over a tile of [`TILE`] nodes, bit-identical to single
//! steps; [`StepBlock`], what a block takes and returns), `pipeline` (blocks of up to
//! [`MAX_BLOCK_STEPS`] steps, the tiles cut into one region per thread and run as a pipeline:
//! the same bits on any thread count).

#[cfg(target_arch = "x86_64")]
mod avx2;
pub(crate) mod kernel;
mod pipeline;
pub(crate) mod tiled;

pub use kernel::{LumpedStep, PARALLEL_FROM_NODES};
pub use tiled::{DEPTH, MAX_BLOCK_STEPS, StepBlock, TILE};
