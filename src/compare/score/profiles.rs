//! Stress profiles of a file beside the exact solution, on the file's own elements or points and
//! at its own times, with the norms of `courant run` ([`ErrorNorms`]) and the diagnostics.

use super::bind::{Bound, bar_extent};
use super::diagnostics::{Diagnostics, Layout, LayoutCheck, Magnitude, SignCheck};
use super::outcome::{Read, ScoreError, Scored, ScoredCase, ScoredProfile};
use super::shift_fit::{FitProfile, fit_profiles};
use super::time_level::TimeShift;
use crate::compare::exact::ExactOnMesh;
use crate::compare::norms::ErrorNorms;
use crate::results::exchange::error::ExchangeError;
use crate::results::exchange::reader::TOUCH;
use crate::results::exchange::record::{Positions, Profile};
use crate::scene::cases::Case;
use crate::scene::reference::Reference;
use courant_solver::Mesh;

/// A layout other than the format's is read when its L1 error is below this fraction of the
/// error as given (a Co = 1 checkerboard behind the front leaves half the error of the file
/// mirrored: 0.5 against 1.0).
const LAYOUT_MARGIN: f64 = 2.0 / 3.0;

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

    /// The cells the values stand for, as a mesh on the bar: the elements, or from the bar's
    /// start through the midpoints between points to its end.
    fn cells(&self, (start, end): (f64, f64)) -> Result<Mesh, String> {
        match self {
            Grid::Mesh(m) => Ok(m.clone()),
            Grid::Points { x, .. } => {
                let mut nodes = vec![start];
                nodes.extend(x.windows(2).map(|w| start + 0.5 * (w[0] + w[1])));
                nodes.push(end);
                Mesh::from_nodes(nodes).map_err(|e| e.to_string())
            }
        }
    }

    /// The exact values at the mirrored positions (`x -> start + end - x`), in the grid's order.
    fn mirrored_exact(&self, reference: &Reference, t: f64, extent: (f64, f64)) -> Vec<f64> {
        let mut values = match self {
            Grid::Mesh(m) => match mirror_mesh(m, extent) {
                Ok(mirrored) => reference.element_averages(&mirrored, t),
                Err(_) => return vec![f64::NAN; m.element_count()],
            },
            Grid::Points { x, .. } => {
                let length = extent.1 - extent.0;
                let mirrored: Vec<f64> = x.iter().rev().map(|x| length - x).collect();
                reference.point_values(&mirrored, t)
            }
        };
        values.reverse();
        values
    }

    /// Exact nodal averages at the points, when they are the nodes of a mesh of the bar (the
    /// first at its start, the last at its end): the mean of the exact element averages on
    /// either side, the one beside it at an end.
    fn nodal_average_exact(
        &self,
        reference: &Reference,
        t: f64,
        (start, end): (f64, f64),
    ) -> Option<Vec<f64>> {
        let Grid::Points { x, .. } = self else {
            return None;
        };
        let length = end - start;
        let tol = TOUCH * length;
        if x.len() < 2 || x[0] > tol || (x[x.len() - 1] - length).abs() > tol {
            return None;
        }
        let mut nodes: Vec<f64> = x.iter().map(|x| start + x).collect();
        let last = nodes.len() - 1;
        nodes[0] = start;
        nodes[last] = end;
        let mesh = Mesh::from_nodes(nodes).ok()?;
        let a = reference.element_averages(&mesh, t);
        let n = a.len();
        Some(
            (0..=n)
                .map(|i| match i {
                    0 => a[0],
                    i if i == n => a[n - 1],
                    i => 0.5 * (a[i - 1] + a[i]),
                })
                .collect(),
        )
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

/// Score the profiles of a time-stepping file against the case's reference: the norms of
/// `courant run` on the file as given, and the diagnostics (`super::diagnostics`): magnitude,
/// sign and layout from the file's L1 errors against the reference read each way, then the time
/// shift fitted on the file as the reference's sign and layout would have it.
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
    let mut grids = Vec::new();
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
        scored.push(ScoredProfile {
            time: p.time,
            x: grid.centres(),
            stress: p.stress.clone(),
            reference: exact,
            norms,
        });
        grids.push(grid);
    }
    let diagnostics = diagnose(bound, reference, extent, profiles, &grids, &scored);
    let elements = match profiles.first().map(|p| &p.positions) {
        Some(positions @ Positions::Elements { .. }) => Some(positions.len()),
        _ => bound.meta.and_then(|m| m.elements).map(|e| e.0),
    };
    Ok(ScoredCase {
        case: bound.file.case.clone(),
        file: bound.file.file.clone(),
        scheme: bound.meta.and_then(|m| m.scheme.clone()),
        applies: bound.applies.clone(),
        mass: bound.mass.map(|m| m.label()),
        elements,
        read: Read {
            values: profiles.iter().map(|p| p.stress.len()).max().unwrap_or(0),
            times: profiles.len(),
            rows: profiles.iter().map(|p| p.stress.len()).sum(),
        },
        dt: bound.dt,
        reference: reference.name(),
        scored: Scored::Profiles {
            profiles: scored,
            points,
        },
        diagnostics,
    })
}

