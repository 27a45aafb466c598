//! What a chart is made of: series, axes, and why a chart cannot be drawn.

use thiserror::Error;

/// Chart width in pixels.
pub const WIDTH: u32 = 640;
/// Chart height in pixels.
pub const HEIGHT: u32 = 400;

/// Number of colours of the palette (series beyond it repeat colours).
pub const PALETTE_SIZE: usize = 8;

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
