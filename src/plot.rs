//! Deterministic SVG line charts for the report.
//!
//! Report contract: every plot is an SVG, needs no system fonts and is deterministic. Charts are
//! rendered with `plotters`' SVG backend into a `String` (this module writes no files): text
//! becomes SVG `<text>` elements, so no font is loaded, and the output carries no timestamps or
//! random ids, so the same input gives byte-identical SVG.
//!
//! ```
//! use courant::plot::{Axes, Series, SeriesStyle, line_chart};
//!
//! let axes = Axes::new("Stress at t = 1", "x", "stress").log_y(false);
//! let numerical = Series::new("numerical", vec![(0.0, 0.0), (0.5, 1.0), (1.0, 1.0)], SeriesStyle::Line);
//! let exact = Series::new("exact", vec![(0.0, 0.0), (0.5, 1.0), (1.0, 1.0)], SeriesStyle::Dashed);
//! let svg = line_chart(&axes, &[numerical, exact]).unwrap();
//! assert!(svg.starts_with("<svg"));
//! ```
//!
//! Points that cannot be drawn (non-finite, or non-positive on a log axis) are skipped; for
//! [`SeriesStyle::Line`] and [`SeriesStyle::Dashed`] they break the line into separate pieces.
//! A series with no drawable point at all is an error ([`PlotError::NoPlottableData`]).

use plotters::coord::combinators::BindKeyPoints;
use plotters::coord::ranged1d::{AsRangedCoord, Ranged, ValueFormatter};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use thiserror::Error;

/// Chart width in pixels.
pub const WIDTH: u32 = 640;
/// Chart height in pixels.
pub const HEIGHT: u32 = 400;

/// Number of colours of the palette (series beyond it repeat colours).
pub const PALETTE_SIZE: usize = 8;

/// The fixed colour palette; series take colours in order (cycling), so charts are deterministic.
/// Okabe–Ito colours (colour-blind safe), black first.
const PALETTE: [RGBColor; PALETTE_SIZE] = [
    RGBColor(0, 0, 0),
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(150, 150, 150),
];

/// Relative margin added on each side of the data range (fraction of the span, in decades on
/// log axes).
const MARGIN: f64 = 0.05;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesStyle {
    /// Solid line through the points, in the given order.
    Line,
    /// Dashed line through the points, in the given order (e.g. an exact solution).
    Dashed,
    /// Filled circles at the points, no line (e.g. measured errors).
    Points,
}

/// One named series of (x, y) points.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// Points, drawn in this order.
    pub points: Vec<(f64, f64)>,
    /// Line, dashed line or points.
    pub style: SeriesStyle,
    /// Palette index of its colour (taken modulo the palette's 8 colours); `None`: the series'
    /// position in the chart, so series take the colours in order.
    pub colour: Option<usize>,
    /// Whether the legend lists it (default true); e.g. several curves of one kind can share a
    /// single legend entry.
    pub in_legend: bool,
}

impl Series {
    /// A series named `name`.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>, style: SeriesStyle) -> Self {
        Self {
            name: name.into(),
            points,
            style,
            colour: None,
            in_legend: true,
        }
    }

    /// The same series drawn in palette colour `index` (modulo 8), e.g. to pair a computed curve
    /// with its closed form.
    #[must_use]
    pub fn with_colour(mut self, index: usize) -> Self {
        self.colour = Some(index);
        self
    }

    /// The same series without a legend entry.
    #[must_use]
    pub fn without_legend(mut self) -> Self {
        self.in_legend = false;
        self
    }
}

/// Title, axis labels and axis scales of a chart.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Axes {
    /// Chart caption.
    pub title: String,
    /// Label under the x axis.
    pub x_label: String,
    /// Label beside the y axis.
    pub y_label: String,
    /// Logarithmic x axis (non-positive x values are skipped).
    pub log_x: bool,
    /// Logarithmic y axis (non-positive y values are skipped).
    pub log_y: bool,
}

