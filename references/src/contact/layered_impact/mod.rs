//! The exact impact of two layered bars (piecewise-constant E, rho, A; free far ends): a striker
//! at `v0` onto a target at rest, by the method of characteristics on the impedance network.
//!
//! ```text
//!   striker (moving at v0)                 target (at rest)
//!   free |--layer--|--layer--|  contact  |--layer--|--layer--|--layer--| free
//!        x = 0                x = L1 (both bars touch here at t = 0)      x = L1 + L2
//! ```
//!
//! **Method (exact event-driven wave tracking).** Every field is the initial one (`N = 0`,
//! `v = v0` in the striker, `0` in the target) plus step waves: in piecewise-constant media the
//! characteristic invariants `N - Z v` (along `dx/dt = +c`) and `N + Z v` (along `-c`) are
//! constant inside a layer, so a step stays a step (Graff, *Wave Motion in Elastic Solids*,
//! 1975, ch. 2; method of characteristics, Courant & Hilbert vol. II, ch. V). A wave of axial
//! force jump `dN` moving in +x carries `dv = -dN/Z`, in -x `dv = +dN/Z` (`Z = A sqrt(E rho)`,
//! tension positive). At a boundary the states just left and right of it after all arrivals
//! of one instant, `(P_l, U_l)` and `(P_r, U_r)` (force, velocity before emitting), are joined:
//!
//! ```text
//!   welded:   N = (Z_l Z_r (U_r - U_l) + Z_r P_l + Z_l P_r)/(Z_l + Z_r),
//!             emitted into the left layer X = N - P_l (moving -x), into the right Y = N - P_r;
//!   free end: emitted -P (the end force returns to zero).
//! ```
//!
//! (for one incident wave this is the transmission `2 Z2/(Z1 + Z2)` and reflection
//! `(Z2 - Z1)/(Z1 + Z2)` of Graff ch. 2). Layer interfaces are always welded, far ends free.
//! The contact interface is welded while the bars touch; at the first instant at which the
//! welded `N` would be tensile it opens (then `N (Z_l + Z_r)/(Z_l Z_r)` is exactly the opening
//! rate of the gap between the two free ends, as for [`ImpactForce`](super::ImpactForce)), and
//! from then on both ends are free. A welded `N = 0` keeps them touching. After opening, the
//! gap `u_target - u_striker` at the interface is integrated exactly (the end velocities are
//! piecewise constant between arrivals); where it closes again with the ends approaching, the
//! bars meet in a new impact at that instant (an event off the arrival lattice) and the contact
//! is welded again until it next opens. Layered bars do re-contact: in the scene
//! `impact_layered` the striker, still carrying most of its momentum, catches the target's
//! end again ([`LayeredImpact::closings`]).
//!
//! Waves arriving at the same boundary at the same instant (within [`ARRIVAL_TOLERANCE`] of the
//! total transit time) are processed together and their emitted waves merged; zero waves are
//! dropped. No amplitude is ever truncated, so the field is exact up to that merging of
//! instants. **Cost:** one event per (boundary, distinct arrival instant). When every layer's
//! travel time is an integer multiple of a common `dtau` (commensurate layers, e.g. the scene
//! `impact_layered`) the instants lie on the lattice `k dtau` and there are at most
//! `(boundaries) x (horizon/dtau)` events; otherwise the number of distinct instants can grow
//! exponentially with time, and tracking stops with a typed error
//! ([`ReferenceError::TooManyEvents`]) once the cap ([`DEFAULT_MAX_EVENTS`] or
//! [`LayeredImpact::with_cap`]) is exceeded. After tracking, a point value costs two binary
//! searches in its layer (prefix sums of the waves), an element average the same plus the waves
//! in flight inside the element.

use std::collections::BTreeMap;

use super::impact::{ARRIVAL_TOLERANCE, ForcePlateau};

mod field;
use crate::error::ReferenceError;
use crate::graded::{Layer, TimeKey};

/// Default cap on the number of boundary events tracked.
pub const DEFAULT_MAX_EVENTS: usize = 2_000_000;

/// Relative force tolerance (of the first plateau force) below which the welded force counts as
/// zero (neither tensile nor compressive).
const FORCE_TOLERANCE: f64 = 1e-12;

