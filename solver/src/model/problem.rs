//! The model: a bar with supports, loads and initial conditions, and the operators derived from
//! it once (element stiffness, lumped nodal mass and its inverse).

use crate::error::InputError;
use crate::model::bar::Bar;
use crate::model::load::{End, Load, NodalLoad};
use std::sync::Arc;

/// Support condition of one end.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Support {
    /// Traction-free unless loaded.
    #[default]
    Free,
    /// Displacement, velocity and acceleration held at zero.
    Fixed,
}

/// Support conditions of both ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Supports {
    /// Left end (node 0).
    pub left: Support,
    /// Right end (node N).
    pub right: Support,
}

impl Supports {
    /// The free-fixed bar of the seed's Figs. 1 and 2: loaded free end on the left.
    pub const FREE_FIXED: Supports = Supports {
        left: Support::Free,
        right: Support::Fixed,
    };
}

/// Initial displacement and velocity, one value per node.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct InitialConditions {
    /// `u(x_i, 0)`; `None` is zero.
    pub displacement: Option<Vec<f64>>,
    /// `v(x_i, 0)`; `None` is zero.
    pub velocity: Option<Vec<f64>>,
}

/// A bar ready to integrate.
#[derive(Debug, Clone)]
pub struct Model {
    bar: Bar,
    supports: Supports,
    loads: Vec<NodalLoad>,
    initial_displacement: Vec<f64>,
    initial_velocity: Vec<f64>,
    stiffness: Vec<f64>,
    /// Shared with the lumped [`crate::mass::MassOperator`] (one copy per run, not two).
    nodal_mass: Arc<[f64]>,
    inverse_mass: Arc<[f64]>,
}

impl Model {
    /// Assemble a model. Rules: load nodes exist and magnitudes are finite; initial fields have
    /// one finite value per node and vanish at fixed nodes; something excites the bar (a nonzero
    /// load or a nonzero initial field).
    pub fn new(
        bar: Bar,
        supports: Supports,
        loads: &[Load],
        initial: InitialConditions,
    ) -> Result<Self, InputError> {
        Self::assemble(bar, supports, loads, initial, true)
    }

    /// A model for modal analysis (spectra, critical steps): no loads, at rest.
    pub fn unloaded(bar: Bar, supports: Supports) -> Self {
        // With no loads and zero initial fields every rule but excitation holds trivially.
        match Self::assemble(bar, supports, &[], InitialConditions::default(), false) {
            Ok(model) => model,
            Err(e) => unreachable!("an unloaded model at rest is always valid: {e}"),
        }
    }

    fn assemble(
        bar: Bar,
        supports: Supports,
        loads: &[Load],
        initial: InitialConditions,
        require_excitation: bool,
    ) -> Result<Self, InputError> {
        let nodes = bar.node_count();
        let last = nodes - 1;
        let area = bar.area();
        let mut resolved = Vec::with_capacity(loads.len());
        for load in loads {
            let nodal = match load {
                Load::Force {
                    node,
                    magnitude,
                    time,
                } => {
                    if *node > last {
                        return Err(InputError::NodeIndex {
                            field: "load node",
                            node: *node,
                            last,
                        });
                    }
                    NodalLoad {
                        node: *node,
                        magnitude: *magnitude,
                        time: time.clone(),
                    }
                }
                Load::Traction {
                    end: End::Left,
                    stress,
                    time,
                } => NodalLoad {
                    node: 0,
                    magnitude: -stress * area[0],
                    time: time.clone(),
                },
                Load::Traction {
                    end: End::Right,
                    stress,
                    time,
                } => NodalLoad {
                    node: last,
                    magnitude: stress * area[area.len() - 1],
                    time: time.clone(),
                },
            };
            if !nodal.magnitude.is_finite() {
                return Err(InputError::Parameter {
                    field: "load magnitude",
                    value: nodal.magnitude,
                    rule: "must be finite",
                });
            }
            nodal.time.validate()?;
            resolved.push(nodal);
        }
        let fixed = |i: usize| {
            (i == 0 && supports.left == Support::Fixed)
                || (i == last && supports.right == Support::Fixed)
        };
        if let Some(load) = resolved.iter().find(|l| fixed(l.node)) {
            return Err(InputError::LoadOnFixedNode { node: load.node });
        }
        let mut fields = [
            ("initial displacement", initial.displacement),
            ("initial velocity", initial.velocity),
        ]
        .map(|(field, values)| {
            let values = values.unwrap_or_else(|| vec![0.0; nodes]);
            (field, values)
        });
        for (field, values) in &fields {
            if values.len() != nodes {
                return Err(InputError::Length {
                    field,
                    expected: nodes,
                    actual: values.len(),
                });
            }
            for (node, &value) in values.iter().enumerate() {
                if !value.is_finite() {
                    return Err(InputError::NodeValue {
                        field,
                        node,
                        value,
                        rule: "must be finite",
                    });
                }
                if fixed(node) && value != 0.0 {
                    return Err(InputError::NodeValue {
                        field,
                        node,
                        value,
                        rule: "must be 0 at a fixed node",
                    });
                }
            }
        }
        let excited = resolved.iter().any(|l| l.magnitude != 0.0)
            || fields.iter().any(|(_, v)| v.iter().any(|&x| x != 0.0));
        if require_excitation && !excited {
            return Err(InputError::NothingExcites { what: "the bar" });
        }
        let stiffness = bar.element_stiffness();
        let nodal_mass = lumped_mass(&bar.element_mass());
        let inverse_mass = (0..nodes)
            .map(|i| if fixed(i) { 0.0 } else { 1.0 / nodal_mass[i] })
            .collect();
        let nodal_mass = Arc::from(nodal_mass);
        let [(_, initial_displacement), (_, initial_velocity)] = std::mem::take(&mut fields);
        Ok(Self {
            bar,
            supports,
            loads: resolved,
            initial_displacement,
            initial_velocity,
            stiffness,
            nodal_mass,
            inverse_mass,
        })
    }

