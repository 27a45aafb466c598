//! The measured critical step of a scheme without a stability analysis ([`LimitKind::Measured`]
//! (super::LimitKind::Measured)): the scheme itself runs in free vibration from a rough initial
//! displacement, and the step is bisected between a run that stays bounded and one the guard
//! stops.
//!
//! ```text
//!   u_i(0) = (-1)^i (1 + i/N)  (0 at fixed nodes): every mode excited, the highest ones most
//!   stable(dt)  <=>  STEPS steps without T + U exceeding GROWTH x its initial value
//!   dt_lo stable, dt_hi not: halve [dt_lo, dt_hi] until dt_hi/dt_lo - 1 <= MEASURED_PRECISION
//! ```
//!
//! What it promises: `dt_lo` (returned) ran [`STEPS`] steps with `T + U` below [`GROWTH`] times
//! its start, and a step `MEASURED_PRECISION` above it did not. A mode growing slower than that
//! over [`STEPS`] steps (spectral radius below about `1 + ln(GROWTH)/(2 STEPS) = 1 + 1e-3`) reads
//! as stable. Cost: about 20 runs of [`STEPS`] steps, O(N) each.

use super::scheme::{Integration, Scheme};
use super::settings::{OutputRequest, StabilityPolicy};
use crate::error::RunError;
use crate::mass::MassKind;
use crate::model::{InitialConditions, Model};
use std::sync::Arc;

/// Relative width of the final bracket `[dt_lo, dt_hi]`.
pub const MEASURED_PRECISION: f64 = 1e-3;

/// Steps of each trial run.
const STEPS: usize = 10_000;

/// Energy growth that stops a trial run as unstable (far above what a stable linear scheme's
/// `T + U` can reach from its start: central difference 500x at 0.999 of its limit, Noh-Bathe's
/// non-normal transient 7.2x).
const GROWTH: f64 = 1e8;

/// The measured critical step of `scheme` with `mass` on the bar and supports of `model`,
/// bracketed from `guess` (any positive step; e.g. central difference's `2/omega_max`).
///
/// # Errors
/// [`RunError::Input`] when a trial run is refused (bad settings for the scheme), or when no
/// stable step is found down to `guess/1e6` or no unstable one up to `1e6 guess`.
pub fn measure_critical_step(
    scheme: &Arc<dyn Scheme>,
    model: &Model,
    mass: MassKind,
    guess: f64,
) -> Result<f64, RunError> {
    let n = model.bar().node_count();
    let displacement: Vec<f64> = (0..n)
        .map(|i| {
            if model.is_fixed(i) {
                0.0
            } else {
                (1.0 - 2.0 * (i % 2) as f64) * (1.0 + i as f64 / n as f64)
            }
        })
        .collect();
    let free = Model::new(
        model.bar().clone(),
        model.supports(),
        &[],
        InitialConditions {
            displacement: Some(displacement),
            velocity: None,
        },
    )?;
    let request = OutputRequest {
        energy_every: STEPS,
        history_every: STEPS,
        ..OutputRequest::default()
    };
    let stable = |dt: f64| -> Result<bool, RunError> {
        let run = Integration {
            mass,
            stability: StabilityPolicy {
                allow_unstable: true,
                blowup_energy_ratio: GROWTH,
            },
            ..Integration::new(dt, scheme.clone())
        };
        match run.run(&free, STEPS, &request) {
            Ok(_) => Ok(true),
            Err(RunError::Diverged { .. }) => Ok(false),
            Err(other) => Err(other),
        }
    };
    let no_bracket = |what: &'static str| {
        RunError::Input(crate::error::InputError::CriticalStepNotBracketed {
            scheme: scheme.label(),
            what,
        })
    };
    let (mut lo, mut hi) = (guess, guess);
    while !stable(lo)? {
        lo *= 0.5;
        if lo < guess * 1e-6 {
            return Err(no_bracket("no stable step found"));
        }
        hi = lo * 2.0;
    }
    if hi == lo {
        hi = lo * 2.0;
        while stable(hi)? {
            lo = hi;
            hi *= 2.0;
            if hi > guess * 1e6 {
                return Err(no_bracket("no unstable step found"));
            }
        }
    }
    while hi / lo - 1.0 > MEASURED_PRECISION {
        let mid = 0.5 * (lo + hi);
        if stable(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(lo)
}
