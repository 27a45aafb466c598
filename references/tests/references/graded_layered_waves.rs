//! Self-tests of the layered-bar reference (`courant_references::graded::LayeredBar`).
//!
//! Sources: Graff, *Wave Motion in Elastic Solids* (1975), ch. 2 (transmission `2 Z2/(Z1 + Z2)`
//! and reflection `(Z2 - Z1)/(Z1 + Z2)` of a stress step at an interface, d'Alembert's
//! solution); courant's methods.md §2-4 (load convention, free-fixed bar, the equal-transit-time
//! layering of the graded bar).
//!
//! What these tests prove, using only the public API and no solver: a homogeneous bar, as one
//! layer or split into layers, reproduces d'Alembert exactly (fields, element averages,
//! energies); at an interface the transmitted and reflected plateaus have the impedance-ratio
//! amplitudes, stress and velocity are continuous, the fixed end doubles the stress; the exact
//! energy balance work = kinetic + strain holds over many reflections; element averages are
//! exact (they equal fine quadrature); the loaded-end displacement is the time integral of the
//! loaded-end velocity; the equal-transit-time layering converges to the graded bar of
//! `GradedBar` at first order; invalid data and an exceeded wave cap give named errors.

use courant_references::graded::{
    GradedBar, Layer, LayeredBar, reflection_coefficient, transmission_coefficient,
};
use courant_references::{DalembertBar, ReferenceError};

fn layer(thickness: f64, modulus: f64, density: f64) -> Layer {
    Layer::new(thickness, modulus, density).unwrap()
}

/// Four layers with different speeds and impedances (incommensurate travel times).
fn mixed_bar() -> LayeredBar {
    LayeredBar::new(
        &[
            layer(0.3, 4.0, 1.0),
            layer(0.2, 1.0, 2.0),
            layer(0.35, 9.0, 0.5),
            layer(0.15, 2.0, 3.0),
        ],
        2.0,
        -1.5,
    )
    .unwrap()
}

#[test]
fn homogeneous_bar_as_one_or_several_layers_reproduces_dalembert_exactly() {
    let dalembert = DalembertBar::new(1.0, 2.0, 0.5, 3.0, -1.0).unwrap();
    let one = LayeredBar::new(&[layer(1.0, 2.0, 0.5)], 3.0, -1.0).unwrap();
    let split = LayeredBar::new(
        &[
            layer(0.2, 2.0, 0.5),
            layer(0.45, 2.0, 0.5),
            layer(0.35, 2.0, 0.5),
        ],
        3.0,
        -1.0,
    )
    .unwrap();
    let transit = dalembert.transit_time();
    for bar in [&one, &split] {
        assert!((bar.transit_time() - transit).abs() < 1e-15);
        for j in 0..=90 {
            // Includes multiples of T/10, where fronts sit exactly on sample points.
            let t = 0.1 * j as f64 * transit;
            let field = bar.field(t).unwrap();
            // Equal impedances never reflect: only the load front and its end reflections.
            assert!(field.wave_count() <= 3 * 12, "{}", field.wave_count());
            for i in 0..=20 {
                let x = i as f64 / 20.0;
                assert!(
                    (field.stress(x) - dalembert.stress(x, t)).abs() < 1e-13,
                    "{x} {t}"
                );
                assert!((field.velocity(x) - dalembert.velocity(x, t)).abs() < 1e-13);
            }
            for (xa, xb) in [(0.0, 1.0), (0.13, 0.41), (0.5, 0.75)] {
                let exact = dalembert.stress_average(xa, xb, t);
                assert!((field.stress_average(xa, xb) - exact).abs() < 1e-13);
            }
            let (e, d) = (field.energies(), dalembert.energies(t));
            let scale = 1e-13 * (1.0 + d.work.abs());
            assert!((e.kinetic - d.kinetic).abs() < scale);
            assert!((e.strain - d.strain).abs() < scale);
            assert!((e.work - d.work).abs() < scale);
        }
    }
}

