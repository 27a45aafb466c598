//! Source of truth: the schemes as the seed and the papers state them, integrated naively here
//! with dense global matrices (nalgebra) — seed eq. 17 for central difference with (bi)penalty,
//! `(M + M_p) a = F - (K + K_p) u - f_p` solved by LU every step; the seed's predictor-corrector
//! flowchart (section 3.2) line by line with `(M + M_p)^-1` applied by LU; and the forward
//! increment Lagrange multiplier (Carpenter, Taylor and Katona 1991) as a constrained solve.
//! All use the half-step start of methods.md §2 (`v^{1/2} = v^0 + dt/2 a^0`; the contact
//! correction of the predictor-corrector and Lagrange multiplier schemes in full).
//!
//! ```text
//!   pair:   o--o--o--o--o--o--a | b--o--o-- ... --o      wall:  F -> o--o-- ... --o--c |//
//!           striker, v0 ->       target at rest                loaded bar at rest
//! ```
//!
//! Proves: the O(1) Sherman-Morrison contact update on the unchanged lumped kernel
//! (`courant_solver::contact`) is the same scheme as the textbook global one, to round-off,
//! for all four schemes, on a two-bar impact and on a loaded bar chattering against a wall,
//! over hundreds of contact switches.

use courant_solver::contact::{
    ContactProblem, ContactScheme, ContactStepper, MassPenalty, Penalty,
};
use courant_solver::{Bar, Mesh};
use nalgebra::{DMatrix, DVector};

/// Dense global operators of a contact problem (bodies numbered one after the other).
struct Dense {
    m: DMatrix<f64>,
    k: DMatrix<f64>,
    n: DVector<f64>,
    g0: f64,
    loads: Vec<(usize, f64)>,
    u: DVector<f64>,
    v: DVector<f64>,
    offsets: Vec<usize>,
}

impl Dense {
    fn new(problem: &ContactProblem) -> Self {
        let size = problem.node_count();
        let mut d = Dense {
            m: DMatrix::zeros(size, size),
            k: DMatrix::zeros(size, size),
            n: DVector::zeros(size),
            g0: problem.initial_gap(),
            loads: Vec::new(),
            u: DVector::zeros(size),
            v: DVector::zeros(size),
            offsets: Vec::new(),
        };
        let mut offset = 0;
        for model in problem.bodies() {
            d.offsets.push(offset);
            for (e, &ke) in model.stiffness().iter().enumerate() {
                let (i, j) = (offset + e, offset + e + 1);
                d.k[(i, i)] += ke;
                d.k[(j, j)] += ke;
                d.k[(i, j)] -= ke;
                d.k[(j, i)] -= ke;
            }
            for (i, &mi) in model.nodal_mass().iter().enumerate() {
                d.m[(offset + i, offset + i)] = mi;
                d.u[offset + i] = model.initial_displacement()[i];
                d.v[offset + i] = model.initial_velocity()[i];
            }
            for load in model.loads() {
                d.loads.push((offset + load.node, load.magnitude));
            }
            offset += model.bar().node_count();
        }
        for c in problem.contact_nodes() {
            d.n[d.offsets[c.body] + c.node] = c.sign;
        }
        d
    }

    /// External forces at any t >= 0 (Heaviside loads, H(0) = 1).
    fn f(&self) -> DVector<f64> {
        let mut f = DVector::zeros(self.u.len());
        for &(i, magnitude) in &self.loads {
            f[i] += magnitude;
        }
        f
    }

    fn gap(&self, u: &DVector<f64>) -> f64 {
        self.n.dot(u) + self.g0
    }

    fn solve(a: &DMatrix<f64>, b: &DVector<f64>) -> DVector<f64> {
        a.clone().lu().solve(b).expect("M + M_p is invertible")
    }

