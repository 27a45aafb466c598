//! Source of truth: the seed's Fig. 5 (Kolman et al., section 3.2): the stabilized
//! predictor-corrector scheme with the neutral bipenalty ratio r = 1 at Co = 0.5 for
//! beta_s in {0.25, 0.25e2, 0.25e4, 0.25e8}; the exact impact force of 1D wave theory
//! (`courant_references::contact::ImpactForce`: equal impedance, F = Z v0/2 for
//! 0 <= t < 2 L1/c, impulse rho A L1 v0); methods.md §7 for the scheme's own limit
//! k_s dt^2/(m_c + m_p) <= 1 and its identity with the forward-increment Lagrange multiplier
//! method at that limit.
//!
//! ```text
//!   striker L1 = 1, v0 = 1 ->       target L2 = 2, at rest
//!   o--o--o-- ... --o--a | b--o--o--o-- ... --o--o--o      E = rho = A = 1 (c = Z = 1)
//!   100 elements               200 elements                 h = 0.01, dt = 0.005 (Co = 0.5)
//! ```
//!
//! Proves, with the bounds stated on the measured values (run `cargo test --test
//! contact_fig5_predictor_corrector -- --nocapture` to print them):
//! - a clean plateau for every beta_s: on 0.2 <= t <= 1.8 the force stays within 0.4 % of
//!   Z v0/2 (measured 0.29 % for beta_s >= 25, 0.27 % for 0.25); impulse within 0.4 % of
//!   rho A L1 v0 for beta_s >= 25 (measured 0.29 %) and 1.5 % for 0.25 (measured 1.0 %); the
//!   contact duration, taken where the force falls through half the plateau, within 0.75 % of
//!   2 L1/c for beta_s >= 25 (measured 0.53 %) and 2.5 % for 0.25 (measured 2.1 %);
//! - it tends to the Lagrange multiplier reference as beta_s grows: the largest force
//!   difference is (1 - kappa) times the start level's force, i.e. 1/(1 + beta_s) here;
//! - above its own limit it is refused, and, when allowed, a persistent contact gains energy
//!   (a bar pressed on a wall by a constant load: kappa = 1.21 lets the kinetic + strain energy
//!   grow past 2.5 times the largest value a stable run reaches), while at kappa <= 1 it only
//!   dissipates.

use courant_references::contact::{ImpactBar, ImpactForce};
use courant_solver::StabilityPolicy;
use courant_solver::contact::{
    ContactError, ContactIntegrator, ContactProblem, ContactRequest, ContactRun, ContactScheme,
    MassPenalty, StepLimit,
};

const BETAS: [f64; 4] = [0.25, 0.25e2, 0.25e4, 0.25e8];
const DT: f64 = 0.005;

fn fig5() -> ContactProblem {
    ContactProblem::fig5(100, 1.0).unwrap()
}

fn exact() -> ImpactForce {
    let bar = |length| ImpactBar::from_material(1.0, 1.0, 1.0, length).unwrap();
    ImpactForce::new(bar(1.0), bar(2.0), 1.0).unwrap()
}

fn run(scheme: ContactScheme, end: f64) -> ContactRun {
    ContactIntegrator::new(DT, scheme)
        .run(
            &fig5(),
            (end / DT).round() as usize,
            &ContactRequest::default(),
        )
        .unwrap()
}

fn predictor_corrector(beta_s: f64) -> ContactScheme {
    ContactScheme::PredictorCorrector(fig5().penalty(beta_s, MassPenalty::Ratio(1.0)).unwrap())
}

/// Largest |F - F_ref| on 0.2 <= t <= 1.8, relative to the plateau F_ref.
fn plateau_deviation(run: &ContactRun, plateau: f64) -> f64 {
    run.history
        .iter()
        .filter(|s| (0.2..=1.8).contains(&s.time))
        .map(|s| (s.force - plateau).abs() / plateau)
        .fold(0.0, f64::max)
}

/// Time at which the force falls through half the plateau after t = 1 (linear between levels).
fn half_plateau_release(run: &ContactRun, plateau: f64) -> f64 {
    let h = &run.history;
    let k = h
        .iter()
        .position(|s| s.time > 1.0 && s.force <= 0.5 * plateau)
        .expect("the force falls");
    let (a, b) = (&h[k - 1], &h[k]);
    a.time + (a.force - 0.5 * plateau) / (a.force - b.force) * (b.time - a.time)
}

