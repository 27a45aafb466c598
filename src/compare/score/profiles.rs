//! Stress profiles of a file beside the exact solution, on the file's own elements or points and
//! at its own times, with the norms of `courant run` ([`ErrorNorms`]) and the diagnostics.

use super::bind::{Bound, bar_extent};
use super::diagnostics::{Diagnostics, SignCheck, combine, fit_shift, integral_from_end};
use super::outcome::{ScoreError, Scored, ScoredCase, ScoredProfile};
use crate::compare::exact::ExactSolution;
use crate::compare::norms::ErrorNorms;
use crate::results::exchange::error::ExchangeError;
use crate::results::exchange::record::{Positions, Profile};
use crate::scene::cases::Case;
use crate::scene::reference::Reference;
use courant_solver::Mesh;

/// Where a profile's exact values are evaluated: a mesh (element averages) or points, with the
/// weight of each value in the norms.
enum Grid {
    Mesh(Mesh),
    Points {
        /// Positions from the bar's start.
        x: Vec<f64>,
        /// Cell lengths.
        weights: Vec<f64>,
    },
}

impl Grid {
    /// The grid of a profile on the bar `[start, end]`: element ends as nodes (the first and
    /// last snapped onto the bar's ends, which they match within the reader's tolerance), or the
    /// points with their cells.
    fn of(positions: &Positions, (start, end): (f64, f64)) -> Result<Grid, String> {
        match positions {
            Positions::Elements { left, right } => {
                let mut nodes = left.clone();
                nodes.push(right[right.len() - 1]);
                let last = nodes.len() - 1;
                nodes[0] = start;
                nodes[last] = end;
                Mesh::from_nodes(nodes)
                    .map(Grid::Mesh)
                    .map_err(|e| e.to_string())
            }
            Positions::Points(x) => Ok(Grid::Points {
                x: x.iter()
                    .map(|&x| (x - start).clamp(0.0, end - start))
                    .collect(),
                weights: cell_lengths(x, start, end),
            }),
        }
    }

    fn weights(&self) -> Vec<f64> {
        match self {
            Grid::Mesh(m) => (0..m.element_count())
                .map(|e| m.element_length(e))
                .collect(),
            Grid::Points { weights, .. } => weights.clone(),
        }
    }

    fn centres(&self) -> Vec<f64> {
        match self {
            Grid::Mesh(m) => (0..m.element_count()).map(|e| m.midpoint(e)).collect(),
            Grid::Points { x, .. } => x.clone(),
        }
    }

    fn exact(&self, reference: &Reference, t: f64) -> Vec<f64> {
        match self {
            Grid::Mesh(m) => reference.element_averages(m, t),
            Grid::Points { x, .. } => reference.point_values(x, t),
        }
    }
}

/// Exact element averages or point values at time `t` of a profile's positions on the bar
/// `extent`.
///
/// # Errors
/// A mesh the solver's `Mesh` refuses.
pub fn exact_values(
    positions: &Positions,
    extent: (f64, f64),
    reference: &Reference,
    t: f64,
) -> Result<Vec<f64>, String> {
    Grid::of(positions, extent).map(|g| g.exact(reference, t))
}

/// The cell of each point: from the midpoint with its left neighbour (or `start`) to the
/// midpoint with its right neighbour (or `end`); the trapezoid rule's weights when the points
/// include both ends. They sum to `end - start`.
pub fn cell_lengths(x: &[f64], start: f64, end: f64) -> Vec<f64> {
    let n = x.len();
    (0..n)
        .map(|i| {
            let lo = if i == 0 {
                start
            } else {
                0.5 * (x[i - 1] + x[i])
            };
            let hi = if i + 1 == n {
                end
            } else {
                0.5 * (x[i] + x[i + 1])
            };
            hi - lo
        })
        .collect()
}