impl Axes {
    /// Linear axes with the given title and labels.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            log_x: false,
            log_y: false,
        }
    }

    /// Sets whether the x axis is logarithmic.
    #[must_use]
    pub fn log_x(mut self, log: bool) -> Self {
        self.log_x = log;
        self
    }

    /// Sets whether the y axis is logarithmic.
    #[must_use]
    pub fn log_y(mut self, log: bool) -> Self {
        self.log_y = log;
        self
    }

    /// Log-log axes with the given title and labels (e.g. a convergence plot).
    pub fn log_log(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self::new(title, x_label, y_label).log_x(true).log_y(true)
    }
}

/// Why a chart could not be drawn.
#[derive(Debug, Error, PartialEq, Eq)]
pub enum PlotError {
    /// No series were given.
    #[error("chart `{title}`: no series to plot")]
    NoSeries {
        /// The chart title.
        title: String,
    },
    /// A series has no point that can be drawn.
    #[error("chart `{title}`: series `{series}` has no plottable point ({reason})")]
    NoPlottableData {
        /// The chart title.
        title: String,
        /// The series name.
        series: String,
        /// Why every point was rejected.
        reason: String,
    },
    /// The plotting backend failed.
    #[error("chart `{title}`: drawing failed: {message}")]
    Drawing {
        /// The chart title.
        title: String,
        /// The backend's message.
        message: String,
    },
}

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

