//! Contact problems: a bar against a rigid wall (Signorini) or two bars meeting end to end.

use super::penalty::{MassPenalty, Penalty};
use crate::error::InputError;
use crate::model::bar::Bar;
use crate::model::load::End;
use crate::model::mesh::Mesh;
use crate::model::{InitialConditions, Model, Supports};

/// Which contact a problem has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactKind {
    /// One bar against a rigid wall beyond its `side` end (Signorini). Wall on the right of node
    /// `c = N`: `g = g0 - u_c` (`N = [-1]`); wall on the left of node 0: `g = g0 + u_0`
    /// (`N = [+1]`).
    Wall {
        /// The bar end that touches the wall.
        side: End,
    },
    /// Two bars end to end: the striker's (body 0) right end node `a` meets the target's
    /// (body 1) left end node `b`; `g = g0 + u_b - u_a` (`N = [-1, +1]` on `(a, b)`).
    Pair,
}

/// One contact node and what the O(1) contact update needs of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactNode {
    /// Body index (0: the wall's bar or the striker; 1: the target).
    pub body: usize,
    /// Node index within the body.
    pub node: usize,
    /// Entry of N: `g = g0 + sum sign * u_node`.
    pub sign: f64,
    /// Lumped nodal mass `m_c`.
    pub mass: f64,
    /// The node's only neighbour (the other node of the contact element).
    pub neighbour: usize,
    /// The contact element (the one joining `node` and `neighbour`).
    pub element: usize,
    /// Its stiffness `k = E A/h`; the bulk force on the node is `k (u_neighbour - u_node)`.
    pub element_stiffness: f64,
}

/// A contact problem: one or two lumped bars (each a [`Model`] with its own supports, loads and
/// initial state), the contact kind and the initial gap `g0 >= 0`.
#[derive(Debug, Clone)]
pub struct ContactProblem {
    bodies: Vec<Model>,
    kind: ContactKind,
    initial_gap: f64,
    nodes: Vec<ContactNode>,
}

impl ContactProblem {
    /// A bar against a rigid wall beyond its `side` end at distance `initial_gap` (`g0 >= 0`).
    ///
    /// # Errors
    /// [`InputError`] if `g0` is negative or not finite, the contact node is fixed, or the
    /// initial displacement already penetrates the wall (`N^T u^0 + g0 < 0`).
    pub fn wall(model: Model, side: End, initial_gap: f64) -> Result<Self, InputError> {
        let last = model.bar().node_count() - 1;
        let (node, sign) = match side {
            End::Left => (0, 1.0),
            End::Right => (last, -1.0),
        };
        let contact = contact_node(&model, 0, node, sign)?;
        Self::build(
            vec![model],
            ContactKind::Wall { side },
            initial_gap,
            vec![contact],
        )
    }

    /// Two bars end to end: `striker`'s right end meets `target`'s left end across the initial
    /// gap `g0 >= 0`. The target's coordinates are its own; only `g0` places it.
    ///
    /// # Errors
    /// [`InputError`] if `g0` is negative or not finite, a contact node is fixed, or the initial
    /// displacements already penetrate.
    pub fn pair(striker: Model, target: Model, initial_gap: f64) -> Result<Self, InputError> {
        let a = striker.bar().node_count() - 1;
        let nodes = vec![
            contact_node(&striker, 0, a, -1.0)?,
            contact_node(&target, 1, 0, 1.0)?,
        ];
        Self::build(vec![striker, target], ContactKind::Pair, initial_gap, nodes)
    }

    /// The impact of two free-free bars: `striker` moving at the uniform velocity `velocity > 0`
    /// toward `target` at rest, across the gap `g0` (seed Fig. 4; methods.md §7).
    ///
    /// # Errors
    /// [`InputError`] if `velocity` is not positive and finite, or as [`Self::pair`].
    pub fn bar_impact(
        striker: Bar,
        target: Bar,
        velocity: f64,
        initial_gap: f64,
    ) -> Result<Self, InputError> {
        crate::model::mesh::positive("impact velocity", velocity)?;
        let free = Supports::default();
        let nodes = striker.node_count();
        let striker = Model::new(
            striker,
            free,
            &[],
            InitialConditions {
                displacement: None,
                velocity: Some(vec![velocity; nodes]),
            },
        )?;
        Self::pair(striker, Model::unloaded(target, free), initial_gap)
    }

    /// A free-free bar moving at `velocity > 0` toward a rigid wall beyond its `side` end.
    ///
    /// # Errors
    /// [`InputError`] if `velocity` is not positive and finite, or as [`Self::wall`].
    pub fn wall_impact(
        bar: Bar,
        side: End,
        velocity: f64,
        initial_gap: f64,
    ) -> Result<Self, InputError> {
        crate::model::mesh::positive("impact velocity", velocity)?;
        let toward = match side {
            End::Left => -velocity,
            End::Right => velocity,
        };
        let nodes = bar.node_count();
        let model = Model::new(
            bar,
            Supports::default(),
            &[],
            InitialConditions {
                displacement: None,
                velocity: Some(vec![toward; nodes]),
            },
        )?;
        Self::wall(model, side, initial_gap)
    }

