//! Measured dispersion of central difference: the phase speed of one standing mode, from a run
//! of the solver.
//!
//! On a uniform free-free bar every sampled cosine `u_j = cos(k x_j)`, `k = n pi/L`, is an exact
//! discrete mode for every mass kind (their matrices all have the Neumann structure), so a run
//! started from it at rest stays in it: `u_j^s = cos(s theta) u_j^0`, with the discrete phase
//! per step `theta = omega_hat dt`. The measured `theta = acos(u^s/u^0)/s` (taken at a step `s`
//! where `s theta` is near `pi/2`, where `acos` is well conditioned) gives the phase-speed ratio
//! `omega_hat/(c k) = theta/(Co kh)`, `Co = c dt/h`. Theory (methods.md §5):
//! `sin(theta/2) = (Co/2) Omega(kh)`.

use courant_solver::{
    Bar, CentralDifference, InitialConditions, MassKind, Mesh, Model, OutputRequest, RunError,
    Support, Supports,
};
use std::f64::consts::PI;

/// A single-mode measurement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeMeasurement {
    /// `kh = n pi / N`.
    pub kh: f64,
    /// Phase per step `theta = omega_hat dt`.
    pub phase_per_step: f64,
    /// `omega_hat / (c k)`.
    pub phase_speed_ratio: f64,
    /// Steps run.
    pub steps: usize,
    /// Largest `|u_j^s - cos(s theta) u_j^0|` over nodes and steps: how single the mode stayed.
    pub mode_leak: f64,
}

/// Run mode `n` of a unit free-free bar of `elements` elements with mass `kind` at Courant number
/// `co` (relative to `c dt / h`) and measure its phase speed.
pub fn measure_mode(
    kind: MassKind,
    elements: usize,
    n: usize,
    co: f64,
) -> Result<ModeMeasurement, RunError> {
    let length = 1.0;
    let bar = Bar::homogeneous(Mesh::uniform(length, elements)?, 1.0, 1.0, 1.0)?;
    let k = n as f64 * PI / length;
    let u0: Vec<f64> = bar.mesh().nodes().iter().map(|&x| (k * x).cos()).collect();
    let initial = InitialConditions {
        displacement: Some(u0.clone()),
        velocity: None,
    };
    let model = Model::new(
        bar,
        Supports {
            left: Support::Free,
            right: Support::Free,
        },
        &[],
        initial,
    )?;
    let h = length / elements as f64;
    let kh = k * h;
    let dt = co * h;
    // Continuum phase per step as a first guess for where s theta ~ pi/2.
    let steps = ((PI / 2.0) / (co * kh)).round().clamp(1.0, 100_000.0) as usize;
    let integrator = CentralDifference {
        mass: kind,
        ..CentralDifference::new(dt)
    };
    // At most 17 nodes recorded (evenly spread, both ends included): enough to see a leak out
    // of the mode, and memory independent of N.
    let stride = elements.div_ceil(16).max(1);
    let mut nodes: Vec<usize> = (0..=elements).step_by(stride).collect();
    if nodes.last() != Some(&elements) {
        nodes.push(elements);
    }
    let request = OutputRequest {
        history_nodes: nodes,
        ..Default::default()
    };
    let out = integrator.run(&model, steps, &request)?;
    let (u_first, u_last) = (u0[0], out.histories[0].samples[steps].displacement);
    let phase_per_step = (u_last / u_first).clamp(-1.0, 1.0).acos() / steps as f64;
    let mut mode_leak = 0.0_f64;
    for history in &out.histories {
        for sample in &history.samples {
            let expected = (sample.step as f64 * phase_per_step).cos() * u0[history.node];
            mode_leak = mode_leak.max((sample.displacement - expected).abs());
        }
    }
    Ok(ModeMeasurement {
        kh,
        phase_per_step,
        phase_speed_ratio: phase_per_step / (co * kh),
        steps,
        mode_leak,
    })
}

