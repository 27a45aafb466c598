//! The report's work-precision studies: for each scheme, the error against the work it cost
//! (steps and node-steps) over a sequence of meshes, "which scheme gives me this accuracy
//! cheapest". Time-stepping studies measure the normalised L1 error of a stress profile;
//! contact studies the L1-in-time error of the contact force over the exact impulse (1D wave
//! theory, methods.md §7).
//!
//! A scheme whose stable step is far below the others' runs at its own Courant number: a study
//! may split its schemes into [`CourantVariant`]s, each with its own Courant setting, and the
//! labels of the points state the setting (CD with penalty at 0.9 of its exact critical step
//! beside the bipenalty schemes at Co = 0.5, so the reader sees what the penalty costs in steps
//! for the same error).

use super::derived_scene;
use crate::scene::cases::Scene;

/// A work-precision study: a scene whose cases are schemes (or mass kinds) times meshes.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPrecisionStudy {
    /// File-friendly name.
    pub name: &'static str,
    /// Heading.
    pub title: &'static str,
    /// The built-in scene it starts from.
    pub scene: &'static str,
    /// Text substitutions making the mesh a list (cases `n<N>-<scheme>-...`); in a contact
    /// study `{n}` and `{2n}` take each of `contact_meshes` in turn.
    pub replacements: &'static [(&'static str, &'static str)],
    /// Contact studies: the striker's element counts, one derived scene each (a contact scene
    /// has one mesh). Empty for time-stepping studies.
    pub contact_meshes: &'static [usize],
    /// Schemes run at their own Courant setting, one derived scene each (per mesh in a contact
    /// study); empty: the scene's schemes at the scene's (or the study's) Courant number.
    pub variants: &'static [CourantVariant],
    /// What the error column measures.
    pub error: &'static str,
}

/// Schemes of a study run at one Courant setting.
#[derive(Debug, Clone, PartialEq)]
pub struct CourantVariant {
    /// The setting as the labels of its points state it, e.g. `Co = 0.5` (relative to the
    /// stiffest element) or `Co = 0.9 Co_crit` (of each case's exact critical step).
    pub courant: &'static str,
    /// Substitutions applied after the study's: the scheme list and its Courant number.
    pub replacements: &'static [(&'static str, &'static str)],
}

/// Error label of time-stepping studies.
const STRESS_L1: &str = "L1 error / |sigma0|";

/// A Fig. 1 scene (`fig1_masses`, `fig1_schemes`) on meshes of 50 to 1600 elements at 0.9 of
/// each case's limit, one profile at t = 0.5 T, no histories.
const FIG1_AT_0_9: &[(&str, &str)] = &[
    (
        "elements = 100",
        "elements = [50, 100, 200, 400, 800, 1600]",
    ),
    ("courant = [1.0, 0.5]", "courant = 0.9"),
    ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
    ("history_points = [0.0, 0.5]", "history_points = []"),
];

