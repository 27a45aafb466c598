//! Self-tests of the d'Alembert reference (`courant_references::dalembert`).
//!
//! Source of the solution: d'Alembert's solution of the wave equation, e.g. Graff, *Wave Motion
//! in Elastic Solids* (1975), ch. 2, with the conventions of courant's methods.md §2-3
//! (traction sigma0 H(t) at the free end x = 0, H(0) = 1, fixed end x = L).
//!
//! What these tests prove, using only the public API and no solver: the implemented fields
//! satisfy the boundary conditions, causality, the constitutive law sigma = E u_x and the
//! kinematic relation v = u_t (so they solve the bar problem, not merely match a formula), the
//! energy balance work = kinetic + strain, the hand-derived plateau values of the first two
//! transits and the 4T periodicity; the closed-form element averages agree with quadrature and
//! are exact when fronts sit on element boundaries; invalid data is rejected with a named error.

use courant_references::{DalembertBar, Energies, ReferenceError};

/// Unit bar of methods.md §1 (L = A = rho = E = 1, c = 1, T = 1) under a compressive load.
fn unit_bar() -> DalembertBar {
    DalembertBar::new(1.0, 1.0, 1.0, 1.0, -1.0).unwrap()
}

/// Steel bar in SI units: E = 210 GPa, rho = 7850 kg/m^3, L = 1 m, A = 1 cm^2, sigma0 = -1 MPa.
fn steel_bar() -> DalembertBar {
    DalembertBar::new(1.0, 2.1e11, 7850.0, 1e-4, -1e6).unwrap()
}

/// Distance (in length units) from `(x, t)` to the nearest front of either family, computed
/// independently of the crate: fronts pass x when c t - x or c t + x is a multiple of 2L.
fn front_clearance(bar: &DalembertBar, x: f64, t: f64) -> f64 {
    let (ct, two_l) = (bar.wave_speed() * t, 2.0 * bar.length());
    let to_multiple = |s: f64| (s - two_l * (s / two_l).round()).abs();
    to_multiple(ct - x).min(to_multiple(ct + x))
}

/// Sample points `(x/L, t/T)` spread over several reflections.
fn sample_points() -> Vec<(f64, f64)> {
    let mut points = Vec::new();
    for i in 0..=20 {
        for j in 1..=60 {
            points.push((i as f64 / 20.0, 0.0731 * j as f64));
        }
    }
    points
}

#[test]
fn constructor_accepts_valid_data_and_derives_speed_impedance_transit_and_end_force() {
    let bar = steel_bar();
    let c = (2.1e11_f64 / 7850.0).sqrt();
    assert_eq!(bar.wave_speed(), c);
    assert_eq!(bar.impedance(), 7850.0 * c);
    assert_eq!(bar.transit_time(), 1.0 / c);
    assert_eq!(bar.end_force(), 1e6 * 1e-4);
    let unit = unit_bar();
    assert_eq!(
        (
            unit.wave_speed(),
            unit.impedance(),
            unit.transit_time(),
            unit.end_force()
        ),
        (1.0, 1.0, 1.0, 1.0)
    );
}

#[test]
fn constructor_rejects_each_invalid_parameter_by_name_value_and_rule() {
    let good = [1.0, 1.0, 1.0, 1.0, -1.0];
    let names = ["length", "modulus", "density", "area"];
    for (index, name) in names.iter().enumerate() {
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut p = good;
            p[index] = bad;
            let err = DalembertBar::new(p[0], p[1], p[2], p[3], p[4]).unwrap_err();
            assert!(
                matches!(err, ReferenceError::InvalidParameter { name: n, rule: "positive and finite", .. } if n == *name),
                "{err:?}"
            );
        }
    }
    for bad in [f64::NAN, f64::INFINITY] {
        let err = DalembertBar::new(1.0, 1.0, 1.0, 1.0, bad).unwrap_err();
        assert!(matches!(
            err,
            ReferenceError::InvalidParameter {
                name: "sigma0",
                rule: "finite",
                ..
            }
        ));
    }
    let err = DalembertBar::new(1.0, -1.0, 1.0, 1.0, 1.0).unwrap_err();
    assert_eq!(err.to_string(), "modulus = -1 must be positive and finite");
    // Zero load and tensile load are valid.
    assert!(DalembertBar::new(1.0, 1.0, 1.0, 1.0, 0.0).is_ok());
    assert!(DalembertBar::new(1.0, 1.0, 1.0, 1.0, 3.0).is_ok());
}

