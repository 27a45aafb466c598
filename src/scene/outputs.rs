//! The `[output]` of a time-stepping scene: profile times, end time, history points and
//! sampling, with times converted to absolute time.

use super::error::{SceneError, Source, positive};
use super::schema::{RawOutput, RawTimeUnit};
use courant_solver::Model;
use toml::Spanned;

/// The output settings, with times converted to absolute time.
pub(super) struct Outputs<'r> {
    pub(super) unit: f64,
    pub(super) profile_times: Vec<f64>,
    pub(super) end_time: f64,
    pub(super) raw: &'r RawOutput,
    pub(super) history_every: Option<usize>,
    pub(super) energy_every: Option<usize>,
}

impl<'r> Outputs<'r> {
    pub(super) fn read(src: &Source, raw: &'r RawOutput, transit: f64) -> Result<Self, SceneError> {
        let unit = match raw.time_unit {
            RawTimeUnit::Absolute => 1.0,
            RawTimeUnit::Transit => transit,
        };
        let profile_span = raw.profile_times.as_ref().map(|p| p.span());
        let given: Vec<f64> = raw
            .profile_times
            .as_ref()
            .map(|p| p.get_ref().clone())
            .unwrap_or_default();
        if let Some(bad) = given.iter().find(|t| !(t.is_finite() && **t >= 0.0)) {
            return Err(src.error(
                profile_span,
                "output.profile_times",
                format!("{bad} must be finite and not negative"),
            ));
        }
        let profile_times: Vec<f64> = given.iter().map(|t| t * unit).collect();
        let end_time = match &raw.end_time {
            Some(e) => positive(src, e, "output.end_time")? * unit,
            None => match profile_times.iter().copied().reduce(f64::max) {
                Some(t) if t > 0.0 => t,
                _ => {
                    return Err(src.error(
                        profile_span,
                        "output.end_time",
                        "is needed when no positive profile time is given",
                    ));
                }
            },
        };
        if let Some(&late) = profile_times
            .iter()
            .find(|&&t| t > end_time * (1.0 + 1e-12))
        {
            return Err(src.error(
                profile_span,
                "output.profile_times",
                format!(
                    "{} is after the end time {}; profile times must lie in [0, end_time]",
                    late / unit,
                    end_time / unit
                ),
            ));
        }
        // `None` means the default: every step up to MAX_SAMPLES steps, then thinned so that a
        // long run keeps about MAX_SAMPLES samples (decided per case, from its step count).
        let every = |v: &Option<Spanned<i64>>, key: &str| -> Result<Option<usize>, SceneError> {
            match v {
                None => Ok(None),
                Some(s) if *s.get_ref() >= 1 => Ok(Some(*s.get_ref() as usize)),
                Some(s) => Err(src.error(
                    Some(s.span()),
                    key,
                    format!("{} must be at least 1", s.get_ref()),
                )),
            }
        };
        Ok(Self {
            unit,
            profile_times,
            end_time,
            raw,
            history_every: every(&raw.history_every, "output.history_every")?,
            energy_every: every(&raw.energy_every, "output.energy_every")?,
        })
    }

    /// History points snapped to the nearest nodes of `model`.
    pub(super) fn history_nodes(
        &self,
        src: &Source,
        model: &Model,
    ) -> Result<Vec<usize>, SceneError> {
        let Some(points) = &self.raw.history_points else {
            return Ok(Vec::new());
        };
        let mesh = model.bar().mesh();
        let (start, length) = (mesh.start(), mesh.length());
        points
            .get_ref()
            .iter()
            .map(|&x| {
                if x.is_finite()
                    && x >= start - 1e-12 * length
                    && x <= start + length * (1.0 + 1e-12)
                {
                    Ok(mesh.nearest_node(x))
                } else {
                    Err(src.error(
                        Some(points.span()),
                        "output.history_points",
                        format!("{x} is outside the bar [0, {length}]"),
                    ))
                }
            })
            .collect()
    }
}
