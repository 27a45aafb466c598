//! The chart entry point: prepare the series, lay out the axes and the legend, draw.

use super::draw::{Ctx, render};
use super::layout::{legend_place, log_ticks};
use super::prepared::{axis_range, clean_text, prepare};
use super::series::{Axes, PlotError, Series};
use plotters::coord::combinators::BindKeyPoints;
use plotters::prelude::*;

/// Renders `series` on `axes` as a 640x400 SVG chart with title, axis labels and a legend.
///
/// Ranges come from the drawable points of all series, widened by a small margin. Colours come
/// from a fixed palette in series order, or the palette index a series names
/// ([`Series::with_colour`]). The result is well-formed XML (text is escaped) and is
/// byte-identical for identical input.
///
/// # Errors
/// [`PlotError::NoSeries`] for an empty `series`, [`PlotError::NoPlottableData`] when a series has
/// no finite point (no positive one on a log axis), [`PlotError::Drawing`] if the backend fails.
pub fn line_chart(axes: &Axes, series: &[Series]) -> Result<String, PlotError> {
    let title = clean_text(&axes.title);
    if series.is_empty() {
        return Err(PlotError::NoSeries { title });
    }
    let prepared = series
        .iter()
        .map(|s| prepare(axes, &title, s))
        .collect::<Result<Vec<_>, _>>()?;

    let all = || prepared.iter().flat_map(|p| p.segments.iter().flatten());
    let x_range = axis_range(all().map(|p| p.0), axes.log_x);
    let y_range = axis_range(all().map(|p| p.1), axes.log_y);

    let (legend, y_range) = legend_place(axes, &prepared, x_range, y_range);
    let ctx = Ctx {
        axes,
        title: &title,
        series: &prepared,
        x_span: x_range.1 - x_range.0,
        y_span: y_range.1 - y_range.0,
        legend,
    };
    let (x, y) = (x_range.0..x_range.1, y_range.0..y_range.1);
    let log = |r: std::ops::Range<f64>| {
        let (bold, light) = log_ticks(r.start, r.end);
        r.log_scale().with_key_points(bold).with_light_points(light)
    };
    match (axes.log_x, axes.log_y) {
        (false, false) => render(&ctx, x, y),
        (true, false) => render(&ctx, log(x), y),
        (false, true) => render(&ctx, x, log(y)),
        (true, true) => render(&ctx, log(x), log(y)),
    }
}
