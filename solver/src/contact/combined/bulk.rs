//! The bulk of a combined contact run over the global node numbering (the bodies' nodes one
//! after the other, no element between bodies): the element constants, the inverse mass
//! (lumped, or the reciprocal mass's tridiagonal `M^-1`), its rank-one contact update and Park's
//! element-by-element displacement prediction with the contact nodes at `theta = 0`.

use crate::contact::problem::ContactProblem;
use crate::error::InputError;
use crate::kernels::park::{ParkOptions, ParkVariant};
use crate::mass::tridiagonal::Tridiagonal;
use crate::mass::{MassKind, MassOperator};

/// What steps the bulk of each body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BulkScheme {
    /// Central difference with the lumped mass (velocity-Verlet form; the same levels as
    /// [`crate::contact::ContactStepper`] to round-off).
    CentralDifference,
    /// Central difference with the reciprocal mass RMM(beta) (`M^-1 = A^-1 C A^-1`, tridiagonal;
    /// methods.md §5): its contact uses `(M + M_p)^-1` by the rank-one (Sherman-Morrison) update.
    Reciprocal {
        /// RMM's beta (beta = 1 is the lumped mass).
        beta: f64,
    },
    /// Park's pull-back scheme (methods.md §6) in every element except at the contact nodes,
    /// which step with central difference (`theta = 0` there; module docs of
    /// [`crate::contact::combined`]). Lumped mass.
    Park(ParkOptions),
}

impl BulkScheme {
    /// Short label: `cd-lmm`, `cd-rmm(beta)`, `park-lts-free`, ...
    pub fn label(&self) -> String {
        match self {
            BulkScheme::CentralDifference => "cd-lmm".into(),
            BulkScheme::Reciprocal { beta } => format!("cd-rmm({beta})"),
            BulkScheme::Park(o) => o.label(),
        }
    }

    /// Internal-force evaluations per step: 2 for Park (element predictions and `K u^{n+1}`),
    /// 1 for central difference.
    pub fn force_evaluations(&self) -> usize {
        match self {
            BulkScheme::Park(_) => 2,
            _ => 1,
        }
    }
}

/// One element over the global numbering: nodes `i`, `i + 1`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Element {
    pub i: usize,
    pub body: usize,
    /// Node index of `i` in its body.
    pub local: usize,
    pub stiffness: f64,
    pub mass: f64,
    /// `dt_e` of the pull-back (own transit time, or the global one without local stepping).
    pub dt_e: f64,
}

/// `M^-1` over the global numbering, zero rows and columns at fixed nodes.
#[derive(Debug, Clone)]
pub(super) enum InverseMass {
    Diagonal(Vec<f64>),
    Tridiagonal(Tridiagonal),
}

impl InverseMass {
    pub(super) fn apply(&self, r: &[f64], a: &mut [f64]) {
        match self {
            InverseMass::Diagonal(d) => {
                for ((ai, ri), di) in a.iter_mut().zip(r).zip(d) {
                    *ai = ri * di;
                }
            }
            InverseMass::Tridiagonal(t) => t.apply(r, a),
        }
    }

    /// Column `j` of `M^-1`: its nonzero entries `(row, value)` (at most three).
    fn column(&self, j: usize) -> Vec<(usize, f64)> {
        match self {
            InverseMass::Diagonal(d) => vec![(j, d[j])],
            InverseMass::Tridiagonal(t) => {
                let mut c = vec![(j, t.diag[j])];
                if j > 0 && t.off[j - 1] != 0.0 {
                    c.push((j - 1, t.off[j - 1]));
                }
                if j < t.off.len() && t.off[j] != 0.0 {
                    c.push((j + 1, t.off[j]));
                }
                c
            }
        }
    }
}

/// The rank-one contact direction `q = M^-1 N` (sparse: the contact nodes and, for RMM, their
/// neighbours) and `s = N^T M^-1 N`. With them, for any right-hand side `r`,
///
/// ```text
///   (M + m_p N N^T)^-1 r = M^-1 r - q m_p (N^T M^-1 r)/(1 + m_p s)      (Sherman-Morrison)
/// ```
///
/// O(bandwidth) per contact node once `M^-1 r` is known: the bipenalty never solves with
/// `M + M_p` (Sherman and Morrison, Ann. Math. Stat. 21 (1950) 124).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactDirection {
    /// `(global node, (M^-1 N)_node)`.
    pub q: Vec<(usize, f64)>,
    /// `s = N^T M^-1 N`.
    pub compliance: f64,
    /// `(global node, N entry)` of the contact node(s).
    pub n: Vec<(usize, f64)>,
}

