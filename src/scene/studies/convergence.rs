//! The report's h-refinement studies: a built-in scene re-run on a sequence of meshes, with
//! the band of observed orders theory allows for each error norm.

use super::derived_scene;
use crate::scene::cases::Scene;

/// An h-refinement study: one scene re-run on a sequence of meshes.
#[derive(Debug, Clone, PartialEq)]
pub struct ConvergenceStudy {
    /// File-friendly name.
    pub name: &'static str,
    /// Heading.
    pub title: &'static str,
    /// What theory predicts (stated beside the observed orders).
    pub expected: &'static str,
    /// The built-in scene it starts from.
    pub scene: &'static str,
    /// Text substitutions applied to the scene (one case per element count must remain).
    pub replacements: &'static [(&'static str, &'static str)],
    /// What theory allows for the L1, L2 and max errors (`None`: measured, no theory to check).
    pub bands: [Option<OrderBand>; 3],
}

/// What theory allows for one error norm of a convergence study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OrderBand {
    /// The order fitted on the finest [`FIT_LEVELS`] meshes lies in `[min, max]`.
    Order {
        /// Lowest order admitted.
        min: f64,
        /// Highest order admitted.
        max: f64,
    },
    /// Exact up to round-off: the error is at most `max_error` on every mesh.
    Exact {
        /// Largest error admitted.
        max_error: f64,
    },
    /// Where no order law is derived: the error decreases from mesh to mesh on the finest
    /// [`FIT_LEVELS`] meshes and the order fitted there is at least `min` (a lower bound).
    Converges {
        /// Lowest order admitted.
        min: f64,
    },
}

/// Convergence without an order law (L1 and L2 of a step front under a scheme whose front
/// law methods.md does not derive); the max error of a step front does not converge.
pub const CONVERGES: [Option<OrderBand>; 3] = [
    Some(OrderBand::Converges { min: 0.0 }),
    Some(OrderBand::Converges { min: 0.0 }),
    None,
];

/// Meshes the least-squares order is fitted on (the finest ones).
pub const FIT_LEVELS: usize = 3;

/// The orders of a dispersive step front (methods.md §3; the bands of
/// `tests/data/airy_front_convergence.csv`).
pub const AIRY_FRONT: [Option<OrderBand>; 3] = [
    Some(OrderBand::Order {
        min: 0.42,
        max: 0.56,
    }),
    Some(OrderBand::Order {
        min: 0.30,
        max: 0.37,
    }),
    Some(OrderBand::Order {
        min: -0.10,
        max: 0.10,
    }),
];

/// The dispersive step front of CD with a consistent, averaged or reciprocal mass: L1 and L2 as
/// [`AIRY_FRONT`]; the max error does not converge (order at most 0.1), but these masses reach
/// its bounded plateau (jump plus overshoot, below 1.3) from below on the meshes studied (AMM(1/2)
/// at 1/2 of its critical Courant number: 0.19 at N = 50, 0.62 at 6400, 0.66 at 12800), so the
/// fitted order may dip to -0.25.
const AIRY_FRONT_MASSES: [Option<OrderBand>; 3] = [
    AIRY_FRONT[0],
    AIRY_FRONT[1],
    Some(OrderBand::Order {
        min: -0.25,
        max: 0.10,
    }),
];

/// First order in every norm.
const FIRST_ORDER: Option<OrderBand> = Some(OrderBand::Order { min: 0.9, max: 1.1 });

/// The Fig. 1 bar with one mass kind at 1/2 of its critical Courant number, N = 50 … 12800, at
/// t = 0.5 T: `mass_kind_study!(name, mass key, mass label, its critical Courant number)`.
macro_rules! mass_kind_study {
    ($name:literal, $mass:literal, $label:literal, $critical:literal) => {
        ConvergenceStudy {
            name: $name,
            title: concat!(
                "Fig. 1 bar, CD with ",
                $label,
                " at Co = 1/2 of ",
                $critical,
                ", t = 0.5 T"
            ),
            expected: "as lumped CD at Co < 1: a dispersive step front (cubic leading dispersion error, methods.md §3 and §5), L1 ~ h^(1/2), L2 ~ h^(1/3), Linf does not converge",
            bands: AIRY_FRONT_MASSES,
            scene: "fig1_masses",
            replacements: &[
                (
                    "elements = 100",
                    "elements = [50, 100, 200, 400, 800, 1600, 3200, 6400, 12800]",
                ),
                (
                    "mass = [\"lmm\", \"cmm\", \"amm\", \"rmm\"]",
                    concat!("mass = \"", $mass, "\""),
                ),
                ("courant = [1.0, 0.5]", "courant = 0.5"),
                ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
                ("history_points = [0.0, 0.5]", "history_points = []"),
            ],
        }
    };
}