    /// One level n: state u = u^n, v = v^{n-1/2} (v^0 at the start, w = 1/2) -> v^{n+1/2},
    /// then u^{n+1} = u^n + dt v^{n+1/2}.
    fn level(&mut self, scheme: &ContactScheme, dt: f64, w: f64) {
        let Penalty {
            stiffness: ks,
            mass: mp,
        } = scheme.penalty();
        let nn = &self.n * self.n.transpose();
        let residual = self.f() - &self.k * &self.u;
        match scheme {
            ContactScheme::Penalty { .. } | ContactScheme::Bipenalty(_) => {
                // Seed eq. 17: (M + M_p) a = F - (K + K_p) u - f_p while g < 0.
                let g = self.gap(&self.u);
                let a = if g < 0.0 {
                    let lhs = &self.m + &nn * mp;
                    let rhs = &residual - (&nn * &self.u) * ks - &self.n * (ks * self.g0);
                    Self::solve(&lhs, &rhs)
                } else {
                    Self::solve(&self.m, &residual)
                };
                self.v += a * (w * dt);
            }
            ContactScheme::PredictorCorrector(_) => {
                // Seed section 3.2, line by line.
                let a_pred = Self::solve(&self.m, &residual);
                let v_pred = &self.v + a_pred * (w * dt);
                let u_pred = &self.u + &v_pred * dt;
                let g = self.gap(&u_pred);
                let a_corr = if g < 0.0 {
                    let f_cont = -(&nn * &u_pred) * ks - &self.n * (ks * self.g0);
                    Self::solve(&(&self.m + &nn * mp), &f_cont)
                } else {
                    DVector::zeros(self.u.len())
                };
                self.v = v_pred + a_corr * dt;
            }
            ContactScheme::LagrangeMultiplier => {
                // Multiplier that makes N^T u^{n+1} + g0 = 0 if it would be negative.
                let a_pred = Self::solve(&self.m, &residual);
                let v_pred = &self.v + a_pred * (w * dt);
                let g = self.gap(&(&self.u + &v_pred * dt));
                let m_inv_n = Self::solve(&self.m, &self.n);
                let j = if g < 0.0 {
                    -g / (dt * self.n.dot(&m_inv_n))
                } else {
                    0.0
                };
                self.v = v_pred + m_inv_n * j;
            }
        }
        self.u += &self.v * dt;
    }
}

/// Run `steps` steps both ways and return the largest state difference relative to the largest
/// velocity seen.
fn compare(problem: &ContactProblem, scheme: ContactScheme, dt: f64, steps: usize) -> f64 {
    let mut dense = Dense::new(problem);
    let mut stepper = ContactStepper::new(problem, dt, scheme).unwrap();
    dense.level(&scheme, dt, 0.5);
    let (mut worst, mut scale) = (0.0_f64, 0.0_f64);
    let mut switches = 0;
    let mut active = false;
    for _ in 0..steps {
        // Both hold u^n (dense: already advanced to u^{n+1}; compare before the next level).
        let sample = stepper.step();
        if sample.active != active {
            switches += 1;
            active = sample.active;
        }
        dense_u_check(&dense, &stepper, &mut worst, &mut scale);
        dense.level(&scheme, dt, 1.0);
    }
    assert!(
        switches >= 2,
        "{}: the contact never switched",
        scheme.label()
    );
    worst / scale
}

fn dense_u_check(dense: &Dense, stepper: &ContactStepper, worst: &mut f64, scale: &mut f64) {
    // After `stepper.step()` the stepper holds u^n, v^{n+1/2}; the dense state holds u^n and
    // v^{n-1/2} (its next level has not run yet), so compare u, and v one level behind.
    for (b, &offset) in dense.offsets.iter().enumerate() {
        for (i, &u) in stepper.displacement(b).iter().enumerate() {
            *worst = worst.max((u - dense.u[offset + i]).abs());
            *scale = scale.max(dense.v[offset + i].abs() * stepper.dt());
        }
    }
}

#[test]
fn every_scheme_is_the_dense_textbook_scheme_to_round_off() {
    let pair = ContactProblem::bar_impact(
        Bar::homogeneous(Mesh::uniform(1.0, 6).unwrap(), 1.0, 1.0, 1.0).unwrap(),
        Bar::homogeneous(Mesh::uniform(2.0, 9).unwrap(), 3.0, 2.0, 1.0).unwrap(),
        1.0,
        0.02,
    )
    .unwrap();
    for (name, problem, co) in [
        ("pair", pair, 0.45),
        (
            "loaded wall",
            courant_solver::bench::loaded_wall(12, 0.01).unwrap(),
            0.5,
        ),
    ] {
        let dt = co * problem.stiffest_transit();
        let bipenalty = problem.penalty(40.0, MassPenalty::Ratio(1.0)).unwrap();
        let soft = problem.penalty(0.3, MassPenalty::Ratio(2.0)).unwrap();
        for scheme in [
            ContactScheme::Penalty {
                stiffness: soft.stiffness,
            },
            ContactScheme::Bipenalty(soft),
            ContactScheme::Bipenalty(bipenalty),
            ContactScheme::PredictorCorrector(bipenalty),
            ContactScheme::PredictorCorrector(soft),
            ContactScheme::LagrangeMultiplier,
        ] {
            let error = compare(&problem, scheme, dt, 600);
            assert!(
                error < 1e-11,
                "{name}, {}: relative state difference {error:e}",
                scheme.label()
            );
        }
    }
}
