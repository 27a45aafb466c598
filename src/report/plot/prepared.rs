//! Series reduced to what can be drawn: runs of drawable points, axis ranges with margins,
//! XML-safe text.

use super::series::{Axes, PlotError, Series, SeriesStyle};

/// Relative margin added on each side of the data range (fraction of the span, in decades on
/// log axes).
const MARGIN: f64 = 0.05;

/// A series reduced to its drawable pieces.
pub struct Prepared {
    pub name: String,
    pub style: SeriesStyle,
    pub colour: Option<usize>,
    pub in_legend: bool,
    /// Maximal runs of consecutive drawable points.
    pub segments: Vec<Vec<(f64, f64)>>,
}

/// A series reduced to its drawable pieces, or why it has none.
pub fn prepare(axes: &Axes, title: &str, s: &Series) -> Result<Prepared, PlotError> {
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
pub fn axis_range(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
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

/// Replaces characters that XML 1.0 forbids (control characters other than tab, newline and
/// carriage return) by spaces; `plotters` escapes `<`, `>`, `&` and quotes itself.
pub fn clean_text(s: &str) -> String {
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
}
