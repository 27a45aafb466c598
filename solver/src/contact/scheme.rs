//! The contact schemes and their O(1) level update (derivations in the module docs of
//! [`crate::contact`]).

use super::penalty::Penalty;
use super::problem::ContactProblem;
use crate::error::InputError;

/// What `courant list --schemes` says of a contact scheme: its name in a contact scene's
/// `[contact] schemes`, what it is, the `[contact]` keys that set it, and its source.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ContactSchemeEntry {
    /// Name in `[contact] schemes`.
    pub name: &'static str,
    /// One line: what it is.
    pub summary: &'static str,
    /// The `[contact]` keys that set it.
    pub parameters: &'static [&'static str],
    /// Where it comes from.
    pub source: &'static str,
}

/// The contact schemes, in the order of [`ContactScheme`]'s variants. Each is the registry's
/// `cd` stepper on the bulk plus an O(1) contact momentum per level (module docs).
pub const CONTACT_SCHEMES: &[ContactSchemeEntry] = &[
    ContactSchemeEntry {
        name: "cd-penalty",
        summary: "central difference with the stiffness penalty k_s",
        parameters: &["beta_s"],
        source: "Kolman et al. (seed) eq. 17; methods.md §7",
    },
    ContactSchemeEntry {
        name: "cd-bipenalty",
        summary: "central difference with stiffness and mass penalties (K_p, M_p)",
        parameters: &["beta_s", "ratio or beta_m"],
        source: "Kopacka et al., IJNME 113 (2018) (the seed's ref. [9]); methods.md §7",
    },
    ContactSchemeEntry {
        name: "predictor-corrector",
        summary: "the seed's stabilized predictor-corrector: contact from the predicted gap, corrected with (M + M_p)^-1",
        parameters: &["beta_s", "ratio or beta_m"],
        source: "Kolman et al. (seed), flowchart after \"Wu\" (attribution unverified); methods.md §7",
    },
    ContactSchemeEntry {
        name: "lagrange-multiplier",
        summary: "forward-increment Lagrange multiplier: the predicted gap made exactly zero",
        parameters: &[],
        source: "Carpenter, Taylor, Katona, IJNME 32 (1991) 103-128",
    },
];

/// A contact scheme. All run on the lumped central-difference bulk (half-step form).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactScheme {
    /// (a) Central difference with the stiffness penalty `k_s` only.
    Penalty {
        /// `k_s`.
        stiffness: f64,
    },
    /// (b) Central difference with bipenalty: `K_p` and `M_p`, the pair block of `M + M_p`
    /// solved in closed form when active. r <= 1 keeps the contact-free step for every
    /// `beta_s`; large `beta_s` makes the contact chatter (module docs, "Energy").
    Bipenalty(Penalty),
    /// (c) The seed's stabilized predictor-corrector scheme (bulk predicted with M only, contact
    /// from the predicted state corrected with `(M + M_p)^-1`). Stable while
    /// `k_s dt^2/(m_c + m_p) <= 1`.
    PredictorCorrector(Penalty),
    /// (d) Forward-increment Lagrange multiplier method (Carpenter, Taylor and Katona 1991): the
    /// predicted gap at `t^{n+1}` is made exactly zero if it would be negative.
    LagrangeMultiplier,
}

impl ContactScheme {
    /// Short label: `cd-penalty`, `cd-bipenalty`, `predictor-corrector`, `lagrange-multiplier`.
    pub fn label(&self) -> &'static str {
        match self {
            ContactScheme::Penalty { .. } => "cd-penalty",
            ContactScheme::Bipenalty(_) => "cd-bipenalty",
            ContactScheme::PredictorCorrector(_) => "predictor-corrector",
            ContactScheme::LagrangeMultiplier => "lagrange-multiplier",
        }
    }

    /// The penalties the scheme uses (zero for the Lagrange multiplier method, `m_p = 0` for
    /// penalty only).
    pub fn penalty(&self) -> Penalty {
        match *self {
            ContactScheme::Penalty { stiffness } => Penalty {
                stiffness,
                mass: 0.0,
            },
            ContactScheme::Bipenalty(p) | ContactScheme::PredictorCorrector(p) => p,
            ContactScheme::LagrangeMultiplier => Penalty {
                stiffness: 0.0,
                mass: 0.0,
            },
        }
    }

    /// True for the central-difference penalty schemes (a) and (b), whose contact-active
    /// system `(K + K_p, M + M_p)` limits the step.
    pub fn is_central_difference(&self) -> bool {
        matches!(
            self,
            ContactScheme::Penalty { .. } | ContactScheme::Bipenalty(_)
        )
    }

    /// Check the parameters: `k_s` positive and finite, `m_p` finite and not negative.
    ///
    /// # Errors
    /// [`InputError::Parameter`] naming the penalty and the rule.
    pub fn validate(&self) -> Result<(), InputError> {
        if matches!(self, ContactScheme::LagrangeMultiplier) {
            return Ok(());
        }
        let p = self.penalty();
        crate::model::mesh::positive("penalty stiffness k_s", p.stiffness)?;
        if !(p.mass.is_finite() && p.mass >= 0.0) {
            return Err(InputError::Parameter {
                field: "penalty mass m_p",
                value: p.mass,
                rule: "must be finite and not negative",
            });
        }
        Ok(())
    }
}