    /// The bar.
    pub fn bar(&self) -> &Bar {
        &self.bar
    }

    /// The supports.
    pub fn supports(&self) -> Supports {
        self.supports
    }

    /// Loads resolved to nodes.
    pub fn loads(&self) -> &[NodalLoad] {
        &self.loads
    }

    /// Initial nodal displacements.
    pub fn initial_displacement(&self) -> &[f64] {
        &self.initial_displacement
    }

    /// Initial nodal velocities.
    pub fn initial_velocity(&self) -> &[f64] {
        &self.initial_velocity
    }

    /// Element stiffnesses `k_e = E_e A_e / h_e`.
    pub fn stiffness(&self) -> &[f64] {
        &self.stiffness
    }

    /// Lumped (row-sum) nodal masses, `m_i = (m_{i-1} + m_i)/2` over the adjacent elements.
    pub fn nodal_mass(&self) -> &[f64] {
        &self.nodal_mass
    }

    /// Inverse lumped masses, 0 at fixed nodes (which removes them from the equations).
    pub fn inverse_mass(&self) -> &[f64] {
        &self.inverse_mass
    }

    /// The lumped nodal masses and their inverses, shared (not copied) with the lumped mass
    /// operator of a run.
    pub(crate) fn shared_lumped_mass(&self) -> (Arc<[f64]>, Arc<[f64]>) {
        (Arc::clone(&self.nodal_mass), Arc::clone(&self.inverse_mass))
    }

    /// True when node `i` is held by a fixed support.
    pub fn is_fixed(&self, i: usize) -> bool {
        self.inverse_mass[i] == 0.0
    }

    /// Element stresses `sigma_e = E_e (u_{e+1} - u_e)/h_e` of a displacement field.
    pub fn element_stress(&self, u: &[f64]) -> Vec<f64> {
        let mesh = self.bar.mesh();
        (0..self.bar.element_count())
            .map(|e| self.bar.modulus()[e] * (u[e + 1] - u[e]) / mesh.element_length(e))
            .collect()
    }

    /// Net internal force on node `i`, `-(K u)_i = N_i - N_{i-1}` with element forces
    /// `N_e = k_e (u_{e+1} - u_e)`.
    pub fn internal_force_at(&self, u: &[f64], i: usize) -> f64 {
        let left = if i > 0 { u[i - 1] } else { 0.0 };
        let right = if i < self.stiffness.len() {
            u[i + 1]
        } else {
            0.0
        };
        self.internal_force_from(i, [left, u[i], right])
    }

    /// [`Self::internal_force_at`] from the displacements `[u_{i-1}, u_i, u_{i+1}]` alone (a
    /// missing neighbour of an end node is ignored): the same operations.
    pub fn internal_force_from(&self, i: usize, [u_left, u_i, u_right]: [f64; 3]) -> f64 {
        let k = &self.stiffness;
        let right = if i < k.len() {
            k[i] * (u_right - u_i)
        } else {
            0.0
        };
        let left = if i > 0 {
            k[i - 1] * (u_i - u_left)
        } else {
            0.0
        };
        right - left
    }

    /// Total external force on node `i` at time `t`.
    pub fn external_force_at(&self, i: usize, t: f64) -> f64 {
        self.loads
            .iter()
            .filter(|l| l.node == i)
            .map(|l| l.force(t))
            .sum()
    }

    /// Acceleration of node `i` under the lumped mass, `a_i = (F_i - (K u)_i)/m_i` (0 at fixed
    /// nodes).
    pub fn acceleration_at(&self, u: &[f64], i: usize, t: f64) -> f64 {
        self.inverse_mass[i] * (self.external_force_at(i, t) + self.internal_force_at(u, i))
    }

