//! Contact with Park's local time stepping and with the reciprocal mass (module docs of
//! `courant_solver::contact::combined`; guide `docs/contact_with_local_stepping.md`).
//!
//! Sources of truth: the discrete momentum balance of the velocity update (closed form, module
//! docs "Momentum"); the lumped central-difference contact stepper (the same scheme in half-step
//! form); the Sherman-Morrison identity checked against nalgebra's dense inverse; the
//! Lagrange multiplier's defining closure `g = 0`; and the step limits measured from the
//! amplification matrix's spectrum, set against the contact-free one (the bipenalty's promise,
//! Kopačka et al., IJNME 113 (2018), the seed's ref. [9]).

use courant_solver::contact::combined::amplification::measured_limit;
use courant_solver::contact::combined::{BulkScheme, CombinedStepper, ContactMode};
use courant_solver::contact::{ContactProblem, ContactScheme, ContactStepper, MassPenalty};
use courant_solver::{Bar, End, Field, MassKind, MassOperator, Mesh, ParkOptions, ParkVariant};

use nalgebra::DMatrix;

/// Per-element values of a bar of `length` in `elements_per_length` elements per unit length,
/// from layers `(end, E)` (rho = A = 1).
fn layered(length: f64, elements_per_length: usize, layers: &[(f64, f64)]) -> Bar {
    let n = (length * elements_per_length as f64).round() as usize;
    let mesh = Mesh::uniform(length, n).unwrap();
    let e: Vec<f64> = (0..n)
        .map(|k| {
            let x = (k as f64 + 0.5) * length / n as f64;
            layers.iter().find(|(end, _)| x < *end).unwrap().1
        })
        .collect();
    Bar::new(
        mesh,
        &Field::PerElement(e),
        &Field::Constant(1.0),
        &Field::Constant(1.0),
    )
    .unwrap()
}

/// The layered impact of the scene `impact_layered_combined`: striker [0, 0.5] E = 1,
/// [0.5, 1] E = 256; target [0, 0.5] E = 16, [0.5, 1.5] E = 1, [1.5, 2] E = 256; rho = A = 1,
/// v0 = 1, gap 0.
fn layered_impact(elements_per_length: usize) -> ContactProblem {
    let striker = layered(1.0, elements_per_length, &[(0.5, 1.0), (1.0, 256.0)]);
    let target = layered(
        2.0,
        elements_per_length,
        &[(0.5, 16.0), (1.5, 1.0), (2.0, 256.0)],
    );
    ContactProblem::bar_impact(striker, target, 1.0, 0.0).unwrap()
}

fn park(local_stepping: bool) -> BulkScheme {
    BulkScheme::Park(ParkOptions {
        theta: 0.5,
        variant: ParkVariant::Free,
        local_stepping,
    })
}

fn schemes(problem: &ContactProblem, beta_s: f64) -> Vec<ContactScheme> {
    let bipenalty = problem.penalty(beta_s, MassPenalty::Ratio(1.0)).unwrap();
    vec![
        ContactScheme::Penalty {
            stiffness: bipenalty.stiffness,
        },
        ContactScheme::Bipenalty(bipenalty),
        ContactScheme::PredictorCorrector(bipenalty),
        ContactScheme::LagrangeMultiplier,
    ]
}

fn incremental(local_stepping: bool) -> BulkScheme {
    BulkScheme::Park(ParkOptions {
        theta: 0.5,
        variant: ParkVariant::Incremental,
        local_stepping,
    })
}

/// The bulks the combination runs: Park (both variants, local and global), CD with LMM and RMM.
fn bulks() -> Vec<BulkScheme> {
    vec![
        park(true),
        park(false),
        incremental(true),
        BulkScheme::CentralDifference,
        BulkScheme::Reciprocal { beta: 0.5 },
    ]
}

fn relative(x: f64, y: f64) -> f64 {
    (x - y).abs() / y.abs().max(f64::MIN_POSITIVE)
}

