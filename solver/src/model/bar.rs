//! Bars: a mesh with per-element modulus `E_e`, density `rho_e` and area `A_e`.
//!
//! Element quantities (methods.md §1): `c_e = sqrt(E_e/rho_e)`, `k_e = E_e A_e/h_e`,
//! `m_e = rho_e A_e h_e`, transit time `h_e/c_e`. Properties given as functions of `x` are sampled
//! at element midpoints, which for a linear `E(x)` is the exact element average.

use crate::error::InputError;
use crate::model::mesh::Mesh;

/// A material property along the bar.
#[derive(Debug, Clone, PartialEq)]
pub enum Field {
    /// The same value everywhere.
    Constant(f64),
    /// Linear between the value at the left end and the value at the right end.
    Linear {
        /// Value at `x_0`.
        left: f64,
        /// Value at `x_N`.
        right: f64,
    },
    /// One value per element.
    PerElement(Vec<f64>),
}

impl Field {
    /// Sample the field on the elements of `mesh` (at midpoints for `Linear`).
    pub fn sample(&self, mesh: &Mesh) -> Vec<f64> {
        let n = mesh.element_count();
        match self {
            Field::Constant(value) => vec![*value; n],
            Field::Linear { left, right } => (0..n)
                .map(|e| {
                    let s = (mesh.midpoint(e) - mesh.start()) / mesh.length();
                    left + (right - left) * s
                })
                .collect(),
            Field::PerElement(values) => values.clone(),
        }
    }

    /// True when the field has the same value on every element.
    pub fn is_constant(&self) -> bool {
        match self {
            Field::Constant(_) => true,
            Field::Linear { left, right } => left == right,
            Field::PerElement(v) => v.windows(2).all(|w| w[0] == w[1]),
        }
    }
}

/// An element property as a bar stores it: one value for a [`Field::Constant`] (a uniform bar
/// of 10^7 elements keeps 8 bytes, not 80 MB, per property), else one value per element.
/// Indexed as a slice would be (`values[e]`, the same number either way).
#[derive(Debug, Clone)]
pub enum ElementValues {
    /// The same value on each of `len` elements.
    Constant {
        /// The value.
        value: f64,
        /// Number of elements.
        len: usize,
    },
    /// One value per element.
    PerElement(Vec<f64>),
}

impl ElementValues {
    /// Number of elements.
    pub fn len(&self) -> usize {
        match self {
            ElementValues::Constant { len, .. } => *len,
            ElementValues::PerElement(v) => v.len(),
        }
    }

    /// True when there are no elements.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The values, element by element.
    pub fn iter(&self) -> impl Iterator<Item = f64> + '_ {
        (0..self.len()).map(|e| self[e])
    }

    /// True when every element has the same value.
    pub fn is_uniform(&self) -> bool {
        match self {
            ElementValues::Constant { .. } => true,
            ElementValues::PerElement(v) => v.windows(2).all(|w| w[0] == w[1]),
        }
    }
}

impl std::ops::Index<usize> for ElementValues {
    type Output = f64;

    /// The value of element `e` (panics beyond the last element, as a slice does).
    fn index(&self, e: usize) -> &f64 {
        match self {
            ElementValues::Constant { value, len } => {
                assert!(e < *len, "element {e} of {len}");
                value
            }
            ElementValues::PerElement(v) => &v[e],
        }
    }
}

impl PartialEq for ElementValues {
    /// The same values on the same number of elements, however stored.
    fn eq(&self, other: &Self) -> bool {
        self.len() == other.len() && self.iter().eq(other.iter())
    }
}

/// A discretised bar: mesh and element properties, validated.
#[derive(Debug, Clone, PartialEq)]
pub struct Bar {
    mesh: Mesh,
    modulus: ElementValues,
    density: ElementValues,
    area: ElementValues,
    /// [`Bar::stiffest_element`], found once when the bar is built (an O(N) scan of square
    /// roots: 4 ms at N = 1e6, which every run's start and Courant number asked for).
    stiffest: (usize, f64),
}

