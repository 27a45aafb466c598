//! A homogeneous layer and the stress transmission and reflection of a step wave at an
//! interface (Graff, *Wave Motion in Elastic Solids* (1975), ch. 2).

use crate::error::ReferenceError;

/// One homogeneous layer of a [`LayeredBar`](super::LayeredBar).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layer {
    thickness: f64,
    modulus: f64,
    density: f64,
}

impl Layer {
    /// Builds a layer after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a value is not positive and finite.
    pub fn new(thickness: f64, modulus: f64, density: f64) -> Result<Self, ReferenceError> {
        Ok(Self {
            thickness: ReferenceError::require_positive("thickness", thickness)?,
            modulus: ReferenceError::require_positive("modulus", modulus)?,
            density: ReferenceError::require_positive("density", density)?,
        })
    }

    /// Thickness (> 0).
    #[must_use]
    pub fn thickness(&self) -> f64 {
        self.thickness
    }

    /// Young's modulus (> 0).
    #[must_use]
    pub fn modulus(&self) -> f64 {
        self.modulus
    }

    /// Mass density (> 0).
    #[must_use]
    pub fn density(&self) -> f64 {
        self.density
    }

    /// Wave speed `sqrt(E/rho)`.
    #[must_use]
    pub fn wave_speed(&self) -> f64 {
        (self.modulus / self.density).sqrt()
    }

    /// Impedance per unit area `sqrt(rho E) = rho c`.
    #[must_use]
    pub fn impedance(&self) -> f64 {
        (self.modulus * self.density).sqrt()
    }

    /// Travel time `thickness/c` across the layer.
    #[must_use]
    pub fn travel_time(&self) -> f64 {
        self.thickness / self.wave_speed()
    }
}

/// Stress transmission coefficient `2 Z2/(Z1 + Z2)` for a step incident from impedance `Z1`
/// onto `Z2` (Graff 1975, ch. 2).
#[must_use]
pub fn transmission_coefficient(z_from: f64, z_to: f64) -> f64 {
    2.0 * z_to / (z_from + z_to)
}

/// Stress reflection coefficient `(Z2 - Z1)/(Z1 + Z2)` for a step incident from `Z1` onto
/// `Z2` (Graff 1975, ch. 2); +1 for a fixed end (`Z2 -> inf`), -1 for a free or loaded end.
#[must_use]
pub fn reflection_coefficient(z_from: f64, z_to: f64) -> f64 {
    (z_to - z_from) / (z_from + z_to)
}