#[test]
fn predictor_corrector_at_courant_half_gives_a_clean_plateau_for_every_beta_s() {
    let exact = exact();
    let plateau = exact.first_plateau();
    let duration = exact.duration();
    assert_eq!((plateau, duration, exact.impulse()), (0.5, 2.0, 1.0));
    for beta_s in BETAS {
        let run = run(predictor_corrector(beta_s), 3.0);
        // kappa at Co = 1 is 4 beta_s/(1 + beta_s): 0.8 for beta_s = 0.25, so the contact-free
        // bulk binds there; from beta_s = 25 on the scheme's own limit (Co ~ 0.5) binds.
        let binding = if beta_s < 1.0 {
            StepLimit::ContactFree
        } else {
            StepLimit::PredictorCorrector
        };
        assert_eq!(run.critical.binding, binding);
        let deviation = plateau_deviation(&run, plateau);
        let impulse = run.impulse / exact.impulse() - 1.0;
        let release = half_plateau_release(&run, plateau) / duration - 1.0;
        println!(
            "beta_s = {beta_s:e}: plateau deviation {deviation:.3e}, impulse error {impulse:.3e}, \
             duration error {release:.3e}, start level {:.4}",
            run.history[0].force
        );
        let (impulse_bound, release_bound) = if beta_s < 1.0 {
            (1.5e-2, 2.5e-2)
        } else {
            (4e-3, 7.5e-3)
        };
        assert!(
            deviation < 4e-3,
            "beta_s = {beta_s}: deviation {deviation:e}"
        );
        assert!(
            impulse.abs() < impulse_bound,
            "beta_s = {beta_s}: {impulse:e}"
        );
        assert!(
            release.abs() < release_bound,
            "beta_s = {beta_s}: {release:e}"
        );
        // The contact is over well before the target's pulse returns (t = 4).
        assert!(
            run.history
                .iter()
                .filter(|s| s.time > 2.5)
                .all(|s| s.force == 0.0)
        );
    }
}

#[test]
fn predictor_corrector_tends_to_the_lagrange_multiplier_reference_as_beta_s_grows() {
    let reference = run(ContactScheme::LagrangeMultiplier, 3.0);
    // The start level merges the two contact half-nodes: J^0 = m_red v0 = m v0/4 over dt/2,
    // i.e. F^0 = Z v0/(2 Co) = 1 at Co = 0.5 (twice the plateau: the lumped node cannot spread
    // the first momentum exchange over the half step it stands for).
    assert!((reference.history[0].force - 1.0).abs() < 1e-12);
    let mut previous = f64::INFINITY;
    for beta_s in BETAS {
        let run = run(predictor_corrector(beta_s), 3.0);
        let difference = run
            .history
            .iter()
            .zip(&reference.history)
            .map(|(a, b)| (a.force - b.force).abs())
            .fold(0.0, f64::max);
        // kappa = k_s dt^2/(m_red + m_p) = 4 Co^2 beta_s/(1 + beta_s) = beta_s/(1 + beta_s).
        let one_minus_kappa = 1.0 / (1.0 + beta_s);
        println!("beta_s = {beta_s:e}: max |F - F_LM| = {difference:.3e}");
        assert!(
            difference <= 1.001 * one_minus_kappa,
            "beta_s = {beta_s}: {difference:e} vs {one_minus_kappa:e}"
        );
        assert!(difference < previous);
        previous = difference;
    }
    assert!(previous < 1e-7);
}

#[test]
fn predictor_corrector_is_refused_above_its_own_limit_and_then_gains_energy() {
    let problem = courant_solver::bench::loaded_wall(100, 0.0).unwrap();
    let scheme = ContactScheme::PredictorCorrector(
        problem.penalty(0.25e4, MassPenalty::Ratio(1.0)).unwrap(),
    );
    let energy_peaks = |co: f64| -> [f64; 4] {
        let dt = co * 0.01;
        let steps = (200.0 / dt).round() as usize;
        let integrator = ContactIntegrator {
            stability: StabilityPolicy {
                allow_unstable: true,
                ..Default::default()
            },
            ..ContactIntegrator::new(dt, scheme)
        };
        let run = integrator
            .run(&problem, steps, &ContactRequest::default())
            .unwrap();
        let quarter = run.history.len() / 4;
        std::array::from_fn(|q| {
            run.history[q * quarter..(q + 1) * quarter]
                .iter()
                .map(|s| s.kinetic + s.strain)
                .fold(0.0, f64::max)
        })
    };
    // kappa = 4 Co^2 beta_s/(1 + beta_s) at the wall (m_c = m/2, m_p = beta_s m/4).
    let refused = ContactIntegrator::new(0.55 * 0.01, scheme)
        .run(&problem, 10, &ContactRequest::default())
        .unwrap_err();
    let ContactError::Unstable(e) = &refused else {
        panic!("{refused}")
    };
    assert_eq!(e.limit, StepLimit::PredictorCorrector);
    // Within the limit (Co = 0.5, kappa = 0.9996): the energy of the sudden load (at most
    // 2 F L^2/(E A) = 2 for a stable scheme) is only dissipated by the contact switches.
    let stable = energy_peaks(0.5);
    // Above it (Co = 0.55, kappa = 1.21): it grows.
    let unstable = energy_peaks(0.55);
    println!(
        "peaks of K + U per quarter of 200 L/c: {stable:.3?} (Co 0.5), {unstable:.3?} (Co 0.55)"
    );
    assert!(stable.iter().all(|&e| e <= 2.0 + 1e-9), "{stable:?}");
    assert!(stable[3] < stable[0]);
    assert!(unstable[3] > 2.5 * stable[0], "{unstable:?}");
}