impl Bar {
    /// Build a bar by sampling modulus, density and area on the mesh's elements. Every element
    /// value must be positive and finite.
    pub fn new(
        mesh: Mesh,
        modulus: &Field,
        density: &Field,
        area: &Field,
    ) -> Result<Self, InputError> {
        let n = mesh.element_count();
        let stored = |field: &Field| match field {
            Field::Constant(value) => ElementValues::Constant {
                value: *value,
                len: n,
            },
            _ => ElementValues::PerElement(field.sample(&mesh)),
        };
        let sampled = [
            ("modulus", stored(modulus)),
            ("density", stored(density)),
            ("area", stored(area)),
        ];
        for (field, values) in &sampled {
            if values.len() != n {
                return Err(InputError::Length {
                    field,
                    expected: n,
                    actual: values.len(),
                });
            }
            if let Some((element, value)) = values
                .iter()
                .enumerate()
                .find(|(_, v)| !(v.is_finite() && *v > 0.0))
            {
                return Err(InputError::ElementProperty {
                    field,
                    element,
                    value,
                    rule: "must be positive and finite",
                });
            }
        }
        let [(_, modulus), (_, density), (_, area)] = sampled;
        let mut bar = Self {
            mesh,
            modulus,
            density,
            area,
            stiffest: (0, f64::INFINITY),
        };
        bar.stiffest = bar.scan_stiffest_element();
        Ok(bar)
    }

    /// The layered (Goupillaud) bar of an equal-transit-time mesh: density and area sampled at
    /// element midpoints, and each element's modulus chosen so that it takes exactly `transit`
    /// to cross, `E_e = rho_e (h_e/transit)^2` (methods.md §4). Lumped CD at Co = 1 on it is the
    /// exact layered model.
    pub fn equal_transit(
        mesh: Mesh,
        transit: f64,
        density: &Field,
        area: &Field,
    ) -> Result<Self, InputError> {
        crate::model::mesh::positive("element transit time", transit)?;
        let rho = density.sample(&mesh);
        let modulus: Vec<f64> = (0..mesh.element_count())
            .map(|e| rho[e] * (mesh.element_length(e) / transit).powi(2))
            .collect();
        Self::new(
            mesh,
            &Field::PerElement(modulus),
            &Field::PerElement(rho),
            area,
        )
    }

    /// A homogeneous bar of constant modulus, density and area.
    pub fn homogeneous(
        mesh: Mesh,
        modulus: f64,
        density: f64,
        area: f64,
    ) -> Result<Self, InputError> {
        Self::new(
            mesh,
            &Field::Constant(modulus),
            &Field::Constant(density),
            &Field::Constant(area),
        )
    }

