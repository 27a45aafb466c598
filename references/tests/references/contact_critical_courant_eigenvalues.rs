//! Checks of the contact stability references (`courant_references::contact`, part 1: critical
//! Courant numbers of penalty/bipenalty contact) against independent eigenvalue computations
//! done here, with no solver.
//!
//! The closed-form critical Courant numbers are compared with the largest eigenvalue of a lumped
//! bar assembled in this file (tridiagonal K and M, the contact spring k_s and penalty mass m_p
//! on the contact node), found by bisection on Sturm counts of the pencil `K - x M` (Sylvester's
//! law of inertia: the number of negative pivots of its LDL^T factorisation is the number of
//! eigenvalues below x). The far end is free: there the contact-free top of the spectrum is
//! exactly Lambda = 4 (the pi-mode, Cr = 1, as for the semi-infinite bar), and the localized
//! contact mode decays like |q|^j, so the far end moves it only by O(|q|^(2N)); N is doubled
//! until Lambda_max is converged to 1e-13, and one test shows that a fixed far end gives the same
//! value. Closed-form properties that need no assembled bar are in
//! `contact_critical_courant_closed_forms.rs`.

use courant_references::contact::{
    signorini_critical_courant_bipenalty, signorini_critical_courant_penalty,
    signorini_critical_courant_ratio, signorini_localized_mode, two_bar_critical_courant,
};

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