    /// [`Self::acceleration_at`] from `[u_{i-1}, u_i, u_{i+1}]` alone: the same operations.
    pub fn acceleration_from(&self, i: usize, u: [f64; 3], t: f64) -> f64 {
        self.inverse_mass[i] * (self.external_force_at(i, t) + self.internal_force_from(i, u))
    }

    /// Strain energy `U = 1/2 sum_e k_e (u_{e+1} - u_e)^2`.
    pub fn strain_energy(&self, u: &[f64]) -> f64 {
        0.5 * self
            .stiffness
            .iter()
            .enumerate()
            .map(|(e, k)| k * (u[e + 1] - u[e]).powi(2))
            .sum::<f64>()
    }
}

/// Row-sum lumped mass: each element gives half its mass to each of its nodes,
/// `M_L = sum_e m_e/2 diag(1, 1)` (e.g. Hughes, The Finite Element Method (1987), §7.3).
pub fn lumped_mass(element_mass: &[f64]) -> Vec<f64> {
    let mut m = vec![0.0; element_mass.len() + 1];
    for (e, me) in element_mass.iter().enumerate() {
        m[e] += 0.5 * me;
        m[e + 1] += 0.5 * me;
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::load::TimeFunction;
    use crate::model::mesh::Mesh;

    fn unit_bar(n: usize) -> Bar {
        Bar::homogeneous(Mesh::uniform(1.0, n).unwrap(), 1.0, 1.0, 1.0).unwrap()
    }

    #[test]
    fn lumped_mass_preserves_total_mass() {
        let m = lumped_mass(&[1.0, 2.0, 3.0]);
        assert_eq!(m, vec![0.5, 1.5, 2.5, 1.5]);
        assert_eq!(m.iter().sum::<f64>(), 6.0);
    }

    #[test]
    fn a_left_traction_pushes_along_minus_sigma_a() {
        let load = Load::Traction {
            end: End::Left,
            stress: -1.0,
            time: TimeFunction::HEAVISIDE,
        };
        let model = Model::new(
            unit_bar(4),
            Supports::FREE_FIXED,
            &[load],
            InitialConditions::default(),
        )
        .unwrap();
        assert_eq!(model.loads()[0].node, 0);
        assert_eq!(model.loads()[0].magnitude, 1.0);
        assert_eq!(model.inverse_mass()[4], 0.0);
    }

    #[test]
    fn a_right_traction_pulls_along_plus_sigma_a() {
        let bar = Bar::homogeneous(Mesh::uniform(1.0, 4).unwrap(), 1.0, 1.0, 2.0).unwrap();
        let load = Load::Traction {
            end: End::Right,
            stress: 3.0,
            time: TimeFunction::HEAVISIDE,
        };
        let supports = Supports {
            left: Support::Fixed,
            right: Support::Free,
        };
        let model = Model::new(bar, supports, &[load], InitialConditions::default()).unwrap();
        assert_eq!(
            (model.loads()[0].node, model.loads()[0].magnitude),
            (4, 6.0)
        );
    }

    #[test]
    fn a_load_on_a_fixed_node_is_refused() {
        let load = Load::Force {
            node: 4,
            magnitude: 1.0,
            time: TimeFunction::HEAVISIDE,
        };
        let err = Model::new(
            unit_bar(4),
            Supports::FREE_FIXED,
            &[load],
            InitialConditions::default(),
        )
        .unwrap_err();
        assert!(err.to_string().contains("node 4, which is fixed"), "{err}");
    }

    #[test]
    fn an_unexcited_bar_is_refused() {
        let err = Model::new(
            unit_bar(4),
            Supports::default(),
            &[],
            InitialConditions::default(),
        )
        .unwrap_err();
        assert!(err.to_string().starts_with("nothing excites the bar"));
    }

    #[test]
    fn initial_motion_of_a_fixed_node_is_refused() {
        let init = InitialConditions {
            displacement: None,
            velocity: Some(vec![1.0; 5]),
        };
        let err = Model::new(unit_bar(4), Supports::FREE_FIXED, &[], init).unwrap_err();
        assert_eq!(
            err.to_string(),
            "initial velocity at node 4 = 1 must be 0 at a fixed node"
        );
    }

    #[test]
    fn load_on_a_missing_node_is_refused() {
        let load = Load::Force {
            node: 9,
            magnitude: 1.0,
            time: TimeFunction::HEAVISIDE,
        };
        let err = Model::new(
            unit_bar(4),
            Supports::FREE_FIXED,
            &[load],
            InitialConditions::default(),
        )
        .unwrap_err();
        assert_eq!(
            err.to_string(),
            "load node = 9 is not a node of the mesh (nodes 0..=4)"
        );
    }
}
