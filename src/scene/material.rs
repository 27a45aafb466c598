//! The material along a bar: fields of `x` or homogeneous layers.

use courant_solver::Field;

/// The material along the bar: fields of `x`, or homogeneous layers.
#[derive(Debug, Clone, PartialEq)]
pub enum Material {
    /// Modulus and density as constant or linear fields.
    Fields {
        /// Modulus field.
        modulus: Field,
        /// Density field.
        density: Field,
    },
    /// Layers from the loaded end: (thickness, modulus, density).
    Layers(Vec<(f64, f64, f64)>),
}

impl Material {
    /// `(E(x), rho(x))` at `x` in `[0, length]` (a layer interface belongs to the layer on its
    /// right).
    pub fn at(&self, x: f64, length: f64) -> (f64, f64) {
        let field = |f: &Field| match f {
            Field::Constant(c) => *c,
            Field::Linear { left, right } => left + (right - left) * x / length,
            Field::PerElement(_) => f64::NAN,
        };
        match self {
            Material::Fields { modulus, density } => (field(modulus), field(density)),
            Material::Layers(layers) => {
                let mut end = 0.0;
                for &(thickness, e, rho) in layers {
                    end += thickness;
                    if x < end {
                        return (e, rho);
                    }
                }
                layers
                    .last()
                    .map_or((f64::NAN, f64::NAN), |&(_, e, rho)| (e, rho))
            }
        }
    }

    /// True for a homogeneous material.
    pub fn is_homogeneous(&self) -> bool {
        match self {
            Material::Fields { modulus, density } => modulus.is_constant() && density.is_constant(),
            Material::Layers(layers) => layers
                .windows(2)
                .all(|w| w[0].1 == w[1].1 && w[0].2 == w[1].2),
        }
    }
}
