//! Self-tests of the graded-bar reference (`courant_references::graded::GradedBar`).
//!
//! Sources: courant's methods.md §4 (travel time, transit, the jump law
//! `[sigma] = sigma0 sqrt(Z(x)/Z1)` and the substitution `r = 2 Z/|b|` to the axisymmetric
//! wave equation); de Hoog, Knight & Stokes, SIAM J. Sci. Stat. Comput. 3 (1982) 357-366 (the
//! Bromwich-line inversion of route (a)); d'Alembert's solution, e.g. Graff, *Wave Motion in
//! Elastic Solids* (1975), ch. 2, for the homogeneous limit.
//!
//! What these tests prove, using only the public API and no solver:
//! - the closed forms (travel time, its inverse, transit time, first-front position) are
//!   consistent with each other and with `dtau/dx = 1/c(x)`, also in the homogeneous limit;
//! - the two independent full-field routes, (a) Laplace transform + de Hoog inversion and
//!   (b) characteristics with tracked fronts + Richardson extrapolation, agree to 1e-9 |sigma0|
//!   in stress and in `Z v` away from fronts, before and after reflections, with the stiff end
//!   loaded and with the soft end loaded (and right next to fronts too);
//! - route (a) without any front subtraction (plain delayed inversion) agrees with the full
//!   route (a) in the first transit, so the subtraction machinery does not bias the result;
//! - the jumps measured from the routes just behind/ahead of each front and their arrival
//!   times match the closed forms (the transport law with reflection +1 at the fixed end and
//!   -1 at the loaded end), and nothing moves before the first arrival;
//! - the boundary conditions hold (traction at x = 0, v = 0 at x = L);
//! - E1 = E2 reduces to d'Alembert, and a very weak grading differs from it only by O(grading);
//! - element averages equal an independent fine quadrature;
//! - invalid data is rejected with named errors, invalid points give NaN.

use courant_references::DalembertBar;
use courant_references::ReferenceError;
use courant_references::graded::{Direction, FieldPoint, GradedBar};

/// Seed Fig. 2 bar (stiff end loaded) and the reversed bar (soft end loaded).
fn bars() -> [GradedBar; 2] {
    [
        GradedBar::seed_fig2(),
        GradedBar::new(1.0, 1.0, 16.0, 1.0, 1.0, -1.0).unwrap(),
    ]
}

/// Time distance from `t` to the nearest pass of a front through `x`, from the closed forms.
fn front_clearance(bar: &GradedBar, x: f64, t: f64) -> f64 {
    bar.passes(x, t + 4.0 * bar.transit_time())
        .iter()
        .map(|p| (p.time - t).abs())
        .fold(f64::INFINITY, f64::min)
}

/// Largest difference between two evaluations, in units of |sigma0|, with velocities scaled by
/// the local impedance.
fn difference(bar: &GradedBar, x: f64, a: FieldPoint, b: FieldPoint) -> f64 {
    let stress = (a.stress - b.stress).abs();
    let velocity = (a.velocity - b.velocity).abs() * bar.impedance(x);
    stress.max(velocity) / bar.sigma0().abs()
}

#[test]
fn closed_forms_of_travel_time_transit_and_front_position_are_consistent() {
    let seed = GradedBar::seed_fig2();
    assert!((seed.transit_time() - 0.4).abs() < 1e-15);
    for bar in bars() {
        let (l, transit) = (bar.length(), bar.transit_time());
        assert!((bar.travel_time(l) - transit).abs() < 1e-15);
        assert_eq!(bar.front_position(transit), Some(l));
        assert_eq!(bar.front_position(1.01 * transit), None);
        for i in 0..=20 {
            let x = i as f64 / 20.0 * l;
            let tau = bar.travel_time(x);
            // Inverse and the literal form of methods.md §4.
            assert!((bar.position_at_travel_time(tau) - x).abs() < 1e-14);
            let literal =
                2.0 * bar.density().sqrt() * (bar.modulus(x).sqrt() - bar.modulus_loaded().sqrt())
                    / bar.gradient();
            assert!((tau - literal).abs() < 1e-14);
            // dtau/dx = 1/c(x) (central difference, step 1e-5).
            if i > 0 && i < 20 {
                let h = 1e-5;
                let slope = (bar.travel_time(x + h) - bar.travel_time(x - h)) / (2.0 * h);
                assert!((slope * bar.wave_speed(x) - 1.0).abs() < 1e-8);
            }
            // The first front reaches x at tau(x).
            assert!((bar.front_position(tau).unwrap() - x).abs() < 1e-14);
        }
        // The first-front jump law.
        let x = 0.37;
        let expected = bar.sigma0() * (bar.impedance(x) / bar.impedance(0.0)).sqrt();
        assert!((bar.first_jump(x) - expected).abs() < 1e-15);
    }
    // Homogeneous limit: tau = x/c exactly, and continuously for a vanishing gradient.
    let homogeneous = GradedBar::new(2.0, 4.0, 4.0, 1.0, 1.0, -1.0).unwrap();
    assert_eq!(homogeneous.gradient(), 0.0);
    assert!((homogeneous.travel_time(0.6) - 0.3).abs() < 1e-16);
    assert!((homogeneous.transit_time() - 1.0).abs() < 1e-16);
    let weak = GradedBar::new(2.0, 4.0, 4.0 * (1.0 + 1e-12), 1.0, 1.0, -1.0).unwrap();
    assert!((weak.travel_time(0.6) - 0.3).abs() < 1e-12);
}