#[test]
fn interface_transmits_and_reflects_with_the_impedance_ratios_and_the_fixed_end_doubles() {
    // Soft (z = 1, c = 1) then stiff (z = 2, c = 2) and the reverse order.
    let soft = layer(0.5, 1.0, 1.0);
    let stiff = layer(0.5, 4.0, 1.0);
    assert_eq!(transmission_coefficient(1.0, 2.0), 4.0 / 3.0);
    assert_eq!(reflection_coefficient(1.0, 2.0), 1.0 / 3.0);
    assert_eq!(transmission_coefficient(2.0, 1.0), 2.0 / 3.0);
    assert_eq!(reflection_coefficient(2.0, 1.0), -1.0 / 3.0);
    for (first, second) in [(soft, stiff), (stiff, soft)] {
        let bar = LayeredBar::new(&[first, second], 1.0, -1.0).unwrap();
        let (z1, z2) = (first.impedance(), second.impedance());
        let (c1, c2) = (first.wave_speed(), second.wave_speed());
        let (trans, refl) = (
            transmission_coefficient(z1, z2),
            reflection_coefficient(z1, z2),
        );
        let s0 = bar.sigma0();
        // The front reaches the interface at t1; probe 40 % of the way to the fixed end.
        let t1 = 0.5 / c1;
        let dt = 0.4 * 0.5 / c2;
        let field = bar.field(t1 + dt).unwrap();
        // Transmitted plateau in layer 2, reflected plateau in layer 1 just behind the
        // interface, the incident plateau further back.
        let transmitted = field.state(0.5 + 0.5 * c2 * dt);
        let reflected = field.state(0.5 - 0.5 * c1 * dt);
        let incident = field.state(0.5 * (0.5 - c1 * dt));
        assert!((transmitted.stress - trans * s0).abs() < 1e-15);
        assert!((transmitted.velocity + trans * s0 / z2).abs() < 1e-15);
        assert!((reflected.stress - (1.0 + refl) * s0).abs() < 1e-15);
        assert!((reflected.velocity - (-s0 + refl * s0) / z1).abs() < 1e-15);
        assert!((incident.stress - s0).abs() < 1e-15);
        assert!((incident.velocity + s0 / z1).abs() < 1e-15);
        // Continuity across the interface (stress and velocity).
        assert!((transmitted.stress - reflected.stress).abs() < 1e-15);
        assert!((transmitted.velocity - reflected.velocity).abs() < 1e-15);
        // Ahead of the transmitted front: at rest.
        assert_eq!(field.stress(0.99), 0.0);
        // The fixed end doubles the transmitted stress and keeps v = 0.
        let at_end = bar.field(t1 + 0.5 / c2 + 0.1 * 0.5 / c2).unwrap();
        assert!((at_end.stress(1.0) - 2.0 * trans * s0).abs() < 1e-15);
        assert_eq!(at_end.velocity(1.0), 0.0);
        let fronts = field.front_positions();
        assert_eq!(fronts.len(), 2, "{fronts:?}");
    }
}

#[test]
fn energy_balance_work_equals_kinetic_plus_strain_over_many_reflections() {
    let bar = mixed_bar();
    let transit = bar.transit_time();
    let mut largest_count = 0;
    for j in 1..=120 {
        let t = 0.0517 * j as f64 * transit;
        let field = bar.field(t).unwrap();
        largest_count = largest_count.max(field.wave_count());
        let e = field.energies();
        assert!(e.work > 0.0);
        assert!(
            (e.work - e.kinetic - e.strain).abs() < 1e-12 * e.work,
            "t/T = {}: {e:?}",
            t / transit
        );
    }
    assert!(largest_count > 100, "{largest_count}");
}

#[test]
fn loaded_end_traction_and_fixed_end_rest_hold_and_load_displacement_integrates_velocity() {
    let bar = mixed_bar();
    let transit = bar.transit_time();
    let mut rate_checks = 0;
    for j in 1..=60 {
        let t = 0.0731 * j as f64 * transit;
        let field = bar.field(t).unwrap();
        assert!((field.stress(0.0) - bar.sigma0()).abs() < 1e-14);
        assert!(field.velocity(bar.length()).abs() < 1e-14);
        // u(0, t) = int v(0, t') dt': central difference where v(0, .) is constant.
        let h = 1e-7 * transit;
        let (before, after) = (bar.field(t - h).unwrap(), bar.field(t + h).unwrap());
        let rate = (after.load_displacement() - before.load_displacement()) / (2.0 * h);
        if (before.velocity(0.0) - after.velocity(0.0)).abs() == 0.0 {
            assert!(
                (rate - field.velocity(0.0)).abs() < 1e-6,
                "t/T {}",
                t / transit
            );
            rate_checks += 1;
        }
    }
    assert!(rate_checks >= 50, "{rate_checks}");
}

