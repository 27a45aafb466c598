//! Part 2 of the contact references: the exact contact force of one-dimensional impact (striker
//! on a target bar or a rigid wall), by tracking the characteristic invariants at the interface.
//!
//! [`ImpactForce`]: a striker (impedance `Z1`, wave speed `c1`, length `L1`, velocity `v0`) hits
//! a target bar (`Z2`, `c2`, `L2`, at rest) or a rigid wall; the bars touch at t = 0 and their
//! far ends are free. The force history is piecewise constant and computed exactly by tracking
//! the characteristic invariants (see [`ImpactForce`]). [`PenaltyWallForce`](super::PenaltyWallForce):
//! the bar hits a
//! penalty spring `k_s` instead of a rigid wall. Source: elementary wave theory of impact, e.g.
//! Graff, *Wave Motion in Elastic Solids* (1975), ch. 2; Johnson, *Impact Strength of Materials*
//! (1972), ch. 3; conventions of methods.md §7.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::error::ReferenceError;
pub use crate::exact::ForcePlateau;

/// A homogeneous elastic bar as seen by 1D impact: impedance `Z = rho c A`, wave speed c,
/// length L.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactBar {
    impedance: f64,
    wave_speed: f64,
    length: f64,
}

impl ImpactBar {
    /// Builds the bar after validating its data.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a value is not positive and finite.
    pub fn new(impedance: f64, wave_speed: f64, length: f64) -> Result<Self, ReferenceError> {
        Ok(Self {
            impedance: ReferenceError::require_positive("impedance", impedance)?,
            wave_speed: ReferenceError::require_positive("wave_speed", wave_speed)?,
            length: ReferenceError::require_positive("length", length)?,
        })
    }

    /// Builds the bar from its material: `c = sqrt(E/rho)`, `Z = rho c A = A sqrt(E rho)`.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if a value is not positive and finite.
    pub fn from_material(
        modulus: f64,
        density: f64,
        area: f64,
        length: f64,
    ) -> Result<Self, ReferenceError> {
        let modulus = ReferenceError::require_positive("modulus", modulus)?;
        let density = ReferenceError::require_positive("density", density)?;
        let area = ReferenceError::require_positive("area", area)?;
        Self::new(
            area * (modulus * density).sqrt(),
            (modulus / density).sqrt(),
            length,
        )
    }

    /// Impedance `Z = rho c A` (force per velocity, > 0).
    #[must_use]
    pub fn impedance(&self) -> f64 {
        self.impedance
    }

    /// Bar wave speed `c = sqrt(E/rho)` (> 0).
    #[must_use]
    pub fn wave_speed(&self) -> f64 {
        self.wave_speed
    }

    /// Length L (> 0).
    #[must_use]
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Transit time `T = L/c`.
    #[must_use]
    pub fn transit_time(&self) -> f64 {
        self.length / self.wave_speed
    }

    /// Mass `rho A L = Z T`.
    #[must_use]
    pub fn mass(&self) -> f64 {
        self.impedance * self.transit_time()
    }
}

/// What the striker hits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ImpactTarget {
    /// An elastic bar at rest, far end free.
    Bar(ImpactBar),
    /// A rigid, fixed wall (the limit `Z2 -> inf`).
    RigidWall,
}

/// Relative time tolerance (of `T1 + T2`) within which two wave arrivals at the interface count
/// as simultaneous; plateaus shorter than this are merged away.
pub const ARRIVAL_TOLERANCE: f64 = 1e-10;

/// Relative force tolerance (of `Z1 v0`) below which an interface force counts as zero.
const FORCE_TOLERANCE: f64 = 1e-12;

/// Most plateaus tracked before giving up (only reached for extreme transit-time ratios).
const MAX_PLATEAUS: usize = 1_000_000;