#[test]
fn routes_a_and_b_agree_to_1e_9_away_from_fronts_at_half_and_one_and_a_half_transits() {
    for bar in bars() {
        let transit = bar.transit_time();
        let mut checked = 0;
        for t_over_t in [0.5, 1.5] {
            let t = t_over_t * transit;
            for i in 0..=20 {
                let x = i as f64 / 20.0 * bar.length();
                if front_clearance(&bar, x, t) < 1e-3 * transit {
                    continue;
                }
                let a = bar.state_laplace(x, t);
                let b = bar.state_characteristics(x, t);
                let d = difference(&bar, x, a, b);
                assert!(
                    d < 1e-9,
                    "E1 = {}, x = {x}, t/T = {t_over_t}: (a) {a:?} (b) {b:?} diff {d:e}",
                    bar.modulus_loaded()
                );
                checked += 1;
            }
        }
        assert!(checked >= 38, "{checked}");
    }
}

#[test]
fn routes_a_and_b_agree_to_1e_9_over_several_reflections_and_next_to_fronts() {
    for bar in bars() {
        let transit = bar.transit_time();
        // Away from fronts, up to four transits (two round trips).
        for t_over_t in [0.23, 0.91, 1.17, 2.31, 3.07, 3.93] {
            for x in [0.0, 0.13, 0.41, 0.77, 1.0] {
                let t = t_over_t * transit;
                if front_clearance(&bar, x, t) < 1e-3 * transit {
                    continue;
                }
                let d = difference(
                    &bar,
                    x,
                    bar.state_laplace(x, t),
                    bar.state_characteristics(x, t),
                );
                assert!(d < 1e-9, "x = {x}, t/T = {t_over_t}: {d:e}");
            }
        }
        // Right next to every front passing x = 0.6 in two transits: route (a) subtracts the
        // exact front expansions, route (b) has the fronts on lattice lines.
        for pass in bar.passes(0.6, 2.0 * transit) {
            for offset in [-1e-6, 1e-6] {
                let t = pass.time + offset * transit;
                let d = difference(
                    &bar,
                    0.6,
                    bar.state_laplace(0.6, t),
                    bar.state_characteristics(0.6, t),
                );
                assert!(d < 1e-9, "{pass:?} offset {offset}: {d:e}");
            }
        }
    }
}

#[test]
fn routes_a_and_b_agree_to_1e_9_for_a_strong_grading_in_both_orientations() {
    // E ratio 100: kappa_max T = 4.5, so route (b) refines its lattice and route (a) uses more
    // abscissae; the default state() switches to route (b) once t - tau > 1.9 T.
    for (e1, e2) in [(100.0, 1.0), (1.0, 100.0)] {
        let bar = GradedBar::new(1.0, e1, e2, 1.0, 1.0, -1.0).unwrap();
        let transit = bar.transit_time();
        assert_eq!(bar.characteristic_cells(), 45);
        for (x, t_over_t) in [(0.2, 0.6), (0.7, 0.9), (0.45, 1.5), (0.9, 1.7)] {
            let t = t_over_t * transit;
            assert!(front_clearance(&bar, x, t) > 1e-3 * transit);
            let d = difference(
                &bar,
                x,
                bar.state_laplace(x, t),
                bar.state_characteristics(x, t),
            );
            assert!(d < 1e-9, "E1 = {e1}, x = {x}, t/T = {t_over_t}: {d:e}");
        }
    }
}

