//! Layered bars by exact wave tracking.
//!
//! [`LayeredBar`]: piecewise-constant layers, exact stress and velocity by tracking every step
//! wave with transmission `2 Z2/(Z1 + Z2)` and reflection `(Z2 - Z1)/(Z1 + Z2)` (stress,
//! incident from side 1) at each interface, +1 at the fixed end and -1 at the loaded end;
//! element averages and energies are exact sums over the tracked waves.

use super::bar::{FieldPoint, GradedBar};
use super::layer::{Layer, reflection_coefficient, transmission_coefficient};
use crate::dalembert::{Energies, FRONT_TOLERANCE};
use crate::error::ReferenceError;
use std::collections::BTreeMap;

/// Default cap on the number of tracked waves of a [`LayeredBar`].
pub const DEFAULT_MAX_WAVES: usize = 200_000;

/// Free-fixed bar of homogeneous layers (loaded end x = 0 first), common area A, under
/// `sigma(0,t) = sigma0 H(t)`; exact by wave tracking.
///
/// Every step wave is followed through its layer; at an interface it spawns a transmitted and
/// a reflected wave ([`transmission_coefficient`], [`reflection_coefficient`]), at the fixed
/// end a reflection +1, at the loaded end -1. Waves entering the same layer in the same
/// direction at the same time (within [`FRONT_TOLERANCE`]) are merged, and waves of exactly
/// zero amplitude (equal impedances) are dropped, so equal-transit-time (Goupillaud) bars grow
/// polynomially. All waves up to time t are tracked: the field is exact (finite sum).
#[derive(Debug, Clone, PartialEq)]
pub struct LayeredBar {
    layers: Vec<Layer>,
    boundaries: Vec<f64>,
    area: f64,
    sigma0: f64,
    max_waves: usize,
}

/// A wave inside a layer at the evaluation time.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Front {
    toward_fixed: bool,
    /// Distance covered in the layer (< thickness).
    reach: f64,
    amplitude: f64,
}

/// The exact field of a [`LayeredBar`] at one time: evaluate it at as many points as needed.
#[derive(Debug, Clone, PartialEq)]
pub struct LayeredField {
    bar: LayeredBar,
    time: f64,
    /// Per layer: stress and velocity of the waves that have crossed the whole layer.
    complete: Vec<(f64, f64)>,
    /// Per layer: waves still inside it.
    partial: Vec<Vec<Front>>,
    load_displacement: f64,
    wave_count: usize,
}

/// Total order on times (`f64::total_cmp`), the key of event queues: the pending-wave queue
/// here, the arrivals of `contact::LayeredImpact`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TimeKey(pub(crate) f64);

impl Eq for TimeKey {}

impl PartialOrd for TimeKey {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for TimeKey {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// Waves waiting to enter a layer: (start time, layer, toward the fixed end) -> amplitude.
struct Pending {
    queue: BTreeMap<(TimeKey, usize, bool), f64>,
    horizon: f64,
    tol: f64,
}

impl Pending {
    /// Adds a wave, merging it with one entering the same layer in the same direction at the
    /// same time; waves of zero amplitude or starting after the horizon are not needed.
    fn push(&mut self, start: f64, layer: usize, toward_fixed: bool, amplitude: f64) {
        if amplitude == 0.0 || start > self.horizon + self.tol {
            return;
        }
        let lo = (TimeKey(start - self.tol), 0, false);
        let hi = (TimeKey(start + self.tol), usize::MAX, true);
        let same = self
            .queue
            .range(lo..=hi)
            .find(|(key, _)| key.1 == layer && key.2 == toward_fixed)
            .map(|(key, _)| *key);
        match same.and_then(|key| self.queue.get_mut(&key)) {
            Some(existing) => *existing += amplitude,
            None => {
                self.queue
                    .insert((TimeKey(start), layer, toward_fixed), amplitude);
            }
        }
    }
}

impl LayeredBar {
    /// Builds the bar from its layers (the first one at the loaded end).
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if `layers` is empty (`name = "layers"`), a layer
    /// value is not positive and finite, `area` is not positive and finite, or `sigma0` is not
    /// finite.
    pub fn new(layers: &[Layer], area: f64, sigma0: f64) -> Result<Self, ReferenceError> {
        if layers.is_empty() {
            return Err(ReferenceError::InvalidParameter {
                name: "layers",
                value: 0.0,
                rule: "at least one layer",
            });
        }
        let mut checked = Vec::with_capacity(layers.len());
        let mut boundaries = vec![0.0];
        let mut x = 0.0;
        for layer in layers {
            let layer = Layer::new(layer.thickness(), layer.modulus(), layer.density())?;
            x += layer.thickness();
            boundaries.push(x);
            checked.push(layer);
        }
        Ok(Self {
            layers: checked,
            boundaries,
            area: ReferenceError::require_positive("area", area)?,
            sigma0: ReferenceError::require_finite("sigma0", sigma0)?,
            max_waves: DEFAULT_MAX_WAVES,
        })
    }