/// Exact contact force of a 1D impact: striker `(Z1, c1, L1)` moving at `v0 > 0` hits a target
/// bar `(Z2, c2, L2)` at rest (or a rigid wall); the bars touch at t = 0, far ends free, contact
/// is unilateral (compression only), frictionless and lossless. Source: elementary wave theory of
/// impact (Graff 1975, ch. 2; Johnson 1972, ch. 3); methods.md §7.
///
/// **Method (exact wave tracking).** With N the axial force (tension positive), `N - Z v` is
/// constant along `dx/dt = +c` and `N + Z v` along `dx/dt = -c`. At the interface the striker
/// delivers the right-going invariant `a(t)`, the target the left-going `b(t)`. In contact
/// (`N1 = N2 = N`, `v1 = v2 = v`):
///
/// ```text
///   N = (Z2 a + Z1 b)/(Z1 + Z2),   v = (b - a)/(Z1 + Z2),   F = -N (compression positive);
///   emitted: into the striker N + Z1 v, into the target N - Z2 v.
/// ```
///
/// A free end (N = 0) returns an invariant with its sign reversed, so
/// `a(t) = -Z1 v0` for `t < 2 T1` and `a(t) = -(N + Z1 v)(t - 2 T1)` after; `b(t) = 0` for
/// `t < 2 T2` and `b(t) = -(N - Z2 v)(t - 2 T2)` after (`T_i = L_i/c_i`). Against a rigid wall
/// `v = 0`, `N = a`. Every change of the interface state therefore happens at a time
/// `2 i T1 + 2 j T2`, and the force is piecewise constant. The contact opens at the first such
/// time at which the welded N would be tensile: then `N (Z1 + Z2)/(Z1 Z2) = a/Z1 + b/Z2` is the
/// opening rate of the gap between the two free ends, so `N > 0` is exactly "the gap opens". A
/// welded `N = 0` keeps the ends touching with zero force (they move together); such interior
/// zero plateaus are kept, trailing ones are dropped. Only the first contact is described; the
/// bars are not followed after the gap opens.
///
/// **Hand results** (checked in the tests):
/// - First plateau `F1 = Z1 Z2 v0/(Z1 + Z2)` while `t < 2 min(T1, T2)`.
/// - Equal impedance (`Z1 = Z2 = Z`, no reflection at the interface): `F = Z v0/2` for
///   `0 <= t < 2 min(T1, T2)`, then 0. Impulse `Z v0 min(T1, T2) = min(m1, m2) v0`, i.e.
///   `rho A L_short v0` for equal materials. Momentum: if `T1 <= T2` the striker stops completely
///   (its momentum loss `m1 v0` is the impulse; its energy `m1 v0^2/2` is all passed on, carried
///   by a compressive pulse of length `2 c2 T1` in the target); the target's end stays at rest,
///   touching at zero force, until that pulse returns from the target's free end at `2 T2`, when
///   the gap opens ([`Self::separation_time`]). If `T1 > T2` the target leaves with uniform `v0`
///   and no stress at `2 T2` (impulse `m2 v0`); the striker keeps `(m1 - m2) v0` and an
///   unloading pulse, its end moves with the target at zero force until the striker's own
///   reflected wave returns at `2 T1`, when the gap opens. Either way the gap opens at
///   `2 max(T1, T2)`.
/// - Equal transit times `T1 = T2 = T`: `F = F1` for `0 <= t < 2T` for every impedance ratio
///   (at 2T the welded N would be `+F1`); impulse `2 T F1`, which is `m1 v0` for `Z1 = Z2` and
///   tends to `2 m1 v0` (elastic bounce) for `Z2 -> inf`.
/// - Rigid wall: `F = Z1 v0` for `0 <= t < 2 T1`; impulse `2 m1 v0`.
/// - Otherwise a staircase: e.g. `Z1 < Z2`, `T2 < T1` continues after 2 T2 with
///   `F2 = F1 (Z2 - Z1)/(Z1 + Z2)`, and so on; `Z1 > Z2`, `T2 < T1` separates at `2 T2`.
///
/// The impulse equals the striker's momentum loss (`m1 v0 - p1`, the only external force on
/// the striker is the contact force) and the target's momentum gain.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactForce {
    striker: ImpactBar,
    target: ImpactTarget,
    velocity: f64,
    plateaus: Vec<ForcePlateau>,
    separation: f64,
}

/// A pending wave arrival at the interface at `2 (i T1 + j T2)`; ordered as a min-heap on time.
#[derive(Debug, Clone, Copy)]
struct Arrival {
    time: f64,
    i: u32,
    j: u32,
}

impl PartialEq for Arrival {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Arrival {}

impl PartialOrd for Arrival {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Arrival {
    fn cmp(&self, other: &Self) -> Ordering {
        // Reversed: BinaryHeap is a max-heap.
        other
            .time
            .total_cmp(&self.time)
            .then_with(|| other.i.cmp(&self.i))
            .then_with(|| other.j.cmp(&self.j))
    }
}

/// The interface state from time `time` on.
#[derive(Debug, Clone, Copy)]
struct InterfaceState {
    time: f64,
    /// Incoming invariants.
    a: f64,
    b: f64,
    /// Axial force (tension positive) and velocity of the interface.
    n: f64,
    v: f64,
}

impl ImpactForce {
    /// Striker hitting an elastic target bar at rest.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if `v0` is not positive and finite (the bars must
    /// approach), or, for extreme transit-time ratios, if the first contact needs more than
    /// 10^6 plateaus (named `transit-time ratio T1/T2`).
    pub fn new(striker: ImpactBar, target: ImpactBar, v0: f64) -> Result<Self, ReferenceError> {
        Self::with_target(striker, ImpactTarget::Bar(target), v0)
    }