/// Source: the same scheme in half-step form (`contact::ContactStepper`). Proves: with the
/// lumped central-difference bulk, the combined stepper's contact levels (gap, force) are the
/// lumped contact stepper's, for every contact scheme, at a wall and between two bars.
#[test]
fn central_difference_bulk_gives_the_lumped_contact_stepper() {
    let pair = layered_impact(8);
    let wall = ContactProblem::wall_impact(
        layered(1.0, 8, &[(0.5, 1.0), (1.0, 256.0)]),
        End::Right,
        1.0,
        0.0,
    )
    .unwrap();
    for problem in [&pair, &wall] {
        let dt = 0.4 * problem.stiffest_transit();
        for scheme in schemes(problem, 1e2) {
            let mut lumped = ContactStepper::new(problem, dt, scheme).unwrap();
            let mut combined =
                CombinedStepper::new(problem, BulkScheme::CentralDifference, scheme, dt).unwrap();
            let scale = problem.contact_mass() * 1.0 / dt;
            for step in 0..400 {
                let (a, b) = (lumped.sample(), combined.level());
                assert!(
                    (a.force - b.force).abs() <= 1e-9 * scale && (a.gap - b.gap).abs() <= 1e-12,
                    "{} step {step}: {a:?} vs {b:?}",
                    scheme.label()
                );
                lumped.step();
                combined.step();
            }
        }
    }
}

/// Source: the discrete momentum balance of the velocity update (module docs "Momentum"):
/// `sum A v^{n+1} - sum A v^n = (1^T N)(F^n + F^{n+1}) dt/2` without loads, `F^k = J^k/(w_k dt)`.
/// Proves: through the impact (contact closing, acting and opening) the total momentum of the
/// pair is conserved to round-off and the target's momentum is the trapezoidal impulse of the
/// reported force, for every bulk and every contact scheme.
#[test]
fn momentum_through_the_impact_to_round_off() {
    let problem = layered_impact(8);
    let p0: f64 = problem.bodies()[0].nodal_mass().iter().sum::<f64>();
    for bulk in bulks() {
        let dt = stable_fraction(&bulk) * problem.stiffest_transit();
        for beta_s in [1.0, 1e4, 1e8] {
            for scheme in schemes(&problem, beta_s) {
                if matches!(scheme, ContactScheme::Penalty { .. }) && beta_s > 1.0 {
                    continue; // its step is far below 0.9 (test below)
                }
                // Below each contact scheme's limit (`step_limits_of_the_combinations`).
                let dt = match scheme {
                    ContactScheme::PredictorCorrector(_) => 0.5 * dt,
                    ContactScheme::Penalty { .. } => 0.7 * dt,
                    _ => dt,
                };
                let mut run = CombinedStepper::new(&problem, bulk, scheme, dt).unwrap();
                let mut target = 0.0;
                let mut previous = run.level().force;
                let steps = (3.0 / dt) as usize;
                let mut contact_levels = 0;
                for _ in 0..steps {
                    let level = run.step();
                    contact_levels += usize::from(level.active);
                    target += 0.5 * dt * (previous + level.force);
                    previous = level.force;
                    let p = run.momenta();
                    let label = format!("{} {} beta_s {beta_s:e}", bulk.label(), scheme.label());
                    assert!(
                        (p[0] + p[1] - p0).abs() <= 1e-12 * p0,
                        "{label}: total momentum {} vs {p0}",
                        p[0] + p[1]
                    );
                    assert!(
                        (p[1] - target).abs() <= 1e-11 * p0,
                        "{label}: target momentum {} vs impulse {target}",
                        p[1]
                    );
                }
                assert!(
                    contact_levels > 10,
                    "{} {}: {contact_levels} contact levels",
                    bulk.label(),
                    scheme.label()
                );
            }
        }
    }
}

/// Source: the same discrete momentum balance at a rigid wall on the right (`1^T N = -1`):
/// `p^{n+1} - p^n = -(F^n + F^{n+1}) dt/2`. Proves: the bar's momentum changes by exactly the
/// delivered contact impulse, in every bulk, for every contact scheme.
#[test]
fn momentum_at_a_wall_changes_by_the_contact_impulse() {
    let problem = ContactProblem::wall_impact(
        layered(1.0, 8, &[(0.5, 1.0), (1.0, 256.0)]),
        End::Right,
        1.0,
        0.0,
    )
    .unwrap();
    let p0: f64 = problem.bodies()[0].nodal_mass().iter().sum::<f64>();
    for bulk in bulks() {
        for scheme in schemes(&problem, 1e4) {
            let dt = stable_fraction(&bulk)
                * problem.stiffest_transit()
                * match scheme {
                    ContactScheme::PredictorCorrector(_) => 0.5,
                    ContactScheme::Penalty { .. } => 0.005,
                    _ => 1.0,
                };
            let mut run = CombinedStepper::new(&problem, bulk, scheme, dt).unwrap();
            let mut impulse = 0.0;
            let mut previous = run.level().force;
            for _ in 0..(1.5 / dt) as usize {
                let level = run.step();
                impulse += 0.5 * dt * (previous + level.force);
                previous = level.force;
                let p = run.momenta()[0];
                assert!(
                    (p - (p0 - impulse)).abs() <= 1e-11 * p0,
                    "{} {}: momentum {p} vs {}",
                    bulk.label(),
                    scheme.label(),
                    p0 - impulse
                );
            }
            assert!(
                impulse > 1.0,
                "{} {}: impulse {impulse}",
                bulk.label(),
                scheme.label()
            );
        }
    }
}