#[test]
fn loaded_end_stress_equals_the_applied_traction_at_all_times_even_after_many_reflections() {
    for bar in [unit_bar(), steel_bar()] {
        let period = bar.transit_time();
        // H(0) = 1: the traction is on at t = 0 inclusive.
        assert_eq!(bar.stress(0.0, 0.0), bar.sigma0());
        for j in 1..=410 {
            // 0.05 T, ..., 20.5 T, including every multiple of T where fronts hit x = 0.
            let t = 0.05 * j as f64 * period;
            assert_eq!(bar.stress(0.0, t), bar.sigma0(), "t/T = {}", t / period);
            assert_eq!(
                bar.stress_mean(0.0, t),
                bar.sigma0(),
                "t/T = {}",
                t / period
            );
        }
    }
}

#[test]
fn fixed_end_displacement_and_velocity_vanish_at_all_times() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        let u_scale = bar.sigma0().abs() / bar.impedance() * period;
        for j in 0..=410 {
            let t = 0.05 * j as f64 * period;
            assert_eq!(bar.velocity(l, t), 0.0);
            assert_eq!(bar.velocity_mean(l, t), 0.0);
            assert!(bar.displacement(l, t).abs() <= 1e-13 * u_scale);
        }
    }
}

#[test]
fn all_fields_vanish_before_the_first_front_arrives() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        for i in 1..=20 {
            let x = i as f64 / 20.0 * l;
            for t in [
                -period,
                0.0,
                0.5 * x / bar.wave_speed(),
                0.999 * x / bar.wave_speed(),
            ] {
                assert_eq!(bar.stress(x, t), 0.0);
                assert_eq!(bar.velocity(x, t), 0.0);
                assert_eq!(bar.displacement(x, t), 0.0);
                assert_eq!(bar.stress_average(0.9999 * x, x, t), 0.0);
            }
        }
        let before = bar.energies(-0.5 * period);
        assert_eq!(
            (before.kinetic, before.strain, before.work),
            (0.0, 0.0, 0.0)
        );
        assert!(bar.front_positions(-0.5 * period).is_empty());
    }
}

#[test]
fn stress_equals_modulus_times_displacement_gradient_away_from_fronts() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        let dx = 1e-4 * l;
        let mut checked = 0;
        for (xr, tr) in sample_points() {
            let (x, t) = (xr * l, tr * period);
            if x - dx < 0.0 || x + dx > l || front_clearance(&bar, x, t) < 2.0 * dx {
                continue;
            }
            let gradient = (bar.displacement(x + dx, t) - bar.displacement(x - dx, t)) / (2.0 * dx);
            let err = (bar.modulus() * gradient - bar.stress(x, t)).abs();
            assert!(
                err <= 1e-9 * bar.sigma0().abs(),
                "x/L = {xr}, t/T = {tr}: {err}"
            );
            checked += 1;
        }
        assert!(checked > 500, "{checked}");
    }
}

#[test]
fn velocity_equals_time_derivative_of_displacement_away_from_fronts() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        let dt = 1e-4 * period;
        let v_scale = bar.sigma0().abs() / bar.impedance();
        let mut checked = 0;
        for (xr, tr) in sample_points() {
            let (x, t) = (xr * l, tr * period);
            if front_clearance(&bar, x, t) < 2.0 * bar.wave_speed() * dt {
                continue;
            }
            let rate = (bar.displacement(x, t + dt) - bar.displacement(x, t - dt)) / (2.0 * dt);
            let err = (rate - bar.velocity(x, t)).abs();
            assert!(err <= 1e-9 * v_scale, "x/L = {xr}, t/T = {tr}: {err}");
            checked += 1;
        }
        assert!(checked > 500, "{checked}");
    }
}

#[test]
fn stress_average_matches_fine_midpoint_quadrature_over_intervals_containing_a_front() {
    let n = 100_000;
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        // (xa, xb, t) in units of L and T; each interval contains the front at that time.
        for (xa, xb, t) in [
            (0.1, 0.7, 0.3137),
            (0.2, 0.95, 1.4321),
            (0.0, 1.0, 2.71),
            (0.55, 0.6, 3.4321),
        ] {
            let (xa, xb, t) = (xa * l, xb * l, t * period);
            let fronts = bar.front_positions(t);
            assert!(fronts.iter().any(|&f| f > xa && f < xb), "{fronts:?}");
            let h = (xb - xa) / n as f64;
            let quadrature: f64 = (0..n)
                .map(|i| bar.stress(xa + (i as f64 + 0.5) * h, t))
                .sum::<f64>()
                / n as f64;
            let exact = bar.stress_average(xa, xb, t);
            // The midpoint rule misses at most one sub-interval per front, of jump <= 2|sigma0|.
            assert!((exact - quadrature).abs() <= 2.0 * bar.sigma0().abs() / n as f64);
            // The average is strictly between the plateau values, not either of them.
            let (left, right) = (bar.stress(xa, t), bar.stress(xb, t));
            assert!(
                exact > left.min(right) && exact < left.max(right),
                "{exact} {left} {right}"
            );
        }
    }
}

