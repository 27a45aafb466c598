//! Self-tests of the exact impact of two layered bars (`courant_references::contact::
//! LayeredImpact`, method of characteristics; Graff, *Wave Motion in Elastic Solids*, 1975,
//! ch. 2). Sources of truth: the homogeneous impact force of `ImpactForce` (elementary wave
//! theory, Graff ch. 2, Johnson 1972 ch. 3), the conservation of momentum and energy of the
//! elastic bars (no external force; lossless contact), `2L/c` for the separation of equal
//! homogeneous bars, and a second route: a node lattice of the characteristic invariants with
//! Courant number 1 in every cell (exact for layers whose travel times are multiples of the
//! step; a different representation: invariants on a grid instead of a list of step waves).

use courant_references::contact::{
    ForcePlateau, ImpactBar, ImpactForce, ImpactLayer, LayeredImpact,
};
use courant_references::{ContactHistory, ExactSolution, ReferenceError};

/// Impulse of the first contact, up to the first opening.
fn first_impulse(impact: &LayeredImpact) -> f64 {
    let sep = impact.separation_time();
    impact
        .force_plateaus()
        .iter()
        .filter(|p| p.start < sep)
        .map(|p| p.force * (p.end.min(sep) - p.start))
        .sum()
}

fn layer(thickness: f64, modulus: f64) -> ImpactLayer {
    ImpactLayer::new(thickness, modulus, 1.0, 1.0).unwrap()
}

/// The scene `impact_layered`: striker [0, 0.5] E = 1, [0.5, 1] E = 256 (contact end); target
/// [0, 0.5] E = 16 (contact end), [0.5, 1.5] E = 1, [1.5, 2] E = 256; rho = A = v0 = 1.
fn scene() -> (Vec<ImpactLayer>, Vec<ImpactLayer>) {
    (
        vec![layer(0.5, 1.0), layer(0.5, 256.0)],
        vec![layer(0.5, 16.0), layer(1.0, 1.0), layer(0.5, 256.0)],
    )
}

#[test]
fn homogeneous_bars_give_the_impact_force_of_elementary_wave_theory() {
    // (striker E, L), (target E, L): equal bars, unequal lengths, a stiffer and a softer striker.
    let cases = [
        ((1.0, 1.0), (1.0, 1.0)),
        ((1.0, 1.0), (1.0, 2.0)),
        ((1.0, 2.0), (1.0, 1.0)),
        ((4.0, 1.0), (1.0, 1.0)),
        ((1.0, 1.0), (9.0, 3.0)),
        ((1.0, 1.0), (4.0, 0.7)),
    ];
    for ((e1, l1), (e2, l2)) in cases {
        let exact = ImpactForce::new(
            ImpactBar::from_material(e1, 1.0, 1.0, l1).unwrap(),
            ImpactBar::from_material(e2, 1.0, 1.0, l2).unwrap(),
            1.0,
        )
        .unwrap();
        // The same bars, each split into three layers (no reflection inside a bar).
        let split = |e: f64, l: f64| vec![layer(0.2 * l, e), layer(0.5 * l, e), layer(0.3 * l, e)];
        for (striker, target) in [
            (vec![layer(l1, e1)], vec![layer(l2, e2)]),
            (split(e1, l1), split(e2, l2)),
        ] {
            let layered = LayeredImpact::new(&striker, &target, 1.0, 10.0).unwrap();
            let what = format!("E {e1}/{e2}, L {l1}/{l2}, {} layers", striker.len());
            let sep = exact.separation_time();
            assert!(
                (layered.separation_time() - sep).abs() < 1e-12 * sep,
                "{what}: {} vs {sep}",
                layered.separation_time()
            );
            assert!(
                (first_impulse(&layered) - exact.impulse()).abs() < 1e-12 * exact.impulse(),
                "{what}"
            );
            for k in 0..997 {
                let t = sep * (k as f64 + 0.5) / 997.0;
                let (a, b) = (layered.contact_force(t), exact.force(t));
                assert!((a - b).abs() < 1e-12, "{what}: F({t}) = {a} vs {b}");
            }
        }
    }
}

#[test]
fn equal_homogeneous_bars_separate_at_two_transits() {
    for (e, l) in [(1.0, 1.0), (4.0, 1.0), (1.0, 3.0)] {
        let bars = vec![layer(l, e)];
        let impact = LayeredImpact::new(&bars, &bars, 1.0, 1.0).unwrap();
        let two_transits = 2.0 * l / e.sqrt();
        assert!((impact.separation_time() - two_transits).abs() < 1e-12 * two_transits);
        // F = Z v0/2 throughout.
        assert!((impact.first_plateau_force() - 0.5 * e.sqrt()).abs() < 1e-15);
    }
}