    /// The equal-transit-time (Goupillaud) layering of a graded bar (methods.md §4): `layers`
    /// layers of travel time `T/layers` each, interfaces at `x(i T/layers)`, layer modulus
    /// `rho (h_i n/T)^2` so that each travel time is exact. It converges at first order to the
    /// graded bar.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if `layers` is 0.
    pub fn equal_transit_layers(bar: &GradedBar, layers: usize) -> Result<Self, ReferenceError> {
        if layers == 0 {
            return Err(ReferenceError::InvalidParameter {
                name: "layers",
                value: 0.0,
                rule: "at least one layer",
            });
        }
        let dtau = bar.transit_time() / layers as f64;
        let built = (0..layers)
            .map(|i| {
                let x0 = bar.position_at_travel_time(i as f64 * dtau);
                let x1 = if i + 1 == layers {
                    bar.length()
                } else {
                    bar.position_at_travel_time((i + 1) as f64 * dtau)
                };
                let h = x1 - x0;
                Layer::new(h, bar.density() * (h / dtau).powi(2), bar.density())
            })
            .collect::<Result<Vec<Layer>, ReferenceError>>()?;
        Self::new(&built, bar.area(), bar.sigma0())
    }

    /// Sets the cap on the number of tracked waves (default [`DEFAULT_MAX_WAVES`]).
    #[must_use]
    pub fn with_max_waves(mut self, max_waves: usize) -> Self {
        self.max_waves = max_waves;
        self
    }

    /// The layers, loaded end first.
    #[must_use]
    pub fn layers(&self) -> &[Layer] {
        &self.layers
    }

    /// Interface positions `0 = x_0 < x_1 < ... < x_n = L`.
    #[must_use]
    pub fn boundaries(&self) -> &[f64] {
        &self.boundaries
    }

    /// Total length L.
    #[must_use]
    pub fn length(&self) -> f64 {
        self.boundaries[self.layers.len()]
    }

    /// Cross-section area A.
    #[must_use]
    pub fn area(&self) -> f64 {
        self.area
    }

    /// Load amplitude sigma0.
    #[must_use]
    pub fn sigma0(&self) -> f64 {
        self.sigma0
    }

    /// Nodal force at x = 0: `F0 = -sigma0 A`.
    #[must_use]
    pub fn end_force(&self) -> f64 {
        -self.sigma0 * self.area
    }

    /// Transit time: the sum of the layer travel times.
    #[must_use]
    pub fn transit_time(&self) -> f64 {
        self.layers.iter().map(Layer::travel_time).sum()
    }

    /// Stress and velocity at `(x, t)`; see [`Self::field`].
    ///
    /// # Errors
    /// As [`Self::field`].
    pub fn state(&self, x: f64, t: f64) -> Result<FieldPoint, ReferenceError> {
        Ok(self.field(t)?.state(x))
    }