    /// The seed's Fig. 4/5 problem: a striker of length 1 at `velocity` onto a bar of length 2 at
    /// rest, both `E = rho = A = 1` (c = Z = 1), touching at t = 0 (`g0 = 0`), far ends free,
    /// `elements_per_length` uniform elements per unit length (the seed uses 100).
    ///
    /// # Errors
    /// [`InputError`] if `elements_per_length` is 0 or too large, or `velocity` is not positive.
    pub fn fig5(elements_per_length: usize, velocity: f64) -> Result<Self, InputError> {
        let bar = |length: f64, elements: usize| -> Result<Bar, InputError> {
            Bar::homogeneous(Mesh::uniform(length, elements)?, 1.0, 1.0, 1.0)
        };
        let n = elements_per_length;
        Self::bar_impact(bar(1.0, n)?, bar(2.0, 2 * n)?, velocity, 0.0)
    }

    fn build(
        bodies: Vec<Model>,
        kind: ContactKind,
        initial_gap: f64,
        nodes: Vec<ContactNode>,
    ) -> Result<Self, InputError> {
        if !(initial_gap.is_finite() && initial_gap >= 0.0) {
            return Err(InputError::Parameter {
                field: "initial gap",
                value: initial_gap,
                rule: "must be finite and not negative (initial penetration is not supported)",
            });
        }
        let problem = Self {
            bodies,
            kind,
            initial_gap,
            nodes,
        };
        let gap = problem.gap_of(|c| problem.bodies[c.body].initial_displacement()[c.node]);
        if gap < 0.0 {
            return Err(InputError::Parameter {
                field: "initial gap with the initial displacement",
                value: gap,
                rule: "must not be negative (initial penetration is not supported)",
            });
        }
        Ok(problem)
    }

    /// `g = g0 + sum_c sign_c u_c` with `u_c` given per contact node.
    pub(crate) fn gap_of(&self, u: impl Fn(&ContactNode) -> f64) -> f64 {
        self.nodes.iter().map(|c| c.sign * u(c)).sum::<f64>() + self.initial_gap
    }

    /// The bodies: one bar (wall) or striker and target (pair).
    pub fn bodies(&self) -> &[Model] {
        &self.bodies
    }

    /// The contact kind.
    pub fn kind(&self) -> ContactKind {
        self.kind
    }

    /// The initial gap `g0`.
    pub fn initial_gap(&self) -> f64 {
        self.initial_gap
    }

    /// The contact node(s), in the order of N's entries.
    pub fn contact_nodes(&self) -> &[ContactNode] {
        &self.nodes
    }

    /// `s = N^T M^-1 N`: `1/m_c` at a wall, `1/m_a + 1/m_b` for a pair.
    pub fn contact_compliance(&self) -> f64 {
        self.nodes.iter().map(|c| 1.0 / c.mass).sum()
    }

    /// The contact mass `m_c = 1/s`: the contact node's mass, or the reduced mass
    /// `m_a m_b/(m_a + m_b)` of the pair.
    pub fn contact_mass(&self) -> f64 {
        1.0 / self.contact_compliance()
    }

    /// Smallest element transit time `min_e h_e/c_e` over all bodies (Courant reference).
    pub fn stiffest_transit(&self) -> f64 {
        self.bodies
            .iter()
            .map(|m| m.bar().stiffest_element().1)
            .fold(f64::INFINITY, f64::min)
    }

    /// Courant number of `dt` relative to the stiffest element of all bodies (methods.md §1).
    pub fn courant_number(&self, dt: f64) -> f64 {
        dt / self.stiffest_transit()
    }

    /// The element the dimensionless penalties refer to: the contact element with the smallest
    /// transit time `h/c` (ties: the striker's), as `(body, element)`. On a uniform lumped bar,
    /// and for two equal bars, its `4 c^2/h^2` is the contact-free `omega_max^2`, so
    /// `r = beta_s/(4 beta_m)` is methods.md's `(k_s/m_p)/omega_max,0^2`.
    pub fn reference_element(&self) -> (usize, usize) {
        let transit = |c: &ContactNode| self.bodies[c.body].bar().element_transit_time(c.element);
        let best = self.nodes.iter().fold(&self.nodes[0], |best, c| {
            if transit(c) < transit(best) { c } else { best }
        });
        (best.body, best.element)
    }

    /// `(k, m) = (E A/h, rho A h)` of the reference element.
    fn reference_stiffness_and_mass(&self) -> (f64, f64) {
        let (body, e) = self.reference_element();
        let model = &self.bodies[body];
        (model.stiffness()[e], model.bar().element_mass()[e])
    }

