//! Critical time step of a contact problem: contact-free bulk, contact-active penalty system,
//! and the predictor-corrector's own limit; exact values by bisection on Sturm counts, a
//! conservative row-sum (Gershgorin) bound and the common, unconservative nodal estimate.

use std::fmt;

use super::penalty::Penalty;
use super::problem::ContactProblem;
use super::scheme::ContactScheme;
use crate::analysis::stability::{bisect_top, lift_above_spectrum};
use crate::error::NoConvergence;
use crate::mass::banded::SymmetricBanded;

/// The symmetric tridiagonal pencil `(K + K_p, M + M_p)` of a contact problem over the global
/// node numbering (the bodies' nodes one after the other), lumped `M`. Rows and columns of
/// fixed nodes are replaced by `K_ii = 0`, `M_ii = 1` (eigenvalue 0, which never controls the
/// step). With `Penalty { 0, 0 }` it is the contact-free pencil.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPencil {
    /// Diagonal of `K + K_p`.
    pub k_diag: Vec<f64>,
    /// Off-diagonal of `K + K_p` (`k_off[i]` couples i and i + 1; 0 between bodies unless the
    /// pair link `-k_s` is there).
    pub k_off: Vec<f64>,
    /// Diagonal of `M + M_p`.
    pub m_diag: Vec<f64>,
    /// Off-diagonal of `M + M_p` (only the relative mass penalty `-m_p` of a pair).
    pub m_off: Vec<f64>,
    /// Global index of each contact node.
    pub contact: Vec<usize>,
}

impl ContactPencil {
    /// Assemble with the penalties active.
    pub fn assemble(problem: &ContactProblem, penalty: Penalty) -> Self {
        let n = problem.node_count();
        let mut p = Self {
            k_diag: vec![0.0; n],
            k_off: vec![0.0; n - 1],
            m_diag: vec![0.0; n],
            m_off: vec![0.0; n - 1],
            contact: Vec::new(),
        };
        let mut offsets = Vec::new();
        let mut offset = 0;
        for model in problem.bodies() {
            offsets.push(offset);
            let k = model.stiffness();
            for (e, &ke) in k.iter().enumerate() {
                let (i, j) = (offset + e, offset + e + 1);
                p.k_diag[i] += ke;
                p.k_diag[j] += ke;
                p.k_off[i] -= ke;
            }
            for (i, &m) in model.nodal_mass().iter().enumerate() {
                p.m_diag[offset + i] = m;
            }
            offset += model.bar().node_count();
        }
        // Penalty blocks k_s N N^T and m_p N N^T; the contact nodes are adjacent (pair) or one.
        let nodes = problem.contact_nodes();
        p.contact = nodes.iter().map(|c| offsets[c.body] + c.node).collect();
        for (a, ca) in nodes.iter().enumerate() {
            let i = p.contact[a];
            p.k_diag[i] += penalty.stiffness;
            p.m_diag[i] += penalty.mass;
            for (b, cb) in nodes.iter().enumerate().skip(a + 1) {
                let j = p.contact[b];
                let lo = i.min(j);
                p.k_off[lo] += penalty.stiffness * ca.sign * cb.sign;
                p.m_off[lo] += penalty.mass * ca.sign * cb.sign;
            }
        }
        // Fixed nodes: decouple.
        let mut offset = 0;
        for model in problem.bodies() {
            for i in 0..model.bar().node_count() {
                if model.is_fixed(i) {
                    let g = offset + i;
                    p.k_diag[g] = 0.0;
                    p.m_diag[g] = 1.0;
                    if g > 0 {
                        p.k_off[g - 1] = 0.0;
                        p.m_off[g - 1] = 0.0;
                    }
                    if g < n - 1 {
                        p.k_off[g] = 0.0;
                        p.m_off[g] = 0.0;
                    }
                }
            }
            offset += model.bar().node_count();
        }
        p
    }

    /// Order of the pencil.
    pub fn order(&self) -> usize {
        self.k_diag.len()
    }