/// One homogeneous layer of a bar in an impact: a [`Layer`] (thickness, modulus, density) and
/// its cross-section area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactLayer {
    material: Layer,
    area: f64,
}

impl ImpactLayer {
    /// Builds the layer after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a value is not positive and finite.
    pub fn new(
        thickness: f64,
        modulus: f64,
        density: f64,
        area: f64,
    ) -> Result<Self, ReferenceError> {
        Ok(Self {
            material: Layer::new(thickness, modulus, density)?,
            area: ReferenceError::require_positive("area", area)?,
        })
    }

    /// Thickness.
    #[must_use]
    pub fn thickness(&self) -> f64 {
        self.material.thickness()
    }

    /// Young's modulus.
    #[must_use]
    pub fn modulus(&self) -> f64 {
        self.material.modulus()
    }

    /// Mass density.
    #[must_use]
    pub fn density(&self) -> f64 {
        self.material.density()
    }

    /// Cross-section area.
    #[must_use]
    pub fn area(&self) -> f64 {
        self.area
    }

    /// Wave speed `sqrt(E/rho)` ([`Layer::wave_speed`]).
    #[must_use]
    pub fn wave_speed(&self) -> f64 {
        self.material.wave_speed()
    }

    /// Bar impedance `Z = A sqrt(E rho)` (force per velocity): the area times
    /// [`Layer::impedance`].
    #[must_use]
    pub fn impedance(&self) -> f64 {
        self.area * self.material.impedance()
    }

    /// Travel time `thickness/c` ([`Layer::travel_time`]).
    #[must_use]
    pub fn travel_time(&self) -> f64 {
        self.material.travel_time()
    }
}

/// The waves of one direction in one layer: start times at the entry boundary (ascending) with
/// prefix sums of their force and velocity jumps.
#[derive(Debug, Clone, Default, PartialEq)]
struct Waves {
    start: Vec<f64>,
    /// `force[k]` = sum of the force jumps of waves `0..k` (length `start.len() + 1`).
    force: Vec<f64>,
    velocity: Vec<f64>,
}

impl Waves {
    fn push(&mut self, start: f64, force: f64, velocity: f64) {
        if self.force.is_empty() {
            self.force.push(0.0);
            self.velocity.push(0.0);
        }
        self.start.push(start);
        let k = self.force.len() - 1;
        self.force.push(self.force[k] + force);
        self.velocity.push(self.velocity[k] + velocity);
    }

    /// Number of waves started at or before `s`.
    fn count_until(&self, s: f64) -> usize {
        self.start.partition_point(|&x| x <= s)
    }

    fn sums(&self, count: usize) -> (f64, f64) {
        if count == 0 {
            (0.0, 0.0)
        } else {
            (self.force[count], self.velocity[count])
        }
    }

    /// The jumps of wave `k`.
    fn jump(&self, k: usize) -> (f64, f64) {
        (
            self.force[k + 1] - self.force[k],
            self.velocity[k + 1] - self.velocity[k],
        )
    }
}

/// Pending arrivals: (instant, boundary) -> (force jump arriving from the left, from the right).
type Arrivals = BTreeMap<(TimeKey, usize), (f64, f64)>;

/// The exact impact of two layered bars (module documentation), tracked to a horizon.
#[derive(Debug, Clone, PartialEq)]
pub struct LayeredImpact {
    layers: Vec<ImpactLayer>,
    /// Boundary positions, `0 = x_0 < ... < x_n = L1 + L2`; the contact is `x_contact`.
    boundaries: Vec<f64>,
    contact: usize,
    velocity: f64,
    /// Right-moving and left-moving waves per layer.
    right: Vec<Waves>,
    left: Vec<Waves>,
    plateaus: Vec<ForcePlateau>,
    first_plateau: f64,
    separation: f64,
    openings: Vec<f64>,
    closings: Vec<f64>,
    valid_until: f64,
    events: usize,
    tol: f64,
}

impl LayeredImpact {
    /// Tracks the impact to `horizon` (and on until the contact is open), with the default
    /// event cap [`DEFAULT_MAX_EVENTS`]. Layers are listed from each bar's own `x = 0`: the
    /// striker's far free end first (its last layer touches the target), the target's contact
    /// layer first.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a bar has no layer, `v0` or `horizon` is not
    /// positive and finite; [`ReferenceError::TooManyEvents`] past the cap.
    pub fn new(
        striker: &[ImpactLayer],
        target: &[ImpactLayer],
        v0: f64,
        horizon: f64,
    ) -> Result<Self, ReferenceError> {
        Self::with_cap(striker, target, v0, horizon, DEFAULT_MAX_EVENTS)
    }