/// One row of a dispersion case: a mode, its closed-form and measured phase-speed ratios.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DispersionRow {
    /// Mode number.
    pub mode: usize,
    /// The measurement.
    pub measured: ModeMeasurement,
    /// `sin(omega_hat dt/2) = (Co/2) Omega(kh)` evaluated by `courant-references`.
    pub closed_form: f64,
}

/// The rows of a dispersion case.
#[derive(Debug, Clone, PartialEq)]
pub struct DispersionResult {
    /// The case.
    pub case: crate::scene::dispersion::DispersionCase,
    /// One row per mode.
    pub rows: Vec<DispersionRow>,
}

impl DispersionResult {
    /// Largest `|measured - closed form|` of the phase-speed ratio.
    pub fn deviation(&self) -> f64 {
        self.rows
            .iter()
            .map(|r| (r.measured.phase_speed_ratio - r.closed_form).abs())
            .fold(0.0, f64::max)
    }

    /// Observed order of the phase error between each mode `n` and `2n` present in the list:
    /// `log2(|e(2n)| / |e(n)|)`, `e = ratio - 1`, for row `i` (the `2n` row), else `None`.
    pub fn observed_order(&self, i: usize) -> Option<f64> {
        let row = &self.rows[i];
        let half = self.rows.iter().find(|r| 2 * r.mode == row.mode)?;
        let (fine, coarse) = (
            (half.measured.phase_speed_ratio - 1.0).abs(),
            (row.measured.phase_speed_ratio - 1.0).abs(),
        );
        (fine > 0.0 && coarse > 0.0).then(|| (coarse / fine).log2())
    }

    /// Smallest observed order over the mode pairs.
    pub fn min_order(&self) -> Option<f64> {
        (0..self.rows.len())
            .filter_map(|i| self.observed_order(i))
            .reduce(f64::min)
    }
}

/// Run every mode of a dispersion case.
pub fn run_dispersion(
    case: &crate::scene::dispersion::DispersionCase,
) -> Result<DispersionResult, RunError> {
    let kind = crate::spectra::closed_form_kind(case.mass);
    let rows = case
        .modes
        .iter()
        .map(|&mode| {
            let measured = measure_mode(case.mass, case.elements, mode, case.courant)?;
            let closed_form =
                courant_references::spectra::phase_speed_ratio(kind, measured.kh, case.courant)
                    .unwrap_or(f64::NAN);
            Ok(DispersionRow {
                mode,
                measured,
                closed_form,
            })
        })
        .collect::<Result<_, RunError>>()?;
    Ok(DispersionResult {
        case: case.clone(),
        rows,
    })
}

/// `case, mass, beta, fourth_order, Co, mode, kh, closed_form, measured, difference, phase_error,
/// observed_order` (order between mode `n/2` and `n`, when both are listed).
pub fn dispersion_table(results: &[DispersionResult]) -> crate::table::Table {
    use crate::table::{Cell, Table};
    let mut table = Table::new(&[
        "case",
        "mass",
        "beta",
        "fourth_order",
        "Co",
        "mode",
        "kh",
        "closed_form",
        "measured",
        "difference",
        "phase_error",
        "observed_order",
    ]);
    for r in results {
        let beta = match r.case.mass {
            MassKind::Averaged { beta } | MassKind::Reciprocal { beta } => Some(beta),
            _ => None,
        };
        for (i, row) in r.rows.iter().enumerate() {
            let m = row.measured;
            table.push(vec![
                r.case.name.as_str().into(),
                r.case.mass.label().into(),
                beta.into(),
                r.case.fourth_order.to_string().into(),
                r.case.courant.into(),
                row.mode.into(),
                m.kh.into(),
                row.closed_form.into(),
                m.phase_speed_ratio.into(),
                (m.phase_speed_ratio - row.closed_form).into(),
                (m.phase_speed_ratio - 1.0).into(),
                Cell::from(r.observed_order(i)),
            ]);
        }
    }
    table
}