#[test]
fn momentum_and_energy_are_conserved_through_the_layered_impact() {
    let (striker, target) = scene();
    let impact = LayeredImpact::new(&striker, &target, 1.0, 12.0).unwrap();
    // Initial: striker mass 1 at v0 = 1.
    let (m0, e0) = (1.0, 0.5);
    let sep = impact.separation_time();
    assert!(sep.is_finite() && sep > 0.0);
    for k in 0..400 {
        let t = 0.03 * k as f64 + 0.0071;
        if t > impact.valid_until() {
            break;
        }
        let (kinetic, strain, momentum) = impact.energy_and_momentum(t);
        assert!(
            (momentum - m0).abs() < 1e-12,
            "t = {t}: momentum {momentum}"
        );
        assert!(
            (kinetic + strain - e0).abs() < 1e-12,
            "t = {t}: energy {} ({kinetic} + {strain})",
            kinetic + strain
        );
    }
    // The impulse is the striker's momentum loss and the target's gain after separation.
    let after = sep + 1e-9;
    let target_momentum: f64 = {
        let l1 = impact.contact_position();
        let n = 20_000;
        let l2 = ExactSolution::domain_length(&impact) - l1;
        (0..n)
            .map(|i| {
                let x0 = l1 + l2 * i as f64 / n as f64;
                let x1 = l1 + l2 * (i + 1) as f64 / n as f64;
                impact.mean_state(x0, x1, after).1 * (x1 - x0)
            })
            .sum()
    };
    assert!(
        (target_momentum - first_impulse(&impact)).abs() < 1e-9,
        "{target_momentum} vs {}",
        first_impulse(&impact)
    );
}

/// Node lattice of the characteristic invariants `alpha = N - Z v` (moving +x) and
/// `beta = N + Z v` (moving -x), one cell per step `dt` of travel time: exact when every layer's
/// travel time is an integer multiple of dt. Returns, per step k, the contact force (compression
/// positive) on `[k dt, (k+1) dt)`, the opening step, and the node states `(x, N, v)` at the
/// given step.
struct Lattice {
    force: Vec<f64>,
    opened: Option<usize>,
    snapshot: Vec<(f64, f64, f64)>,
}

fn lattice(
    striker: &[(f64, f64)],
    target: &[(f64, f64)],
    dt: f64,
    steps: usize,
    snapshot_step: usize,
) -> Lattice {
    // Cells: (Z, dx, body); rho = A = 1, so Z = sqrt(E), c = sqrt(E).
    let mut cells = Vec::new();
    for (body, layers) in [(0, striker), (1, target)] {
        for &(thickness, modulus) in layers {
            let c = modulus.sqrt();
            let n = (thickness / c / dt).round() as usize;
            assert!(
                ((n as f64) * dt - thickness / c).abs() < 1e-12,
                "commensurate"
            );
            for _ in 0..n {
                cells.push((modulus.sqrt(), thickness / n as f64, body));
            }
        }
    }
    let cn = cells.len();
    let contact = cells.iter().position(|c| c.2 == 1).unwrap();
    // alpha[j]: arriving at node j + 1 from cell j; beta[j]: arriving at node j from cell j.
    let v_init = |j: usize| if cells[j].2 == 0 { 1.0 } else { 0.0 };
    let mut alpha: Vec<f64> = (0..cn).map(|j| -cells[j].0 * v_init(j)).collect();
    let mut beta: Vec<f64> = (0..cn).map(|j| cells[j].0 * v_init(j)).collect();
    let mut touching = true;
    let mut out = Lattice {
        force: Vec::new(),
        opened: None,
        snapshot: Vec::new(),
    };
    for k in 0..steps {
        // Node states: (left side N, v), (right side N, v).
        let mut states = Vec::with_capacity(cn + 1);
        for node in 0..=cn {
            let state = if node == 0 {
                let (z, b) = (cells[0].0, beta[0]);
                ((0.0, b / z), (0.0, b / z))
            } else if node == cn {
                let (z, a) = (cells[cn - 1].0, alpha[cn - 1]);
                ((0.0, -a / z), (0.0, -a / z))
            } else {
                let (zl, zr, a, b) = (
                    cells[node - 1].0,
                    cells[node].0,
                    alpha[node - 1],
                    beta[node],
                );
                let v = (b - a) / (zl + zr);
                let n = a + zl * v;
                if node == contact && touching && n > 1e-12 {
                    touching = false;
                    out.opened = Some(k);
                }
                if node == contact && !touching {
                    ((0.0, -a / zl), (0.0, b / zr))
                } else {
                    ((n, v), (n, v))
                }
            };
            states.push(state);
        }
        out.force.push(-states[contact].0.0);
        if k == snapshot_step {
            let mut x = 0.0;
            for (node, s) in states.iter().enumerate() {
                out.snapshot.push((x, s.1.0, s.1.1));
                if node < cn {
                    x += cells[node].1;
                }
            }
        }
        // Emit: alpha leaves node j into cell j (its right side), beta into cell j - 1.
        for j in 0..cn {
            let (n, v) = states[j].1;
            alpha[j] = n - cells[j].0 * v;
            let (n, v) = states[j + 1].0;
            beta[j] = n + cells[j].0 * v;
        }
    }
    out
}

