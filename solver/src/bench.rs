//! What the benches, the timing examples, `courant bench` and the tests that check the step
//! kernels directly need of the solver's internals, gathered in one place so the rest of the
//! crate can stay private. Not a stable interface: it follows the kernels, and it is hidden from
//! the documentation.
//!
//! - The step kernels, driven without the time loop: [`LumpedStep`] (one lumped
//!   step, or blocks of steps with [`StepBlock`]), [`MatrixMassStep`] (CMM, AMM, RMM)
//!   and [`ParkStep`] (Park's folded step).
//! - The constants the timing tables divide by: [`TILE`], [`DEPTH`], [`MAX_BLOCK_STEPS`],
//!   [`PARALLEL_FROM_NODES`].
//! - The bars every bench and many tests run on (`graded_seed_bar`, `seed_bar`, `graded_bar`,
//!   `loaded_wall`, `smooth_half_velocity`, `matrix_step`).

pub use crate::fixtures::{
    graded_bar, graded_seed_bar, loaded_wall, matrix_step, seed_bar, smooth_half_velocity,
};
pub use crate::kernels::lumped::{
    DEPTH, LumpedStep, MAX_BLOCK_STEPS, PARALLEL_FROM_NODES, StepBlock, TILE,
};
pub use crate::kernels::matrix_mass::{MatrixMassStep, StartState, TWO_THREADS_FROM_NODES};
pub use crate::kernels::park::ParkStep;