    /// The mesh.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// Number of elements.
    pub fn element_count(&self) -> usize {
        self.mesh.element_count()
    }

    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.mesh.node_count()
    }

    /// Element moduli `E_e`.
    pub fn modulus(&self) -> &ElementValues {
        &self.modulus
    }

    /// Element densities `rho_e`.
    pub fn density(&self) -> &ElementValues {
        &self.density
    }

    /// Element areas `A_e`.
    pub fn area(&self) -> &ElementValues {
        &self.area
    }

    /// Wave speed of element `e`, `c_e = sqrt(E_e/rho_e)`.
    pub fn wave_speed(&self, e: usize) -> f64 {
        (self.modulus[e] / self.density[e]).sqrt()
    }

    /// Transit time of element `e`, `h_e/c_e`: the time a wave needs to cross it.
    pub fn element_transit_time(&self, e: usize) -> f64 {
        self.mesh.element_length(e) / self.wave_speed(e)
    }

    /// Transit time of the whole bar, `T = sum_e h_e/c_e`.
    pub fn transit_time(&self) -> f64 {
        (0..self.element_count())
            .map(|e| self.element_transit_time(e))
            .sum()
    }

    /// Element stiffnesses `k_e = E_e A_e/h_e`.
    pub fn element_stiffness(&self) -> Vec<f64> {
        (0..self.element_count())
            .map(|e| self.modulus[e] * self.area[e] / self.mesh.element_length(e))
            .collect()
    }

    /// Element masses `m_e = rho_e A_e h_e`.
    pub fn element_mass(&self) -> Vec<f64> {
        (0..self.element_count())
            .map(|e| self.density[e] * self.area[e] * self.mesh.element_length(e))
            .collect()
    }

    /// The element with the smallest transit time (the stiffest element in the Courant-number
    /// sense) and that time, `min_e h_e/c_e` (the first such element on a tie).
    pub fn stiffest_element(&self) -> (usize, f64) {
        self.stiffest
    }

    /// [`Self::stiffest_element`] by a scan of every element.
    fn scan_stiffest_element(&self) -> (usize, f64) {
        (0..self.element_count())
            .map(|e| (e, self.element_transit_time(e)))
            .fold(
                (0, f64::INFINITY),
                |best, cur| if cur.1 < best.1 { cur } else { best },
            )
    }

    /// Courant number of a time step, relative to the stiffest element (methods.md §1):
    /// `Co = dt * max_e(c_e/h_e)`.
    pub fn courant_number(&self, dt: f64) -> f64 {
        dt / self.stiffest_element().1
    }

    /// True when modulus, density and area are the same on every element.
    pub fn is_homogeneous(&self) -> bool {
        self.modulus.is_uniform() && self.density.is_uniform() && self.area.is_uniform()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_modulus_is_sampled_at_midpoints() {
        let mesh = Mesh::uniform(1.0, 4).unwrap();
        let bar = Bar::new(
            mesh,
            &Field::Linear {
                left: 16.0,
                right: 0.0 + 1.0,
            },
            &Field::Constant(1.0),
            &Field::Constant(1.0),
        )
        .unwrap();
        let expected = [
            16.0 - 15.0 * 0.125,
            16.0 - 15.0 * 0.375,
            16.0 - 15.0 * 0.625,
            16.0 - 15.0 * 0.875,
        ];
        assert_eq!(bar.modulus().iter().collect::<Vec<_>>(), expected);
        assert!(!bar.is_homogeneous());
        assert_eq!(bar.stiffest_element().0, 0);
    }

    #[test]
    fn stiffest_element_is_the_first_of_least_transit_time() {
        // Closed form: transit h_e sqrt(rho_e/E_e); elements 1 and 3 take h/2 (up to the rounding
        // of their lengths), the least: the first is the stiffest.
        let mesh = Mesh::uniform(1.0, 5).unwrap();
        let modulus = Field::PerElement(vec![1.0, 4.0, 2.0, 4.0, 1.0]);
        let one = Field::Constant(1.0);
        let bar = Bar::new(mesh, &modulus, &one, &one).unwrap();
        assert_eq!(bar.stiffest_element(), (1, 0.2 / 2.0));
        assert_eq!(bar.stiffest_element(), bar.scan_stiffest_element());
        assert_eq!(bar.courant_number(0.05), 0.5);
    }

    #[test]
    fn non_positive_properties_name_the_element() {
        let mesh = Mesh::uniform(1.0, 4).unwrap();
        let err = Bar::new(
            mesh,
            &Field::Linear {
                left: 1.0,
                right: -1.0,
            },
            &Field::Constant(1.0),
            &Field::Constant(1.0),
        )
        .unwrap_err();
        assert_eq!(
            err.to_string(),
            "modulus of element 2 = -0.25 must be positive and finite"
        );
    }

    #[test]
    fn transit_time_of_a_unit_bar_is_one() {
        let bar = Bar::homogeneous(Mesh::uniform(1.0, 10).unwrap(), 1.0, 1.0, 1.0).unwrap();
        assert!((bar.transit_time() - 1.0).abs() < 1e-14);
        assert!((bar.courant_number(0.1) - 1.0).abs() < 1e-14);
    }
}