    /// Penalties from dimensionless values: `k_s = beta_s k`, `m_p = beta_m m` with `(k, m)` of
    /// [`Self::reference_element`]; `beta_m` from `mass` (`Ratio(r)`: `beta_m = beta_s/(4 r)`).
    ///
    /// # Errors
    /// [`InputError`] if `beta_s` is not positive and finite, or the mass penalty is invalid
    /// (`r` not positive and finite, `beta_m` negative or not finite).
    pub fn penalty(&self, beta_s: f64, mass: MassPenalty) -> Result<Penalty, InputError> {
        crate::model::mesh::positive("beta_s", beta_s)?;
        let beta_m = match mass {
            MassPenalty::None => 0.0,
            MassPenalty::Ratio(r) => {
                crate::model::mesh::positive("penalty ratio r", r)?;
                beta_s / (4.0 * r)
            }
            MassPenalty::Dimensionless(beta_m) => {
                if !(beta_m.is_finite() && beta_m >= 0.0) {
                    return Err(InputError::Parameter {
                        field: "beta_m",
                        value: beta_m,
                        rule: "must be finite and not negative",
                    });
                }
                beta_m
            }
        };
        let (k, m) = self.reference_stiffness_and_mass();
        Ok(Penalty {
            stiffness: beta_s * k,
            mass: beta_m * m,
        })
    }

    /// `(beta_s, beta_m)` of `penalty` for [`Self::reference_element`].
    pub fn dimensionless(&self, penalty: Penalty) -> (f64, f64) {
        let (k, m) = self.reference_stiffness_and_mass();
        (penalty.stiffness / k, penalty.mass / m)
    }

    /// Total number of nodes of all bodies.
    pub fn node_count(&self) -> usize {
        self.bodies.iter().map(|m| m.bar().node_count()).sum()
    }

    /// True when some load or initial field is nonzero.
    pub(crate) fn is_excited(&self) -> bool {
        self.bodies.iter().any(|m| {
            m.loads().iter().any(|l| l.magnitude != 0.0)
                || m.initial_displacement().iter().any(|&x| x != 0.0)
                || m.initial_velocity().iter().any(|&x| x != 0.0)
        })
    }
}

/// The contact node `node` of `model` (an end node) with N entry `sign`.
fn contact_node(
    model: &Model,
    body: usize,
    node: usize,
    sign: f64,
) -> Result<ContactNode, InputError> {
    if model.is_fixed(node) {
        return Err(InputError::ContactNodeFixed { node, body });
    }
    let last = model.bar().node_count() - 1;
    let (neighbour, element) = if node == 0 {
        (1, 0)
    } else {
        (last - 1, last - 1)
    };
    Ok(ContactNode {
        body,
        node,
        sign,
        mass: model.nodal_mass()[node],
        neighbour,
        element,
        element_stiffness: model.stiffness()[element],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Support;

    fn bar(n: usize) -> Bar {
        Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 1.0, 1.0, 1.0).unwrap()
    }

    #[test]
    fn wall_gap_sign_depends_on_the_side() {
        let p = ContactProblem::wall_impact(bar(4), End::Right, 1.0, 0.5).unwrap();
        let c = p.contact_nodes()[0];
        assert_eq!((c.node, c.sign, c.neighbour, c.element), (4, -1.0, 3, 3));
        assert_eq!(p.bodies()[0].initial_velocity()[0], 1.0);
        let p = ContactProblem::wall_impact(bar(4), End::Left, 1.0, 0.5).unwrap();
        let c = p.contact_nodes()[0];
        assert_eq!((c.node, c.sign, c.neighbour, c.element), (0, 1.0, 1, 0));
        assert_eq!(p.bodies()[0].initial_velocity()[0], -1.0);
        assert_eq!(p.contact_mass(), 0.125);
    }

    #[test]
    fn pair_has_reduced_mass_and_dimensionless_penalties() {
        let p = ContactProblem::fig5(10, 1.0).unwrap();
        assert_eq!(p.kind(), ContactKind::Pair);
        assert!((p.contact_mass() - 0.025).abs() < 1e-16);
        assert_eq!(p.node_count(), 11 + 21);
        let pen = p.penalty(0.25e4, MassPenalty::Ratio(1.0)).unwrap();
        let (bs, bm) = p.dimensionless(pen);
        assert!((bs - 2500.0).abs() < 1e-9 && (bm - 625.0).abs() < 1e-9);
    }

    #[test]
    fn bad_contact_data_is_refused_with_the_rule() {
        let err = ContactProblem::wall_impact(bar(4), End::Right, 1.0, -1.0).unwrap_err();
        assert!(err.to_string().starts_with("initial gap = -1"), "{err}");
        let fixed = Model::new(
            bar(4),
            Supports {
                left: Support::Free,
                right: Support::Fixed,
            },
            &[],
            InitialConditions {
                displacement: None,
                velocity: Some(vec![1.0, 1.0, 1.0, 1.0, 0.0]),
            },
        )
        .unwrap();
        let err = ContactProblem::wall(fixed, End::Right, 0.0).unwrap_err();
        assert!(err.to_string().contains("is fixed"), "{err}");
        let p = ContactProblem::fig5(10, 1.0).unwrap();
        assert!(p.penalty(0.0, MassPenalty::None).is_err());
        assert!(p.penalty(1.0, MassPenalty::Ratio(-1.0)).is_err());
    }
}