/// Labelled (bold) and unlabelled (light) grid values of a log axis on `lo..hi`: whole decades
/// when the range holds at least four of them, otherwise 1-2-5 (or 1..9) multiples of decades.
fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let (d0, d1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let inside = |v: &f64| *v >= lo * (1.0 - 1e-12) && *v <= hi * (1.0 + 1e-12);
    let multiples = |ms: &[f64]| -> Vec<f64> {
        (d0..=d1)
            .flat_map(|d| ms.iter().map(move |m| m * 10f64.powi(d)))
            .filter(inside)
            .collect()
    };
    let decades = multiples(&[1.0]);
    if decades.len() >= 4 {
        let step = decades.len().div_ceil(8);
        let bold: Vec<f64> = decades.iter().copied().step_by(step).collect();
        let light = if decades.len() <= 8 {
            multiples(&[2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0])
        } else {
            Vec::new()
        };
        return (bold, light);
    }
    let one_two_five = multiples(&[1.0, 2.0, 5.0]);
    let all = multiples(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
    if one_two_five.len() >= 3 {
        let light = all
            .into_iter()
            .filter(|v| !one_two_five.contains(v))
            .collect();
        (one_two_five, light)
    } else if all.len() >= 2 {
        (all, Vec::new())
    } else {
        // Less than a factor of two: fall back to the range ends.
        (vec![lo, hi], Vec::new())
    }
}

/// Font size of a chart title: 20 px, smaller for long titles so the whole title fits the
/// 640 px chart (about 0.55 em per character of a sans-serif face), never below 11 px.
fn title_font_size(title: &str) -> u32 {
    let chars = title.chars().count().max(1) as f64;
    (600.0 / (0.55 * chars)).floor().clamp(11.0, 20.0) as u32
}

/// Approximate size of the plotting area in pixels (the 640x400 chart less title, labels and
/// margins), for the legend box estimate.
const PLOT_AREA_PX: (f64, f64) = (560.0, 300.0);

/// Where the legend goes, and the y range to draw: the corner whose legend box holds the fewest
/// data points (lines sampled between their points; ties go to upper right, upper left, lower
/// right, lower left in that order). The box is estimated from the legend's entries (20 px each)
/// and its longest label (7 px per character plus the sample). When every corner would cover
/// data, the y range is extended downwards (by the box height, in the axis' own scale) so the
/// legend sits in the lower right over empty space instead of over a curve.
fn legend_place(
    axes: &Axes,
    series: &[Prepared],
    x_range: (f64, f64),
    y_range: (f64, f64),
) -> (SeriesLabelPosition, (f64, f64)) {
    let entries: Vec<&Prepared> = series.iter().filter(|s| s.in_legend).collect();
    let longest = entries
        .iter()
        .map(|s| s.name.chars().count())
        .max()
        .unwrap_or(0);
    let box_w = ((longest as f64 * 7.0 + 50.0) / PLOT_AREA_PX.0).clamp(0.2, 0.95);
    let box_h = ((entries.len() as f64 * 20.0 + 12.0) / PLOT_AREA_PX.1).clamp(0.1, 0.9);
    let counts = corner_counts(axes, series, x_range, y_range, box_w, box_h);
    let corners = [
        SeriesLabelPosition::UpperRight,
        SeriesLabelPosition::UpperLeft,
        SeriesLabelPosition::LowerRight,
        SeriesLabelPosition::LowerLeft,
    ];
    let best = (0..4).min_by_key(|&i| counts[i]).unwrap_or(0);
    if counts[best] == 0 || entries.is_empty() || box_h >= 0.6 {
        return (corners[best].clone(), y_range);
    }
    // Data fills [0, 1] of the axis; give the legend the band [0, box_h] below it.
    let grow = box_h / (1.0 - box_h);
    let lower = if axes.log_y {
        let (lo, hi) = (y_range.0.log10(), y_range.1.log10());
        10f64.powf(lo - (hi - lo) * grow)
    } else {
        y_range.0 - (y_range.1 - y_range.0) * grow
    };
    (SeriesLabelPosition::LowerRight, (lower, y_range.1))
}

/// Data points (lines sampled between their points) inside a `box_w x box_h` box (fractions of
/// the plotting area) at each corner: upper right, upper left, lower right, lower left.
fn corner_counts(
    axes: &Axes,
    series: &[Prepared],
    x_range: (f64, f64),
    y_range: (f64, f64),
    box_w: f64,
    box_h: f64,
) -> [usize; 4] {
    let unit = |v: f64, (lo, hi): (f64, f64), log: bool| {
        if log {
            (v.log10() - lo.log10()) / (hi.log10() - lo.log10())
        } else {
            (v - lo) / (hi - lo)
        }
    };
    let to_unit =
        |&(x, y): &(f64, f64)| (unit(x, x_range, axes.log_x), unit(y, y_range, axes.log_y));
    let mut counts = [0usize; 4];
    let mut count = |(u, v): (f64, f64)| {
        let right = u > 1.0 - box_w;
        let left = u < box_w;
        let upper = v > 1.0 - box_h;
        let lower = v < box_h;
        for (i, hit) in [upper && right, upper && left, lower && right, lower && left]
            .into_iter()
            .enumerate()
        {
            counts[i] += usize::from(hit);
        }
    };
    for s in series {
        for seg in &s.segments {
            let pts: Vec<(f64, f64)> = seg.iter().map(to_unit).collect();
            pts.iter().copied().for_each(&mut count);
            if s.style != SeriesStyle::Points {
                for w in pts.windows(2) {
                    for k in 1..16 {
                        let t = f64::from(k) / 16.0;
                        count((
                            w[0].0 + t * (w[1].0 - w[0].0),
                            w[0].1 + t * (w[1].1 - w[0].1),
                        ));
                    }
                }
            }
        }
    }
    counts
}

/// A series reduced to its drawable pieces.
struct Prepared {
    name: String,
    style: SeriesStyle,
    colour: Option<usize>,
    in_legend: bool,
    /// Maximal runs of consecutive drawable points.
    segments: Vec<Vec<(f64, f64)>>,
}

struct Ctx<'a> {
    axes: &'a Axes,
    title: &'a str,
    series: &'a [Prepared],
    x_span: f64,
    y_span: f64,
    legend: SeriesLabelPosition,
}