#[test]
fn a_characteristic_lattice_at_courant_one_agrees_with_the_wave_tracking() {
    let (striker, target) = scene();
    let impact = LayeredImpact::new(&striker, &target, 1.0, 8.0).unwrap();
    // Travel times: 0.5, 1/32 | 1/8, 1, 1/32: all multiples of 1/64 (two cells in the thinnest).
    let dt = 1.0 / 64.0;
    let raw_s = [(0.5, 1.0), (0.5, 256.0)];
    let raw_t = [(0.5, 16.0), (1.0, 1.0), (0.5, 256.0)];
    // The lattice has no re-contact (it falls between its instants): compare until then.
    let recontact = impact.closings()[0];
    let snap = (recontact / dt).floor() as usize - 1;
    let lat = lattice(&raw_s, &raw_t, dt, snap + 1, snap);
    let opened = lat.opened.expect("the lattice contact opens") as f64 * dt;
    assert!(
        (opened - impact.separation_time()).abs() < 1e-12,
        "lattice {opened} vs tracking {}",
        impact.separation_time()
    );
    for (k, f) in lat.force.iter().enumerate() {
        let t = (k as f64 + 0.5) * dt;
        let exact = impact.contact_force(t);
        assert!((f - exact).abs() < 1e-11, "t = {t}: lattice {f} vs {exact}");
    }
    let t = (snap as f64 + 0.5) * dt;
    for &(x, n, v) in &lat.snapshot {
        let (en, ev) = impact.state(x, t);
        assert!(
            (n - en).abs() < 1e-11 && (v - ev).abs() < 1e-11,
            "x = {x}, t = {t}: lattice ({n}, {v}) vs ({en}, {ev})"
        );
    }
}

#[test]
fn the_layered_scene_has_its_hand_computed_first_plateau_and_a_staircase() {
    let (striker, target) = scene();
    let impact = LayeredImpact::new(&striker, &target, 1.0, 8.0).unwrap();
    // Z1 = 16 (E = 256), Z2 = 4 (E = 16): F1 = 16 * 4/20 = 3.2 until the first reflection
    // returns: the striker's interface at 2/32 of a time unit, the target's at 2/8.
    assert!((impact.first_plateau_force() - 3.2).abs() < 1e-14);
    assert!((impact.contact_force(0.03) - 3.2).abs() < 1e-14);
    let plateaus: &[ForcePlateau] = impact.force_plateaus();
    assert!(plateaus.len() > 3, "{plateaus:?}");
    assert!((plateaus[0].end - 1.0 / 16.0).abs() < 1e-12, "{plateaus:?}");
    assert!(impact.contact_impulse() > 0.0 && impact.contact_impulse() < 2.0);
    assert_eq!(ExactSolution::name(&impact), "layered-impact");
    // The striker keeps most of its momentum and catches the target's end again.
    assert!(
        impact.separation_time() == 0.25,
        "{}",
        impact.separation_time()
    );
    assert!(!impact.closings().is_empty() && impact.closings()[0] > 0.25);
    assert!(impact.contact().is_some());
}

#[test]
fn incommensurate_layers_stop_at_the_event_cap_with_a_typed_error() {
    let striker = vec![layer(1.0, 1.0), layer(std::f64::consts::SQRT_2, 7.0)];
    let target = vec![layer(std::f64::consts::PI, 3.0), layer(1.0, 0.5)];
    let err = LayeredImpact::with_cap(&striker, &target, 1.0, 200.0, 500).unwrap_err();
    assert!(
        matches!(err, ReferenceError::TooManyEvents { cap: 500, .. }),
        "{err}"
    );
    assert!(
        LayeredImpact::new(&[], &target, 1.0, 1.0).is_err()
            && LayeredImpact::new(&striker, &target, 0.0, 1.0).is_err()
            && ImpactLayer::new(1.0, -1.0, 1.0, 1.0).is_err()
    );
}