/// What the contact did at one level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LevelUpdate {
    /// `g^n = N^T u^n + g0`.
    pub gap: f64,
    /// Whether the scheme applied contact at this level.
    pub active: bool,
    /// Contact momentum `J^n` along N (compression positive).
    pub impulse: f64,
    /// `F^n = J^n/(w_n dt)`.
    pub force: f64,
}

/// The level-n data at the contact node(s), in the order of N's entries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LevelInput {
    /// `w_n`: 1/2 at the start level, 1 after.
    pub weight: f64,
    /// `u^n` at the contact nodes.
    pub displacement: [f64; 2],
    /// `v^{n-1/2}` (`v^0` at the start) at the contact nodes.
    pub velocity: [f64; 2],
    /// Bulk residual `F^n - (K u^n)` at the contact nodes.
    pub residual: [f64; 2],
}

/// The contact update of one level (module docs of [`crate::contact`]).
pub(crate) fn level_update(
    scheme: &ContactScheme,
    problem: &ContactProblem,
    dt: f64,
    input: &LevelInput,
) -> LevelUpdate {
    let nodes = problem.contact_nodes();
    let (mut approach, mut n_a, mut n_v, mut s) = (0.0, 0.0, 0.0, 0.0);
    for (i, c) in nodes.iter().enumerate() {
        approach += c.sign * input.displacement[i];
        n_a += c.sign * input.residual[i] / c.mass;
        n_v += c.sign * input.velocity[i];
        s += 1.0 / c.mass;
    }
    let gap = approach + problem.initial_gap();
    let w = input.weight;
    let (active, impulse) = contact_momentum(
        scheme,
        &MomentumInput {
            gap,
            relative_velocity: n_v,
            relative_acceleration: n_a,
            compliance: s,
            weight: w,
            dt,
        },
        false,
    );
    LevelUpdate {
        gap,
        active,
        impulse,
        force: impulse / (w * dt),
    }
}

/// The scalars the contact momentum of a level depends on (module docs of [`crate::contact`]):
/// `g^n`, `N^T v^{n-1/2}`, `N^T a0` (the contact-free acceleration `a0 = M^-1 R`),
/// `s = N^T M^-1 N` (`M^-1` lumped, or any symmetric inverse mass such as RMM's), `w_n`, `dt`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MomentumInput {
    pub gap: f64,
    pub relative_velocity: f64,
    pub relative_acceleration: f64,
    pub compliance: f64,
    pub weight: f64,
    pub dt: f64,
}

/// `(active, J^n)`: the contact momentum along N of one level, the O(1) formulas of the module
/// docs of [`crate::contact`], which need `M^-1` only through `N^T M^-1 R` and `s`.
/// `bilateral`: apply the contact whatever the sign of the (predicted) gap, the linear
/// contact-active map whose amplification matrix gives the persistent-contact step limit.
pub(crate) fn contact_momentum(
    scheme: &ContactScheme,
    input: &MomentumInput,
    bilateral: bool,
) -> (bool, f64) {
    let MomentumInput {
        gap,
        relative_velocity: n_v,
        relative_acceleration: n_a,
        compliance: s,
        weight: w,
        dt,
    } = *input;
    match *scheme {
        ContactScheme::Penalty { .. } | ContactScheme::Bipenalty(_) => {
            if bilateral || gap < 0.0 {
                let Penalty {
                    stiffness: ks,
                    mass: mp,
                } = scheme.penalty();
                let n_a0 = n_a - ks * gap * s;
                let lambda = -ks * gap - mp * n_a0 / (1.0 + mp * s);
                (true, w * dt * lambda)
            } else {
                (false, 0.0)
            }
        }
        ContactScheme::PredictorCorrector(Penalty {
            stiffness: ks,
            mass: mp,
        }) => {
            let predicted = gap + dt * (n_v + w * dt * n_a);
            if bilateral || predicted < 0.0 {
                (true, -dt * ks * predicted / (1.0 + mp * s))
            } else {
                (false, 0.0)
            }
        }
        ContactScheme::LagrangeMultiplier => {
            let predicted = gap + dt * (n_v + w * dt * n_a);
            if bilateral || predicted < 0.0 {
                (true, -predicted / (dt * s))
            } else {
                (false, 0.0)
            }
        }
    }
}
