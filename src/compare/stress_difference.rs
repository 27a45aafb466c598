//! How far two runs' stress profiles are apart: the metric `stress_difference` of an
//! expectation with `relative_to` (e.g. Park's scheme at theta = 0 against central difference,
//! which it must equal: methods.md §6).
//!
//! ```text
//!   stress_difference = max_k max_e |sigma_a,e(t_k) - sigma_b,e(t_k)|  /  max_k max_e |sigma_b,e(t_k)|
//! ```
//!
//! over the profile times `t_k` both runs recorded (matched to half a step), on the same
//! elements: relative to the peak of the case compared with, so a wave front's scale sets it.

/// One profile of a run: its time, element midpoints (or points) and stresses.
pub struct ProfileView<'a> {
    /// Output time.
    pub time: f64,
    /// Positions.
    pub x: &'a [f64],
    /// Stresses.
    pub stress: &'a [f64],
}

/// The difference of `a` from `b` (formula above), within `tolerance` of time for matching
/// profiles.
///
/// # Errors
/// Why it cannot be measured: no common profile time, another mesh, or a zero reference peak.
pub fn stress_difference(
    a: &[ProfileView<'_>],
    b: &[ProfileView<'_>],
    tolerance: f64,
) -> Result<f64, String> {
    let (mut worst, mut peak, mut common) = (0.0_f64, 0.0_f64, 0);
    for pa in a {
        let Some(pb) = b.iter().find(|pb| (pb.time - pa.time).abs() <= tolerance) else {
            continue;
        };
        if pa.x.len() != pb.x.len()
            || pa
                .x
                .iter()
                .zip(pb.x)
                .any(|(p, q)| (p - q).abs() > 1e-12 * (1.0 + q.abs()))
        {
            return Err(format!(
                "the profiles at t = {} are on different meshes ({} and {} values)",
                pa.time,
                pa.x.len(),
                pb.x.len()
            ));
        }
        common += 1;
        for (s, r) in pa.stress.iter().zip(pb.stress) {
            worst = worst.max((s - r).abs());
            peak = peak.max(r.abs());
        }
    }
    if common == 0 {
        return Err("no profile time in common".into());
    }
    if peak == 0.0 {
        return Err("the case compared with has no stress: no scale".into());
    }
    Ok(worst / peak)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_profiles_differ_by_zero_and_a_shifted_one_by_its_shift_over_the_peak() {
        let x = [0.25, 0.75];
        let a = [ProfileView {
            time: 1.0,
            x: &x,
            stress: &[-1.0, 0.0],
        }];
        let b = [ProfileView {
            time: 1.0,
            x: &x,
            stress: &[-2.0, 0.0],
        }];
        assert_eq!(stress_difference(&a, &a, 1e-9), Ok(0.0));
        assert_eq!(stress_difference(&a, &b, 1e-9), Ok(0.5));
        let later = [ProfileView {
            time: 2.0,
            x: &x,
            stress: &[-2.0, 0.0],
        }];
        assert!(stress_difference(&a, &later, 1e-9).is_err());
        let other_mesh = [ProfileView {
            time: 1.0,
            x: &[0.5],
            stress: &[1.0],
        }];
        assert!(
            stress_difference(&a, &other_mesh, 1e-9)
                .unwrap_err()
                .contains("meshes")
        );
    }
}
