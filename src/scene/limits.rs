//! The limits a scene is validated against (`scene::budget` checks them): the defaults, and the
//! explicit opt-in for one large run (`courant run --large`). Only the elements of one bar, the
//! elements validated and the output values differ; the node-step, case and reference limits are
//! the same for both.

/// The limits a scene is validated against: [`Limits::DEFAULT`], or [`Limits::LARGE`] when the
/// user opts in (`courant run --large`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Most elements of one bar.
    pub elements: i64,
    /// Most elements validated per scene (weighted: a matrix mass or contact case counts several
    /// times, `scene::budget`).
    pub validated_elements: f64,
    /// Most numbers a scene records and writes.
    pub output_values: f64,
    /// Whether these are the large-run limits (an error then does not suggest `--large`).
    pub large: bool,
}

/// Elements of one bar with `--large`: the solver's mesh cap. Measured here (release build,
/// `benches/bar1e7.toml`, `benches/RESULTS.md`): `courant run --large` of a lumped Fig. 1 bar of
/// 10^7 elements (validation, 2223 steps, comparison and files) took 84 to 124 s of wall time on
/// the shared 2-core machine and peaked at 1.11 GB. A bar this size cannot run one transit
/// within the node-step limit (`scene::budget::MAX_NODE_STEPS`), so such runs are short probes
/// of speed and memory; and validating one takes seconds (10^6 lumped elements validated in 0.47
/// to 0.9 s here, `scene::budget::MAX_VALIDATED_ELEMENTS`), not the default's quarter second:
/// that is why they are an opt-in.
pub const LARGE_ELEMENTS: i64 = courant_solver::model::MAX_ELEMENTS as i64;

/// Output values with `--large`: one profile time of the largest bar (six columns), doubled.
pub const LARGE_OUTPUT_VALUES: f64 = 12.0 * LARGE_ELEMENTS as f64;

impl Limits {
    /// The limits of every scene unless the user opts in: each scene validates in about a
    /// second (the table of `scene::budget`).
    pub const DEFAULT: Limits = Limits {
        elements: 500_000,
        validated_elements: 5e5,
        output_values: 2e7,
        large: false,
    };
    /// The opt-in for large runs (`courant run --large`): [`LARGE_ELEMENTS`] per bar and per
    /// scene (validated), [`LARGE_OUTPUT_VALUES`] output values.
    pub const LARGE: Limits = Limits {
        elements: LARGE_ELEMENTS,
        validated_elements: LARGE_ELEMENTS as f64,
        output_values: LARGE_OUTPUT_VALUES,
        large: true,
    };

    /// What to tell a user refused by these limits.
    pub fn hint(&self) -> &'static str {
        if self.large {
            ""
        } else {
            " (`courant run --large` raises this limit for one large run)"
        }
    }
}

impl Default for Limits {
    fn default() -> Self {
        Self::DEFAULT
    }
}