    /// Number of eigenvalues of `K u = lambda M u` below `x`: the negative pivots of the
    /// `LDL^T` factorisation of `K - x M` (Sylvester's law of inertia, `M` positive definite).
    /// O(n), no allocation; a zero pivot is replaced by a tiny negative one.
    pub fn count_below(&self, x: f64) -> usize {
        let mut count = 0;
        let mut pivot = 1.0;
        for i in 0..self.order() {
            let diag = self.k_diag[i] - x * self.m_diag[i];
            pivot = if i == 0 {
                diag
            } else {
                let off = self.k_off[i - 1] - x * self.m_off[i - 1];
                if off == 0.0 {
                    diag
                } else {
                    diag - off * off / pivot
                }
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

    /// Upper bound on the largest eigenvalue: for each row, the smaller of the row sum of
    /// `|M^-1 K|` (the infinity norm bounds the spectral radius of `M^-1 K`) and the pencil
    /// bound `sum_j |K_ij| / (M_ii - sum_{j != i} |M_ij|)` (from the row of the largest entry of
    /// an eigenvector; M here is diagonally dominant), taken row by row only where the mass is
    /// diagonal and as the smaller of the two maxima over the pair rows.
    pub fn row_sum_bound(&self) -> f64 {
        let n = self.order();
        let k_abs_row = |i: usize| -> f64 {
            let left = if i > 0 { self.k_off[i - 1].abs() } else { 0.0 };
            let right = if i + 1 < n { self.k_off[i].abs() } else { 0.0 };
            self.k_diag[i].abs() + left + right
        };
        let m_coupled =
            |i: usize| (i > 0 && self.m_off[i - 1] != 0.0) || (i + 1 < n && self.m_off[i] != 0.0);
        let mut plain = 0.0_f64;
        let (mut pencil, mut norm) = (0.0_f64, 0.0_f64);
        for i in 0..n {
            if !m_coupled(i) {
                plain = plain.max(k_abs_row(i) / self.m_diag[i]);
                continue;
            }
            // Pencil (diagonal-dominance) bound.
            let left = if i > 0 { self.m_off[i - 1].abs() } else { 0.0 };
            let right = if i + 1 < n { self.m_off[i].abs() } else { 0.0 };
            let margin = self.m_diag[i] - left - right;
            pencil = pencil.max(if margin > 0.0 {
                k_abs_row(i) / margin
            } else {
                f64::INFINITY
            });
            // Row i of M^-1 K: M is diagonal outside the 2x2 coupled block (a, a + 1).
            let a = if i + 1 < n && self.m_off[i] != 0.0 {
                i
            } else {
                i - 1
            };
            let b = a + 1;
            let det = self.m_diag[a] * self.m_diag[b] - self.m_off[a] * self.m_off[a];
            let (own, other) = if i == a {
                (self.m_diag[b] / det, -self.m_off[a] / det)
            } else {
                (self.m_diag[a] / det, -self.m_off[a] / det)
            };
            let j = if i == a { b } else { a };
            let k_at = |r: usize, c: usize| -> f64 {
                match r.abs_diff(c) {
                    0 => self.k_diag[r],
                    1 => self.k_off[r.min(c)],
                    _ => 0.0,
                }
            };
            let lo = a.saturating_sub(1);
            let hi = (b + 1).min(n - 1);
            let row: f64 = (lo..=hi)
                .map(|c| (own * k_at(i, c) + other * k_at(j, c)).abs())
                .sum();
            norm = norm.max(row);
        }
        plain.max(pencil.min(norm))
    }

    /// Largest eigenvalue by bisection on [`Self::count_below`], to a relative width of about two
    /// ulps, starting from [`Self::row_sum_bound`] (grown if round-off left an eigenvalue above):
    /// at most [`crate::analysis::BOUND_DOUBLINGS`] doublings and
    /// [`crate::analysis::BISECTION_STEPS`] halvings.
    ///
    /// # Errors
    /// [`NoConvergence`] when no finite bound above the spectrum is found or the bisection does
    /// not close (entries whose products overflow, e.g. a bar area of 1e300).
    pub fn largest_eigenvalue(&self) -> Result<f64, NoConvergence> {
        let n = self.order();
        let start = self.row_sum_bound() * (1.0 + 1e-12);
        if start <= 0.0 {
            return Ok(0.0);
        }
        let all_below = |x: f64| self.count_below(x) == n;
        let hi = lift_above_spectrum(start, all_below)?;
        bisect_top(hi, 2.0 * f64::EPSILON, all_below)
    }

    /// The same pencil as two `SymmetricBanded` matrices (bandwidth 1), for cross-checks with
    /// `SymmetricBanded::negative_pivots_of_shifted`.
    pub fn to_banded(&self) -> (SymmetricBanded, SymmetricBanded) {
        let n = self.order();
        let mut k = SymmetricBanded::zeros(n, 1);
        let mut m = SymmetricBanded::zeros(n, 1);
        for i in 0..n {
            k.add(i, i, self.k_diag[i]);
            m.add(i, i, self.m_diag[i]);
            if i + 1 < n {
                k.add(i, i + 1, self.k_off[i]);
                m.add(i, i + 1, self.m_off[i]);
            }
        }
        (k, m)
    }
}

/// Relative tolerance within which a contact limit counts as equal to the contact-free one.
pub const LIMIT_TIE: f64 = 1e-12;

/// Which limit gives the applicable critical step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepLimit {
    /// The contact-free bulk: `2/omega_max` of `(K, M)`.
    ContactFree,
    /// The contact-active penalty system: `2/omega_max` of `(K + K_p, M + M_p)`.
    ContactActive,
    /// The predictor-corrector's own limit `k_s dt^2/(m_c + m_p) <= 1`.
    PredictorCorrector,
    /// A combined bulk's limit measured from the spectral radius of its one-step amplification
    /// matrix with the contact always active ([`super::combined::amplification`]).
    Measured,
    /// Park's a-priori rule `alpha_e = dt/dt_e <= 1` in every element (methods.md §6): a
    /// sufficient condition of the scheme on a uniform mesh, not a measured limit.
    ParkRule,
}

impl fmt::Display for StepLimit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            StepLimit::ContactFree => "the contact-free bulk (2/omega_max of K vs M)",
            StepLimit::ContactActive => {
                "the contact-active system (2/omega_max of K + K_p vs M + M_p)"
            }
            StepLimit::PredictorCorrector => {
                "the predictor-corrector limit k_s dt^2/(m_c + m_p) <= 1"
            }
            StepLimit::Measured => {
                "the measured limit rho(G) <= 1 of the combined step with the contact active"
            }
            StepLimit::ParkRule => "Park's rule alpha_e = dt/dt_e <= 1 in every element",
        })
    }
}