#[test]
fn default_state_switches_routes_without_a_visible_seam() {
    let bar = GradedBar::seed_fig2();
    let transit = bar.transit_time();
    let x = 0.3;
    let tau = bar.travel_time(x);
    // Both sides of the switch at t - tau = 5T, away from fronts.
    for t in [tau + 4.97 * transit, tau + 5.03 * transit] {
        assert!(front_clearance(&bar, x, t) > 1e-2 * transit);
        let d = difference(&bar, x, bar.state(x, t), bar.state_characteristics(x, t));
        assert!(d < 1e-9, "t/T = {}: {d:e}", t / transit);
    }
}

#[test]
fn plain_delayed_inversion_without_front_subtraction_agrees_in_the_first_transit() {
    for bar in bars() {
        let transit = bar.transit_time();
        let mut checked = 0;
        for x in [0.0, 0.1, 0.25, 0.4, 0.55] {
            let tau = bar.travel_time(x);
            for fraction in [0.1, 0.3, 0.6] {
                let t = tau + fraction * (transit - tau);
                let Some(raw) = bar.first_transit_laplace(x, t) else {
                    continue;
                };
                let d = difference(&bar, x, raw, bar.state_laplace(x, t));
                assert!(d < 1e-8, "x = {x}, fraction {fraction}: {d:e}");
                checked += 1;
            }
        }
        assert!(checked >= 15, "{checked}");
        // Outside its range it declines instead of returning a wrong value.
        assert!(bar.first_transit_laplace(0.5, 0.9 * transit).is_none());
        assert!(
            bar.first_transit_laplace(0.5, 0.1 * bar.travel_time(0.5))
                .is_none()
        );
    }
}

#[test]
fn jumps_measured_from_both_routes_and_arrival_times_match_the_closed_forms() {
    for bar in bars() {
        let transit = bar.transit_time();
        for x in [0.05, 0.3, 0.62, 0.95] {
            let passes = bar.passes(x, 3.0 * transit);
            // Arrival times: 2kT + tau and 2(k+1)T - tau, amplitude (-1)^k sigma0 sqrt(z/z1).
            let tau = bar.travel_time(x);
            let amplitude = bar.sigma0() * (bar.modulus(x) / bar.modulus_loaded()).powf(0.25);
            assert_eq!(passes.len(), 3);
            assert_eq!(passes[0].direction, Direction::TowardFixedEnd);
            assert!((passes[0].time - tau).abs() < 1e-15);
            assert!((passes[1].time - (2.0 * transit - tau)).abs() < 1e-15);
            assert!((passes[2].time - (2.0 * transit + tau)).abs() < 1e-15);
            assert!((passes[0].stress_jump - amplitude).abs() < 1e-15);
            assert!((passes[1].stress_jump - amplitude).abs() < 1e-15);
            assert!((passes[2].stress_jump + amplitude).abs() < 1e-15);
            assert!((passes[0].stress_jump - bar.first_jump(x)).abs() < 1e-15);
            for pass in &passes {
                // Measured: field 1e-7 T after minus 1e-7 T before the arrival. The smooth
                // variation over 2e-7 T is below 1e-6.
                let delta = 1e-7 * transit;
                for (route, before, after) in [
                    (
                        "laplace",
                        bar.state_laplace(x, pass.time - delta),
                        bar.state_laplace(x, pass.time + delta),
                    ),
                    (
                        "characteristics",
                        bar.state_characteristics(x, pass.time - delta),
                        bar.state_characteristics(x, pass.time + delta),
                    ),
                ] {
                    let ds = after.stress - before.stress;
                    let dv = after.velocity - before.velocity;
                    assert!(
                        (ds - pass.stress_jump).abs() < 1e-6,
                        "{route} {pass:?}: {ds}"
                    );
                    assert!(
                        (dv - pass.velocity_jump).abs() * bar.impedance(x) < 1e-6,
                        "{route} {pass:?}: {dv}"
                    );
                }
            }
            // Nothing arrives earlier: zero just ahead of the first front (both routes).
            let ahead = tau - 1e-6 * transit;
            assert_eq!(
                bar.state_laplace(x, ahead),
                FieldPoint {
                    stress: 0.0,
                    velocity: 0.0
                }
            );
            assert_eq!(
                bar.state_characteristics(x, ahead),
                FieldPoint {
                    stress: 0.0,
                    velocity: 0.0
                }
            );
        }
        // The first jump measured by the plain inversion (no front information used at all).
        for x in [0.2, 0.45] {
            let t = bar.travel_time(x) + 1e-6 * transit;
            let raw = bar.first_transit_laplace(x, t).unwrap();
            assert!((raw.stress - bar.first_jump(x)).abs() < 1e-4, "{raw:?}");
        }
    }
}

