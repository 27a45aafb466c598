//! Source of truth: the Noh-Bathe update (Noh & Bathe, Comput. Struct. 129 (2013) 178-193; the
//! equations as OpenSees `ExplicitBathe`) reduced to one degree of freedom, whose amplification
//! matrix on `(u, dt v)` was derived in closed form for courant (module docs of
//! `courant_solver::schemes::noh_bathe`; an independent numpy implementation of the scheme gave
//! the same numbers).
//!
//! ```text
//!   one element, fixed-free, lumped:  m = 1/2, k = E   =>   omega^2 = 2E
//!   (u, dt v)^{n+1} = A(Omega, p) (u, dt v)^n,   Omega = omega dt
//! ```
//!
//! Proves: (1) one step of courant's scheme equals A to 1e-14 at every Omega up to its limit
//! and for every p in [1/2, 3/4], and gives the reference implementation's numbers; (2) the
//! closed-form limit `Omega_crit = 2/sqrt((1-p)(3p-1))` is the largest Omega with spectral
//! radius <= 1 (a dense scan), the radius returns to 1 there and is smallest at `2/p` with
//! value `(p^2 - 4p + 2)/p^2`; (3) the modified energy `E_mod = T + U - (p dt)^2/8 a M a`
//! changes by exactly `det A` per step; (4) at p = 1/2 the scheme is two central-difference
//! half steps on a loaded graded bar, to round-off.

use crate::common;

use common::{amplification, determinant, noh_bathe, run, spectral_radius};
use courant_solver::bench::graded_seed_bar;
use courant_solver::schemes::noh_bathe::NohBatheScheme;
use courant_solver::{
    Bar, CentralDifference, InitialConditions, MassKind, Mesh, Model, OutputRequest, Supports,
};

/// One step of the scheme on the one-element bar with omega = 3: `(u1, dt v1)` and the
/// modified energies before and after.
fn one_step(p: f64, dt: f64, u0: f64, v0: f64) -> ([f64; 2], [f64; 2]) {
    // omega^2 = k/m = E/(1/2): E = 4.5 gives omega = 3.
    let model = Model::new(
        Bar::homogeneous(Mesh::uniform(1.0, 1).unwrap(), 4.5, 1.0, 1.0).unwrap(),
        Supports::FREE_FIXED,
        &[],
        InitialConditions {
            displacement: Some(vec![u0, 0.0]),
            velocity: Some(vec![v0, 0.0]),
        },
    )
    .unwrap();
    let out = run(&noh_bathe(p, dt, MassKind::Lumped, true), &model, 1, &[0]).unwrap();
    let s = out.histories[0].samples[1];
    let e = &out.energy.samples;
    let modified = |i: usize| e[i].kinetic_staggered + e[i].strain;
    (
        [s.displacement, dt * s.velocity],
        [modified(0), modified(1)],
    )
}

#[test]
fn one_step_equals_the_closed_form_amplification_matrix() {
    let omega = 3.0;
    for p in [0.5, 0.54, 0.6, 0.7, 0.75] {
        let limit = NohBatheScheme::critical_omega(p);
        for w in [0.01, 0.1, 0.5, 1.0, 2.0, 3.0, 2.0 / p, 0.999 * limit, limit] {
            let (u0, v0) = (0.7, -0.2);
            let dt = w / omega;
            let ([u1, dtv1], [e0, e1]) = one_step(p, dt, u0, v0);
            let a = amplification(w, p);
            let expected = [
                a[0][0] * u0 + a[0][1] * dt * v0,
                a[1][0] * u0 + a[1][1] * dt * v0,
            ];
            let scale = u0.abs().max((dt * v0).abs()).max(expected[1].abs());
            assert!(
                (u1 - expected[0]).abs() <= 1e-14 * scale,
                "p {p}, W {w}: u {u1} vs {}",
                expected[0]
            );
            assert!(
                (dtv1 - expected[1]).abs() <= 1e-14 * scale,
                "p {p}, W {w}: dt v {dtv1} vs {}",
                expected[1]
            );
            // E_mod is the quadratic form Q of A^T Q A = det(A) Q: it changes by det A exactly.
            assert!(
                (e1 - determinant(w, p) * e0).abs() <= 1e-13 * e0.abs(),
                "p {p}, W {w}: E_mod {e0} -> {e1}, det {}",
                determinant(w, p)
            );
        }
    }
    // The reference implementation's numbers (numpy, the same equations): omega = 3, dt = 0.3.
    let ([u1, dtv1], _) = one_step(0.54, 0.3, 0.7, -0.2);
    assert!((u1 - 0.377937280180).abs() < 1e-12, "{u1}");
    assert!((dtv1 + 0.516866216175).abs() < 1e-12, "{dtv1}");
}