/// The diagnostics of a file's profiles (`grids` their grids, `scored` their exact values).
fn diagnose(
    bound: &Bound,
    reference: &Reference,
    extent: (f64, f64),
    profiles: &[Profile],
    grids: &[Grid],
    scored: &[ScoredProfile],
) -> Diagnostics {
    let scale = reference.stress_scale();
    let max = profiles
        .iter()
        .flat_map(|p| p.stress.iter())
        .fold(0.0_f64, |m, s| m.max(s.abs()));
    let magnitude = Magnitude { max, scale };
    if magnitude.diverged() {
        let why = "not measured: the code diverged (see magnitude)".to_string();
        return Diagnostics {
            magnitude: Ok(magnitude),
            shift: Err(why.clone()),
            sign: Err(why.clone()),
            layout: Err(why),
        };
    }
    // L1 errors (normalised as the norms are: by L, |sigma0| and the profile count) of the
    // file read each way: [given, mirrored, nodal averages] x [as signed, negated].
    let norm = (extent.1 - extent.0) * scale * profiles.len().max(1) as f64;
    let mut errors = [[0.0; 2]; 3];
    let mut nodal_possible = true;
    for ((p, grid), s) in profiles.iter().zip(grids).zip(scored) {
        let weights = grid.weights();
        let mirrored = grid.mirrored_exact(reference, p.time, extent);
        let nodal = grid.nodal_average_exact(reference, p.time, extent);
        nodal_possible &= nodal.is_some();
        let nodal = nodal.unwrap_or_else(|| s.reference.clone());
        for (layout, exact) in [&s.reference, &mirrored, &nodal].into_iter().enumerate() {
            for (i, w) in weights.iter().enumerate() {
                errors[layout][0] += w * (p.stress[i] - exact[i]).abs();
                errors[layout][1] += w * (-p.stress[i] - exact[i]).abs();
            }
        }
    }
    let errors = errors.map(|e| e.map(|x| x / norm));
    let candidates: &[usize] = if nodal_possible { &[0, 1, 2] } else { &[0, 1] };
    let (best_layout, best_sign) = candidates
        .iter()
        .flat_map(|&l| [(l, 0), (l, 1)])
        .min_by(|a, b| errors[a.0][a.1].total_cmp(&errors[b.0][b.1]))
        .unwrap_or((0, 0));
    let sign_check = SignCheck {
        error: errors[best_layout][0],
        error_flipped: errors[best_layout][1],
    };
    let given = errors[0][best_sign];
    let layout = if best_layout != 0 && errors[best_layout][best_sign] < LAYOUT_MARGIN * given {
        [Layout::AsGiven, Layout::Mirrored, Layout::NodalAverages][best_layout]
    } else {
        Layout::AsGiven
    };
    let layout_check = LayoutCheck {
        layout,
        error: given,
        error_read: if layout == Layout::AsGiven {
            given
        } else {
            errors[best_layout][best_sign]
        },
    };
    // The shift is fitted on the file as the reference's sign and layout would have it.
    let factor = if sign_check.matches() == Some(false) {
        -1.0
    } else {
        1.0
    };
    let shift = match bound.dt {
        None => Err("not measurable: no dt".to_string()),
        Some((dt, _)) => fit_shift_of(reference, extent, profiles, grids, factor, layout, dt),
    };
    Diagnostics {
        magnitude: Ok(magnitude),
        shift,
        sign: Ok(sign_check),
        layout: Ok(layout_check),
    }
}

/// The time shift of the profiles on their cells (`shift_fit`), the values multiplied by
/// `factor` and, for a mirrored file, put back where they belong.
fn fit_shift_of(
    reference: &Reference,
    extent: (f64, f64),
    profiles: &[Profile],
    grids: &[Grid],
    factor: f64,
    layout: Layout,
    dt: f64,
) -> Result<TimeShift, String> {
    let mut cells = Vec::new();
    let mut values = Vec::new();
    for (p, grid) in profiles.iter().zip(grids) {
        let mut v: Vec<f64> = p.stress.iter().map(|s| factor * s).collect();
        let mut mesh = grid.cells(extent)?;
        if layout == Layout::Mirrored {
            v.reverse();
            mesh = mirror_mesh(&mesh, extent)?;
        }
        cells.push(mesh);
        values.push(v);
    }
    let fit: Vec<FitProfile<'_>> = profiles
        .iter()
        .zip(&cells)
        .zip(&values)
        .map(|((p, mesh), v)| FitProfile {
            time: p.time,
            weights: (0..mesh.element_count())
                .map(|e| mesh.element_length(e))
                .collect(),
            values: v,
        })
        .collect();
    let exact = |i: usize, t: f64| reference.element_averages(&cells[i], t);
    match fit_profiles(&fit, dt, &exact) {
        Some((steps, residual)) => Ok(TimeShift {
            steps,
            residual,
            profiles: fit.len(),
            spread: spread(&fit, dt, &exact),
        }),
        None => Err(
            "not measurable: the exact solution does not change over a step at these times".into(),
        ),
    }
}

/// The largest difference between the shifts of single profiles (0 for one profile, or when
/// a profile alone does not fix one).
fn spread(fit: &[FitProfile<'_>], dt: f64, exact: &dyn Fn(usize, f64) -> Vec<f64>) -> f64 {
    let shifts: Vec<f64> = (0..fit.len())
        .filter_map(|i| {
            let one = [FitProfile {
                time: fit[i].time,
                weights: fit[i].weights.clone(),
                values: fit[i].values,
            }];
            fit_profiles(&one, dt, &|_, t| exact(i, t)).map(|(s, _)| s)
        })
        .collect();
    let (lo, hi) = shifts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &s| {
            (lo.min(s), hi.max(s))
        });
    if shifts.len() < 2 { 0.0 } else { hi - lo }
}

/// The mesh `x -> start + end - x`, its elements in increasing order.
fn mirror_mesh(mesh: &Mesh, (start, end): (f64, f64)) -> Result<Mesh, String> {
    let nodes: Vec<f64> = mesh
        .nodes()
        .iter()
        .rev()
        .map(|x| (start + end - x).clamp(start, end))
        .collect();
    Mesh::from_nodes(nodes).map_err(|e| e.to_string())
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