#[test]
fn stress_average_equals_pointwise_stress_on_intervals_without_fronts() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        let width = 0.01 * l;
        let mut checked = 0;
        for (xr, tr) in sample_points() {
            let (xa, t) = (xr * l * 0.99, tr * period);
            let xb = xa + width;
            let mid = 0.5 * (xa + xb);
            if front_clearance(&bar, mid, t) <= width {
                continue;
            }
            assert_eq!(bar.stress_average(xa, xb, t), bar.stress(mid, t));
            checked += 1;
        }
        assert!(checked > 500, "{checked}");
    }
}

#[test]
fn element_averages_are_exact_when_the_front_sits_on_an_element_boundary() {
    let bar = unit_bar();
    let n = 100;
    let element =
        |e: usize, t: f64| bar.stress_average(e as f64 / n as f64, (e + 1) as f64 / n as f64, t);
    // t = 0.5: incident front at x = 0.5; loaded half at sigma0, the rest at rest.
    for e in 0..n {
        let expected = if e < 50 { bar.sigma0() } else { 0.0 };
        assert!((element(e, 0.5) - expected).abs() <= 1e-15, "element {e}");
    }
    // t = 1.5: reflected front at x = 0.5; doubled stress behind it (x > 0.5).
    for e in 0..n {
        let expected = if e < 50 {
            bar.sigma0()
        } else {
            2.0 * bar.sigma0()
        };
        assert!((element(e, 1.5) - expected).abs() <= 1e-15, "element {e}");
    }
    // t = 1: the front sits on the fixed end, every element is at sigma0.
    for e in 0..n {
        assert!(
            (element(e, 1.0) - bar.sigma0()).abs() <= 1e-15,
            "element {e}"
        );
    }
}

fn assert_energy_balance(bar: &DalembertBar) {
    let period = bar.transit_time();
    for t in [0.3, 0.5, 1.0, 1.5, 2.0, 2.7, 3.99, 10.5] {
        let Energies {
            kinetic,
            strain,
            work,
        } = bar.energies(t * period);
        assert!(work > 0.0 && kinetic >= 0.0 && strain > 0.0);
        let residual = (work - (kinetic + strain)).abs() / work;
        assert!(residual <= 1e-13, "t/T = {t}: residual {residual:e}");
    }
}

#[test]
fn work_of_end_force_equals_kinetic_plus_strain_energy_for_unit_data() {
    assert_energy_balance(&unit_bar());
}

#[test]
fn work_of_end_force_equals_kinetic_plus_strain_energy_for_si_steel_data() {
    assert_energy_balance(&steel_bar());
}

#[test]
fn energies_split_equally_between_kinetic_and_strain_during_first_transit() {
    for bar in [unit_bar(), steel_bar()] {
        let t = 0.4 * bar.transit_time();
        let e = bar.energies(t);
        let expected = bar.sigma0() * bar.sigma0() * bar.area() * t / (2.0 * bar.impedance());
        assert!((e.kinetic - expected).abs() <= 1e-14 * expected);
        assert!((e.strain - expected).abs() <= 1e-14 * expected);
    }
}

#[test]
fn first_transit_carries_stress_sigma0_and_velocity_minus_sigma0_over_z_behind_the_front() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        let v_behind = -bar.sigma0() / bar.impedance();
        for t in [0.2, 0.5, 0.9] {
            let t = t * period;
            let front = bar.wave_speed() * t;
            assert_eq!(bar.front_positions(t), vec![front]);
            for x in [0.0, 0.5 * front, 0.99 * front] {
                assert_eq!(bar.stress(x, t), bar.sigma0());
                assert_eq!(bar.velocity(x, t), v_behind);
            }
            for x in [1.01 * front, 0.5 * (front + l), l] {
                assert_eq!((bar.stress(x, t), bar.velocity(x, t)), (0.0, 0.0));
            }
        }
    }
}

#[test]
fn after_fixed_end_reflection_stress_doubles_and_velocity_vanishes_behind_the_front() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        for t in [1.2, 1.5, 1.9] {
            let t = t * period;
            let front = 2.0 * l - bar.wave_speed() * t;
            assert_eq!(bar.front_positions(t), vec![front]);
            for x in [1.01 * front, 0.5 * (front + l), l] {
                assert_eq!(bar.stress(x, t), 2.0 * bar.sigma0());
                assert_eq!(bar.velocity(x, t), 0.0);
            }
            for x in [0.0, 0.99 * front] {
                assert_eq!(bar.stress(x, t), bar.sigma0());
                assert_eq!(bar.velocity(x, t), -bar.sigma0() / bar.impedance());
            }
        }
    }
}

