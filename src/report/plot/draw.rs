//! Drawing a prepared chart with `plotters`' SVG backend into a string.

use super::layout::{LABEL_FONT, tick_formatter, title_font_size};
use super::prepared::{Prepared, clean_text};
use super::series::{Axes, HEIGHT, PALETTE_SIZE, PlotError, SeriesStyle, WIDTH};
use plotters::coord::ranged1d::{AsRangedCoord, Ranged, ValueFormatter};
use plotters::element::DashedPathElement;
use plotters::prelude::*;

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

/// What one chart draws.
pub struct Ctx<'a> {
    pub axes: &'a Axes,
    pub title: &'a str,
    pub series: &'a [Prepared],
    pub x_span: f64,
    pub y_span: f64,
    pub legend: SeriesLabelPosition,
}

/// Draw the chart of `ctx` on the coordinates `x`, `y` (linear or log) as an SVG string.
pub fn render<X, Y>(ctx: &Ctx<'_>, x: X, y: Y) -> Result<String, PlotError>
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
        .label_style(("sans-serif", LABEL_FONT))
        .axis_desc_style(("sans-serif", LABEL_FONT + 1))
        .light_line_style(RGBColor(235, 235, 235))
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(|err| e(&err))?;

    // Series that coincide stay visible: solid lines are drawn widest first and thinnest last
    // (nested bands), points as hollow circles from largest to smallest (concentric rings).
    let count = |style: SeriesStyle| ctx.series.iter().filter(|s| s.style == style).count();
    let (lines, points) = (count(SeriesStyle::Line), count(SeriesStyle::Points));
    let (mut line_rank, mut point_rank) = (0, 0);
    for (i, s) in ctx.series.iter().enumerate() {
        let color = PALETTE[s.colour.unwrap_or(i) % PALETTE.len()];
        let width = match s.style {
            SeriesStyle::Line => {
                line_rank += 1;
                nested_size(line_rank - 1, lines, 1, 4)
            }
            _ => 2,
        };
        let radius = match s.style {
            SeriesStyle::Points => {
                point_rank += 1;
                nested_size(point_rank - 1, points, 2, 6)
            }
            _ => 3,
        };
        let line = ShapeStyle::from(color).stroke_width(width);
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
                        .map(|&p| Circle::new(p, radius, color.stroke_width(2))),
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
                SeriesStyle::Points => {
                    Circle::new((lx + 10, ly), radius, color.stroke_width(2)).into_dyn()
                }
            });
    }

    chart
        .configure_series_labels()
        .position(ctx.legend.clone())
        .label_font(("sans-serif", LABEL_FONT))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|err| e(&err))?;
    root.present().map_err(|err| e(&err))?;
    Ok(())
}

/// The size of the `rank`-th of `count` series, from `largest` (first) down to `smallest`
/// (last): the first series drawn is the widest, so a later one on top of it leaves it visible.
fn nested_size(rank: usize, count: usize, smallest: u32, largest: u32) -> u32 {
    if count <= 1 {
        return (smallest + largest) / 2;
    }
    let span = (largest - smallest) as usize;
    largest - ((rank * span + (count - 1) / 2) / (count - 1)) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nested_sizes_run_from_largest_to_smallest() {
        let sizes: Vec<u32> = (0..4).map(|r| nested_size(r, 4, 1, 4)).collect();
        assert_eq!(sizes, vec![4, 3, 2, 1]);
        assert_eq!(nested_size(0, 1, 1, 4), 2);
        assert_eq!(nested_size(6, 7, 2, 6), 2);
    }
}