    /// As [`Self::new`] with a cap of `max_events` boundary events.
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn with_cap(
        striker: &[ImpactLayer],
        target: &[ImpactLayer],
        v0: f64,
        horizon: f64,
        max_events: usize,
    ) -> Result<Self, ReferenceError> {
        for (name, bar) in [("striker layers", striker), ("target layers", target)] {
            if bar.is_empty() {
                return Err(ReferenceError::InvalidParameter {
                    name,
                    value: 0.0,
                    rule: "at least one layer",
                });
            }
        }
        let velocity = ReferenceError::require_positive("v0", v0)?;
        let horizon = ReferenceError::require_positive("horizon", horizon)?;
        let layers: Vec<ImpactLayer> = striker.iter().chain(target).copied().collect();
        let mut boundaries = vec![0.0];
        for l in &layers {
            boundaries.push(boundaries[boundaries.len() - 1] + l.thickness());
        }
        let transit: f64 = layers.iter().map(ImpactLayer::travel_time).sum();
        let (zs, zt) = (
            layers[striker.len() - 1].impedance(),
            layers[striker.len()].impedance(),
        );
        let mut me = Self {
            right: vec![Waves::default(); layers.len()],
            left: vec![Waves::default(); layers.len()],
            layers,
            boundaries,
            contact: striker.len(),
            velocity,
            plateaus: Vec::new(),
            first_plateau: zs * zt / (zs + zt) * velocity,
            separation: f64::INFINITY,
            openings: Vec::new(),
            closings: Vec::new(),
            valid_until: horizon,
            events: 0,
            tol: ARRIVAL_TOLERANCE * transit,
        };
        me.track(horizon, max_events)?;
        Ok(me)
    }

    /// Processes every boundary event up to `horizon` (and the contact's opening).
    fn track(&mut self, horizon: f64, max_events: usize) -> Result<(), ReferenceError> {
        let n = self.layers.len();
        let force_tol = FORCE_TOLERANCE * self.first_plateau;
        // Contact end states: striker side (N, v), target side (N, v); the gap after opening.
        let (mut left_end, mut right_end) = ((0.0, self.velocity), (0.0, 0.0));
        let mut touching = true;
        let (mut gap, mut gap_rate, mut gap_time) = (0.0, 0.0, 0.0);
        let gap_tol = self.tol * self.velocity;
        let mut queue = Arrivals::new();
        queue.insert((TimeKey(0.0), self.contact), (0.0, 0.0));
        while let Some(((TimeKey(t), b), (from_left, from_right))) = queue.pop_first() {
            // While touching, go on past the horizon until the contact opens.
            if !touching && t > horizon + self.tol {
                break;
            }
            self.events += 1;
            if self.events > max_events {
                return Err(ReferenceError::TooManyEvents {
                    reference: "layered impact",
                    what: "boundary events (raise the cap with LayeredImpact::with_cap)",
                    cap: max_events,
                });
            }
            let (x_out, y_out) = if b == 0 {
                (0.0, -from_right)
            } else if b == n {
                (-from_left, 0.0)
            } else if b != self.contact {
                // Welded layer interface: the states on both sides agree before the arrivals.
                let (zl, zr) = (self.layers[b - 1].impedance(), self.layers[b].impedance());
                let d = 2.0 * (zr * from_left + zl * from_right) / (zl + zr);
                (d - from_left, d - from_right)
            } else {
                let (zl, zr) = (self.layers[b - 1].impedance(), self.layers[b].impedance());
                let (pl, ul) = (left_end.0 + from_left, left_end.1 - from_left / zl);
                let (pr, ur) = (right_end.0 + from_right, right_end.1 + from_right / zr);
                if !touching {
                    gap += gap_rate * (t - gap_time);
                    gap_time = t;
                }
                let welded = (zl * zr * (ur - ul) + zr * pl + zl * pr) / (zl + zr);
                if touching && welded > force_tol {
                    touching = false;
                    self.openings.push(t);
                    gap = 0.0;
                    gap_time = t;
                } else if !touching && gap <= gap_tol && welded < -force_tol {
                    // The separated ends meet again while approaching: a new impact.
                    touching = true;
                    self.closings.push(t);
                }
                let (nl, nr) = if touching {
                    (welded, welded)
                } else {
                    (0.0, 0.0)
                };
                let (x, y) = (nl - pl, nr - pr);
                left_end = (nl, ul + x / zl);
                right_end = (nr, ur - y / zr);
                self.push_plateau(t, nl, left_end.1, force_tol);
                if !touching {
                    gap_rate = right_end.1 - left_end.1;
                    let closes = t - gap / gap_rate;
                    if gap_rate < 0.0 && closes <= horizon {
                        // Checked when it comes: later arrivals may change the rate first.
                        self.schedule(&mut queue, closes.max(t), b, (0.0, 0.0));
                    }
                }
                (x, y)
            };
            // Emit: X moves -x into layer b - 1, Y moves +x into layer b.
            if b > 0 && x_out != 0.0 {
                let layer = self.layers[b - 1];
                self.left[b - 1].push(t, x_out, x_out / layer.impedance());
                self.schedule(&mut queue, t + layer.travel_time(), b - 1, (0.0, x_out));
            }
            if b < n && y_out != 0.0 {
                let layer = self.layers[b];
                self.right[b].push(t, y_out, -y_out / layer.impedance());
                self.schedule(&mut queue, t + layer.travel_time(), b + 1, (y_out, 0.0));
            }
        }
        self.separation = self.openings.first().copied().unwrap_or(f64::INFINITY);
        while self.plateaus.last().is_some_and(|p| p.force == 0.0) {
            self.plateaus.pop();
        }
        Ok(())
    }