    /// Striker hitting a rigid wall: `F = Z1 v0` for `2 L1/c1`.
    ///
    /// # Errors
    /// [`ReferenceError::InvalidParameter`] if `v0` is not positive and finite.
    pub fn rigid_wall(striker: ImpactBar, v0: f64) -> Result<Self, ReferenceError> {
        Self::with_target(striker, ImpactTarget::RigidWall, v0)
    }

    /// Striker hitting `target`.
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn with_target(
        striker: ImpactBar,
        target: ImpactTarget,
        v0: f64,
    ) -> Result<Self, ReferenceError> {
        let striker = ImpactBar::new(striker.impedance, striker.wave_speed, striker.length)?;
        let target = match target {
            ImpactTarget::Bar(bar) => {
                ImpactTarget::Bar(ImpactBar::new(bar.impedance, bar.wave_speed, bar.length)?)
            }
            ImpactTarget::RigidWall => ImpactTarget::RigidWall,
        };
        let velocity = ReferenceError::require_positive("v0", v0)?;
        let (plateaus, separation) = track(striker, target, velocity)?;
        Ok(Self {
            striker,
            target,
            velocity,
            plateaus,
            separation,
        })
    }

    /// The striker.
    #[must_use]
    pub fn striker(&self) -> ImpactBar {
        self.striker
    }

    /// The target.
    #[must_use]
    pub fn target(&self) -> ImpactTarget {
        self.target
    }

    /// Impact velocity v0.
    #[must_use]
    pub fn impact_velocity(&self) -> f64 {
        self.velocity
    }

    /// First plateau `F1 = Z1 Z2 v0/(Z1 + Z2)` (`Z1 v0` against a rigid wall).
    #[must_use]
    pub fn first_plateau(&self) -> f64 {
        match self.target {
            ImpactTarget::Bar(t) => {
                let (z1, z2) = (self.striker.impedance, t.impedance);
                z1 * z2 / (z1 + z2) * self.velocity
            }
            ImpactTarget::RigidWall => self.striker.impedance * self.velocity,
        }
    }

    /// Contact force at time t, compression positive, right-continuous (the new value at a
    /// step); 0 for `t < 0` and `t >= duration()`, NaN for NaN.
    #[must_use]
    pub fn force(&self, t: f64) -> f64 {
        if t.is_nan() {
            return f64::NAN;
        }
        if t < 0.0 || t >= self.duration() {
            return 0.0;
        }
        let k = self.plateaus.partition_point(|p| p.start <= t);
        self.plateaus[k - 1].force
    }

    /// End of the last plateau with positive force.
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.plateaus.last().map_or(0.0, |p| p.end)
    }

    /// Time at which the gap opens (`>= duration()`; larger when the ends keep touching at zero
    /// force, e.g. equal impedance with `T1 > T2`).
    #[must_use]
    pub fn separation_time(&self) -> f64 {
        self.separation
    }

    /// The piecewise-constant force history, in time order, ending with a positive plateau.
    #[must_use]
    pub fn plateaus(&self) -> &[ForcePlateau] {
        &self.plateaus
    }

    /// Impulse `int F dt` = the striker's momentum loss = the target's momentum gain.
    #[must_use]
    pub fn impulse(&self) -> f64 {
        self.plateaus
            .iter()
            .map(|p| p.force * (p.end - p.start))
            .sum()
    }

    /// Work `int F v dt` done by the striker on the target through the interface: the striker's
    /// energy loss, equal to the target's energy (kinetic + strain) after separation.
    #[must_use]
    pub fn energy_transferred(&self) -> f64 {
        self.plateaus
            .iter()
            .map(|p| p.force * p.interface_velocity * (p.end - p.start))
            .sum()
    }