impl ContactDirection {
    /// `N^T x`.
    pub fn project(&self, x: &[f64]) -> f64 {
        self.n.iter().map(|&(i, s)| s * x[i]).sum()
    }

    /// `a <- a + c q`.
    pub fn add_scaled(&self, c: f64, a: &mut [f64]) {
        for &(i, qi) in &self.q {
            a[i] += c * qi;
        }
    }

    /// `x <- (M + m_p N N^T)^-1 r` given `x = M^-1 r` on entry (Sherman-Morrison).
    pub fn penalized_inverse(&self, mass_penalty: f64, x: &mut [f64]) {
        let c = -mass_penalty * self.project(x) / (1.0 + mass_penalty * self.compliance);
        self.add_scaled(c, x);
    }
}

/// The assembled bulk: elements, masses, the inverse mass, fixed nodes, body offsets.
#[derive(Debug, Clone)]
pub(super) struct Assembly {
    pub elements: Vec<Element>,
    /// Lumped nodal masses `A` (the momentum weights for every mass: RMM keeps `1^T M = 1^T A`).
    pub lumped: Vec<f64>,
    pub inverse: InverseMass,
    pub fixed: Vec<bool>,
    pub offsets: Vec<usize>,
    /// Elements at each node (1 at a body's end, 2 inside).
    pub count: Vec<f64>,
    /// Per body: its mass operator (for `M v` in the energies; RMM needs a solve there).
    pub operators: Vec<MassOperator>,
}

impl Assembly {
    pub(super) fn new(problem: &ContactProblem, bulk: &BulkScheme) -> Result<Self, InputError> {
        let global_transit = problem.stiffest_transit();
        let local_stepping = matches!(bulk, BulkScheme::Park(o) if o.local_stepping);
        let kind = match *bulk {
            BulkScheme::Reciprocal { beta } => MassKind::Reciprocal { beta },
            _ => MassKind::Lumped,
        };
        let n = problem.node_count();
        let mut a = Self {
            elements: Vec::new(),
            lumped: Vec::with_capacity(n),
            inverse: InverseMass::Diagonal(Vec::new()),
            fixed: Vec::with_capacity(n),
            offsets: Vec::new(),
            count: vec![0.0; n],
            operators: Vec::new(),
        };
        let mut diag = Vec::with_capacity(n);
        let mut off = Vec::with_capacity(n.saturating_sub(1));
        for (b, model) in problem.bodies().iter().enumerate() {
            let offset = a.lumped.len();
            a.offsets.push(offset);
            let bar = model.bar();
            for (e, (&k, m)) in model.stiffness().iter().zip(bar.element_mass()).enumerate() {
                a.elements.push(Element {
                    i: offset + e,
                    body: b,
                    local: e,
                    stiffness: k,
                    mass: m,
                    dt_e: if local_stepping {
                        bar.element_transit_time(e)
                    } else {
                        global_transit
                    },
                });
                a.count[offset + e] += 1.0;
                a.count[offset + e + 1] += 1.0;
            }
            a.lumped.extend_from_slice(model.nodal_mass());
            a.fixed
                .extend((0..bar.node_count()).map(|i| model.is_fixed(i)));
            let operator = MassOperator::new(model, kind)?;
            match &operator {
                MassOperator::Reciprocal { inverse, .. } => {
                    diag.extend_from_slice(&inverse.diag);
                    off.extend_from_slice(&inverse.off);
                }
                _ => {
                    diag.extend((0..bar.node_count()).map(|i| {
                        if model.is_fixed(i) {
                            0.0
                        } else {
                            1.0 / model.nodal_mass()[i]
                        }
                    }));
                    off.extend(std::iter::repeat_n(0.0, bar.node_count() - 1));
                }
            }
            // No element, and no inverse-mass coupling, between two bodies.
            if b + 1 < problem.bodies().len() {
                off.push(0.0);
            }
            a.operators.push(operator);
        }
        a.inverse = match kind {
            MassKind::Reciprocal { .. } => InverseMass::Tridiagonal(Tridiagonal { diag, off }),
            _ => InverseMass::Diagonal(diag),
        };
        Ok(a)
    }

