//! Checks of the impact references (`courant_references::contact`, part 2: exact contact forces
//! of one-dimensional impact) against independent computations done here, with no solver.
//!
//! The exact wave-tracking force histories are compared with a brute-force characteristic
//! lattice written here (each bar cut into cells of one time step's travel, Riemann invariants
//! shifted cell by cell, free-end reflections, unilateral contact with a tracked gap), which also
//! gives each bar's momentum and energy after separation; with hand results (plateaus,
//! durations, impulses) and limits (Z2 -> Z1, Z2 -> inf). The penalty-regularised wall is checked
//! against the same lattice with a spring boundary. Sources: Graff, *Wave Motion in Elastic
//! Solids* (1975), ch. 2; Johnson, *Impact Strength of Materials* (1972), ch. 3; methods.md §7.

use courant_references::ReferenceError;
use courant_references::contact::{ImpactBar, ImpactForce, PenaltyWallForce};

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

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
    assert!(rel(impact.plateaus()[0].force, s.impedance() * v0) < 1e-14);
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
    // Fields are private: an invalid bar cannot be built, so only `new` can refuse it.
    assert_eq!(
        name(ImpactBar::new(1.0, f64::NAN, 1.0).unwrap_err()),
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
        let expected = bar.impedance() * v0 * (1.0 - (-t / tau).exp());
        assert!(
            (wall.force(t) - expected).abs() < 1e-14 * bar.impedance() * v0,
            "t = {t}"
        );
    }
    // After one time constant: 1 - 1/e of the rigid-wall force.
    let fraction = wall.force(tau) / (bar.impedance() * v0);
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