    /// Tracks every wave up to time t and returns the exact field at t.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] with `name = "t"` if t is not finite, or if more
    /// than the wave cap ([`Self::with_max_waves`]) waves would be needed to reach t.
    pub fn field(&self, t: f64) -> Result<LayeredField, ReferenceError> {
        if !t.is_finite() {
            return Err(ReferenceError::InvalidParameter {
                name: "t",
                value: t,
                rule: "finite",
            });
        }
        let n = self.layers.len();
        let transit = self.transit_time();
        let tol = (FRONT_TOLERANCE * (transit + t.abs())).min(0.125 * transit);
        let mut complete = vec![(0.0, 0.0); n];
        let mut partial = vec![Vec::new(); n];
        let mut load_displacement = 0.0;
        let mut wave_count = 0;
        let mut pending = Pending {
            queue: BTreeMap::new(),
            horizon: t,
            tol,
        };
        pending.push(0.0, 0, true, self.sigma0);
        while let Some(((TimeKey(start), i, toward), amplitude)) = pending.queue.pop_first() {
            if amplitude == 0.0 {
                continue;
            }
            wave_count += 1;
            if wave_count > self.max_waves {
                return Err(ReferenceError::InvalidParameter {
                    name: "t",
                    value: t,
                    rule: "reachable within the wave cap of the layered bar (raise it with with_max_waves)",
                });
            }
            let layer = self.layers[i];
            let (z, travel) = (layer.impedance(), layer.travel_time());
            let v_jump = if toward {
                -amplitude / z
            } else {
                amplitude / z
            };
            let end = start + travel;
            if i == 0 {
                // Velocity of the loaded end jumps when a wave leaves it or comes back to it.
                if toward {
                    load_displacement += v_jump * (t - start).max(0.0);
                } else {
                    load_displacement += v_jump * (t - end).max(0.0);
                }
            }
            if end > t + tol {
                partial[i].push(Front {
                    toward_fixed: toward,
                    reach: (layer.wave_speed() * (t - start).max(0.0)).min(layer.thickness()),
                    amplitude,
                });
                continue;
            }
            complete[i].0 += amplitude;
            complete[i].1 += v_jump;
            match (toward, i) {
                (true, i) if i + 1 == n => pending.push(end, i, false, amplitude),
                (true, i) => {
                    let z2 = self.layers[i + 1].impedance();
                    pending.push(
                        end,
                        i + 1,
                        true,
                        amplitude * transmission_coefficient(z, z2),
                    );
                    pending.push(end, i, false, amplitude * reflection_coefficient(z, z2));
                }
                (false, 0) => pending.push(end, 0, true, -amplitude),
                (false, i) => {
                    let z2 = self.layers[i - 1].impedance();
                    pending.push(
                        end,
                        i - 1,
                        false,
                        amplitude * transmission_coefficient(z, z2),
                    );
                    pending.push(end, i, true, amplitude * reflection_coefficient(z, z2));
                }
            }
        }
        Ok(LayeredField {
            bar: self.clone(),
            time: t,
            complete,
            partial,
            load_displacement,
            wave_count,
        })
    }
}

impl LayeredField {
    /// The time of this field.
    #[must_use]
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Number of waves tracked to build it (after merging).
    #[must_use]
    pub fn wave_count(&self) -> usize {
        self.wave_count
    }

    fn layer_of(&self, x: f64) -> Option<usize> {
        let margin = FRONT_TOLERANCE * self.bar.length();
        if !x.is_finite() || x < -margin || x > self.bar.length() + margin {
            return None;
        }
        let idx = self.bar.boundaries.partition_point(|&b| b <= x);
        Some(idx.saturating_sub(1).min(self.bar.layers.len() - 1))
    }

    /// Waves of layer i behind which the point `x` lies (`slack` widens the test).
    fn behind(&self, i: usize, x: f64, slack: f64) -> impl Iterator<Item = &Front> {
        let (x0, x1) = (self.bar.boundaries[i], self.bar.boundaries[i + 1]);
        self.partial[i].iter().filter(move |f| {
            if f.toward_fixed {
                x - x0 <= f.reach + slack
            } else {
                x1 - x <= f.reach + slack
            }
        })
    }

    fn sum_at(&self, i: usize, x: f64, slack: f64) -> FieldPoint {
        let z = self.bar.layers[i].impedance();
        let (mut stress, mut velocity) = self.complete[i];
        for f in self.behind(i, x, slack) {
            stress += f.amplitude;
            velocity += if f.toward_fixed {
                -f.amplitude
            } else {
                f.amplitude
            } / z;
        }
        FieldPoint { stress, velocity }
    }

    /// Stress and velocity at x, right-continuous in t (a front within [`FRONT_TOLERANCE`] of
    /// x has arrived). At an interface the layer on the fixed-end side is used (both sides
    /// agree unless a front sits there). NaN outside `[0, L]`.
    #[must_use]
    pub fn state(&self, x: f64) -> FieldPoint {
        match self.layer_of(x) {
            Some(i) => self.sum_at(i, x, FRONT_TOLERANCE * self.bar.length()),
            None => FieldPoint::NAN,
        }
    }

    /// Stress at x.
    #[must_use]
    pub fn stress(&self, x: f64) -> f64 {
        self.state(x).stress
    }

