//! SVG charts of `courant::report::plot`.
//!
//! Source of truth: the report contract "every plot as SVG, no system fonts, deterministic".
//! What this proves: for a profile-like chart (stress vs x, numerical line + exact dashed) and a
//! log-log convergence chart (error vs N, points + reference line), `line_chart` returns an SVG
//! document that starts with `<svg` and ends with `</svg>`, is well-formed XML by the shared
//! checker `tests/common/xml.rs` (balanced tags, quoted attributes, valid entities), is byte-identical on a second call and
//! contains the series names and axis labels as text (so no font was needed to lay it out). It
//! also proves that an all-NaN series is reported as an error naming the series (no panic) and
//! that a title with `<`, `&`, `>` is escaped into well-formed XML.
//! It does not judge how the chart looks.

use courant::report::plot::{Axes, PlotError, Series, SeriesStyle, line_chart};

// The XML checker shared by the integration tests (its own test is in report_generation.rs).
use crate::xml;

fn assert_valid_svg(svg: &str) {
    let t = svg.trim();
    assert!(
        t.starts_with("<svg"),
        "does not start with <svg: {:?}",
        &t[..t.len().min(80)]
    );
    assert!(t.ends_with("</svg>"), "does not end with </svg>");
    if let Err(e) = xml::parse_xml(svg) {
        panic!("SVG is not well-formed: {e}");
    }
}

fn profile_chart() -> (Axes, Vec<Series>) {
    let n = 64;
    let exact: Vec<(f64, f64)> = (0..=n)
        .map(|i| {
            let x = i as f64 / n as f64;
            (x, if x < 0.5 { -1.0 } else { 0.0 })
        })
        .collect();
    let numerical: Vec<(f64, f64)> = exact
        .iter()
        .enumerate()
        .map(|(i, &(x, s))| (x, s + 0.05 * ((i as f64) * 0.7).sin()))
        .collect();
    let axes = Axes::new("Stress profile at t = 0.5", "x / L", "stress / (E v0 / c)");
    let series = vec![
        Series::new("numerical (CD, lumped)", numerical, SeriesStyle::Line),
        Series::new("exact (d'Alembert)", exact, SeriesStyle::Dashed),
    ];
    (axes, series)
}

fn convergence_chart() -> (Axes, Vec<Series>) {
    let ns = [25.0, 50.0, 100.0, 200.0, 400.0, 800.0];
    let errors: Vec<(f64, f64)> = ns.iter().map(|&n: &f64| (n, 0.3 / n.powf(0.98))).collect();
    let slope: Vec<(f64, f64)> = ns.iter().map(|&n: &f64| (n, 0.5 / n)).collect();
    let axes = Axes::log_log("L2 error vs elements", "N (elements)", "relative L2 error");
    let series = vec![
        Series::new("L2 error", errors, SeriesStyle::Points),
        Series::new("slope -1", slope, SeriesStyle::Line),
    ];
    (axes, series)
}

fn check_chart(axes: &Axes, series: &[Series]) {
    let svg = line_chart(axes, series).expect("chart renders");
    assert_valid_svg(&svg);
    let again = line_chart(axes, series).expect("chart renders twice");
    assert!(svg == again, "second call gave a different SVG");
    let escaped = |s: &str| {
        s.replace('&', "&amp;")
            .replace('\'', "&apos;")
            .replace('"', "&quot;")
    };
    for text in [&axes.title, &axes.x_label, &axes.y_label]
        .into_iter()
        .chain(series.iter().map(|s| &s.name))
    {
        assert!(svg.contains(&escaped(text)), "SVG lacks the text {text:?}");
    }
}

#[test]
fn profile_chart_is_deterministic_well_formed_svg() {
    let (axes, series) = profile_chart();
    check_chart(&axes, &series);
}

#[test]
fn log_log_convergence_chart_is_deterministic_well_formed_svg() {
    let (axes, series) = convergence_chart();
    check_chart(&axes, &series);
}

#[test]
fn all_nan_series_is_an_error_naming_it() {
    let (axes, mut series) = profile_chart();
    series.push(Series::new(
        "broken",
        vec![(f64::NAN, 1.0), (0.5, f64::NAN)],
        SeriesStyle::Line,
    ));
    let err = line_chart(&axes, &series).expect_err("all-NaN series must be rejected");
    assert!(
        matches!(&err, PlotError::NoPlottableData { series, .. } if series == "broken"),
        "{err:?}"
    );
    assert!(err.to_string().contains("broken"), "{err}");
}

#[test]
fn no_positive_value_on_log_axis_is_an_error() {
    let (axes, _) = convergence_chart();
    let series = [Series::new(
        "zeros",
        vec![(10.0, 0.0), (20.0, -1.0)],
        SeriesStyle::Points,
    )];
    assert!(matches!(
        line_chart(&axes, &series),
        Err(PlotError::NoPlottableData { .. })
    ));
    assert!(matches!(
        line_chart(&axes, &[]),
        Err(PlotError::NoSeries { .. })
    ));
}

#[test]
fn gaps_and_single_points_still_render() {
    let axes = Axes::new("gaps", "x", "y");
    let series = [
        Series::new(
            "gappy",
            vec![(0.0, 1.0), (1.0, f64::NAN), (2.0, 3.0), (3.0, 2.0)],
            SeriesStyle::Line,
        ),
        Series::new("single", vec![(1.5, 2.0)], SeriesStyle::Points),
    ];
    assert_valid_svg(&line_chart(&axes, &series).expect("renders"));
    let flat = [Series::new(
        "flat",
        vec![(0.0, 0.0), (1.0, 0.0)],
        SeriesStyle::Dashed,
    )];
    assert_valid_svg(&line_chart(&axes, &flat).expect("flat data renders"));
}

#[test]
fn markup_characters_in_text_are_escaped() {
    let (mut axes, mut series) = profile_chart();
    axes.title = "a < b && c > d \"q\" 'x' </svg>".to_owned();
    axes.x_label = "x <m>".to_owned();
    series[0].name = "num & <exact>".to_owned();
    let svg = line_chart(&axes, &series).expect("chart renders");
    assert_valid_svg(&svg);
    assert!(
        svg.contains("a &lt; b &amp;&amp; c &gt; d"),
        "title not escaped"
    );
    assert!(
        svg.contains("num &amp; &lt;exact&gt;"),
        "series name not escaped"
    );
}