/// Source: the forward-increment Lagrange multiplier's definition (Carpenter, Taylor and Katona,
/// IJNME 32 (1991)): the predicted gap is made zero. Proves: the contact nodes stepping by
/// central difference inside Park's bulk (and RMM's nonlocal `M^-1 N`) keep the closure exact:
/// after every active level the next gap is zero to round-off.
#[test]
fn lagrange_multiplier_closes_the_gap_exactly_in_every_bulk() {
    let problem = layered_impact(8);
    for bulk in bulks() {
        let dt = stable_fraction(&bulk) * problem.stiffest_transit();
        let mut run =
            CombinedStepper::new(&problem, bulk, ContactScheme::LagrangeMultiplier, dt).unwrap();
        let mut closures = 0;
        let mut was_active = run.level().active;
        for _ in 0..(2.0 / dt) as usize {
            let level = run.step();
            if was_active {
                closures += 1;
                assert!(
                    level.gap.abs() <= 1e-13,
                    "{}: gap {}",
                    bulk.label(),
                    level.gap
                );
            }
            was_active = level.active;
        }
        assert!(closures > 10, "{}", bulk.label());
    }
}

/// Source: the explicit dense inverse of `M + m_p N N^T` (nalgebra), `M` the inverse of RMM's
/// assembled `M^-1`. Proves: the rank-one (Sherman-Morrison) update of the direct inverse is
/// `(M + M_p)^-1` to round-off, at a wall and between two bars, for several RMM betas.
#[test]
fn sherman_morrison_update_of_the_reciprocal_mass_is_the_dense_inverse() {
    let pair = layered_impact(4);
    let wall = ContactProblem::wall_impact(
        layered(1.0, 6, &[(0.5, 1.0), (1.0, 256.0)]),
        End::Left,
        1.0,
        0.0,
    )
    .unwrap();
    for problem in [&pair, &wall] {
        for beta in [0.0, 0.5, 2.0] {
            let bulk = BulkScheme::Reciprocal { beta };
            let run = CombinedStepper::new(
                problem,
                bulk,
                ContactScheme::LagrangeMultiplier,
                0.1 * problem.stiffest_transit(),
            )
            .unwrap();
            let n = run.node_count();
            // Dense M^-1, block by block, from the operator's product with unit vectors.
            let mut inverse = DMatrix::<f64>::zeros(n, n);
            for b in 0..problem.bodies().len() {
                let range = run.body_range(b);
                let op =
                    MassOperator::new(&problem.bodies()[b], MassKind::Reciprocal { beta }).unwrap();
                let m = range.len();
                for j in 0..m {
                    let mut e = vec![0.0; m];
                    e[j] = 1.0;
                    let mut col = vec![0.0; m];
                    op.apply_inverse(&e, &mut col);
                    for i in 0..m {
                        inverse[(range.start + i, range.start + j)] = col[i];
                    }
                }
            }
            let mass = inverse.clone().try_inverse().unwrap();
            let d = run.direction();
            let mut nn = DMatrix::<f64>::zeros(n, n);
            for &(i, si) in &d.n {
                for &(j, sj) in &d.n {
                    nn[(i, j)] = si * sj;
                }
            }
            for m_p in [0.01, 1.0, 1e4] {
                let dense = (&mass + &nn * m_p).try_inverse().unwrap();
                let r: Vec<f64> = (0..n).map(|i| ((i * 7 + 3) % 11) as f64 - 5.0).collect();
                let rv = nalgebra::DVector::from_vec(r.clone());
                let expected = &dense * &rv;
                let mut x: Vec<f64> = (&inverse * &rv).iter().copied().collect();
                d.penalized_inverse(m_p, &mut x);
                let scale = expected.amax();
                for i in 0..n {
                    assert!(
                        (x[i] - expected[i]).abs() <= 1e-10 * scale,
                        "beta {beta} m_p {m_p} node {i}: {} vs {}",
                        x[i],
                        expected[i]
                    );
                }
                // q has at most three entries per contact node: O(bandwidth), no solve.
                assert!(d.q.len() <= 3 * d.n.len());
            }
        }
    }
}

