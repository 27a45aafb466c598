//! Deterministic SVG line charts for the report.
//!
//! Report contract: every plot is an SVG, needs no system fonts and is deterministic. Charts are
//! rendered with `plotters`' SVG backend into a `String` (this module writes no files): text
//! becomes SVG `<text>` elements, so no font is loaded, and the output carries no timestamps or
//! random ids, so the same input gives byte-identical SVG.
//!
//! ```
//! use courant::report::plot::{Axes, Series, SeriesStyle, line_chart};
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
//!
//! - [`series`]: series, axes, errors; [`prepared`]: drawable pieces and ranges; [`layout`]:
//!   ticks, title size, legend corner; [`draw`]: the SVG backend; [`chart`]: [`line_chart`].

pub mod chart;
pub mod draw;
pub mod layout;
pub mod prepared;
pub mod series;

pub use chart::line_chart;
pub use series::{Axes, HEIGHT, PALETTE_SIZE, PlotError, Series, SeriesStyle, WIDTH};