/// Score the profiles of a time-stepping file against the case's reference.
///
/// # Errors
/// A mesh the solver's `Mesh` refuses (e.g. more than 10^7 elements), named by file and line.
pub fn score_profiles(
    bound: &Bound,
    case: &Case,
    reference: &Reference,
    profiles: &[Profile],
) -> Result<ScoredCase, ScoreError> {
    let extent = bar_extent(case);
    let (scale, sign) = (reference.stress_scale(), reference.load_sign());
    let points = matches!(
        profiles.first().map(|p| &p.positions),
        Some(Positions::Points(_))
    );
    let mut scored = Vec::new();
    let (mut error, mut error_flipped) = (0.0, 0.0);
    let mut fits = Vec::new();
    for p in profiles {
        let grid = Grid::of(&p.positions, extent).map_err(|why| {
            ExchangeError::at(
                &bound.file.file,
                p.lines.first().copied().unwrap_or(0),
                1,
                "",
                why,
            )
        })?;
        let exact = grid.exact(reference, p.time);
        let extreme = reference.extreme(p.time);
        let norms = match &grid {
            Grid::Mesh(mesh) => ErrorNorms::of(mesh, &p.stress, &exact, extreme, scale, sign),
            Grid::Points { weights, .. } => ErrorNorms::weighted(
                weights,
                extent.1 - extent.0,
                &p.stress,
                &exact,
                extreme,
                scale,
                sign,
            ),
        };
        let weights = grid.weights();
        let centres = grid.centres();
        for ((w, s), e) in weights.iter().zip(&p.stress).zip(&exact) {
            error += w * (s - e).abs();
            error_flipped += w * (-s - e).abs();
        }
        if let Some((dt, _)) = bound.dt {
            fits.push((grid, p, exact.clone(), weights, dt));
        }
        scored.push(ScoredProfile {
            time: p.time,
            x: centres,
            stress: p.stress.clone(),
            reference: exact,
            norms,
        });
    }
    // Mean normalised L1 errors, as the norms normalise: by L, |sigma0| and the profile count.
    let norm = (extent.1 - extent.0) * scale * profiles.len().max(1) as f64;
    let sign_check = SignCheck {
        error: error / norm,
        error_flipped: error_flipped / norm,
    };
    // The shift is fitted on the file as the reference's sign would have it.
    let factor = if sign_check.matches() == Some(false) {
        -1.0
    } else {
        1.0
    };
    let fitted: Vec<(f64, f64)> = fits
        .iter()
        .filter_map(|(grid, p, exact, weights, dt)| {
            let integral = |v: &[f64]| integral_from_end(weights, v);
            let file: Vec<f64> = p.stress.iter().map(|s| factor * s).collect();
            let now = integral(exact);
            let later = integral(&grid.exact(reference, p.time + dt));
            let (d, e): (Vec<f64>, Vec<f64>) = if p.time >= *dt {
                let earlier = integral(&grid.exact(reference, p.time - dt));
                later
                    .iter()
                    .zip(&earlier)
                    .map(|(a, b)| 0.5 * (a - b))
                    .zip(integral(&file).iter().zip(&now).map(|(f, x)| f - x))
                    .unzip()
            } else {
                later
                    .iter()
                    .zip(&now)
                    .map(|(a, b)| a - b)
                    .zip(integral(&file).iter().zip(&now).map(|(f, x)| f - x))
                    .unzip()
            };
            fit_shift(weights, &e, &d)
        })
        .collect();
    let (shift, load) = if bound.dt.is_some() {
        combine(&fitted)
    } else {
        let why = "not measurable: no dt".to_string();
        (Err(why.clone()), Err(why))
    };
    let elements = match profiles.first().map(|p| &p.positions) {
        Some(positions @ Positions::Elements { .. }) => Some(positions.len()),
        _ => bound.meta.and_then(|m| m.elements).map(|e| e.0),
    };
    Ok(ScoredCase {
        case: bound.file.case.clone(),
        file: bound.file.file.clone(),
        scheme: bound.meta.and_then(|m| m.scheme.clone()),
        mass: bound.mass.map(|m| m.label()),
        elements,
        dt: bound.dt,
        reference: reference.name(),
        scored: Scored::Profiles {
            profiles: scored,
            points,
        },
        diagnostics: Diagnostics {
            shift,
            sign: Ok(sign_check),
            load,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_are_the_trapezoid_rule_on_points_that_include_the_ends() {
        assert_eq!(
            cell_lengths(&[0.0, 0.5, 1.0], 0.0, 1.0),
            vec![0.25, 0.5, 0.25]
        );
        let mid = cell_lengths(&[0.25, 0.75], 0.0, 1.0);
        assert_eq!(mid, vec![0.5, 0.5], "midpoints' cells reach the ends");
    }
}