/// The built-in work-precision studies.
pub const WORK_PRECISION_STUDIES: &[WorkPrecisionStudy] = &[
    WorkPrecisionStudy {
        name: "fig1_masses",
        title: "Fig. 1 bar, t = 0.5 T: each mass kind at 0.875-0.9 of its critical Courant number",
        scene: "fig1_masses",
        replacements: FIG1_AT_0_9,
        contact_meshes: &[],
        variants: &[],
        error: STRESS_L1,
    },
    WorkPrecisionStudy {
        name: "fig2_schemes",
        title: "Fig. 2 graded bar at t = 0.5 T, CD, Park and Noh-Bathe (Co = 0.5)",
        scene: "fig2",
        replacements: &[
            ("elements = 100", "elements = [50, 100, 200, 400]"),
            ("profile_times = [0.5, 1.5]", "profile_times = [0.5]"),
        ],
        contact_meshes: &[],
        variants: &[],
        error: STRESS_L1,
    },
    WorkPrecisionStudy {
        name: "fig1_schemes",
        title: "Fig. 1 bar, t = 0.5 T: CD, Park (local stepping), Noh-Bathe at 0.9 of each one's limit",
        scene: "fig1_schemes",
        replacements: FIG1_AT_0_9,
        contact_meshes: &[],
        variants: &[],
        error: STRESS_L1,
    },
    WorkPrecisionStudy {
        name: "fig2_own_limits",
        title: "Fig. 2 graded bar, t = 0.5 T: CD, Park (local stepping), Noh-Bathe at 0.9 of each limit",
        scene: "courant_sweep_own_limits",
        replacements: &[
            ("elements = 100", "elements = [50, 100, 200, 400]"),
            (
                "courant = [0.1, 0.25, 0.5, 0.75, 0.9, 1.0]",
                "courant = 0.9",
            ),
        ],
        contact_meshes: &[],
        variants: &[],
        error: STRESS_L1,
    },
    WorkPrecisionStudy {
        name: "fig5_contact",
        title: "Fig. 5 impact, contact schemes (beta_s = 2500, r = 1)",
        scene: "fig5",
        replacements: &[
            (
                "striker = { length = 1.0, elements = 100 }",
                "striker = { length = 1.0, elements = {n} }",
            ),
            (
                "target = { length = 2.0, elements = 200 }",
                "target = { length = 2.0, elements = {2n} }",
            ),
            // Graded by the force the bars receive (the seed's eps_s x penetration of CD with
            // bipenalty rattles at beta_s = 2500; fig5 shows it).
            (
                "beta_s = [0.25, 25.0, 2500.0, 2.5e7]",
                "beta_s = 2500.0\nforce = \"transferred\"",
            ),
            // Every variant runs below its critical step: refuse it otherwise.
            ("allow_unstable = true", "allow_unstable = false"),
        ],
        contact_meshes: &[25, 50, 100, 200, 400, 800],
        variants: &[
            CourantVariant {
                courant: "Co = 0.5",
                replacements: &[(
                    FIG5_SCHEMES,
                    "schemes = [\"cd-bipenalty\", \"predictor-corrector\", \"lagrange-multiplier\"]",
                )],
            },
            // Penalty only: Cr = 0.0200 at beta_s = 2500 (two bars, methods.md §7), unstable at
            // Co = 0.5; at 0.9 of its exact critical step it needs about 28 times the steps.
            CourantVariant {
                courant: "Co = 0.9 Co_crit",
                replacements: &[
                    (FIG5_SCHEMES, "schemes = [\"cd-penalty\"]"),
                    (
                        "courant = 0.5",
                        "courant = 0.9\ncourant_unit = \"critical\"",
                    ),
                ],
            },
        ],
        error: "L1 force error / impulse",
    },
    WorkPrecisionStudy {
        name: COMBINATION_STUDY,
        title: "Layered impact: Park-LTS + bipenalty vs CD + penalty",
        scene: "impact_layered_combined",
        replacements: &[
            (
                "striker = { length = 1.0, elements = 32,",
                "striker = { length = 1.0, elements = {n},",
            ),
            (
                "target = { length = 2.0, elements = 64,",
                "target = { length = 2.0, elements = {2n},",
            ),
        ],
        contact_meshes: &[8, 16, 32, 64, 128, 256],
        variants: &[
            // Park's rule alpha_e <= 1 is its limit at this unit: 0.9 of the stiffest element's
            // transit time. beta_s = 1: the stiffer bipenalty chatters in this impact
            // (impact_layered_combined).
            CourantVariant {
                courant: "Co = 0.9",
                replacements: &[
                    (COMBINED_BULKS, "bulk = \"park-lts\""),
                    (COMBINED_SCHEMES, "schemes = \"cd-bipenalty\""),
                    (COMBINED_BETA_S, "beta_s = 1.0"),
                    ("courant = 0.45", "courant = 0.9"),
                ],
            },
            // The penalty at 0.9 of its exact contact-active limit (about 0.79 at beta_s = 1
            // and 0.014 at 1e4 for two bars, methods.md §7).
            CourantVariant {
                courant: "Co = 0.9 Co_crit",
                replacements: &[
                    (COMBINED_BULKS, "bulk = \"cd-lmm\""),
                    (COMBINED_SCHEMES, "schemes = \"cd-penalty\""),
                    (COMBINED_BETA_S, "beta_s = [1.0, 1e4]"),
                    (
                        "courant = 0.45",
                        "courant = 0.9\ncourant_unit = \"critical\"",
                    ),
                ],
            },
            // Context: the global step with the bipenalty and with the Lagrange multiplier.
            CourantVariant {
                courant: "Co = 0.9",
                replacements: &[
                    (COMBINED_BULKS, "bulk = \"cd-lmm\""),
                    (
                        COMBINED_SCHEMES,
                        "schemes = [\"cd-bipenalty\", \"lagrange-multiplier\"]",
                    ),
                    (COMBINED_BETA_S, "beta_s = 1.0"),
                    ("courant = 0.45", "courant = 0.9"),
                ],
            },
        ],
        error: "L1 force error / impulse",
    },
];