    /// Mean (centre-of-mass) velocity of the striker after separation, `v0 - impulse/m1`.
    #[must_use]
    pub fn striker_mean_velocity_after(&self) -> f64 {
        self.velocity - self.impulse() / self.striker.mass()
    }
}

/// Exact wave tracking of the first contact; returns the plateaus (trailing zero-force ones
/// dropped) and the time the gap opens.
fn track(
    striker: ImpactBar,
    target: ImpactTarget,
    v0: f64,
) -> Result<(Vec<ForcePlateau>, f64), ReferenceError> {
    let z1 = striker.impedance;
    let t1 = striker.transit_time();
    let (z2, t2) = match target {
        ImpactTarget::Bar(bar) => (bar.impedance, bar.transit_time()),
        ImpactTarget::RigidWall => (f64::INFINITY, f64::INFINITY),
    };
    let rigid = matches!(target, ImpactTarget::RigidWall);
    let time_tol = ARRIVAL_TOLERANCE * if rigid { t1 } else { t1 + t2 };
    let force_tol = FORCE_TOLERANCE * z1 * v0;

    let weld = |time: f64, a: f64, b: f64| -> InterfaceState {
        let (n, v) = if rigid {
            (a, 0.0)
        } else {
            ((z2 * a + z1 * b) / (z1 + z2), (b - a) / (z1 + z2))
        };
        InterfaceState { time, a, b, n, v }
    };
    // Invariants emitted into the striker and the target by a state.
    let out1 = |s: &InterfaceState| s.n + z1 * s.v;
    let out2 = |s: &InterfaceState| s.n - z2 * s.v;
    let at = |history: &[InterfaceState], tau: f64| -> InterfaceState {
        let k = history.partition_point(|s| s.time <= tau + time_tol);
        history[k.max(1) - 1]
    };
    let arrival = |i: u32, j: u32| -> Arrival {
        let time = if rigid {
            2.0 * f64::from(i) * t1
        } else {
            2.0 * (f64::from(i) * t1 + f64::from(j) * t2)
        };
        Arrival { time, i, j }
    };

    let mut history = vec![weld(0.0, -z1 * v0, 0.0)];
    let mut queue = BinaryHeap::new();
    let spawn = |queue: &mut BinaryHeap<Arrival>, i: u32, j: u32| {
        queue.push(arrival(i + 1, j));
        if !rigid {
            queue.push(arrival(i, j + 1));
        }
    };
    spawn(&mut queue, 0, 0);

    let separation = loop {
        let Some(next) = queue.pop() else {
            // Nothing will ever change again: cannot happen for a physical impact (the
            // striker's release wave always returns), kept as a guard.
            return Err(ReferenceError::InvalidParameter {
                name: "transit-time ratio T1/T2",
                value: t1 / t2,
                rule: "such that the contact ends",
            });
        };
        let last = history[history.len() - 1];
        if next.time <= last.time + time_tol {
            continue;
        }
        let t = next.time;
        let a = if t < 2.0 * t1 - time_tol {
            -z1 * v0
        } else {
            -out1(&at(&history, t - 2.0 * t1))
        };
        let b = if rigid || t < 2.0 * t2 - time_tol {
            0.0
        } else {
            -out2(&at(&history, t - 2.0 * t2))
        };
        if a == last.a && b == last.b {
            continue;
        }
        let state = weld(t, a, b);
        if state.n > force_tol {
            break t;
        }
        history.push(state);
        if history.len() > MAX_PLATEAUS {
            return Err(ReferenceError::InvalidParameter {
                name: "transit-time ratio T1/T2",
                value: t1 / t2,
                rule: "such that the first contact ends within 10^6 plateaus",
            });
        }
        spawn(&mut queue, next.i, next.j);
    };

    let mut plateaus: Vec<ForcePlateau> = history
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let end = history.get(k + 1).map_or(separation, |n| n.time);
            let force = if -s.n > force_tol { -s.n } else { 0.0 };
            ForcePlateau {
                start: s.time,
                end,
                force,
                interface_velocity: s.v,
            }
        })
        .collect();
    while plateaus.last().is_some_and(|p| p.force == 0.0) {
        plateaus.pop();
    }
    Ok((plateaus, separation))
}

impl crate::exact::ContactHistory for ImpactForce {
    fn contact_force(&self, t: f64) -> f64 {
        self.force(t)
    }

    fn force_plateaus(&self) -> &[ForcePlateau] {
        &self.plateaus
    }

    fn first_plateau_force(&self) -> f64 {
        self.first_plateau()
    }

    fn contact_duration(&self) -> f64 {
        self.duration()
    }

    fn separation_time(&self) -> f64 {
        self.separation
    }

    fn contact_impulse(&self) -> f64 {
        self.impulse()
    }
}