#[test]
fn the_closed_form_limit_is_where_the_spectral_radius_leaves_one() {
    for p in [0.5, 0.52, 0.54, 0.6, 0.65, 0.7, 0.75] {
        let limit = NohBatheScheme::critical_omega(p);
        // A11 = A22 and det A as stated.
        let a = amplification(1.3, p);
        assert_eq!(a[0][0], a[1][1]);
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        assert!((det - determinant(1.3, p)).abs() < 1e-14, "p {p}");
        // Radius <= 1 on [0, Omega_crit] (20001 points), 1 at the limit, > 1 just above.
        let worst = (0..=20_000)
            .map(|k| spectral_radius(amplification(limit * k as f64 / 20_000.0, p)))
            .fold(0.0_f64, f64::max);
        assert!(
            worst <= 1.0 + 1e-12,
            "p {p}: radius {worst} below the limit"
        );
        assert!(
            (spectral_radius(amplification(limit, p)) - 1.0).abs() < 1e-9,
            "p {p}"
        );
        assert!(
            spectral_radius(amplification(1.0001 * limit, p)) > 1.0,
            "p {p}"
        );
        // Strongest damping at the bifurcation Omega = 2/p (a double real eigenvalue).
        let at_bifurcation = spectral_radius(amplification(2.0 / p, p));
        let expected = (p * p - 4.0 * p + 2.0) / (p * p);
        assert!(
            (at_bifurcation - expected.abs()).abs() < 1e-6,
            "p {p}: {at_bifurcation} vs {expected}"
        );
    }
    // p = 0.54: 1.8725 times central difference's Omega = 2, radius 0.4513 at 2/p.
    let limit = NohBatheScheme::critical_omega(0.54);
    assert!((limit / 2.0 - 1.87251).abs() < 1e-5, "{limit}");
    assert!((spectral_radius(amplification(2.0 / 0.54, 0.54)) - 0.451303).abs() < 1e-5);
}

#[test]
fn at_p_one_half_the_scheme_is_two_central_difference_half_steps() {
    let model = graded_seed_bar(50).unwrap();
    let dt = 1.5 * model.bar().stiffest_element().1;
    let steps = 200;
    let request = OutputRequest {
        profile_steps: (0..=steps).step_by(10).collect(),
        history_nodes: vec![0, 25],
        ..OutputRequest::default()
    };
    let nb = noh_bathe(0.5, dt, MassKind::Lumped, false)
        .run(&model, steps, &request)
        .unwrap();
    let half = OutputRequest {
        profile_steps: (0..=2 * steps).step_by(20).collect(),
        history_nodes: vec![0, 25],
        history_every: 2,
        ..OutputRequest::default()
    };
    let cd = CentralDifference::new(0.5 * dt)
        .run(&model, 2 * steps, &half)
        .unwrap();
    let peak = cd
        .profiles
        .iter()
        .flat_map(|p| p.stress.iter())
        .fold(0.0_f64, |m, s| m.max(s.abs()));
    assert_eq!(nb.profiles.len(), cd.profiles.len());
    for (a, b) in nb.profiles.iter().zip(&cd.profiles) {
        for (x, y) in a.stress.iter().zip(&b.stress) {
            assert!((x - y).abs() <= 1e-12 * peak, "t {}: {x} vs {y}", a.time);
        }
    }
    for (a, b) in nb.histories.iter().zip(&cd.histories) {
        assert_eq!(a.samples.len(), b.samples.len());
        for (x, y) in a.samples.iter().zip(&b.samples) {
            assert!((x.displacement - y.displacement).abs() <= 1e-12 * peak);
            assert!(
                (x.velocity - y.velocity).abs() <= 1e-12 * peak,
                "node {}: {x:?} vs {y:?}",
                a.node
            );
        }
    }
}