    /// `q = M^-1 N`, `s = N^T q` of the problem's contact node(s).
    pub(super) fn direction(&self, problem: &ContactProblem) -> ContactDirection {
        let n: Vec<(usize, f64)> = problem
            .contact_nodes()
            .iter()
            .map(|c| (self.offsets[c.body] + c.node, c.sign))
            .collect();
        let mut q: Vec<(usize, f64)> = Vec::new();
        for &(j, sign) in &n {
            for (i, value) in self.inverse.column(j) {
                match q.iter_mut().find(|(k, _)| *k == i) {
                    Some(entry) => entry.1 += sign * value,
                    None => q.push((i, sign * value)),
                }
            }
        }
        let mut d = ContactDirection {
            q,
            compliance: 0.0,
            n,
        };
        let mut dense = vec![0.0; self.lumped.len()];
        for &(i, v) in &d.q {
            dense[i] = v;
        }
        d.compliance = d.project(&dense);
        d
    }

    /// `R = F(t) - K u` over the global numbering (0 at fixed nodes).
    pub(super) fn residual(&self, problem: &ContactProblem, u: &[f64], t: f64, r: &mut [f64]) {
        r.iter_mut().for_each(|x| *x = 0.0);
        for e in &self.elements {
            let f = e.stiffness * (u[e.i + 1] - u[e.i]);
            r[e.i] += f;
            r[e.i + 1] -= f;
        }
        for (b, model) in problem.bodies().iter().enumerate() {
            for load in model.loads() {
                r[self.offsets[b] + load.node] += load.force(t);
            }
        }
        for (ri, &fixed) in r.iter_mut().zip(&self.fixed) {
            if fixed {
                *ri = 0.0;
            }
        }
    }

    /// Park's displacement `u^{n+1}` (methods.md §6 steps 1-4, element by element, the true
    /// `alpha_e = dt/dt_e`), with `theta` replaced by 0 at the nodes flagged in `cd_nodes`
    /// (there `u^{n+1} = u^n + dt v^n + dt^2/2 a^n`, central difference's).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn park_displacement(
        &self,
        problem: &ContactProblem,
        options: &ParkOptions,
        cd_nodes: &[bool],
        [u, v, a]: [&[f64]; 3],
        dt: f64,
        t: f64,
        next: &mut [f64],
    ) {
        let incremental = options.variant == ParkVariant::Incremental;
        next.iter_mut().for_each(|x| *x = 0.0);
        for e in &self.elements {
            let model = &problem.bodies()[e.body];
            let alpha = dt / e.dt_e;
            let beta1 = alpha * (1.0 + 3.0 * alpha - alpha * alpha) / 6.0;
            let beta2 = alpha * (alpha * alpha - 1.0) / 6.0;
            let half = 0.5 * e.mass;
            let (i, j) = (e.i, e.i + 1);
            let force = |global: usize, local: usize| {
                let push = model.external_force_at(local, t + e.dt_e);
                let f = if incremental {
                    push - model.external_force_at(local, t)
                } else {
                    push
                };
                f * half / self.lumped[global]
            };
            let (fi, fj) = (force(i, e.local), force(j, e.local + 1));
            let pushed = |k: usize| u[k] + e.dt_e * v[k] + 0.5 * e.dt_e * e.dt_e * a[k];
            let stretch = pushed(j) - pushed(i);
            let at = if incremental {
                let d = stretch - (u[j] - u[i]);
                [
                    a[i] + (fi + e.stiffness * d) / half,
                    a[j] + (fj - e.stiffness * d) / half,
                ]
            } else {
                [
                    (fi + e.stiffness * stretch) / half,
                    (fj - e.stiffness * stretch) / half,
                ]
            };
            for (side, k) in [i, j].into_iter().enumerate() {
                next[k] += u[k] + dt * v[k] + e.dt_e * e.dt_e * (beta1 * a[k] + beta2 * at[side]);
            }
        }
        for k in 0..next.len() {
            let u_cd = u[k] + dt * v[k] + 0.5 * dt * dt * a[k];
            next[k] = if self.fixed[k] {
                0.0
            } else if cd_nodes[k] {
                u_cd
            } else {
                options.theta * next[k] / self.count[k] + (1.0 - options.theta) * u_cd
            };
        }
    }

    /// `y = M v` over the global numbering (RMM: `A C^-1 A v` by its solve; O(N)).
    pub(super) fn mass_times(&self, v: &[f64], y: &mut [f64]) {
        for (b, op) in self.operators.iter().enumerate() {
            let start = self.offsets[b];
            let end = self.offsets.get(b + 1).copied().unwrap_or(v.len());
            op.apply(&v[start..end], &mut y[start..end]);
        }
    }
}
