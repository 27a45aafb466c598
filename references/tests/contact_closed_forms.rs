//! Checks of the contact references (`courant_references::contact`) against independent
//! computations done here, with no solver.
//!
//! Part 1, stability of penalty/bipenalty contact: the closed-form critical Courant numbers are
//! compared with the largest eigenvalue of a lumped bar assembled in this file (tridiagonal K and
//! M, the contact spring k_s and penalty mass m_p on the contact node), found by bisection on
//! Sturm counts of the pencil `K - x M` (Sylvester's law of inertia: the number of negative
//! pivots of its LDL^T factorisation is the number of eigenvalues below x). The far end is free:
//! there the contact-free top of the spectrum is exactly Lambda = 4 (the pi-mode, Cr = 1, as for
//! the semi-infinite bar), and the localized contact mode decays like |q|^j, so the far end moves
//! it only by O(|q|^(2N)); N is doubled until Lambda_max is converged to 1e-13, and one test
//! shows that a fixed far end gives the same value.
//!
//! Part 2, impact: the exact wave-tracking force histories are compared with a brute-force
//! characteristic lattice written here (each bar cut into cells of one time step's travel,
//! Riemann invariants shifted cell by cell, free-end reflections, unilateral contact with a
//! tracked gap), which also gives each bar's momentum and energy after separation; with hand
//! results (plateaus, durations, impulses) and limits (Z2 -> Z1, Z2 -> inf).

use courant_references::ReferenceError;
use courant_references::contact::{
    ImpactBar, ImpactForce, ImpactTarget, PenaltyWallForce, signorini_critical_courant_bipenalty,
    signorini_critical_courant_penalty, signorini_critical_courant_ratio, signorini_localized_mode,
    two_bar_critical_courant,
};

// =============================================================================================
// Part 1: eigenvalues of assembled lumped bars
// =============================================================================================

/// Steel-like bar data in SI units (so the dimensionless mapping is exercised): E [Pa],
/// rho [kg/m^3], A [m^2], L [m].
const E: f64 = 2.1e11;
const RHO: f64 = 7850.0;
const AREA: f64 = 1e-4;
const LENGTH: f64 = 0.5;

/// A symmetric tridiagonal pencil (K, M), M positive definite.
#[derive(Debug, Clone)]
struct Pencil {
    k_diag: Vec<f64>,
    k_off: Vec<f64>,
    m_diag: Vec<f64>,
    m_off: Vec<f64>,
}

impl Pencil {
    fn zeros(n: usize) -> Self {
        Self {
            k_diag: vec![0.0; n],
            k_off: vec![0.0; n - 1],
            m_diag: vec![0.0; n],
            m_off: vec![0.0; n - 1],
        }
    }

    fn len(&self) -> usize {
        self.k_diag.len()
    }

    /// Adds the element (nodes i, i+1) with stiffness k and lumped mass m.
    fn add_element(&mut self, i: usize, k: f64, m: f64) {
        self.k_diag[i] += k;
        self.k_diag[i + 1] += k;
        self.k_off[i] -= k;
        self.m_diag[i] += 0.5 * m;
        self.m_diag[i + 1] += 0.5 * m;
    }

    /// Number of eigenvalues of `K u = lambda M u` below x: negative pivots of `K - x M`.
    fn count_below(&self, x: f64) -> usize {
        let mut count = 0;
        let mut pivot = 1.0;
        for i in 0..self.len() {
            let diag = self.k_diag[i] - x * self.m_diag[i];
            pivot = if i == 0 {
                diag
            } else {
                let off = self.k_off[i - 1] - x * self.m_off[i - 1];
                diag - off * off / pivot
            };
            if pivot == 0.0 {
                pivot = -f64::EPSILON * (diag.abs() + f64::MIN_POSITIVE);
            }
            if pivot < 0.0 {
                count += 1;
            }
        }
        count
    }