    /// Records the contact force from t on (compression positive), closing the previous plateau.
    fn push_plateau(&mut self, t: f64, welded: f64, velocity: f64, force_tol: f64) {
        let force = if -welded > force_tol { -welded } else { 0.0 };
        if let Some(last) = self.plateaus.last_mut() {
            if last.force == force && (force == 0.0 || last.interface_velocity == velocity) {
                return;
            }
            last.end = t;
        }
        self.plateaus.push(ForcePlateau {
            start: t,
            end: f64::INFINITY,
            force,
            interface_velocity: velocity,
        });
    }

    /// Adds an arrival, merged with one at the same boundary within the tolerance.
    fn schedule(&self, queue: &mut Arrivals, t: f64, boundary: usize, (l, r): (f64, f64)) {
        let lo = (TimeKey(t - self.tol), boundary);
        let hi = (TimeKey(t + self.tol), boundary);
        let same = queue
            .range(lo..=hi)
            .find(|(key, _)| key.1 == boundary)
            .map(|(key, _)| *key);
        match same.and_then(|key| queue.get_mut(&key)) {
            Some(entry) => {
                entry.0 += l;
                entry.1 += r;
            }
            None => {
                queue.insert((TimeKey(t), boundary), (l, r));
            }
        }
    }

    /// Impact velocity v0.
    #[must_use]
    pub fn impact_velocity(&self) -> f64 {
        self.velocity
    }

    /// All layers, striker first (its far end first), then the target's (contact layer first).
    #[must_use]
    pub fn layers(&self) -> &[ImpactLayer] {
        &self.layers
    }

    /// Boundary positions on the common axis (striker at `[0, L1]`, target at `[L1, L1 + L2]`).
    #[must_use]
    pub fn boundaries(&self) -> &[f64] {
        &self.boundaries
    }

    /// Position `L1` of the contact interface on the common axis.
    #[must_use]
    pub fn contact_position(&self) -> f64 {
        self.boundaries[self.contact]
    }

    /// Number of boundary events tracked (the work of the construction).
    #[must_use]
    pub fn event_count(&self) -> usize {
        self.events
    }

    /// The time up to which the fields are exact: the horizon.
    #[must_use]
    pub fn valid_until(&self) -> f64 {
        self.valid_until
    }

    /// The instants at which the contact opens (the first is [`ContactHistory::separation_time`]).
    #[must_use]
    pub fn openings(&self) -> &[f64] {
        &self.openings
    }

    /// The instants at which the separated ends meet again (later impacts), before the horizon.
    #[must_use]
    pub fn closings(&self) -> &[f64] {
        &self.closings
    }
}
