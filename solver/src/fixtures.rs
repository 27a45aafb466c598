//! The seed paper's canonical bars, shared by tests, benchmarks and examples.
//!
//! ```text
//!   sigma0 f(t) ==> o---o---o--- ... ---o //  fixed
//!                   x = 0              x = L = 1
//! ```

use crate::error::InputError;
use crate::model::bar::{Bar, Field};
use crate::model::load::{End, Load, TimeFunction};
use crate::model::mesh::Mesh;
use crate::model::{InitialConditions, Model, Supports};

/// The unit free-fixed bar of the seed's Figs. 1 and 2 (L = A = rho = 1, `elements` uniform
/// elements, modulus `modulus`), loaded at its free left end by the traction
/// `sigma0 f(t)`, `sigma0 = -1` (compressive), fixed at the right end, starting at rest.
pub fn seed_bar(elements: usize, modulus: Field, time: TimeFunction) -> Result<Model, InputError> {
    let bar = Bar::new(
        Mesh::uniform(1.0, elements)?,
        &modulus,
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )?;
    let load = Load::Traction {
        end: End::Left,
        stress: -1.0,
        time,
    };
    Model::new(
        bar,
        Supports::FREE_FIXED,
        &[load],
        InitialConditions::default(),
    )
}

/// The graded bar of the seed's Fig. 2: modulus linear from 16 at the loaded end to 1 at the
/// fixed end, Heaviside load.
pub fn graded_seed_bar(elements: usize) -> Result<Model, InputError> {
    seed_bar(
        elements,
        Field::Linear {
            left: 16.0,
            right: 1.0,
        },
        TimeFunction::HEAVISIDE,
    )
}

/// The bar of the seed's Fig. 2 alone: unit length, `elements` uniform elements, modulus linear
/// from 16 to 1, unit density and area.
pub fn graded_bar(elements: usize) -> Result<Bar, InputError> {
    Bar::new(
        Mesh::uniform(1.0, elements)?,
        &Field::Linear {
            left: 16.0,
            right: 1.0,
        },
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
}

/// A persistent, switching contact: a unit bar of `elements` elements (E = rho = A = 1) at rest,
/// `gap` from a rigid wall on its right, pushed toward it by a constant force 1 on its left end
/// (touching, the wall force returns to 0 every 4 L/c).
pub fn loaded_wall(
    elements: usize,
    gap: f64,
) -> Result<crate::contact::ContactProblem, InputError> {
    let bar = Bar::homogeneous(Mesh::uniform(1.0, elements)?, 1.0, 1.0, 1.0)?;
    let load = Load::Force {
        node: 0,
        magnitude: 1.0,
        time: TimeFunction::HEAVISIDE,
    };
    let model = Model::new(
        bar,
        Supports::default(),
        &[load],
        InitialConditions::default(),
    )?;
    crate::contact::ContactProblem::wall(model, End::Right, gap)
}

/// The benchmarks' start state (`benches/cd_step.rs`, `courant bench`, and the C reference
/// `benches/c_reference/cd_step.c`): a smooth, bounded half-step velocity
/// `1e-3 cos(pi x / 2L)` on the `elements + 1` nodes of the unit bar, zero at the fixed right end,
/// so that every nodal value stays a normal float however many steps a benchmark takes.
pub fn smooth_half_velocity(elements: usize) -> Vec<f64> {
    (0..=elements)
        .map(|i| {
            if i == elements {
                0.0
            } else {
                1e-3 * (std::f64::consts::FRAC_PI_2 * i as f64 / elements as f64).cos()
            }
        })
        .collect()
}

/// The matrix-mass step of `model` with mass `kind` at half the kind's critical Courant number
/// (of the stiffest element), at rest in `u` and `r` with [`smooth_half_velocity`] as `v^{1/2}`:
/// the step the benchmarks (`mass_kind_step`), the harness `step_pair` and the kernel's unit
/// tests time and check.
pub fn matrix_step(
    model: &Model,
    kind: crate::mass::MassKind,
) -> Result<crate::kernels::matrix_mass::kernel::MatrixMassStep, InputError> {
    let n = model.bar().element_count();
    let dt = 0.5 * kind.critical_courant() * model.bar().stiffest_element().1;
    let mass = crate::mass::MassOperator::new(model, kind)?;
    let (v_half, zeros) = (smooth_half_velocity(n), vec![0.0; n + 1]);
    let start = crate::kernels::matrix_mass::kernel::StartState {
        displacement: &zeros,
        half_step_velocity: &v_half,
        acceleration: &zeros,
        residual: &zeros,
        kinetic_staggered: 0.0,
    };
    let stiffness = model.stiffness();
    Ok(crate::kernels::matrix_mass::kernel::MatrixMassStep::new(
        dt, stiffness, mass, &start,
    ))
}

/// A lumped kernel on [`graded_seed_bar`] of `n` elements at half its stiffest element's step,
/// from rest with the half-step velocity `sin(0.37 i)` (0 at the fixed end): the lumped kernels'
/// unit-test bar.
#[cfg(test)]
pub(crate) fn graded_test_kernel(n: usize) -> crate::kernels::lumped::kernel::LumpedStep {
    let model = graded_seed_bar(n).unwrap();
    let dt = 0.5 * model.bar().stiffest_element().1;
    let v: Vec<f64> = (0..=n)
        .map(|i| if i == n { 0.0 } else { (i as f64 * 0.37).sin() })
        .collect();
    crate::kernels::lumped::kernel::LumpedStep::new(&model, dt, &vec![0.0; n + 1], &v)
}
