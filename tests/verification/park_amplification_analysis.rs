//! Source of truth: the uniform-mesh amplification analysis of Park's scheme (methods.md §6),
//! derived here independently of the solver. For a standing mode `u_i = U cos(k x_i)` of a
//! uniform lumped bar, `a = -lambda u` with `lambda = (4c^2/h^2) sin^2(kh/2)`, and the average of
//! the two element accelerations at a node is `-lambda u~`. One step of the scheme is then the
//! 2x2 map on (U, V):
//!
//! ```text
//!   A = -lambda U,   u~ = U + dt_e V + dt_e^2 A/2
//!   u_fs = U + dt V + dt_e^2 (beta1 A - beta2 lambda u~),   u_cd = U + dt V + dt^2 A/2
//!   U' = theta u_fs + (1 - theta) u_cd,   V' = V + dt/2 (A - lambda U')
//! ```
//!
//! Proves: the solver's runs follow this map exactly (single-mode run, 1e-12); the phase error
//! per step is (2 theta - 1)(1 - alpha^2)(kh)^2/24 to leading order (coefficient asserted to 2 %);
//! theta = 1/2 removes it (the error then falls ~16x when kh halves); the spectral radius is
//! <= 1 for alpha <= 1 at every kh, and > 1 just above alpha = 1.

use courant_solver::{
    Bar, CentralDifference, InitialConditions, Mesh, Model, OutputRequest, ParkOptions,
    ParkVariant, Support, Supports,
};
use std::f64::consts::PI;

/// The one-step matrix of the scheme for a mode (`c = h = 1`, so `dt = dt_e alpha`, `dt_e = 1`).
fn step_matrix(kh: f64, alpha: f64, theta: f64) -> [[f64; 2]; 2] {
    let lambda = 4.0 * (kh / 2.0).sin().powi(2);
    let (dt, dte) = (alpha, 1.0);
    let beta1 = alpha * (1.0 + 3.0 * alpha - alpha * alpha) / 6.0;
    let beta2 = alpha * (alpha * alpha - 1.0) / 6.0;
    let map = |u: f64, v: f64| {
        let a = -lambda * u;
        let ut = u + dte * v + 0.5 * dte * dte * a;
        let u_fs = u + dt * v + dte * dte * (beta1 * a - beta2 * lambda * ut);
        let u_cd = u + dt * v + 0.5 * dt * dt * a;
        let u_next = theta * u_fs + (1.0 - theta) * u_cd;
        (u_next, v + 0.5 * dt * (a - lambda * u_next))
    };
    let (c1, c2) = (map(1.0, 0.0), map(0.0, 1.0));
    [[c1.0, c2.0], [c1.1, c2.1]]
}

/// Eigenvalues of a real 2x2 matrix as (modulus of the larger, argument of the complex pair or 0).
fn spectrum(m: [[f64; 2]; 2]) -> (f64, f64) {
    let tr = m[0][0] + m[1][1];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let disc = tr * tr / 4.0 - det;
    if disc < 0.0 {
        (det.sqrt(), (-disc).sqrt().atan2(tr / 2.0))
    } else {
        let r = (tr / 2.0).abs() + disc.sqrt();
        (r, if tr >= 0.0 { 0.0 } else { PI })
    }
}

/// Phase-speed ratio minus one: `arg(eigenvalue) / (c k dt) - 1`, `c k dt = alpha kh`.
fn phase_error(kh: f64, alpha: f64, theta: f64) -> f64 {
    spectrum(step_matrix(kh, alpha, theta)).1 / (alpha * kh) - 1.0
}

#[test]
fn solver_runs_follow_the_analysed_map() {
    let n = 40;
    let mode = 3;
    let bar = Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 1.0, 1.0, 1.0).unwrap();
    let k = mode as f64 * PI;
    let u0: Vec<f64> = bar.mesh().nodes().iter().map(|x| (k * x).cos()).collect();
    let model = Model::new(
        bar,
        Supports {
            left: Support::Free,
            right: Support::Free,
        },
        &[],
        InitialConditions {
            displacement: Some(u0),
            velocity: None,
        },
    )
    .unwrap();
    for (alpha, theta, variant) in [
        (0.5, 0.5, ParkVariant::Free),
        (0.8, 1.0, ParkVariant::Incremental),
        (0.3, 0.25, ParkVariant::Free),
    ] {
        let h = 1.0 / n as f64;
        let park = ParkOptions {
            theta,
            variant,
            local_stepping: true,
        };
        let integrator = CentralDifference {
            park: Some(park),
            ..CentralDifference::new(alpha * h)
        };
        let steps = 60;
        let out = integrator
            .run(
                &model,
                steps,
                &OutputRequest {
                    history_nodes: vec![0, 7],
                    ..Default::default()
                },
            )
            .unwrap();
        let m = step_matrix(k * h, alpha, theta);
        // Time in units of h/c: V scales by h, so iterate (U, V h).
        let (mut u, mut v) = (1.0, 0.0);
        for s in 0..=steps {
            for history in &out.histories {
                let expected = u * (k * history.x).cos();
                let got = history.samples[s].displacement;
                assert!(
                    (got - expected).abs() < 1e-12,
                    "alpha {alpha} theta {theta} step {s} node {}: {got} vs {expected}",
                    history.node
                );
            }
            (u, v) = (m[0][0] * u + m[0][1] * v, m[1][0] * u + m[1][1] * v);
        }
    }
}

#[test]
fn leading_phase_error_is_two_theta_minus_one_times_one_minus_alpha_squared_over_24() {
    for theta in [0.0, 0.25, 0.75, 1.0] {
        for alpha in [0.3, 0.6, 0.9] {
            let kh = 0.02;
            let coefficient = phase_error(kh, alpha, theta) / (kh * kh);
            let theory = (2.0 * theta - 1.0) * (1.0 - alpha * alpha) / 24.0;
            assert!(
                (coefficient - theory).abs() <= 0.02 * theory.abs(),
                "theta {theta} alpha {alpha}: {coefficient} vs {theory}"
            );
        }
    }
}

#[test]
fn theta_one_half_cancels_the_second_order_phase_error() {
    for alpha in [0.3, 0.6, 0.9] {
        let ratio = phase_error(0.2, alpha, 0.5) / phase_error(0.1, alpha, 0.5);
        assert!(
            (14.0..=18.0).contains(&ratio),
            "alpha {alpha}: error ratio {ratio} (fourth order wants 16)"
        );
        let cd_ratio = phase_error(0.2, alpha, 0.0) / phase_error(0.1, alpha, 0.0);
        assert!(
            (3.8..=4.2).contains(&cd_ratio),
            "alpha {alpha}: CD ratio {cd_ratio}"
        );
    }
}

#[test]
fn spectral_radius_is_at_most_one_up_to_alpha_one_and_above_one_just_beyond() {
    for theta in [0.0, 0.5, 1.0] {
        for alpha in [0.1, 0.5, 0.9, 1.0] {
            for i in 1..=200 {
                let kh = PI * i as f64 / 200.0;
                let (rho, _) = spectrum(step_matrix(kh, alpha, theta));
                assert!(
                    rho <= 1.0 + 1e-12,
                    "theta {theta} alpha {alpha} kh {kh}: spectral radius {rho}"
                );
            }
        }
        let (rho, _) = spectrum(step_matrix(PI, 1.02, theta));
        assert!(
            rho > 1.0 + 1e-3,
            "theta {theta}: alpha = 1.02 should be unstable at kh = pi, radius {rho}"
        );
    }
}