fn prepare(axes: &Axes, title: &str, s: &Series) -> Result<Prepared, PlotError> {
    let drawable = |&(x, y): &(f64, f64)| {
        x.is_finite() && y.is_finite() && (!axes.log_x || x > 0.0) && (!axes.log_y || y > 0.0)
    };
    let mut segments = Vec::new();
    let mut current = Vec::new();
    for p in &s.points {
        if drawable(p) {
            current.push(*p);
        } else if !current.is_empty() {
            segments.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        segments.push(current);
    }
    if segments.is_empty() {
        let reason = if s.points.is_empty() {
            "it has no points".to_owned()
        } else {
            let mut why = format!("all {} points are non-finite", s.points.len());
            match (axes.log_x, axes.log_y) {
                (true, true) => why.push_str(" or have x <= 0 or y <= 0 on log axes"),
                (true, false) => why.push_str(" or have x <= 0 on a log x axis"),
                (false, true) => why.push_str(" or have y <= 0 on a log y axis"),
                (false, false) => {}
            }
            why
        };
        return Err(PlotError::NoPlottableData {
            title: title.to_owned(),
            series: s.name.clone(),
            reason,
        });
    }
    Ok(Prepared {
        name: clean_text(&s.name),
        style: s.style,
        colour: s.colour,
        in_legend: s.in_legend,
        segments,
    })
}

/// The axis range covering `values` (all drawable, at least one) plus a margin.
fn axis_range(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values {
        let v = if log { v.log10() } else { v };
        lo = lo.min(v);
        hi = hi.max(v);
    }
    let span = hi - lo;
    let pad = if span > 0.0 && span.is_finite() {
        span * MARGIN
    } else if log {
        0.5 // half a decade around a single value
    } else if lo == 0.0 {
        1.0
    } else {
        0.1 * lo.abs()
    };
    let (lo, hi) = (lo - pad, hi + pad);
    if log {
        (10f64.powf(lo), 10f64.powf(hi))
    } else {
        (lo, hi)
    }
}

fn render<X, Y>(ctx: &Ctx<'_>, x: X, y: Y) -> Result<String, PlotError>
where
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y::CoordDescType: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let mut svg = String::new();
    draw(ctx, x, y, &mut svg).map_err(|message| PlotError::Drawing {
        title: ctx.title.to_owned(),
        message,
    })?;
    Ok(svg)
}

fn draw<X, Y>(ctx: &Ctx<'_>, x: X, y: Y, svg: &mut String) -> Result<(), String>
where
    X: AsRangedCoord<Value = f64>,
    Y: AsRangedCoord<Value = f64>,
    X::CoordDescType: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y::CoordDescType: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let e = |err: &dyn std::fmt::Display| err.to_string();
    let root = SVGBackend::with_string(svg, (WIDTH, HEIGHT)).into_drawing_area();
    root.fill(&WHITE).map_err(|err| e(&err))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(ctx.title, ("sans-serif", title_font_size(ctx.title)))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(64)
        .build_cartesian_2d(x, y)
        .map_err(|err| e(&err))?;

    let x_fmt = tick_formatter(ctx.axes.log_x, ctx.x_span);
    let y_fmt = tick_formatter(ctx.axes.log_y, ctx.y_span);
    chart
        .configure_mesh()
        .x_desc(clean_text(&ctx.axes.x_label))
        .y_desc(clean_text(&ctx.axes.y_label))
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(|err| e(&err))?;

    for (i, s) in ctx.series.iter().enumerate() {
        let color = PALETTE[s.colour.unwrap_or(i) % PALETTE.len()];
        let line = ShapeStyle::from(color).stroke_width(2);
        let anno = match s.style {
            SeriesStyle::Line => chart
                .draw_series(
                    s.segments
                        .iter()
                        .map(|seg| PathElement::new(seg.clone(), line)),
                )
                .map_err(|err| e(&err))?,
            SeriesStyle::Dashed => chart
                .draw_series(
                    s.segments
                        .iter()
                        .map(|seg| DashedPathElement::new(seg.clone(), 8, 5, line)),
                )
                .map_err(|err| e(&err))?,
            SeriesStyle::Points => chart
                .draw_series(
                    s.segments
                        .iter()
                        .flatten()
                        .map(|&p| Circle::new(p, 3, color.filled())),
                )
                .map_err(|err| e(&err))?,
        };
        if !s.in_legend {
            continue;
        }
        let style = s.style;
        anno.label(s.name.as_str())
            .legend(move |(lx, ly)| match style {
                SeriesStyle::Line => {
                    PathElement::new(vec![(lx, ly), (lx + 20, ly)], line).into_dyn()
                }
                SeriesStyle::Dashed => {
                    DashedPathElement::new(vec![(lx, ly), (lx + 20, ly)], 6, 3, line).into_dyn()
                }
                SeriesStyle::Points => Circle::new((lx + 10, ly), 3, color.filled()).into_dyn(),
            });
    }

    chart
        .configure_series_labels()
        .position(ctx.legend.clone())
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|err| e(&err))?;
    root.present().map_err(|err| e(&err))?;
    Ok(())
}