/// Critical time steps of a contact problem under one scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactCriticalStep {
    /// Exact `2/omega_max` of the contact-free bodies.
    pub contact_free: f64,
    /// Exact `2/omega_max` of the contact-active pencil `(K + K_p, M + M_p)` (equal to
    /// `contact_free` for the Lagrange multiplier method, which has no penalty).
    pub contact_active: f64,
    /// `sqrt((m_c + m_p)/k_s)`: the predictor-corrector's limit (infinite without `k_s`).
    pub predictor_corrector: f64,
    /// The step the scheme is checked against: `min(contact_free, contact_active)` for (a) and
    /// (b), `min(contact_free, predictor_corrector)` for (c), `contact_free` for (d); a contact
    /// limit within the relative [`LIMIT_TIE`] of the contact-free one counts as equal to it.
    pub applicable: f64,
    /// Which limit gives `applicable`.
    pub binding: StepLimit,
    /// Conservative counterpart of `applicable` from the row-sum (Gershgorin) bounds of the
    /// pencils involved ([`ContactPencil::row_sum_bound`]); never above `applicable`.
    pub gershgorin: f64,
    /// The common nodal estimate: `min(min_e h_e/c_e, 2/sqrt((k + k_s)/(m_c + m_p)))` with the
    /// contact element's `k` and the contact node's `m_c` (the bulk by its element estimate).
    /// NOT conservative: the localized contact mode lies above the contact row's ratio
    /// (references::contact, part 1).
    pub nodal: f64,
    /// `min_e h_e/c_e` over all bodies, to turn steps into Courant numbers.
    pub stiffest_transit: f64,
}