/// The study of the combination on the layered impact: Park-LTS + bipenalty against CD-LMM +
/// penalty, graded against the exact `LayeredImpact` force (the report states the saving at
/// equal error from its points, `compare::work_precision::equal_error_saving`).
pub const COMBINATION_STUDY: &str = "impact_combined";

/// The two methods the combination study compares at equal error: the fast one and the ones it
/// is set against.
pub const COMBINATION_FAST: &str = "park-lts-cd-bipenalty-bs1";
/// The global-step penalty runs of the combination study.
pub const COMBINATION_SLOW: [&str; 2] = ["cd-penalty-bs1", "cd-penalty-bs10000"];

/// The bulk list of the built-in impact_layered_combined scene.
const COMBINED_BULKS: &str = "bulk = [\"park-lts\", \"cd-rmm\"]";
/// Its scheme list.
const COMBINED_SCHEMES: &str =
    "schemes = [\"cd-bipenalty\", \"predictor-corrector\", \"lagrange-multiplier\"]";
/// Its beta_s list.
const COMBINED_BETA_S: &str = "beta_s = [1.0, 1e4, 1e8]";

/// The scheme list of the built-in fig5 scene.
const FIG5_SCHEMES: &str = "schemes = [\"cd-penalty\", \"cd-bipenalty\", \"predictor-corrector\", \"lagrange-multiplier\"]";

/// A study's derived scenes: one per contact mesh (one in all for a time-stepping study) and
/// Courant variant, each with the variant's setting when the study has several.
pub fn study_scenes(
    study: &WorkPrecisionStudy,
) -> Result<Vec<(Option<&'static str>, Scene)>, String> {
    let meshes: Vec<Option<usize>> = if study.contact_meshes.is_empty() {
        vec![None]
    } else {
        study.contact_meshes.iter().copied().map(Some).collect()
    };
    let no_variant = [CourantVariant {
        courant: "",
        replacements: &[],
    }];
    let variants = if study.variants.is_empty() {
        &no_variant[..]
    } else {
        study.variants
    };
    let mut scenes = Vec::new();
    for n in meshes {
        for variant in variants {
            let replacements: Vec<(&str, String)> = study
                .replacements
                .iter()
                .chain(variant.replacements)
                .map(|(from, to)| {
                    let to = match n {
                        Some(n) => to
                            .replace("{2n}", &(2 * n).to_string())
                            .replace("{n}", &n.to_string()),
                        None => to.to_string(),
                    };
                    (*from, to)
                })
                .collect();
            let borrowed: Vec<(&str, &str)> =
                replacements.iter().map(|(f, t)| (*f, t.as_str())).collect();
            let scene = derived_scene(study.name, study.scene, &borrowed)?;
            let setting = (study.variants.len() > 1).then_some(variant.courant);
            scenes.push((setting, scene));
        }
    }
    Ok(scenes)
}