#[test]
fn boundary_conditions_hold_traction_at_the_loaded_end_and_rest_at_the_fixed_end() {
    for bar in bars() {
        let transit = bar.transit_time();
        for t_over_t in [0.3, 0.8, 1.4, 2.2, 3.6] {
            let t = t_over_t * transit;
            for route in [bar.state_laplace(0.0, t), bar.state_characteristics(0.0, t)] {
                assert!((route.stress - bar.sigma0()).abs() < 1e-10, "{route:?}");
            }
            for route in [bar.state_laplace(1.0, t), bar.state_characteristics(1.0, t)] {
                assert!(
                    route.velocity.abs() * bar.impedance(1.0) < 1e-10,
                    "{route:?}"
                );
            }
        }
        // At the fixed end the arriving front doubles (reflection +1).
        let at_end = bar.state_characteristics(1.0, transit);
        assert!((at_end.stress - 2.0 * bar.first_jump(1.0)).abs() < 1e-12);
    }
}

#[test]
fn homogeneous_bar_reduces_exactly_to_dalembert_and_weak_grading_stays_close() {
    let dalembert = DalembertBar::new(1.0, 1.0, 1.0, 1.0, -1.0).unwrap();
    let homogeneous = GradedBar::new(1.0, 1.0, 1.0, 1.0, 1.0, -1.0).unwrap();
    let weak = GradedBar::new(1.0, 1.0, 1.0 + 1e-6, 1.0, 1.0, -1.0).unwrap();
    for j in 1..=30 {
        let t = 0.137 * j as f64;
        for i in 0..=10 {
            let x = i as f64 / 10.0;
            let exact = FieldPoint {
                stress: dalembert.stress(x, t),
                velocity: dalembert.velocity(x, t),
            };
            assert!(
                difference(&homogeneous, x, homogeneous.state(x, t), exact) < 1e-14,
                "x {x} t {t}: {:?} vs {exact:?}",
                homogeneous.state(x, t)
            );
            assert!(
                difference(
                    &homogeneous,
                    x,
                    homogeneous.state_characteristics(x, t),
                    exact
                ) < 1e-12
            );
            if front_clearance(&weak, x, t) > 1e-3 && t < 3.0 {
                // The weak grading moves the field by O(1e-6) and both routes see it alike.
                let a = weak.state_laplace(x, t);
                assert!(difference(&weak, x, a, exact) < 1e-5, "x {x} t {t}");
                assert!(difference(&weak, x, a, weak.state_characteristics(x, t)) < 1e-9);
            }
        }
    }
    for (xa, xb, t) in [(0.1, 0.3, 0.2), (0.2, 0.9, 1.5), (0.0, 1.0, 0.45)] {
        let exact = dalembert.stress_average(xa, xb, t);
        assert!((homogeneous.stress_average(xa, xb, t) - exact).abs() < 1e-14);
    }
}