/// A step each bulk is stable at on the layered impact (fractions of the stiffest element's
/// transit time; the measured limits are in `step_limits_of_the_combinations`): Park-LTS with
/// the free variant 0.5 (it grows by 41 % per step at 0.9 on this mesh), RMM(0.5) 0.75 (its
/// contact-free limit is 0.83), the others 0.9.
fn stable_fraction(bulk: &BulkScheme) -> f64 {
    match bulk {
        BulkScheme::Park(o) if o.local_stepping && o.variant == ParkVariant::Free => 0.5,
        BulkScheme::Reciprocal { .. } => 0.75,
        _ => 0.9,
    }
}

/// Run `scheme` on `bulk` to t = 6 (contact over by t = 2.7); `(E^0, E_end, largest E)` with
/// `E = 1/2 v M v - dt^2/8 a M a + 1/2 u K u (+ 1/2 k_s g^2)`.
fn energies(
    problem: &ContactProblem,
    bulk: BulkScheme,
    scheme: ContactScheme,
    dt: f64,
) -> [f64; 3] {
    let mut run = CombinedStepper::new(problem, bulk, scheme, dt).unwrap();
    let total = |run: &mut CombinedStepper<'_>| {
        let e = run.energy();
        e.kinetic_staggered + e.strain + e.penalty_spring
    };
    let start = total(&mut run);
    let mut largest = start;
    for _ in 0..(6.0 / dt) as usize {
        run.step();
        largest = largest.max(total(&mut run));
    }
    [start, total(&mut run), largest]
}

/// Source: contact is passive and the bulk schemes conserve (CD) or dissipate (Park, theta =
/// 1/2, alpha < 1) `E` (module docs "Energy"; the initial energy 1/2 m v0^2 = 1/2 of the
/// striker, up to the start level's `dt^2/8 a M a`). Proves: the Lagrange multiplier and the
/// predictor-corrector (below its limit) create no energy in any bulk; the energy Park's
/// pull-back takes out is in the bulk (the same contact, Lagrange multiplier, ends lower under
/// Park-LTS than under CD-LMM); and it measures the bipenalty's chatter gain on CD-LMM (a
/// finding of `docs/contact_with_local_stepping.md`).
#[test]
fn energy_bookkeeping_through_the_impact() {
    let problem = layered_impact(8);
    let transit = problem.stiffest_transit();
    let mut lm_end = Vec::new();
    for bulk in bulks() {
        let dt = stable_fraction(&bulk) * transit;
        for beta_s in [1.0, 1e4, 1e8] {
            for scheme in schemes(&problem, beta_s) {
                let dt = match scheme {
                    ContactScheme::PredictorCorrector(_) => 0.5 * dt,
                    ContactScheme::Penalty { .. } | ContactScheme::Bipenalty(_) => continue,
                    ContactScheme::LagrangeMultiplier => dt,
                };
                let [start, end, largest] = energies(&problem, bulk, scheme, dt);
                let label = format!("{} {} beta_s {beta_s:e}", bulk.label(), scheme.label());
                assert!((start - 0.5).abs() < 0.02, "{label}: E0 = {start}");
                assert!(end <= 0.5 && end > 0.3, "{label}: E0 {start} end {end}");
                if matches!(scheme, ContactScheme::LagrangeMultiplier) {
                    assert!(largest <= 0.5 * (1.0 + 1e-12), "{label}: largest {largest}");
                    lm_end.push((bulk.label(), end));
                }
            }
        }
    }
    let end_of = |label: &str| lm_end.iter().find(|(l, _)| l == label).unwrap().1;
    assert!(end_of("park-lts-incremental") < end_of("cd-lmm") - 0.05);
    // The bipenalty's chatter gains energy on CD-LMM at Co = 0.9, r = 1, beta_s = 1e4.
    let bipenalty = problem.penalty(1e4, MassPenalty::Ratio(1.0)).unwrap();
    let [_, end, _] = energies(
        &problem,
        BulkScheme::CentralDifference,
        ContactScheme::Bipenalty(bipenalty),
        0.9 * transit,
    );
    assert!(end > 2.0, "cd-lmm bipenalty end energy {end}");
}

