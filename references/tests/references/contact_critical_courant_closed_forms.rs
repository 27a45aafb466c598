//! Checks of the contact stability references (`courant_references::contact`, part 1: critical
//! Courant numbers of penalty/bipenalty contact) that need no assembled bar: the localized mode
//! is the admissible root of both quadratics of the module docs (methods.md §7; Kopačka et al.,
//! IJNME 113 (2018)), the closed forms stay accurate from tiny to huge penalties, the bipenalty
//! limit tends to `1/sqrt(r)`, and invalid parameters are named. The comparison with the
//! eigenvalues of assembled lumped bars is in `contact_critical_courant_eigenvalues.rs`.

use courant_references::ReferenceError;
use courant_references::contact::{
    signorini_critical_courant_bipenalty, signorini_critical_courant_penalty,
    signorini_critical_courant_ratio, signorini_localized_mode, two_bar_critical_courant,
};

fn courant_of(lambda: f64) -> f64 {
    2.0 / lambda.sqrt()
}

/// `beta_s = 10^(k/4)`, k = -8..=32: a log grid from 1e-2 to 1e8.
fn beta_grid() -> Vec<f64> {
    (-8..=32).map(|k| 10f64.powf(f64::from(k) / 4.0)).collect()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

#[test]
fn localized_mode_is_the_admissible_root_of_both_quadratics() {
    for r in [1.5, 2.0, 4.0, 16.0] {
        for beta_s in [1e-2, 0.3, 1.0, 7.0, 1e3, 1e6] {
            let (kappa, mu) = (beta_s, beta_s / (4.0 * r));
            let mode = signorini_localized_mode(kappa, mu).unwrap().unwrap();
            let (q, lambda) = (mode.decay_ratio, mode.lambda);
            assert!(-1.0 < q && q < 0.0);
            assert!(lambda > 4.0);
            // Interior dispersion and the contact row.
            assert!(rel(2.0 - q - 1.0 / q, lambda) < 1e-13);
            assert!(rel(1.0 + kappa - (0.5 + mu) * lambda, q) < 1e-9 * (1.0 + kappa) / q.abs());
            // The quadratic in q, scaled by its largest term.
            let p = (mu - 0.5) * q * q + (kappa - 2.0 * mu) * q + (mu + 0.5);
            let scale = (mu - 0.5).abs() * q * q + (kappa - 2.0 * mu).abs() * q.abs() + mu + 0.5;
            assert!(p.abs() < 1e-13 * scale, "r = {r}, beta_s = {beta_s}: {p}");
            // Bracket by the nodal ratio and the Gershgorin row sum of the contact row.
            assert!((1.0 + kappa) / (0.5 + mu) < lambda);
            assert!(lambda < (2.0 + kappa) / (0.5 + mu));
            assert!(rel(mode.critical_courant, courant_of(lambda)) < 1e-14);
        }
    }
}

#[test]
fn penalty_form_is_accurate_from_tiny_to_huge_penalties() {
    // Tiny: Cr = 1 - beta_s^2/8 + ..., below half an ulp of 1 for beta_s = 1e-8.
    assert_eq!(signorini_critical_courant_penalty(1e-8).unwrap(), 1.0);
    assert_eq!(signorini_critical_courant_penalty(0.0).unwrap(), 1.0);
    let small = 1e-3;
    let series = 1.0 - small * small / 8.0;
    assert!(rel(signorini_critical_courant_penalty(small).unwrap(), series) < 1e-12);
    // Huge: Cr^2 = 2/(1 + beta sqrt(1 + 1/beta^2)) = 2/(1 + beta) to 1/(2 beta^2) relative.
    for beta_s in [1e8, 1e12, 1e100, 1e300] {
        let cr = signorini_critical_courant_penalty(beta_s).unwrap();
        let asymptote = (2.0 / (1.0 + beta_s)).sqrt();
        assert!(cr.is_finite() && cr > 0.0);
        assert!(rel(cr, asymptote) < 4.0 * f64::EPSILON, "{beta_s}: {cr}");
        // The bipenalty route with beta_m = 0 agrees.
        let bi = signorini_critical_courant_bipenalty(beta_s, 0.0).unwrap();
        assert!(rel(bi, cr) < 8.0 * f64::EPSILON, "{beta_s}: {bi} vs {cr}");
    }
}

#[test]
fn bipenalty_tends_to_one_over_sqrt_r() {
    for r in [1.5, 2.0, 4.0, 16.0, 100.0] {
        let cr = signorini_critical_courant_ratio(1e12, r).unwrap();
        assert!(rel(cr, 1.0 / r.sqrt()) < 1e-10, "r = {r}: {cr}");
        // Monotone decrease in beta_s at fixed r.
        let mut previous = 1.0;
        for beta_s in beta_grid() {
            let c = signorini_critical_courant_ratio(beta_s, r).unwrap();
            assert!(c <= previous && c > 1.0 / r.sqrt());
            previous = c;
        }
    }
    assert_eq!(
        signorini_critical_courant_ratio(1e6, f64::INFINITY).unwrap(),
        signorini_critical_courant_penalty(1e6).unwrap()
    );
}

#[test]
fn invalid_stability_parameters_are_rejected() {
    let name = |e: ReferenceError| match e {
        ReferenceError::InvalidParameter { name, .. } => name,
        _ => "other",
    };
    assert_eq!(
        name(signorini_critical_courant_penalty(-1.0).unwrap_err()),
        "beta_s"
    );
    assert_eq!(
        name(signorini_critical_courant_bipenalty(1.0, f64::NAN).unwrap_err()),
        "beta_m"
    );
    assert_eq!(
        name(signorini_critical_courant_ratio(1.0, 0.0).unwrap_err()),
        "r"
    );
    assert_eq!(
        name(signorini_critical_courant_penalty(f64::INFINITY).unwrap_err()),
        "beta_s"
    );
    assert_eq!(
        name(two_bar_critical_courant(1.0, -1.0).unwrap_err()),
        "beta_m"
    );
}