#[test]
fn element_averages_are_exact_against_fine_quadrature() {
    let bar = mixed_bar();
    let transit = bar.transit_time();
    for t_over_t in [0.4, 1.3, 2.7] {
        let field = bar.field(t_over_t * transit).unwrap();
        for (xa, xb) in [(0.0, 1.0), (0.05, 0.33), (0.29, 0.31), (0.6, 0.95)] {
            let average = field.stress_average(xa, xb);
            // Exact piecewise quadrature: split at interfaces and fronts, midpoint values.
            let mut cuts: Vec<f64> = vec![xa, xb];
            cuts.extend(bar.boundaries().iter().copied());
            cuts.extend(field.front_positions());
            cuts.retain(|&x| x >= xa && x <= xb);
            cuts.sort_by(f64::total_cmp);
            let piecewise: f64 = cuts
                .windows(2)
                .map(|w| (w[1] - w[0]) * field.stress(0.5 * (w[0] + w[1])))
                .sum::<f64>()
                / (xb - xa);
            assert!(
                (average - piecewise).abs() < 1e-13,
                "{average} vs {piecewise}"
            );
            // Blind composite midpoint rule: error at most (sum of jumps) * h/(xb - xa).
            let n = 20_000;
            let h = (xb - xa) / n as f64;
            let blind: f64 = (0..n)
                .map(|k| field.stress(xa + (k as f64 + 0.5) * h))
                .sum::<f64>()
                / n as f64;
            assert!(
                (average - blind).abs() < 50.0 * h / (xb - xa),
                "{average} vs {blind}"
            );
        }
    }
}

#[test]
fn equal_transit_layering_converges_to_the_graded_bar() {
    let graded = GradedBar::seed_fig2();
    let transit = graded.transit_time();
    let t = 0.7 * transit;
    let (xa, xb) = (0.05, 0.3); // behind the first front, before any reflection
    let exact = graded.stress_average(xa, xb, t);
    // An interface of every layering below (n divisible by 4): travel time 3T/4.
    let x_probe = graded.position_at_travel_time(0.75 * transit);
    let exact_jump = graded.first_jump(x_probe);
    let mut errors = Vec::new();
    for n in [20, 40, 80, 160] {
        let layered = LayeredBar::equal_transit_layers(&graded, n).unwrap();
        assert!((layered.transit_time() - transit).abs() < 1e-14);
        assert!((layered.boundaries()[3 * n / 4] - x_probe).abs() < 1e-14);
        let average_error = (layered.field(t).unwrap().stress_average(xa, xb) - exact).abs();
        // Just behind the first front at the probe: the product of the transmission
        // coefficients, which tends to sigma0 sqrt(Z(x)/Z1).
        let behind = layered
            .field(0.75 * transit + 1e-9)
            .unwrap()
            .stress(x_probe);
        errors.push((average_error, (behind - exact_jump).abs()));
    }
    for pair in errors.windows(2) {
        let (coarse, fine) = (pair[0], pair[1]);
        // At least first order: halving the layer thickness at least halves the error
        // (up to 20 %), both for the element average and for the front jump.
        assert!(fine.0 < coarse.0 / 1.6, "{errors:?}");
        assert!(fine.1 < coarse.1 / 1.6, "{errors:?}");
    }
    assert!(errors[3].0 < 1e-4 && errors[3].1 < 1e-2, "{errors:?}");
}

#[test]
fn invalid_layers_and_an_exceeded_wave_cap_give_named_errors() {
    for (index, name) in ["thickness", "modulus", "density"].iter().enumerate() {
        let mut p = [1.0, 1.0, 1.0];
        p[index] = -1.0;
        let err = Layer::new(p[0], p[1], p[2]).unwrap_err();
        assert!(matches!(err, ReferenceError::InvalidParameter { name: n, .. } if n == *name));
    }
    assert!(matches!(
        LayeredBar::new(&[], 1.0, 1.0).unwrap_err(),
        ReferenceError::InvalidParameter { name: "layers", .. }
    ));
    assert!(matches!(
        LayeredBar::new(&[layer(1.0, 1.0, 1.0)], 0.0, 1.0).unwrap_err(),
        ReferenceError::InvalidParameter { name: "area", .. }
    ));
    assert!(matches!(
        LayeredBar::new(&[layer(1.0, 1.0, 1.0)], 1.0, f64::NAN).unwrap_err(),
        ReferenceError::InvalidParameter { name: "sigma0", .. }
    ));
    let capped = mixed_bar().with_max_waves(50);
    let err = capped.field(20.0 * capped.transit_time()).unwrap_err();
    assert!(matches!(
        err,
        ReferenceError::InvalidParameter { name: "t", .. }
    ));
    assert!(capped.field(0.5 * capped.transit_time()).is_ok());
    assert!(mixed_bar().field(f64::INFINITY).is_err());
    // Before the load and outside the bar.
    let field = mixed_bar().field(-1.0).unwrap();
    assert_eq!(field.stress(0.5), 0.0);
    assert!(field.stress(1.5).is_nan());
    assert!(field.stress_average(0.6, 0.5).is_nan());
}