/// Composite Simpson with `n` (even) panels on every piece between the closed-form front
/// positions, using route (b): independent of the Gauss rule and of route (a).
fn fine_average(bar: &GradedBar, xa: f64, xb: f64, t: f64, n: usize) -> f64 {
    let mut cuts = vec![xa];
    cuts.extend(
        bar.front_positions(t)
            .into_iter()
            .filter(|&x| x > xa && x < xb),
    );
    cuts.push(xb);
    let mut sum = 0.0;
    for w in cuts.windows(2) {
        let h = (w[1] - w[0]) / n as f64;
        for k in 0..=n {
            let weight = if k == 0 || k == n {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            // Evaluate just inside the piece (beyond the front tolerance): the end values are the
            // one-sided limits.
            let x = (w[0] + k as f64 * h).clamp(w[0] + 1e-8, w[1] - 1e-8);
            sum += weight * h / 3.0 * bar.state_characteristics_with(x, t, 16, 3).stress;
        }
    }
    sum / (xb - xa)
}

#[test]
fn element_averages_equal_fine_quadrature_with_and_without_fronts_inside() {
    for bar in bars() {
        let transit = bar.transit_time();
        for (xa, xb, t_over_t) in [
            (0.1, 0.2, 0.5),  // front inside (first transit)
            (0.0, 0.05, 0.5), // behind the front, at the loaded end
            (0.6, 0.9, 1.5),  // reflected front inside
            (0.0, 1.0, 1.5),  // whole bar
        ] {
            let t = t_over_t * transit;
            let average = bar.stress_average(xa, xb, t);
            let fine = fine_average(&bar, xa, xb, t, 200);
            assert!(
                (average - fine).abs() < 1e-9,
                "[{xa}, {xb}] t/T {t_over_t}: {average} vs {fine}"
            );
        }
        // A mesh of averages reproduces the average over its span.
        let t = 1.3 * transit;
        let nodes: Vec<f64> = (0..=8).map(|i| i as f64 / 8.0).collect();
        let pieces = bar.stress_averages(&nodes, t);
        let mean: f64 = pieces.iter().sum::<f64>() / 8.0;
        assert!((mean - bar.stress_average(0.0, 1.0, t)).abs() < 1e-11);
    }
}

#[test]
fn invalid_data_is_rejected_by_name_and_invalid_points_give_nan() {
    let good = [1.0, 16.0, 1.0, 1.0, 1.0, -1.0];
    let names = [
        "length",
        "modulus_loaded",
        "modulus_fixed",
        "density",
        "area",
    ];
    for (index, name) in names.iter().enumerate() {
        for bad in [0.0, -2.0, f64::NAN, f64::INFINITY] {
            let mut p = good;
            p[index] = bad;
            let err = GradedBar::new(p[0], p[1], p[2], p[3], p[4], p[5]).unwrap_err();
            assert!(
                matches!(err, ReferenceError::InvalidParameter { name: n, .. } if n == *name),
                "{err:?}"
            );
        }
    }
    let err = GradedBar::new(1.0, 16.0, 1.0, 1.0, 1.0, f64::NAN).unwrap_err();
    assert!(matches!(
        err,
        ReferenceError::InvalidParameter { name: "sigma0", .. }
    ));
    let bar = GradedBar::seed_fig2();
    assert!(bar.state(1.5, 0.2).stress.is_nan());
    assert!(bar.state(-0.1, 0.2).velocity.is_nan());
    assert!(bar.state_laplace(0.5, f64::NAN).stress.is_nan());
    assert!(
        bar.state_characteristics_with(0.5, 0.2, 0, 2)
            .stress
            .is_nan()
    );
    assert!(
        bar.state_characteristics_with(0.5, 0.2, 8, 0)
            .stress
            .is_nan()
    );
    assert!(bar.stress_average(0.5, 0.4, 0.2).is_nan());
    // Beyond their documented ranges the routes decline instead of running for ever.
    let transit = bar.transit_time();
    assert!(bar.state(0.5, 2000.0 * transit).stress.is_nan());
    assert!(bar.state_laplace(0.5, 30.0 * transit).stress.is_nan());
    let homogeneous = GradedBar::new(1.0, 1.0, 1.0, 1.0, 1.0, -1.0).unwrap();
    let dalembert = DalembertBar::new(1.0, 1.0, 1.0, 1.0, -1.0).unwrap();
    assert_eq!(
        homogeneous.stress(0.3, 1e6 + 0.1),
        dalembert.stress(0.3, 1e6 + 0.1)
    );
    assert_eq!(
        bar.state(0.5, -1.0),
        FieldPoint {
            stress: 0.0,
            velocity: 0.0
        }
    );
    assert!(bar.front_positions(f64::NAN).is_empty());
}

/// Timing of a 1000-point profile; run with
/// `cargo test -p courant-references --release --test graded_bar_two_routes -- --ignored --nocapture`.
#[test]
#[ignore = "timing only"]
fn timing_of_a_1000_point_stress_profile() {
    for bar in bars() {
        let xs: Vec<f64> = (0..1000).map(|i| i as f64 / 999.0).collect();
        for t_over_t in [0.5, 1.5, 3.5] {
            let start = std::time::Instant::now();
            let profile = bar.stress_profile(&xs, t_over_t * bar.transit_time());
            let elapsed = start.elapsed();
            assert!(profile.iter().all(|s| s.is_finite()));
            println!(
                "E1 = {:>2}, t = {t_over_t} T: 1000-point profile in {elapsed:?}",
                bar.modulus_loaded()
            );
        }
        let nodes: Vec<f64> = (0..=1000).map(|i| i as f64 / 1000.0).collect();
        let start = std::time::Instant::now();
        let averages = bar.stress_averages(&nodes, 1.5 * bar.transit_time());
        println!("1000 element averages in {:?}", start.elapsed());
        assert!(averages.iter().all(|s| s.is_finite()));
    }
}