/// Source: the spectral radius of the amplification matrix in the contact-active state
/// (`amplification::measured_limit`), set against the contact-free one of the same bulk (the
/// bipenalty's promise, Kopačka et al. 2018; r = 1 neutral, methods.md §7), the
/// predictor-corrector's `kappa <= 1` (Co = 1/2 for large beta_s, methods.md §7) and penalty's
/// `sqrt(2/beta_s)`-like fall. Proves: with the contact nodes at the global step by CD, the
/// bipenalty and the Lagrange multiplier keep the contact-free step of Park (local and global)
/// and of RMM for beta_s up to 1e8; Park-LTS's own limit on this layered mesh is below its rule
/// `alpha_e <= 1` (finding).
#[test]
fn step_limits_of_the_combinations() {
    let problem = layered_impact(8);
    let transit = problem.stiffest_transit();
    let lm = ContactScheme::LagrangeMultiplier;
    for bulk in [
        park(false),
        incremental(true),
        BulkScheme::CentralDifference,
        BulkScheme::Reciprocal { beta: 0.5 },
    ] {
        let free = measured_limit(&problem, bulk, lm, ContactMode::Off).unwrap() / transit;
        for beta_s in [1.0, 1e4, 1e8] {
            let limit = |scheme| {
                measured_limit(&problem, bulk, scheme, ContactMode::Bilateral).unwrap() / transit
            };
            let [penalty, bipenalty, pc, lagrange] =
                <[ContactScheme; 4]>::try_from(schemes(&problem, beta_s))
                    .unwrap()
                    .map(limit);
            let label = format!("{} beta_s {beta_s:e}", bulk.label());
            // The bipenalty keeps the contact-free step, or the a-priori rule alpha = 1 where the
            // finite mesh's own limit lies above it.
            assert!(
                bipenalty >= free.min(1.0) * (1.0 - 1e-6),
                "{label}: bipenalty {bipenalty} free {free}"
            );
            assert!(
                relative(lagrange, free) < 1e-6,
                "{label}: LM {lagrange} free {free}"
            );
            assert!(pc >= 0.5 * free.min(1.0) && pc <= free, "{label}: PC {pc}");
            if beta_s >= 1e4 {
                assert!(
                    penalty <= 1.1 * (2.0 / beta_s).sqrt(),
                    "{label}: penalty {penalty}"
                );
            }
        }
        // Park-LTS (incremental): 0.979 of the stiffest transit, below alpha_e <= 1.
        if bulk == incremental(true) {
            assert!(
                free < 0.99 && free > 0.95,
                "park-lts-incremental free {free}"
            );
        }
    }
}

/// The largest `kinetic + strain` of the real masses over `steps` steps of the persistent
/// (bilateral) contact from the impact's initial state, over its initial value.
fn growth(problem: &ContactProblem, bulk: BulkScheme, scheme: ContactScheme, dt: f64) -> f64 {
    let mut run =
        CombinedStepper::allowing_unstable(problem, bulk, scheme, ContactMode::Bilateral, dt)
            .unwrap();
    let start = {
        let e = run.energy();
        e.kinetic + e.strain
    };
    let mut largest: f64 = 0.0;
    for _ in 0..20_000 {
        run.step();
        let e = run.energy();
        let x = e.kinetic + e.strain;
        largest = largest.max(if x.is_finite() { x } else { f64::INFINITY });
        if largest > 1e6 * start {
            break;
        }
    }
    largest / start
}

/// Source: the measured limit of `step_limits_of_the_combinations` (amplification matrix),
/// checked by running: the stability rows at 0.99, 1.00 and 1.01 of it, as the report's stability
/// table grades them (bounded at and below the limit, the blow-up guard's ratio of ten exceeded
/// above it). Proves: the measured limit of Park-LTS + bipenalty (beta_s = 1e8, r = 1) and of
/// RMM + bipenalty is the step where a persistent contact run turns unstable.
#[test]
fn stability_rows_at_the_measured_limit() {
    let problem = layered_impact(8);
    let bipenalty = problem.penalty(1e8, MassPenalty::Ratio(1.0)).unwrap();
    let scheme = ContactScheme::Bipenalty(bipenalty);
    for bulk in [incremental(true), BulkScheme::Reciprocal { beta: 0.5 }] {
        let limit = measured_limit(&problem, bulk, scheme, ContactMode::Bilateral).unwrap();
        for (factor, stable) in [(0.99, true), (1.0, true), (1.01, false)] {
            let ratio = growth(&problem, bulk, scheme, factor * limit);
            let label = format!("{} at {factor} of {limit}", bulk.label());
            if stable {
                assert!(ratio < 10.0, "{label}: grew {ratio}");
            } else {
                assert!(ratio > 10.0, "{label}: grew only {ratio}");
            }
        }
    }
}