    /// Largest eigenvalue by bisection on Sturm counts, to a relative width of ~2 ulps.
    fn lambda_max(&self) -> f64 {
        let n = self.len();
        let mut hi = (0..n)
            .map(|i| self.k_diag[i] / self.m_diag[i])
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE);
        while self.count_below(hi) < n {
            hi *= 2.0;
        }
        let mut lo = 0.0;
        for _ in 0..2000 {
            if hi - lo <= 2.0 * f64::EPSILON * hi {
                break;
            }
            let mid = 0.5 * (lo + hi);
            if self.count_below(mid) == n {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        0.5 * (lo + hi)
    }
}

/// Element data of an N-element bar of [`LENGTH`]: (h, k = EA/h, m = rho A h, c^2/h^2).
fn element_data(elements: usize) -> (f64, f64, f64, f64) {
    let h = LENGTH / elements as f64;
    let c2 = E / RHO;
    (h, E * AREA / h, RHO * AREA * h, c2 / (h * h))
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum FarEnd {
    Free,
    Fixed,
}

/// Bar of N lumped elements with a rigid-wall contact at node 0 carrying `k_s = beta_s k` and
/// `m_p = beta_m m`; returns the pencil and `c^2/h^2`.
fn wall_bar(elements: usize, beta_s: f64, beta_m: f64, far: FarEnd) -> (Pencil, f64) {
    let (_, k, m, c2_h2) = element_data(elements);
    let mut p = Pencil::zeros(elements + 1);
    for e in 0..elements {
        p.add_element(e, k, m);
    }
    p.k_diag[0] += beta_s * k;
    p.m_diag[0] += beta_m * m;
    if far == FarEnd::Fixed {
        // Dirichlet at node N: delete its row and column.
        p.k_diag.pop();
        p.m_diag.pop();
        p.k_off.pop();
        p.m_off.pop();
    }
    (p, c2_h2)
}

/// Two equal bars of N elements each, joined at nodes N and N+1 by the relative link
/// `K_p = k_s [[1,-1],[-1,1]]`, `M_p = m_p [[1,-1],[-1,1]]` (methods.md §7); far ends free.
fn two_bars(elements: usize, beta_s: f64, beta_m: f64) -> (Pencil, f64) {
    let (_, k, m, c2_h2) = element_data(elements);
    let mut p = Pencil::zeros(2 * elements + 2);
    for e in 0..elements {
        p.add_element(e, k, m);
        p.add_element(elements + 1 + e, k, m);
    }
    let (a, b) = (elements, elements + 1);
    let (ks, mp) = (beta_s * k, beta_m * m);
    p.k_diag[a] += ks;
    p.k_diag[b] += ks;
    p.k_off[a] = -ks;
    p.m_diag[a] += mp;
    p.m_diag[b] += mp;
    p.m_off[a] = -mp;
    (p, c2_h2)
}

/// `Lambda_max = lambda_max h^2/c^2` of the assembled bar.
fn lambda_of(pencil_and_scale: (Pencil, f64)) -> f64 {
    let (p, c2_h2) = pencil_and_scale;
    p.lambda_max() / c2_h2
}

/// `Lambda_max` converged in N: doubles N from 200 until two meshes agree to 1e-13.
fn converged_lambda(build: impl Fn(usize) -> (Pencil, f64)) -> f64 {
    let mut n = 200;
    let mut previous = lambda_of(build(n));
    loop {
        n *= 2;
        let current = lambda_of(build(n));
        if (current - previous).abs() <= 1e-13 * current {
            return current;
        }
        assert!(
            n < 400_000,
            "Lambda_max not converged in N: {previous} vs {current}"
        );
        previous = current;
    }
}

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
fn penalty_only_matches_the_eigenvalues_of_an_assembled_bar() {
    let mut worst: f64 = 0.0;
    for beta_s in beta_grid() {
        let numeric = courant_of(converged_lambda(|n| wall_bar(n, beta_s, 0.0, FarEnd::Free)));
        let closed = signorini_critical_courant_penalty(beta_s).unwrap();
        worst = worst.max(rel(closed, numeric));
        assert!(
            rel(closed, numeric) < 1e-8,
            "beta_s = {beta_s}: closed {closed} vs eigenvalue {numeric}"
        );
    }
    assert!(worst < 1e-8, "worst relative error {worst}");
}

#[test]
fn bipenalty_matches_the_eigenvalues_of_an_assembled_bar_for_r_above_one() {
    for r in [2.0, 4.0, 16.0] {
        for beta_s in beta_grid() {
            let beta_m = beta_s / (4.0 * r);
            let numeric = courant_of(converged_lambda(|n| {
                wall_bar(n, beta_s, beta_m, FarEnd::Free)
            }));
            let closed = signorini_critical_courant_bipenalty(beta_s, beta_m).unwrap();
            let by_ratio = signorini_critical_courant_ratio(beta_s, r).unwrap();
            assert!(
                rel(closed, numeric) < 1e-8,
                "r = {r}, beta_s = {beta_s}: closed {closed} vs eigenvalue {numeric}"
            );
            assert!(rel(by_ratio, closed) < 1e-14, "r = {r}, beta_s = {beta_s}");
            assert!(closed < 1.0);
        }
    }
}

#[test]
fn ratio_at_most_one_keeps_the_contact_free_courant_number() {
    // Free far end: the contact-free bar has Lambda_max = 4 exactly (Cr = 1); r <= 1 must not
    // raise it for any beta_s (the sign-flip argument of the module docs), and the closed form
    // returns exactly 1.
    for r in [0.25, 0.5, 0.99, 1.0] {
        for beta_s in beta_grid().into_iter().chain([1e10, 1e12]) {
            let beta_m = beta_s / (4.0 * r);
            let lambda = lambda_of(wall_bar(200, beta_s, beta_m, FarEnd::Free));
            assert!(
                lambda <= 4.0 * (1.0 + 1e-12),
                "r = {r}, beta_s = {beta_s}: Lambda_max = {lambda} > 4"
            );
            // Finite bar: Cr is at most slightly above the semi-infinite value 1.
            assert!(courant_of(lambda) < 1.0 + 1e-3);
            assert_eq!(
                signorini_critical_courant_bipenalty(beta_s, beta_m).unwrap(),
                1.0
            );
            assert_eq!(signorini_critical_courant_ratio(beta_s, r).unwrap(), 1.0);
            assert!(signorini_localized_mode(beta_s, beta_m).unwrap().is_none());
        }
    }
}

#[test]
fn beta_s_over_beta_m_equal_to_four_is_a_sharp_threshold() {
    for beta_s in [1e2, 1e4, 1e6, 1e8] {
        // Slightly below 4: no localized mode, Lambda_max <= 4.
        let beta_m_below = beta_s / (4.0 * (1.0 - 1e-3));
        let lambda_below = lambda_of(wall_bar(200, beta_s, beta_m_below, FarEnd::Free));
        assert!(
            lambda_below <= 4.0 * (1.0 + 1e-12),
            "beta_s = {beta_s}: {lambda_below}"
        );
        assert_eq!(
            signorini_critical_courant_bipenalty(beta_s, beta_m_below).unwrap(),
            1.0
        );
        // Exactly 4.
        let lambda_at = lambda_of(wall_bar(200, beta_s, beta_s / 4.0, FarEnd::Free));
        assert!(
            lambda_at <= 4.0 * (1.0 + 1e-12),
            "beta_s = {beta_s}: {lambda_at}"
        );
        // Slightly above 4: a localized mode appears, Cr < 1, and the closed form holds.
        let beta_m_above = beta_s / (4.0 * (1.0 + 1e-3));
        let lambda_above = converged_lambda(|n| wall_bar(n, beta_s, beta_m_above, FarEnd::Free));
        assert!(
            lambda_above > 4.0 * (1.0 + 1e-5),
            "beta_s = {beta_s}: {lambda_above}"
        );
        let closed = signorini_critical_courant_bipenalty(beta_s, beta_m_above).unwrap();
        assert!(closed < 1.0);
        assert!(
            rel(closed, courant_of(lambda_above)) < 1e-8,
            "beta_s = {beta_s}"
        );
    }
}

#[test]
fn far_end_condition_does_not_change_the_localized_mode() {
    for (beta_s, beta_m) in [(10.0, 0.0), (1e4, 1e4 / 16.0), (3.0, 0.1)] {
        let free = lambda_of(wall_bar(400, beta_s, beta_m, FarEnd::Free));
        let fixed = lambda_of(wall_bar(400, beta_s, beta_m, FarEnd::Fixed));
        assert!(
            rel(free, fixed) < 1e-13,
            "{beta_s}, {beta_m}: {free} vs {fixed}"
        );
    }
    // Contact-free: free-free gives exactly 4 (Cr = 1), fixed-free 4 cos^2(pi/(4N)).
    let n = 200;
    let free = lambda_of(wall_bar(n, 0.0, 0.0, FarEnd::Free));
    let fixed = lambda_of(wall_bar(n, 0.0, 0.0, FarEnd::Fixed));
    assert!(rel(free, 4.0) < 1e-13);
    let expected = 4.0 * (std::f64::consts::PI / (4.0 * n as f64)).cos().powi(2);
    assert!(rel(fixed, expected) < 1e-13, "{fixed} vs {expected}");
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
fn naive_quadratic_formula_loses_the_digits_the_stable_form_keeps() {
    // Textbook roots of (mu^2 - 1/4) L^2 + (1 - 2 mu kappa) L + kappa^2 = 0 against the
    // eigenvalue of the assembled bar, r = 4, large beta_s.
    let mut naive_worst: f64 = 0.0;
    for beta_s in [1e8, 1e9, 1e10] {
        let (kappa, mu) = (beta_s, beta_s / 16.0);
        let exact = converged_lambda(|n| wall_bar(n, kappa, mu, FarEnd::Free));
        let (a, b, c) = (mu * mu - 0.25, 1.0 - 2.0 * mu * kappa, kappa * kappa);
        let disc = b * b - 4.0 * a * c;
        let naive = if disc >= 0.0 {
            let roots = [
                (-b + disc.sqrt()) / (2.0 * a),
                (-b - disc.sqrt()) / (2.0 * a),
            ];
            // Best case for the naive form: take whichever root is closer.
            roots
                .iter()
                .map(|l| rel(*l, exact))
                .fold(f64::INFINITY, f64::min)
        } else {
            f64::INFINITY
        };
        naive_worst = naive_worst.max(naive);
        let stable = signorini_localized_mode(kappa, mu).unwrap().unwrap().lambda;
        assert!(
            rel(stable, exact) < 1e-12,
            "beta_s = {beta_s}: {stable} vs {exact}"
        );
        // The discriminant itself: 1 + kappa (kappa - 4 mu) exactly representable here.
        let true_disc = 1.0 + kappa * (kappa - 4.0 * mu);
        assert!(
            rel(disc, true_disc) > 1e-6 || disc < 0.0,
            "beta_s = {beta_s}"
        );
    }
    assert!(
        naive_worst > 1e-9,
        "naive formula unexpectedly accurate: {naive_worst}"
    );
}

#[test]
fn nodal_estimate_is_not_conservative_and_row_sums_are() {
    // Lumped M is diagonal, so M^-1 K has rows K_ij/M_ii: nodal estimate max K_ii/M_ii,
    // Gershgorin bound max sum_j |K_ij|/M_ii.
    let cases = [
        (0.1, 0.0),
        (1.0, 0.0),
        (10.0, 0.0),
        (1e3, 0.0),
        (1e6, 0.0),
        (10.0, 10.0 / 16.0),
        (1e4, 1e4 / 16.0),
    ];
    for (beta_s, beta_m) in cases {
        let (p, c2_h2) = wall_bar(200, beta_s, beta_m, FarEnd::Free);
        let n = p.len();
        let lambda_max = p.lambda_max();
        let nodal = (0..n)
            .map(|i| p.k_diag[i] / p.m_diag[i])
            .fold(0.0, f64::max);
        let gershgorin = (0..n)
            .map(|i| {
                let left = if i > 0 { p.k_off[i - 1].abs() } else { 0.0 };
                let right = if i + 1 < n { p.k_off[i].abs() } else { 0.0 };
                (p.k_diag[i].abs() + left + right) / p.m_diag[i]
            })
            .fold(0.0, f64::max);
        assert!(
            nodal < lambda_max,
            "{beta_s}, {beta_m}: nodal {nodal} >= {lambda_max}"
        );
        assert!(gershgorin >= lambda_max, "{beta_s}, {beta_m}");
        // In Courant numbers: the nodal estimate allows a step that is unstable.
        let cr_true = courant_of(lambda_max / c2_h2);
        assert!(courant_of(nodal / c2_h2) > cr_true);
        assert!(courant_of(gershgorin / c2_h2) <= cr_true);
        // Penalty only: the literal (k + k_s)/m with the element mass is lower still.
        if beta_m == 0.0 {
            let (_, k, m, _) = element_data(200);
            assert!((k + beta_s * k) / m < lambda_max);
        }
    }
    // A concrete case: beta_s = 1, penalty only. Nodal Lambda = 2 (1 + 1) = 4 gives Cr = 1;
    // the true Cr is sqrt(2/(1 + sqrt 2)) = 0.910.
    let cr = signorini_critical_courant_penalty(1.0).unwrap();
    assert!((cr - (2.0 / (1.0 + 2f64.sqrt())).sqrt()).abs() < 1e-15 && cr < 0.911);
}

#[test]
fn two_bars_with_a_relative_link_match_the_doubled_wall() {
    let grid: Vec<f64> = (-4..=16).map(|k| 10f64.powf(f64::from(k) / 2.0)).collect();
    for beta_s in grid {
        for r in [2.0, 4.0, 16.0, f64::INFINITY] {
            let beta_m = if r.is_infinite() {
                0.0
            } else {
                beta_s / (4.0 * r)
            };
            let numeric = courant_of(converged_lambda(|n| two_bars(n, beta_s, beta_m)));
            let closed = two_bar_critical_courant(beta_s, beta_m).unwrap();
            assert!(
                rel(closed, numeric) < 1e-8,
                "beta_s = {beta_s}, r = {r}: closed {closed} vs eigenvalue {numeric}"
            );
            if r.is_infinite() {
                // methods.md: Cr_two(beta_s) = Cr_wall(2 beta_s).
                let wall = signorini_critical_courant_penalty(2.0 * beta_s).unwrap();
                assert!(rel(closed, wall) < 1e-14);
            }
        }
        // r <= 1 stays neutral for two bars too.
        // The assembled diagonal k + k_s carries a rounding error of eps k_s, and the in-phase
        // pi-mode (u_a = u_b, link unstretched, Lambda = 4, modal mass ~ 2N m without m_p)
        // feels it as a spring of that size: tolerance eps beta_s/N on top of 1e-12.
        for r in [0.5, 1.0] {
            let lambda = lambda_of(two_bars(200, beta_s, beta_s / (4.0 * r)));
            let tol = 1e-12 + 8.0 * f64::EPSILON * beta_s / 200.0;
            assert!(
                lambda <= 4.0 * (1.0 + tol),
                "beta_s = {beta_s}, r = {r}: {lambda}"
            );
            assert_eq!(
                two_bar_critical_courant(beta_s, beta_s / (4.0 * r)).unwrap(),
                1.0
            );
        }
    }
    // The mass penalty must be doubled too: the wall with (2 beta_s, beta_m) is different.
    let (beta_s, beta_m) = (10.0, 10.0 / 8.0);
    let numeric = courant_of(converged_lambda(|n| two_bars(n, beta_s, beta_m)));
    let wrong = signorini_critical_courant_bipenalty(2.0 * beta_s, beta_m).unwrap();
    assert!(rel(wrong, numeric) > 1e-3);
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

// =============================================================================================
// Part 2: impact, against a brute-force characteristic lattice
// =============================================================================================

/// One bar of the lattice: cell k holds the right-going invariant `alpha = N - Z v` and the
/// left-going `beta = N + Z v`; each cell is one time step's travel long (mass Z dt).
#[derive(Debug, Clone)]
struct LatticeBar {
    z: f64,
    alpha: Vec<f64>,
    beta: Vec<f64>,
}

impl LatticeBar {
    fn new(z: f64, cells: usize, v: f64) -> Self {
        Self {
            z,
            alpha: vec![-z * v; cells],
            beta: vec![z * v; cells],
        }
    }

    /// Momentum `sum Z dt v`, `v = (beta - alpha)/(2Z)`.
    fn momentum(&self, dt: f64) -> f64 {
        self.alpha
            .iter()
            .zip(&self.beta)
            .map(|(a, b)| 0.5 * dt * (b - a))
            .sum()
    }

    /// Energy: density `(alpha^2 + beta^2)/(4 E A)` over cells of length `c dt`, i.e.
    /// `(alpha^2 + beta^2) dt/(4 Z)` per cell.
    fn energy(&self, dt: f64) -> f64 {
        self.alpha
            .iter()
            .zip(&self.beta)
            .map(|(a, b)| (a * a + b * b) * dt / (4.0 * self.z))
            .sum()
    }
}

/// Result of a lattice run.
#[derive(Debug, Clone)]
struct LatticeRun {
    /// Contact force (compression positive) on each step `[k dt, (k+1) dt)`.
    force: Vec<f64>,
    /// Step at which the gap first opened.
    opened: Option<usize>,
    /// Striker (momentum, energy) and target (momentum, energy) right after the gap opened.
    after: Option<(f64, f64, f64, f64)>,
}

/// Brute-force characteristic lattice: striker of `n1` cells (impedance z1, velocity v0) on a
/// target of `n2` cells (impedance z2, at rest) or a rigid wall (`target = None`); far ends free,
/// unilateral contact with a gap. Exact when both transit times are whole numbers of steps.
fn lattice(z1: f64, n1: usize, v0: f64, target: Option<(f64, usize)>, steps: usize) -> LatticeRun {
    let dt = 1.0;
    let mut s = LatticeBar::new(z1, n1, v0);
    let mut t = target.map(|(z2, n2)| LatticeBar::new(z2, n2, 0.0));
    let mut gap = 0.0;
    let tol = 1e-13 * z1 * v0;
    let mut run = LatticeRun {
        force: Vec::new(),
        opened: None,
        after: None,
    };
    for step in 0..steps {
        let a = s.alpha[n1 - 1];
        let b = t.as_ref().map_or(0.0, |t| t.beta[0]);
        let z2 = t.as_ref().map_or(f64::INFINITY, |t| t.z);
        let welded_n = if t.is_some() {
            (z2 * a + z1 * b) / (z1 + z2)
        } else {
            a
        };
        let (n, v1, v2) = if gap <= 0.0 && welded_n <= tol {
            let v = if t.is_some() {
                (b - a) / (z1 + z2)
            } else {
                0.0
            };
            (welded_n.min(0.0), v, v)
        } else {
            if run.opened.is_none() {
                run.opened = Some(step);
                let (p2, e2) = t
                    .as_ref()
                    .map_or((0.0, 0.0), |t| (t.momentum(dt), t.energy(dt)));
                run.after = Some((s.momentum(dt), s.energy(dt), p2, e2));
            }
            let v2 = if t.is_some() { b / z2 } else { 0.0 };
            (0.0, -a / z1, v2)
        };
        run.force.push(-n);
        if run.opened.is_some() {
            gap += dt * (v2 - v1);
        }
        // Shift the striker: alpha to the right, beta to the left, free far end at cell 0.
        let reflected = -s.beta[0];
        s.alpha.rotate_right(1);
        s.alpha[0] = reflected;
        s.beta.rotate_left(1);
        s.beta[n1 - 1] = n + z1 * v1;
        if let Some(t) = t.as_mut() {
            let n2 = t.alpha.len();
            let reflected = -t.alpha[n2 - 1];
            t.alpha.rotate_right(1);
            t.alpha[0] = n - z2 * v2;
            t.beta.rotate_left(1);
            t.beta[n2 - 1] = reflected;
        }
    }
    run
}

/// A case with transit times of whole lattice steps: `(Z1, n1)` on `(Z2, n2)`; wave speeds are
/// arbitrary (lengths follow from them), v0 = 3.
fn compare_with_lattice(z1: f64, n1: usize, target: Option<(f64, usize)>) -> ImpactForce {
    let v0 = 3.0;
    let (c1, c2) = (1.3, 0.7);
    let striker = ImpactBar::new(z1, c1, c1 * n1 as f64).unwrap();
    let impact = match target {
        Some((z2, n2)) => {
            ImpactForce::new(striker, ImpactBar::new(z2, c2, c2 * n2 as f64).unwrap(), v0).unwrap()
        }
        None => ImpactForce::rigid_wall(striker, v0).unwrap(),
    };
    let steps = 40 * (n1 + target.map_or(0, |t| t.1));
    let run = lattice(z1, n1, v0, target, steps);
    let opened = run.opened.expect("the lattice contact never opened");
    let scale = z1 * v0;
    for (k, f) in run.force.iter().enumerate().take(opened + 5) {
        let t = k as f64 + 0.5;
        let reference = impact.force(t);
        assert!(
            (reference - f).abs() < 1e-12 * scale,
            "Z2/Z1 = {:?}, n1 = {n1}: step {k}: wave tracking {reference} vs lattice {f}",
            target.map(|t| (t.0 / z1, t.1))
        );
    }
    assert!(rel(impact.separation_time(), opened as f64) < 1e-12);
    // Momentum and energy of each bar after separation, from the lattice fields.
    let (p1, e1, p2, e2) = run.after.unwrap();
    let m1 = striker.mass();
    let (momentum0, energy0) = (m1 * v0, 0.5 * m1 * v0 * v0);
    let impulse = impact.impulse();
    assert!(
        rel(momentum0 - p1, impulse) < 1e-12,
        "striker momentum loss vs impulse"
    );
    assert!(
        rel(e1 + e2, energy0) < 1e-12,
        "lattice energy not conserved"
    );
    // The striker's energy loss is the work done through the interface.
    let work = impact.energy_transferred();
    assert!(
        (energy0 - e1 - work).abs() < 1e-12 * energy0,
        "striker energy loss vs work"
    );
    if target.is_some() {
        assert!(rel(p2, impulse) < 1e-12, "target momentum vs impulse");
        assert!(
            rel(e2, impact.energy_transferred()) < 1e-12,
            "target energy vs work"
        );
    } else {
        assert!(impact.energy_transferred().abs() < 1e-12 * energy0);
    }

    impact
}

#[test]
fn wave_tracking_matches_the_lattice_for_many_impedances_and_lengths() {
    let counts = [
        (30, 50),
        (50, 30),
        (40, 40),
        (20, 50),
        (70, 30),
        (37, 11),
        (90, 13),
        (11, 90),
    ];
    for z_ratio in [1.0, 3.0, 1.0 / 3.0, 1.7, 0.05, 20.0] {
        for (n1, n2) in counts {
            compare_with_lattice(2.0, n1, Some((2.0 * z_ratio, n2)));
        }
    }
    compare_with_lattice(2.0, 40, None);
}

#[test]
fn equal_impedance_gives_half_z_v0_for_twice_the_shorter_transit() {
    // Same material (rho = 7850, E = 210 GPa, A = 1 cm^2), striker shorter, equal, longer.
    let (e, rho, area, v0): (f64, f64, f64, f64) = (2.1e11, 7850.0, 1e-4, 5.0);
    let c = (e / rho).sqrt();
    for (l1, l2) in [(0.3, 0.8), (0.5, 0.5), (0.8, 0.3)] {
        let s = ImpactBar::from_material(e, rho, area, l1).unwrap();
        let t = ImpactBar::from_material(e, rho, area, l2).unwrap();
        let impact = ImpactForce::new(s, t, v0).unwrap();
        let z = rho * c * area;
        let l_short = f64::min(l1, l2);
        assert_eq!(impact.plateaus().len(), 1);
        assert!(rel(impact.plateaus()[0].force, 0.5 * z * v0) < 1e-14);
        assert!(rel(impact.duration(), 2.0 * l_short / c) < 1e-12);
        assert!(rel(impact.impulse(), rho * area * l_short * v0) < 1e-12);
        // The gap opens at 2 L_long/c: the ends touch at zero force until the longer bar's
        // reflected wave is back.
        assert!(rel(impact.separation_time(), 2.0 * l1.max(l2) / c) < 1e-12);
        // Energy: a shorter or equal striker passes on all of its energy and stops.
        let energy0 = 0.5 * s.mass() * v0 * v0;
        if l1 <= l2 {
            assert!(rel(impact.energy_transferred(), energy0) < 1e-12);
            assert!(impact.striker_mean_velocity_after().abs() < 1e-12 * v0);
        }
        if l1 == l2 {
            // The target leaves as a rigid body with v0: its kinetic energy is all of it.
            let v_target = impact.impulse() / t.mass();
            assert!(rel(0.5 * t.mass() * v_target * v_target, energy0) < 1e-12);
        }
        if l1 > l2 {
            // The target leaves with uniform v0 and no stress: momentum m2 v0, energy m2 v0^2/2.
            assert!(rel(impact.impulse(), t.mass() * v0) < 1e-12);
            assert!(rel(impact.energy_transferred(), 0.5 * t.mass() * v0 * v0) < 1e-12);
        }
    }
}

#[test]
fn equal_impedance_with_different_wave_speeds_uses_transit_times() {
    // Z1 = Z2 but c2 = 3 c1: duration 2 min(T1, T2), impulse min(m1, m2) v0.
    let s = ImpactBar::new(5.0, 1.0, 1.0).unwrap();
    for l2 in [1.5, 6.0] {
        let t = ImpactBar::new(5.0, 3.0, l2).unwrap();
        let impact = ImpactForce::new(s, t, 2.0).unwrap();
        let t_min = s.transit_time().min(t.transit_time());
        assert!(rel(impact.duration(), 2.0 * t_min) < 1e-12);
        assert!(rel(impact.impulse(), s.mass().min(t.mass()) * 2.0) < 1e-12);
    }
}

#[test]
fn equal_transit_times_give_one_plateau_for_every_impedance_ratio() {
    let (z1, v0) = (4.0, 1.5);
    let s = ImpactBar::new(z1, 2.0, 1.0).unwrap(); // T = 0.5
    for z2 in [0.1, 1.0, 4.0, 9.0, 1e3] {
        let t = ImpactBar::new(z2, 5.0, 2.5).unwrap(); // T = 0.5
        let impact = ImpactForce::new(s, t, v0).unwrap();
        let f1 = z1 * z2 * v0 / (z1 + z2);
        assert_eq!(impact.plateaus().len(), 1, "z2 = {z2}");
        assert!(rel(impact.force(0.3), f1) < 1e-14);
        assert!(rel(impact.duration(), 1.0) < 1e-12);
        // Striker momentum loss m1 v0 * 2 Z2/(Z1 + Z2).
        assert!(rel(impact.impulse(), s.mass() * v0 * 2.0 * z2 / (z1 + z2)) < 1e-12);
    }
}

#[test]
fn staircase_first_steps_by_hand() {
    let (z1, v0) = (1.0, 1.0);
    // Striker with T1 = 5 on targets with T2 = 1.
    let s = ImpactBar::new(z1, 1.0, 5.0).unwrap();
    // Light striker on a short heavy target: F2 = F1 (Z2 - Z1)/(Z1 + Z2) after 2 T2.
    let z2 = 3.0;
    let impact = ImpactForce::new(s, ImpactBar::new(z2, 1.0, 1.0).unwrap(), v0).unwrap();
    let f1 = z1 * z2 * v0 / (z1 + z2);
    assert!(rel(impact.force(1.0), f1) < 1e-14);
    assert!(rel(impact.force(3.0), f1 * (z2 - z1) / (z1 + z2)) < 1e-13);
    assert!(rel(impact.force(2.0), f1 * (z2 - z1) / (z1 + z2)) < 1e-13);
    assert!(impact.duration() > 2.0);
    // Heavy striker on a short light target: separation at 2 T2 after one plateau.
    let z2 = 1.0 / 3.0;
    let impact = ImpactForce::new(s, ImpactBar::new(z2, 1.0, 1.0).unwrap(), v0).unwrap();
    assert_eq!(impact.plateaus().len(), 1);
    assert!(rel(impact.duration(), 2.0) < 1e-12);
    assert!(rel(impact.separation_time(), 2.0) < 1e-12);
}

#[test]
fn rigid_wall_gives_z_v0_for_two_transits() {
    let s = ImpactBar::from_material(70e9, 2700.0, 2e-4, 0.4).unwrap();
    let v0 = 10.0;
    let impact = ImpactForce::rigid_wall(s, v0).unwrap();
    assert_eq!(impact.plateaus().len(), 1);
    assert!(rel(impact.plateaus()[0].force, s.impedance * v0) < 1e-14);
    assert!(rel(impact.duration(), 2.0 * s.transit_time()) < 1e-14);
    assert!(rel(impact.impulse(), 2.0 * s.mass() * v0) < 1e-14);
    assert!(rel(impact.striker_mean_velocity_after(), -v0) < 1e-13);
    assert_eq!(impact.force(-1e-9), 0.0);
    assert_eq!(impact.force(impact.duration()), 0.0);
}

#[test]
fn limits_of_the_impedance_ratio() {
    let (z1, v0) = (2.0, 1.0);
    let s = ImpactBar::new(z1, 1.0, 1.0).unwrap();
    let sample = |impact: &ImpactForce, reference: &dyn Fn(f64) -> f64, end: f64| {
        (0..4000)
            .map(|i| end * (f64::from(i) + 0.5) / 4000.0)
            .map(|t| (impact.force(t) - reference(t)).abs())
            .fold(0.0, f64::max)
    };
    // Z2 -> Z1: the equal-impedance history, from both sides, shorter and longer targets.
    for l2 in [0.6, 1.7] {
        let equal = ImpactForce::new(s, ImpactBar::new(z1, 1.0, l2).unwrap(), v0).unwrap();
        let equal_force = |t: f64| equal.force(t);
        for eps in [1e-6, -1e-6] {
            let near = ImpactForce::new(s, ImpactBar::new(z1 * (1.0 + eps), 1.0, l2).unwrap(), v0)
                .unwrap();
            assert!(sample(&near, &equal_force, 6.0) < 1e-5 * z1 * v0);
            assert!(rel(near.impulse(), equal.impulse()) < 1e-5);
        }
    }
    // Z2 -> inf: the rigid wall, for targets shorter and longer than the striker.
    let wall = ImpactForce::rigid_wall(s, v0).unwrap();
    let wall_force = |t: f64| wall.force(t);
    for l2 in [1.0 / 7.0, 3.0] {
        let stiff = ImpactForce::new(s, ImpactBar::new(1e7 * z1, 1.0, l2).unwrap(), v0).unwrap();
        assert!(
            sample(&stiff, &wall_force, 3.0) < 1e-5 * z1 * v0,
            "l2 = {l2}"
        );
        assert!(rel(stiff.impulse(), wall.impulse()) < 1e-5);
        assert!(rel(stiff.duration(), wall.duration()) < 1e-5);
    }
}

#[test]
fn incommensurate_lengths_satisfy_momentum_and_energy_bounds() {
    let v0 = 1.0;
    let s = ImpactBar::new(1.0, 1.0, 1.0).unwrap();
    let energy0 = 0.5 * s.mass() * v0 * v0;
    for z2 in [0.3, 1.0, 2.5] {
        for l2 in [2f64.sqrt(), 1.0 / 3f64.sqrt(), std::f64::consts::PI, 0.1] {
            let t = ImpactBar::new(z2, 1.0, l2).unwrap();
            let impact = ImpactForce::new(s, t, v0).unwrap();
            let (impulse, work) = (impact.impulse(), impact.energy_transferred());
            assert!(impulse > 0.0 && impulse <= 2.0 * s.mass() * v0 * (1.0 + 1e-12));
            // Each bar's energy is at least its rigid-body kinetic energy.
            let p1 = s.mass() * v0 - impulse;
            assert!(work >= impulse * impulse / (2.0 * t.mass()) * (1.0 - 1e-12));
            assert!(energy0 - work >= p1 * p1 / (2.0 * s.mass()) * (1.0 - 1e-12) - 1e-15);
            assert!(
                impact
                    .plateaus()
                    .iter()
                    .all(|p| p.force >= 0.0 && p.end > p.start)
            );
            // The first plateau is F1 for 2 min(T1, T2).
            let f1 = z2 / (1.0 + z2) * v0;
            assert!(rel(impact.force(0.0), f1) < 1e-14);
            assert!(impact.force(2.0 * l2.min(1.0) * (1.0 - 1e-9)) == impact.force(0.0));
        }
    }
    // Compare an incommensurate length with its commensurate neighbour on the lattice.
    compare_with_lattice(1.0, 100, Some((2.5, 141)));
}

#[test]
fn invalid_impact_data_are_rejected() {
    let s = ImpactBar::new(1.0, 1.0, 1.0).unwrap();
    let name = |e: ReferenceError| match e {
        ReferenceError::InvalidParameter { name, .. } => name,
        _ => "other",
    };
    assert_eq!(name(ImpactForce::new(s, s, 0.0).unwrap_err()), "v0");
    assert_eq!(
        name(ImpactBar::new(-1.0, 1.0, 1.0).unwrap_err()),
        "impedance"
    );
    assert_eq!(
        name(ImpactBar::from_material(1.0, 0.0, 1.0, 1.0).unwrap_err()),
        "density"
    );
    assert_eq!(
        name(PenaltyWallForce::new(s, 1.0, 0.0).unwrap_err()),
        "stiffness"
    );
    let bad = ImpactBar {
        impedance: 1.0,
        wave_speed: f64::NAN,
        length: 1.0,
    };
    assert_eq!(
        name(ImpactForce::with_target(bad, ImpactTarget::RigidWall, 1.0).unwrap_err()),
        "wave_speed"
    );
}

// ---------------------------------------------------------------------------------------------
// Penalty-regularised wall
// ---------------------------------------------------------------------------------------------

/// Lattice for a bar (n cells, dt = T/n) hitting a unilateral penalty spring k_s: the contact
/// end solves `Z u' + k_s u = -a` exactly over each step with the incoming invariant a frozen;
/// returns the step-averaged force. First order in dt.
fn penalty_lattice(z: f64, n: usize, dt: f64, v0: f64, ks: f64, steps: usize) -> Vec<f64> {
    let mut bar = LatticeBar::new(z, n, v0);
    let tau = z / ks;
    let decay = (-dt / tau).exp();
    let mut u = 0.0;
    let mut in_contact = true;
    let mut force = Vec::with_capacity(steps);
    for _ in 0..steps {
        let a = bar.alpha[n - 1];
        let (n_force, v) = if in_contact {
            let u_inf = -a / ks;
            let u_next = u_inf + (u - u_inf) * decay;
            let mean = u_inf + (u - u_inf) * (tau / dt) * (1.0 - decay);
            let v = (u_next - u) / dt;
            u = u_next;
            if u <= 0.0 {
                in_contact = false;
            }
            (-ks * mean.max(0.0), v)
        } else {
            (0.0, -a / z)
        };
        force.push(-n_force);
        let reflected = -bar.beta[0];
        bar.alpha.rotate_right(1);
        bar.alpha[0] = reflected;
        bar.beta.rotate_left(1);
        bar.beta[n - 1] = n_force + z * v;
    }
    force
}

#[test]
fn penalty_wall_first_transit_rises_with_time_constant_z_over_ks() {
    let bar = ImpactBar::new(2.0, 1.0, 1.0).unwrap(); // T = 1
    let (v0, ks) = (1.5, 20.0);
    let wall = PenaltyWallForce::new(bar, v0, ks).unwrap();
    let tau = wall.time_constant();
    assert!(rel(tau, 0.1) < 1e-15);
    for t in [0.0, 1e-9, 0.05, 0.1, 0.5, 1.0, 2.0] {
        let expected = bar.impedance * v0 * (1.0 - (-t / tau).exp());
        assert!(
            (wall.force(t) - expected).abs() < 1e-14 * bar.impedance * v0,
            "t = {t}"
        );
    }
    // After one time constant: 1 - 1/e of the rigid-wall force.
    let fraction = wall.force(tau) / (bar.impedance * v0);
    assert!((fraction - (1.0 - (-1.0f64).exp())).abs() < 1e-14);
}

#[test]
fn penalty_wall_matches_a_lattice_with_a_spring_boundary() {
    let z = 2.0;
    let v0 = 1.0;
    // tau = 0.3 T: the contact ends in the second transit; tau = 2 T: it outlasts 4T.
    for ks in [z / 0.3, z / 2.0] {
        let bar = ImpactBar::new(z, 1.0, 1.0).unwrap();
        let wall = PenaltyWallForce::new(bar, v0, ks).unwrap();
        let end = wall.valid_until();
        let errors: Vec<f64> = [2000, 4000]
            .iter()
            .map(|&n| {
                let dt = 1.0 / n as f64;
                let steps = (end / dt).floor() as usize;
                let lattice = penalty_lattice(z, n, dt, v0, ks, steps);
                lattice
                    .iter()
                    .enumerate()
                    .take(steps.saturating_sub(2))
                    .map(|(k, f)| (wall.force((k as f64 + 0.5) * dt) - f).abs())
                    .fold(0.0, f64::max)
            })
            .collect();
        assert!(errors[1] < 2e-3 * z * v0, "k_s = {ks}: {errors:?}");
        assert!(errors[1] < 0.6 * errors[0], "not converging: {errors:?}");
    }
}

#[test]
fn penalty_wall_duration_and_impulse() {
    let z = 2.0;
    let v0 = 1.0;
    let bar = ImpactBar::new(z, 1.0, 1.0).unwrap();
    // Soft spring: no closed form beyond 4T.
    let soft = PenaltyWallForce::new(bar, v0, z / 2.0).unwrap();
    assert!(soft.duration().is_none() && soft.impulse().is_none());
    assert!(soft.force(4.5).is_nan());
    // Impulse formula against a quadrature of force(t).
    let wall = PenaltyWallForce::new(bar, v0, z / 0.3).unwrap();
    let end = wall.duration().unwrap();
    assert!(end > 2.0 && end < 4.0);
    assert!(wall.force(end * (1.0 - 1e-12)) >= 0.0 && wall.force(end * (1.0 - 1e-12)) < 1e-9);
    let m = 200_000;
    let h = end / f64::from(m);
    let simpson: f64 = (0..=m)
        .map(|i| {
            let w = if i == 0 || i == m {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * wall.force(f64::from(i) * h * (1.0 - 1e-15))
        })
        .sum::<f64>()
        * h
        / 3.0;
    assert!(
        rel(wall.impulse().unwrap(), simpson) < 1e-8,
        "{:?} vs {simpson}",
        wall.impulse()
    );
    // Stiff limit: the rigid wall (force Z v0 for 2T, impulse 2 m v0).
    let rigid = ImpactForce::rigid_wall(bar, v0).unwrap();
    for ks in [1e4, 1e6, 1e8] {
        let stiff = PenaltyWallForce::new(bar, v0, ks).unwrap();
        let tau = stiff.time_constant();
        assert!(rel(stiff.impulse().unwrap(), rigid.impulse()) < 2.0 * tau);
        let sigma_star = (stiff.duration().unwrap() - 2.0) / tau;
        assert!(
            (sigma_star - 1.678_346_990_016_660_5).abs() < 1e-6,
            "{sigma_star}"
        );
        assert!(rel(stiff.force(1.0), z * v0) < 1e-12);
    }
}