#[test]
fn loaded_end_displacement_grows_linearly_until_the_reflection_returns() {
    for bar in [unit_bar(), steel_bar()] {
        let period = bar.transit_time();
        for j in 0..=40 {
            let t = 0.05 * j as f64 * period;
            let expected = -bar.sigma0() * t / bar.impedance();
            let u = bar.displacement(0.0, t);
            assert!(
                (u - expected).abs() <= 1e-14 * (bar.sigma0() / bar.impedance() * period).abs()
            );
        }
    }
}

#[test]
fn front_mean_values_are_the_average_of_the_limits_before_and_after_arrival() {
    let bar = unit_bar();
    // Incident front exactly at x = 0.25 at t = 0.25, and at x = 0.75 after reflection.
    assert_eq!(bar.stress(0.25, 0.25), bar.sigma0());
    assert_eq!(bar.stress_mean(0.25, 0.25), 0.5 * bar.sigma0());
    assert_eq!(bar.velocity(0.25, 0.25), -bar.sigma0());
    assert_eq!(bar.velocity_mean(0.25, 0.25), -0.5 * bar.sigma0());
    assert_eq!(bar.stress_mean(0.75, 1.25), 1.5 * bar.sigma0());
    assert_eq!(bar.velocity_mean(0.75, 1.25), -0.5 * bar.sigma0());
    // Round-off in x = i h and t = n dt (Co = 1) still finds the front: 0.1 * 3 != 0.3.
    let (x, t) = (3.0 * 0.1, 0.3);
    assert_ne!(x, t);
    assert_eq!(bar.velocity_mean(x, t), -0.5 * bar.sigma0());
    assert_eq!(bar.velocity(x, t), -bar.sigma0());
}

#[test]
fn fields_are_periodic_with_period_four_transit_times() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        let u_scale = (bar.sigma0() / bar.impedance() * period).abs();
        for (xr, tr) in sample_points() {
            let (x, t) = (xr * l, tr * period);
            if front_clearance(&bar, x, t) < 1e-6 * l {
                continue;
            }
            for shift in [4.0, 8.0, 40.0] {
                let later = t + shift * period;
                assert_eq!(bar.stress(x, later), bar.stress(x, t));
                assert_eq!(bar.velocity(x, later), bar.velocity(x, t));
                let du = (bar.displacement(x, later) - bar.displacement(x, t)).abs();
                assert!(du <= 1e-12 * u_scale);
            }
        }
    }
}

#[test]
fn very_late_times_are_evaluated_in_bounded_work_consistently_with_periodicity() {
    let bar = unit_bar();
    // 4T * 2^20 is exact in binary, so the reduced time equals t exactly.
    let shift = 4.0 * 1_048_576.0;
    for t in [0.25, 1.75, 2.5, 3.125] {
        assert_eq!(bar.stress(0.6, t + shift), bar.stress(0.6, t));
        assert_eq!(bar.velocity(0.6, t + shift), bar.velocity(0.6, t));
        assert_eq!(bar.displacement(0.6, t + shift), bar.displacement(0.6, t));
        assert_eq!(bar.front_positions(t + shift), bar.front_positions(t));
    }
    assert!(bar.stress(0.5, 1e300).is_finite());
}

#[test]
fn invalid_evaluation_input_gives_nan_instead_of_panicking() {
    let bar = unit_bar();
    assert!(bar.stress(0.5, f64::NAN).is_nan());
    assert!(bar.velocity(f64::NAN, 1.0).is_nan());
    assert!(bar.displacement(1.5, 1.0).is_nan());
    assert!(bar.stress_average(0.6, 0.4, 1.0).is_nan());
    assert!(bar.stress_average(0.5, 0.5, 1.0).is_nan());
    assert!(bar.energies(f64::INFINITY).work.is_nan());
    assert!(bar.front_positions(f64::NAN).is_empty());
}

#[test]
fn front_positions_are_sorted_and_mark_where_the_stress_jumps() {
    for bar in [unit_bar(), steel_bar()] {
        let (l, period) = (bar.length(), bar.transit_time());
        for j in 0..=200 {
            let t = 0.0517 * j as f64 * period;
            let fronts = bar.front_positions(t);
            assert!(fronts.windows(2).all(|w| w[0] < w[1]));
            assert!(fronts.iter().all(|&f| (0.0..=l).contains(&f)));
            for &f in &fronts {
                let (before, after) = ((f - 1e-3 * l).max(0.0), (f + 1e-3 * l).min(l));
                if before < f && after > f {
                    assert_ne!(bar.stress(before, t), bar.stress(after, t));
                }
            }
        }
    }
}