/// The built-in convergence studies.
pub const CONVERGENCE_STUDIES: &[ConvergenceStudy] = &[
    ConvergenceStudy {
        name: "fig1_co0.5",
        title: "Fig. 1 bar, lumped CD at Co = 0.5, t = 0.5 T",
        expected: "L1 ~ h^(1/2), L2 ~ h^(1/3), Linf does not converge (dispersive step front, methods.md §3)",
        bands: AIRY_FRONT,
        scene: "fig1",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600, 3200, 6400, 12800]",
            ),
            ("courant = [1.0, 0.5, 0.1]", "courant = 0.5"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
            ("history_points = [0.0, 0.5]", "history_points = []"),
        ],
    },
    ConvergenceStudy {
        name: "fig1_co1",
        title: "Fig. 1 bar, lumped CD at Co = 1, t = 0.5 T",
        expected: "exact to round-off on every mesh (methods.md §3)",
        bands: [Some(OrderBand::Exact { max_error: 1e-10 }); 3],
        scene: "fig1",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600, 3200, 6400, 12800]",
            ),
            ("courant = [1.0, 0.5, 0.1]", "courant = 1.0"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
            ("history_points = [0.0, 0.5]", "history_points = []"),
        ],
    },
    mass_kind_study!("fig1_cmm", "cmm", "CMM", "1/sqrt(3)"),
    mass_kind_study!("fig1_amm", "amm", "AMM(1/2)", "sqrt(2/3)"),
    mass_kind_study!("fig1_rmm", "rmm", "RMM(1/2)", "sqrt(2/3)"),
    ConvergenceStudy {
        name: "layered_co1",
        title: "Two-layer bar (impedance ratio 16), equal-transit meshes, CD at Co = 1, t = 0.5/1.2/2.6 T",
        expected: "exact to round-off on every mesh: interfaces at nodes, every element at its own Courant number 1 (methods.md §4); round-off stays below the 1e-14 N^2 of methods.md §3 (3e-10 measured at N = 3200, where that bound is 1e-7)",
        bands: [Some(OrderBand::Exact { max_error: 1e-9 }); 3],
        scene: "layered",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600, 3200]",
            ),
            (
                "scheme = [\"cd\", \"park-lts\", \"noh-bathe\"]",
                "scheme = \"cd\"",
            ),
            ("courant = [1.0, 0.5]", "courant = 1.0"),
        ],
    },
    ConvergenceStudy {
        name: "fig2_park_lts",
        title: "Fig. 2 graded bar, Park with local stepping, Co = 0.5, t = 0.5 T",
        expected: "no order law derived for a step front under Park's scheme (methods.md §6 gives its phase error for smooth waves only): graded for convergence, L1 and L2 decreasing on the finest meshes with a positive order; compare with CD below",
        bands: CONVERGES,
        scene: "fig2",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\", \"noh-bathe\"]",
                "scheme = \"park-lts\"",
            ),
            ("p = 0.54\n", ""),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    },
    ConvergenceStudy {
        name: "fig2_cd",
        title: "Fig. 2 graded bar, lumped CD, Co = 0.5, t = 0.5 T",
        expected: "step front dispersed by CD's cubic dispersion, as on the Fig. 1 bar: L1 ~ h^(1/2) whatever the local Courant number (methods.md §3: the exponent comes from w ~ h^(2/3), the local Co only sets the constant); L2 graded for convergence (the graded bar's L2 drifts at these N)",
        bands: [AIRY_FRONT[0], Some(OrderBand::Converges { min: 0.0 }), None],
        scene: "fig2",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\", \"noh-bathe\"]",
                "scheme = \"cd\"",
            ),
            ("theta = 0.5\npark_variant = \"free\"\np = 0.54\n", ""),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    },
    ConvergenceStudy {
        name: "fig2_equal_transit",
        title: "Fig. 2 graded bar on equal-transit-time meshes, lumped CD at Co = 1, t = 0.5 T",
        expected: "first order: the exact layered (Goupillaud) model of the graded bar (methods.md §4)",
        bands: [FIRST_ORDER; 3],
        scene: "fig2",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]\nspacing = \"equal-transit\"",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\", \"noh-bathe\"]",
                "scheme = \"cd\"",
            ),
            ("theta = 0.5\npark_variant = \"free\"\np = 0.54\n", ""),
            ("courant = 0.5", "courant = 1.0"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    },
    ConvergenceStudy {
        name: "fig1_noh_bathe",
        title: "Fig. 1 bar, Noh-Bathe (p = 0.54) at 0.9 of its exact limit (Co = 1.69), t = 0.5 T",
        expected: "no order law derived for a step front under the dissipative Noh-Bathe scheme: graded for convergence, L1 and L2 decreasing on the finest meshes with a positive order (compare fig1_co0.5)",
        bands: CONVERGES,
        scene: "fig1_schemes",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600, 3200, 6400]",
            ),
            (
                "scheme = [\"cd\", \"park-lts\", \"noh-bathe\"]",
                "scheme = \"noh-bathe\"",
            ),
            ("courant = [1.0, 0.5]", "courant = 0.9"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
            ("history_points = [0.0, 0.5]", "history_points = []"),
        ],
    },
    ConvergenceStudy {
        name: "fig2_noh_bathe",
        title: "Fig. 2 graded bar, Noh-Bathe (p = 0.54), Co = 0.5, t = 0.5 T",
        expected: "no order law derived for a step front under the dissipative Noh-Bathe scheme: graded for convergence, L1 and L2 decreasing on the finest meshes with a positive order; compare with CD and Park above",
        bands: CONVERGES,
        scene: "fig2",
        replacements: &[
            (
                "elements = 100",
                "elements = [50, 100, 200, 400, 800, 1600]",
            ),
            (
                "scheme = [\"cd\", \"park-global\", \"park-lts\", \"noh-bathe\"]",
                "scheme = \"noh-bathe\"",
            ),
            ("theta = 0.5\npark_variant = \"free\"\n", ""),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
    },
];

impl ConvergenceStudy {
    /// The study's scene: its built-in scene with the study's substitutions.
    pub fn scene(&self) -> Result<Scene, String> {
        derived_scene(self.name, self.scene, self.replacements)
    }
}
