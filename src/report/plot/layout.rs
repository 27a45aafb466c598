//! Layout of a chart: log-axis grid values, tick labels, title size and the legend's corner.

use super::prepared::Prepared;
use super::series::{Axes, SeriesStyle};
use plotters::prelude::SeriesLabelPosition;

/// Labelled (bold) and unlabelled (light) grid values of a log axis on `lo..hi`: whole decades
/// when the range holds at least four of them, otherwise 1-2-5 (or 1..9) multiples of decades.
pub fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
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

/// What the SVG backend writes as `font-size` per unit of the size it is given (plotters
/// scales a font size in points to pixels by 0.806: 15 is written 12.1 px).
pub const PX_PER_FONT_UNIT: f64 = 0.806_451_612_903_225_8;

/// Font size of tick labels and legend entries: 15, written 12.1 px, legible at the 640 px the
/// report shows a chart at (the axis descriptions are one larger).
pub const LABEL_FONT: u32 = 15;

/// Font size of a chart title: 20 (16.1 px), smaller for long titles so the whole title fits the
/// 640 px chart (about 0.55 em per character of a sans-serif face), never below 11 (8.9 px; the
/// built-in report's titles all fit at 15 or more, 12.1 px: `tests/pipeline/report_generation.rs`).
pub fn title_font_size(title: &str) -> u32 {
    let chars = title.chars().count().max(1) as f64;
    (600.0 / (0.55 * PX_PER_FONT_UNIT * chars))
        .floor()
        .clamp(11.0, 20.0) as u32
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
pub fn legend_place(
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

/// Tick labels: plain decimals for moderate magnitudes, `1e-5` style otherwise; on linear axes
/// values within rounding noise of zero print as `0`.
pub fn tick_formatter(log: bool, span: f64) -> impl Fn(&f64) -> String {
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

#[cfg(test)]
mod tests {
    use super::*;

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
    #[test]
    fn long_titles_shrink_to_fit() {
        assert_eq!(title_font_size("fig1: stress at t = 0.5"), 20);
        let long = "Fig. 2 graded bar on equal-transit-time meshes, lumped CD at Co = 1, t = 0.5 T";
        let size = title_font_size(long);
        assert_eq!(size, 17);
        assert!(f64::from(size) * PX_PER_FONT_UNIT * 0.55 * long.chars().count() as f64 <= 600.0);
        assert_eq!(title_font_size(&"x".repeat(500)), 11);
    }
}