impl ContactCriticalStep {
    /// All estimates for `problem` under `scheme`.
    ///
    /// # Errors
    /// [`NoConvergence`] from [`ContactPencil::largest_eigenvalue`].
    pub fn of(problem: &ContactProblem, scheme: &ContactScheme) -> Result<Self, NoConvergence> {
        let step = |lambda: f64| {
            if lambda > 0.0 {
                2.0 / lambda.sqrt()
            } else {
                f64::INFINITY
            }
        };
        let free = ContactPencil::assemble(
            problem,
            Penalty {
                stiffness: 0.0,
                mass: 0.0,
            },
        );
        let free_bound = free.row_sum_bound();
        let contact_free = step(free.largest_eigenvalue()?);
        let penalty = scheme.penalty();
        let (contact_active, active_bound) = if penalty.stiffness > 0.0 || penalty.mass > 0.0 {
            let active = ContactPencil::assemble(problem, penalty);
            (step(active.largest_eigenvalue()?), active.row_sum_bound())
        } else {
            (contact_free, free_bound)
        };
        let m_c = problem.contact_mass();
        let predictor_corrector = if penalty.stiffness > 0.0 {
            ((m_c + penalty.mass) / penalty.stiffness).sqrt()
        } else {
            f64::INFINITY
        };
        // Within LIMIT_TIE of each other (two bisections and the assembly differ by a few ulps; at
        // r = 1 the two are equal in exact arithmetic) the contact-free limit is named.
        let pick = |other: f64, limit: StepLimit| {
            if other < contact_free * (1.0 - LIMIT_TIE) {
                (other, limit)
            } else {
                (contact_free, StepLimit::ContactFree)
            }
        };
        let ((applicable, binding), gershgorin) = match scheme {
            ContactScheme::Penalty { .. } | ContactScheme::Bipenalty(_) => (
                pick(contact_active, StepLimit::ContactActive),
                step(free_bound.max(active_bound)),
            ),
            ContactScheme::PredictorCorrector(_) => (
                pick(predictor_corrector, StepLimit::PredictorCorrector),
                step(free_bound).min(predictor_corrector),
            ),
            ContactScheme::LagrangeMultiplier => {
                ((contact_free, StepLimit::ContactFree), step(free_bound))
            }
        };
        let stiffest_transit = problem.stiffest_transit();
        let contact_ratio = problem
            .contact_nodes()
            .iter()
            .map(|c| (c.element_stiffness + penalty.stiffness) / (c.mass + penalty.mass))
            .fold(0.0, f64::max);
        let nodal = stiffest_transit.min(step(contact_ratio));
        Ok(Self {
            contact_free,
            contact_active,
            predictor_corrector,
            applicable,
            binding,
            gershgorin,
            nodal,
            stiffest_transit,
        })
    }

    /// Courant number of a step, relative to the stiffest element.
    pub fn courant(&self, dt: f64) -> f64 {
        dt / self.stiffest_transit
    }

    /// Critical Courant number of the applicable step.
    pub fn critical_courant(&self) -> f64 {
        self.courant(self.applicable)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::MassPenalty;
    use crate::model::bar::Bar;
    use crate::model::load::End;
    use crate::model::mesh::Mesh;

    fn wall(n: usize) -> ContactProblem {
        let bar = Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 1.0, 1.0, 1.0).unwrap();
        ContactProblem::wall_impact(bar, End::Right, 1.0, 0.0).unwrap()
    }

    #[test]
    fn sturm_count_agrees_with_the_banded_inertia() {
        let p = ContactProblem::fig5(5, 1.0).unwrap();
        let pen = p.penalty(30.0, MassPenalty::Ratio(2.0)).unwrap();
        let pencil = ContactPencil::assemble(&p, pen);
        let (k, m) = pencil.to_banded();
        for x in [1.0, 50.0, 399.0, 400.0, 401.0, 1e3, 1e4, 1e5] {
            assert_eq!(
                pencil.count_below(x),
                k.negative_pivots_of_shifted(&m, x),
                "x = {x}"
            );
        }
    }

    /// A bar of area 1e300 made the doubling of the bisection's bound loop forever (its
    /// off-diagonal squared overflows): now a typed error within the iteration bounds.
    #[test]
    fn an_overflowing_pencil_is_an_error_not_a_hang() {
        let bar = Bar::homogeneous(Mesh::uniform(1.0, 10).unwrap(), 1.0, 1.0, 1e300).unwrap();
        let problem = ContactProblem::wall_impact(bar, End::Right, 1.0, 0.0).unwrap();
        let started = std::time::Instant::now();
        let e = ContactCriticalStep::of(&problem, &ContactScheme::LagrangeMultiplier).unwrap_err();
        assert!(started.elapsed().as_secs_f64() < 1.0);
        assert!(e.to_string().contains("critical-step bisection"), "{e}");
    }

    #[test]
    fn contact_free_free_free_bar_has_courant_one() {
        let c = ContactCriticalStep::of(&wall(50), &ContactScheme::LagrangeMultiplier).unwrap();
        assert!((c.critical_courant() - 1.0).abs() < 1e-14);
        assert_eq!(c.binding, StepLimit::ContactFree);
    }

    #[test]
    fn penalty_wall_orders_nodal_exact_and_gershgorin() {
        let p = wall(200);
        let pen = p.penalty(10.0, MassPenalty::None).unwrap();
        let c = ContactCriticalStep::of(
            &p,
            &ContactScheme::Penalty {
                stiffness: pen.stiffness,
            },
        )
        .unwrap();
        assert_eq!(c.binding, StepLimit::ContactActive);
        assert!(c.gershgorin < c.applicable && c.applicable < c.nodal);
    }
}