/// Tick labels: plain decimals for moderate magnitudes, `1e-5` style otherwise; on linear axes
/// values within rounding noise of zero print as `0`.
fn tick_formatter(log: bool, span: f64) -> impl Fn(&f64) -> String {
    let zero_tol = if log { 0.0 } else { span.abs() * 1e-9 };
    move |&v: &f64| {
        if v == 0.0 || v.abs() <= zero_tol {
            return "0".to_owned();
        }
        let a = v.abs();
        if !(1e-3..1e4).contains(&a) {
            let s = format!("{v:.2e}");
            let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
            format!("{}e{exp}", trim_zeros(mantissa))
        } else {
            let decimals = (3 - a.log10().floor() as i32).clamp(0, 6) as usize;
            trim_zeros(&format!("{v:.decimals$}")).to_owned()
        }
    }
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

/// Replaces characters that XML 1.0 forbids (control characters other than tab, newline and
/// carriage return) by spaces; `plotters` escapes `<`, `>`, `&` and quotes itself.
fn clean_text(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_control() && !matches!(c, '\t' | '\n' | '\r') {
                ' '
            } else {
                c
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_have_margins_and_handle_single_values() {
        let (lo, hi) = axis_range([0.0, 1.0].into_iter(), false);
        assert!(lo < 0.0 && hi > 1.0);
        let (lo, hi) = axis_range([2.0].into_iter(), false);
        assert!(lo < 2.0 && hi > 2.0);
        let (lo, hi) = axis_range([1e-3, 1e-1].into_iter(), true);
        assert!(lo < 1e-3 && hi > 1e-1 && lo > 0.0);
        let (lo, hi) = axis_range([5.0].into_iter(), true);
        assert!(lo < 5.0 && hi > 5.0 && lo > 0.0);
    }

    #[test]
    fn log_ticks_use_decades_or_one_two_five() {
        let (bold, light) = log_ticks(4e-5, 2.5e-1);
        assert_eq!(bold.len(), 4); // 1e-4 .. 1e-1
        assert!(light.len() > 8);
        let (bold, _) = log_ticks(4e-4, 2.5e-2);
        assert_eq!(bold.len(), 6); // 5e-4, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2
        let (bold, _) = log_ticks(21.0, 950.0);
        assert_eq!(bold, vec![50.0, 100.0, 200.0, 500.0]);
        let (bold, _) = log_ticks(1e-12, 1e6);
        assert!(bold.len() <= 9, "{bold:?}");
        let (bold, _) = log_ticks(3.0, 3.5);
        assert_eq!(bold, vec![3.0, 3.5]);
    }

    #[test]
    fn tick_labels_are_short() {
        let f = tick_formatter(false, 1.0);
        assert_eq!(f(&0.5), "0.5");
        assert_eq!(f(&1e-12), "0");
        assert_eq!(f(&2.0), "2");
        let g = tick_formatter(true, 1.0);
        assert_eq!(g(&1e-5), "1e-5");
        assert_eq!(g(&100.0), "100");
        assert_eq!(g(&2.5e6), "2.5e6");
    }

    /// Short titles keep 20 px; a 78-character title shrinks to fit 600 px at 0.55 em per
    /// character; nothing goes below 11 px.
    #[test]
    fn long_titles_shrink_to_fit() {
        assert_eq!(title_font_size("fig1: stress at t = 0.5"), 20);
        let long = "Fig. 2 graded bar on equal-transit-time meshes, lumped CD at Co = 1, t = 0.5 T";
        let size = title_font_size(long);
        assert_eq!(size, 13);
        assert!(f64::from(size) * 0.55 * long.chars().count() as f64 <= 600.0);
        assert_eq!(title_font_size(&"x".repeat(500)), 11);
    }
}