    /// Velocity at x.
    #[must_use]
    pub fn velocity(&self, x: f64) -> f64 {
        self.state(x).velocity
    }

    /// Exact means of stress and velocity over `[xa, xb]` (closed form: each wave contributes
    /// its amplitude times the length of the interval behind it). NaN unless
    /// `0 <= xa < xb <= L`.
    #[must_use]
    pub fn average(&self, xa: f64, xb: f64) -> FieldPoint {
        let margin = FRONT_TOLERANCE * self.bar.length();
        if !(xa.is_finite() && xb.is_finite() && xa < xb)
            || xa < -margin
            || xb > self.bar.length() + margin
        {
            return FieldPoint::NAN;
        }
        let (mut stress, mut velocity) = (0.0, 0.0);
        for (i, layer) in self.bar.layers.iter().enumerate() {
            let (x0, x1) = (self.bar.boundaries[i], self.bar.boundaries[i + 1]);
            let (lo, hi) = (xa.max(x0), xb.min(x1));
            if hi <= lo {
                continue;
            }
            let z = layer.impedance();
            stress += self.complete[i].0 * (hi - lo);
            velocity += self.complete[i].1 * (hi - lo);
            for f in &self.partial[i] {
                let (b0, b1) = if f.toward_fixed {
                    (x0, x0 + f.reach)
                } else {
                    (x1 - f.reach, x1)
                };
                let overlap = (hi.min(b1) - lo.max(b0)).max(0.0);
                stress += f.amplitude * overlap;
                velocity += if f.toward_fixed {
                    -f.amplitude
                } else {
                    f.amplitude
                } / z
                    * overlap;
            }
        }
        FieldPoint {
            stress: stress / (xb - xa),
            velocity: velocity / (xb - xa),
        }
    }

    /// Exact mean stress over `[xa, xb]` (see [`Self::average`]).
    #[must_use]
    pub fn stress_average(&self, xa: f64, xb: f64) -> f64 {
        self.average(xa, xb).stress
    }

    /// Positions of the fronts inside the layers, ascending, without duplicates.
    #[must_use]
    pub fn front_positions(&self) -> Vec<f64> {
        let mut out: Vec<f64> = self
            .partial
            .iter()
            .enumerate()
            .flat_map(|(i, fronts)| {
                let (x0, x1) = (self.bar.boundaries[i], self.bar.boundaries[i + 1]);
                fronts.iter().map(move |f| {
                    if f.toward_fixed {
                        x0 + f.reach
                    } else {
                        x1 - f.reach
                    }
                })
            })
            .collect();
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }

    /// Displacement `u(0, t) = int_0^t v(0, t') dt'` of the loaded end (exact: v(0, .) is
    /// piecewise constant).
    #[must_use]
    pub fn load_displacement(&self) -> f64 {
        self.load_displacement
    }

    /// Kinetic energy `int rho A v^2/2`, strain energy `int A sigma^2/(2E)` (exact: the fields
    /// are piecewise constant, evaluated between fronts) and the work `end_force() u(0, t)` of
    /// the constant end force, computed independently: `work = kinetic + strain`.
    #[must_use]
    pub fn energies(&self) -> Energies {
        let area = self.bar.area;
        let (mut kinetic, mut strain) = (0.0, 0.0);
        for (i, layer) in self.bar.layers.iter().enumerate() {
            let (x0, x1) = (self.bar.boundaries[i], self.bar.boundaries[i + 1]);
            let mut cuts = vec![x0, x1];
            cuts.extend(self.partial[i].iter().map(|f| {
                if f.toward_fixed {
                    x0 + f.reach
                } else {
                    x1 - f.reach
                }
            }));
            cuts.sort_by(f64::total_cmp);
            for w in cuts.windows(2) {
                let width = w[1] - w[0];
                if width <= 0.0 {
                    continue;
                }
                // Midpoints lie strictly between fronts: classify them exactly.
                let FieldPoint { stress, velocity } = self.sum_at(i, 0.5 * (w[0] + w[1]), 0.0);
                kinetic += 0.5 * layer.density() * area * velocity * velocity * width;
                strain += 0.5 * area * stress * stress / layer.modulus() * width;
            }
        }
        Energies {
            kinetic,
            strain,
            work: self.bar.end_force() * self.load_displacement,
        }
    }
}
