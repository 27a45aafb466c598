//! The report's "stability at the extremes" table: one row per time-stepping case of the
//! stability scenes, with the step ratio `dt / dt_crit` against the limit of the case's scheme,
//! the verdict theory predicts (stable when `dt < dt_crit`, marginal within 1e-9 of it, unstable
//! above), what the run did, and whether courant's divergence guard caught it (step, node,
//! Courant number).
//!
//! The limit (column `limit`) is the scheme's own: central difference (any mass) the exact
//! `dt_crit = 2 / omega_max` of the assembled system (Hughes, *The Finite Element Method*, 2000,
//! §9.3); Park's scheme `alpha_e = dt/dt_e <= 1` in every element, `dt_crit = min_e dt_e`
//! (methods.md §6). Contact rows (methods.md §7) take `dt_crit` of the case's scheme
//! (`ContactCriticalStep::applicable`: the contact-active pencil `(K + K_p, M + M_p)` for CD with
//! (bi)penalty, the predictor-corrector's `sqrt((m_c + m_p)/k_s)`). Linear theory of the *closed*
//! contact predicts growth above it; a unilateral contact opens as soon as the contact-local mode
//! grows, so a run between that limit and the contact-free one is predicted `contact-unstable`:
//! bounded, possibly pumping energy into the bars, while above the contact-free limit the bulk
//! modes grow and the run is `unstable`.
//!
//! A contact case with a combined bulk (`contact::combined`) is judged against the limit it was
//! built with: the measured spectral radius of its one-step amplification matrix with the
//! contact active and off (`measured rho(G) <= 1`, read as the contact and contact-free limits
//! above), or Park's rule `alpha_e <= 1` (sufficient only: `beyond bound` above it).
//!
//! "Stable" promises bounded energy, not only a run that finishes: a completed run whose
//! `energy_ratio` exceeds [`ENERGY_BAND`] is observed as `energy growth` and, where stability
//! was predicted, disagrees with the prediction.
//!
//! "Marginal" (at the limit) allows growth, but only the double root's: the critical mode's
//! amplitude grows at most linearly, its energy like `n^2` (methods.md §2). A marginal row
//! agrees when it completes or is caught with its energy within that law ([`Growth`]: the
//! growth exponent over the last doubling of its own energy log, and its energy ratio against
//! `1.5 + 4 (1 + n)^2`), without the critical mode's content of the initial state; faster growth
//! disagrees, whatever the run's end. Contact switching is not linear, so a contact row at 1.00
//! of its linear limit may break the law; its scene then states that as a finding.

use super::case::CaseResult;
use super::contact::ContactResult;
use super::growth::{ENERGY_BAND, Growth, time_stepping_energy_ratio, time_stepping_growth};
use super::outcome::SceneOutcome;
use crate::results::case::Status;
use crate::results::table::Table;
use crate::scene::cases::Scene;
use crate::scene::finding::{Finding, Observed};
use courant_solver::contact::{ContactSample, StepLimit};

/// Width of the "marginal" band of `dt / dt_crit` around 1.
const MARGINAL: f64 = 1e-9;

/// Largest energy a completed run may create, relative to its energy scale, and still be
/// observed as `stable`: `-(T + U - W)_end / scale` above it is `energy created`. Central
/// difference keeps its balance to round-off (below 1e-12 in every report run, 1e6 steps
/// included); Park's incremental variant and the global step dissipate (a negative value);
/// Park's free variant with local stepping creates 1.2e-3 in 3 transits of the graded_1e4 bar
/// (methods.md §6: the literal element acceleration does not keep a static state static).
pub const ENERGY_CREATED: f64 = 1e-6;

/// The predicted verdict for a step ratio `dt / dt_crit`.
pub fn predicted(ratio: f64) -> &'static str {
    if ratio > 1.0 + MARGINAL {
        "unstable"
    } else if ratio >= 1.0 - MARGINAL {
        "marginal"
    } else {
        "stable"
    }
}

/// The predicted verdict for a step ratio against a limit that is only sufficient (Park's
/// `alpha_e <= 1` on a graded mesh): as [`predicted`] up to the limit, `beyond bound` above it,
/// where theory predicts nothing.
pub fn predicted_by_bound(ratio: f64) -> &'static str {
    match predicted(ratio) {
        "unstable" => "beyond bound",
        verdict => verdict,
    }
}

/// The predicted verdict of a contact run from `dt / dt_crit` of its scheme and
/// `dt / dt_free` of the contact-free bodies: as [`predicted`], except that a step above the
/// contact limit but below the contact-free one is `contact-unstable` (bounded by the opening of
/// the unilateral contact).
pub fn predicted_contact(ratio: f64, ratio_free: f64) -> &'static str {
    match predicted(ratio) {
        "unstable" if predicted(ratio_free) == "stable" => "contact-unstable",
        verdict => verdict,
    }
}

/// One row of the table.
#[derive(Debug, Clone, PartialEq)]
pub struct StabilityRow {
    /// Scene name.
    pub scene: String,
    /// Case name.
    pub case: String,
    /// The limit `dt_crit` stands for: `2/omega_max`, `alpha_e <= 1`, or a contact limit.
    pub limit: &'static str,
    /// `dt / dt_crit`.
    pub ratio: f64,
    /// Predicted verdict.
    pub predicted: &'static str,
    /// True when the run completed every step.
    pub completed: bool,
    /// The guard's report when the run diverged.
    pub caught: Option<String>,
    /// Steps taken.
    pub steps: usize,
    /// Relative energy-balance error of the run (0 when not logged; none for contact).
    pub energy_balance: Option<f64>,
    /// Contact: central difference's conserved energy of the real masses at the end over the
    /// initial energy (a diverged run: `kinetic + strain` where the guard stopped it); time
    /// stepping: [`time_stepping_energy_ratio`].
    pub energy_ratio: Option<f64>,
    /// Time stepping: energy the scheme created by the end of the run, relative to the energy
    /// scale, `max(0, (T + U - W)_end / scale)` (0 for contact rows).
    pub energy_created: f64,
    /// The run's energy growth against the double-root law at the limit ([`Growth`],
    /// methods.md §2); graded on marginal rows. `None` without two energy samples or energy
    /// supplied.
    pub growth: Option<Growth>,
    /// The disagreement with theory the scene states for this case (`[[finding]]`), if any.
    pub finding: Option<Finding>,
}

impl StabilityRow {
    /// Build a row from a case result; `dt_crit` is the limit of the case's scheme.
    pub fn new(scene: &str, r: &CaseResult) -> Self {
        let ratio = r.run.dt / r.run.limit.dt();
        let (caught, end) = match &r.run.status {
            Status::Completed => (None, None),
            Status::Diverged(d) => (
                Some(format!(
                    "step {}, node {}, Co {:.4}",
                    d.step, d.node, d.courant
                )),
                Some((d.step, d.energy_ratio)),
            ),
        };
        Self {
            scene: scene.to_string(),
            case: r.run.case.clone(),
            limit: r.run.limit.name(),
            ratio,
            predicted: if r.run.limit.sufficient_only() {
                predicted_by_bound(ratio)
            } else {
                predicted(ratio)
            },
            completed: caught.is_none(),
            caught,
            steps: r.run.steps,
            energy_balance: Some(r.energy.relative_balance_error()),
            energy_ratio: time_stepping_energy_ratio(&r.energy),
            energy_created: (-r.energy_lost()).max(0.0),
            growth: time_stepping_growth(&r.energy, end),
            finding: None,
        }
    }

    /// Build a row from a contact result.
    pub fn from_contact(scene: &str, r: &ContactResult) -> Self {
        let critical = &r.run.critical;
        let ratio = r.run.dt / critical.applicable;
        let caught = r
            .diverged
            .as_ref()
            .map(|d| format!("step {}, node {}, Co {:.4}", d.step, d.node, d.courant));
        // Contact runs start from the striker's kinetic energy: the energy supplied is the first
        // sample's.
        let energy = |s: &ContactSample| s.kinetic + s.strain;
        let supplied = r.run.history.first().map_or(0.0, energy);
        let log: Vec<(usize, f64)> = if supplied > 0.0 {
            r.run
                .history
                .iter()
                .map(|s| (s.step, energy(s) / supplied))
                .collect()
        } else {
            Vec::new()
        };
        let end = r.diverged.as_ref().map(|d| (d.step, d.energy_ratio));
        Self {
            scene: scene.to_string(),
            case: r.case.clone(),
            limit: match critical.binding {
                StepLimit::ContactFree => "2/omega_max (contact-free)",
                StepLimit::ContactActive => "2/omega_max (contact-active)",
                StepLimit::PredictorCorrector => "k_s dt^2/(m_c + m_p) <= 1",
                StepLimit::Measured => "measured rho(G) <= 1 (combined)",
                StepLimit::ParkRule => "alpha_e <= 1 (combined)",
            },
            ratio,
            predicted: match critical.binding {
                StepLimit::ParkRule => predicted_by_bound(ratio),
                _ => predicted_contact(ratio, r.run.dt / critical.contact_free),
            },
            completed: caught.is_none(),
            caught,
            steps: r.run.steps,
            energy_balance: None,
            // A completed run: CD's conserved energy left in the bodies; a diverged one: the
            // guard's own measure (kinetic + strain) where it stopped the run, since the
            // staggered energy is not positive above the critical step.
            energy_ratio: r.energy_ratio_conserved.or(r.energy_ratio),
            energy_created: 0.0,
            growth: Growth::of(&log, end),
            finding: None,
        }
    }

    /// True when the run completed with its energy ratio above [`ENERGY_BAND`] (or NaN).
    pub fn energy_growth(&self) -> bool {
        self.completed
            && self
                .energy_ratio
                .is_some_and(|e| e > ENERGY_BAND || e.is_nan())
    }

    /// True when the run completed having created more than [`ENERGY_CREATED`] of its energy
    /// scale.
    pub fn energy_created(&self) -> bool {
        self.completed && self.energy_created > ENERGY_CREATED
    }

    /// What the run did, in kind.
    pub fn observed_kind(&self) -> Observed {
        if !self.completed {
            Observed::Diverged
        } else if self.energy_growth() {
            Observed::EnergyGrowth
        } else if self.energy_created() {
            Observed::EnergyCreated
        } else {
            Observed::Stable
        }
    }

    /// What the run did: `diverged` (the guard stopped it), `energy growth x<ratio>` (completed,
    /// energy beyond [`ENERGY_BAND`]), `energy created <fraction> of the energy scale` (completed, more than
    /// [`ENERGY_CREATED`] of its energy scale created) or `stable`.
    /// A marginal row adds its growth against the double-root law
    /// ([`Growth::describe`]: `within the n^2 law (p = ...)` or `beyond the n^2 law (...)`).
    pub fn observed(&self) -> String {
        let kind = self.observed_kind_text();
        match (&self.growth, self.predicted) {
            (Some(g), "marginal") => format!("{kind}; {}", g.describe()),
            _ => kind,
        }
    }

    fn observed_kind_text(&self) -> String {
        match self.observed_kind() {
            Observed::EnergyGrowth => format!(
                "energy growth x{:.3}",
                self.energy_ratio.unwrap_or(f64::NAN)
            ),
            Observed::EnergyCreated => format!(
                "energy created {:.2e} of the energy scale",
                self.energy_created
            ),
            kind => kind.name().into(),
        }
    }

    /// Theory and run agree: a predicted-stable run completes with bounded energy, a
    /// predicted-unstable run is caught by the guard, a contact-unstable run stays bounded
    /// (completes, whatever energy the contact pumps in). A marginal run (at the limit, where the
    /// critical mode has a double root, methods.md §2) may stay bounded, grow or be caught as
    /// long as its energy grows within the double root's `n^2` law ([`Growth::within_law`]);
    /// faster growth disagrees, and so does energy *created* without growth, the scheme's own
    /// defect, not the double root, as it does below the limit (one rule for both). `None`
    /// beyond a sufficient bound, where nothing was predicted.
    pub fn agrees(&self) -> Option<bool> {
        match self.predicted {
            "stable" => Some(self.observed_kind() == Observed::Stable),
            "contact-unstable" => Some(self.completed),
            "unstable" => Some(self.caught.is_some()),
            "beyond bound" => None,
            _ => Some(
                self.observed_kind() != Observed::EnergyCreated
                    && self.growth.is_none_or(|g| g.within_law()),
            ),
        }
    }
}

impl StabilityRow {
    /// The verdict of the row: `(pass, finding, source)`. A row that agrees with theory passes;
    /// one that disagrees fails unless the scene states that disagreement as a finding (then it
    /// passes as a finding); a stated finding the run no longer shows fails. `None` for a row
    /// beyond a sufficient bound without a stated finding: nothing was predicted.
    pub fn verdict(&self) -> Option<(bool, bool, String)> {
        let observed = self.observed_kind();
        match (self.agrees(), &self.finding) {
            (None, None) => None,
            (agrees, Some(f)) if f.observed == observed => {
                Some((true, agrees == Some(false), f.source.clone()))
            }
            (_, Some(f)) => Some((
                false,
                false,
                format!(
                    "the scene states `{}` as a finding ({}), the run is `{}`",
                    f.observed.name(),
                    f.source,
                    observed.name()
                ),
            )),
            (Some(agrees), None) => Some((agrees, false, limit_source(self.limit).to_string())),
        }
    }
}

/// Where a scheme's limit comes from, for a verdict's source.
fn limit_source(limit: &str) -> &'static str {
    if limit.starts_with("2/omega_max (contact") || limit.starts_with("k_s") {
        "exact critical step of the contact scheme (methods.md §7)"
    } else if limit.starts_with("measured") {
        "measured spectral radius of the combined one-step amplification matrix, contact active and off (docs/contact_with_local_stepping.md)"
    } else if limit.starts_with("alpha_e") {
        "Park's alpha_e <= 1 (methods.md §6)"
    } else {
        "exact 2/omega_max of the assembled system (Hughes 2000, §9.3)"
    }
}

/// The rows of one scene: every time-stepping and contact case of a stability scene
/// (`[scene] stability = true`), none for another scene.
pub fn stability_rows(scene: &Scene, outcome: &SceneOutcome) -> Vec<StabilityRow> {
    if !scene.stability {
        return Vec::new();
    }
    let stepping = outcome
        .results
        .iter()
        .map(|r| StabilityRow::new(&scene.name, r));
    let contact = outcome
        .contact
        .iter()
        .map(|r| StabilityRow::from_contact(&scene.name, r));
    stepping
        .chain(contact)
        .map(|mut row| {
            row.finding = scene
                .findings
                .iter()
                .find(|f| f.cases.contains(&row.case))
                .cloned();
            row
        })
        .collect()
}

/// `scene, case, limit, dt_over_dt_crit, predicted, observed, guard, steps, energy_balance,
/// energy_ratio, agrees`.
pub fn stability_table(rows: &[StabilityRow]) -> Table {
    let mut table = Table::new(&[
        "scene",
        "case",
        "limit",
        "dt_over_dt_crit",
        "predicted",
        "observed",
        "guard",
        "steps",
        "energy_balance",
        "energy_ratio",
        "agrees",
        "verdict",
    ]);
    for row in rows {
        table.push(vec![
            row.scene.as_str().into(),
            row.case.as_str().into(),
            row.limit.into(),
            row.ratio.into(),
            row.predicted.into(),
            row.observed().into(),
            row.caught.clone().unwrap_or_else(|| "-".into()).into(),
            row.steps.into(),
            row.energy_balance.into(),
            row.energy_ratio.into(),
            match row.agrees() {
                Some(true) => "yes",
                Some(false) => "no",
                None => "not predicted",
            }
            .into(),
            row.verdict()
                .map_or("-", |(pass, finding, _)| match (pass, finding) {
                    (true, true) => "finding",
                    (true, false) => "pass",
                    (false, _) => "FAIL",
                })
                .into(),
        ]);
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Source of truth: the module's verdict rule (marginal within 1e-9 of dt_crit). Proves the
    /// bands: below, within 1e-9 of, and above the critical step.
    #[test]
    fn predicted_verdict_bands() {
        assert_eq!(predicted(0.99), "stable");
        assert_eq!(predicted(1.0 - 1e-6), "stable");
        assert_eq!(predicted(1.0), "marginal");
        assert_eq!(predicted(1.0 + 1e-10), "marginal");
        assert_eq!(predicted(1.01), "unstable");
        // A sufficient bound (Park's alpha_e <= 1 on a graded mesh) predicts nothing above it.
        assert_eq!(predicted_by_bound(0.99), "stable");
        assert_eq!(predicted_by_bound(1.0), "marginal");
        assert_eq!(predicted_by_bound(1.01), "beyond bound");
    }

    fn row(predicted: &'static str, completed: bool, energy_ratio: Option<f64>) -> StabilityRow {
        StabilityRow {
            scene: "s".into(),
            case: "c".into(),
            limit: "2/omega_max",
            ratio: 1.0,
            predicted,
            completed,
            caught: (!completed).then(|| "step 5, node 0, Co 1.0100".into()),
            steps: 5,
            energy_balance: None,
            energy_ratio,
            energy_created: 0.0,
            growth: None,
            finding: None,
        }
    }

    /// Source of truth: the verdict rules of [`StabilityRow::verdict`] and [`ENERGY_CREATED`].
    /// Proves: a predicted-stable run that created 1.2e-3 of its energy scale is observed as
    /// `energy created` and fails; stating that as a finding makes it pass as a finding; a stated
    /// finding the run does not show fails; creation below [`ENERGY_CREATED`] is stable; a row
    /// beyond a sufficient bound has no verdict unless a finding is stated for it.
    #[test]
    fn energy_created_and_stated_findings() {
        let mut created = row("stable", true, Some(1.0));
        created.energy_created = 1.2e-3;
        assert_eq!(
            created.observed(),
            "energy created 1.20e-3 of the energy scale"
        );
        assert_eq!(created.agrees(), Some(false));
        assert!(matches!(created.verdict(), Some((false, false, _))));
        let finding = |observed| Finding {
            cases: vec!["c".into()],
            observed,
            source: "measured here".into(),
        };
        created.finding = Some(finding(Observed::EnergyCreated));
        assert_eq!(
            created.verdict(),
            Some((true, true, "measured here".into()))
        );
        created.finding = Some(finding(Observed::EnergyGrowth));
        assert!(matches!(created.verdict(), Some((false, false, _))));
        let mut round_off = row("stable", true, Some(1.0));
        round_off.energy_created = 0.5 * ENERGY_CREATED;
        assert_eq!(round_off.observed(), "stable");
        assert!(matches!(round_off.verdict(), Some((true, false, _))));
        let mut beyond = row("beyond bound", true, Some(1.0));
        assert_eq!(beyond.verdict(), None);
        beyond.finding = Some(finding(Observed::Stable));
        assert_eq!(
            beyond.verdict(),
            Some((true, false, "measured here".into()))
        );
    }

    /// Source of truth: the meaning of "stable" (bounded energy, [`ENERGY_BAND`] = 1.5).
    /// Proves: a predicted-stable run that completes with its energy multiplied by 14 is observed
    /// as energy growth and disagrees; within the band (or with no ratio) it is stable and agrees;
    /// contact-unstable rows agree whenever they complete; marginal rows agree either way;
    /// predicted-unstable rows agree only when caught.
    #[test]
    fn energy_growth_is_not_stability() {
        let growing = row("stable", true, Some(14.29));
        assert!(growing.energy_growth());
        assert_eq!(growing.observed(), "energy growth x14.290");
        assert_eq!(growing.agrees(), Some(false));
        for bounded in [Some(0.99), Some(1.104), Some(ENERGY_BAND), None] {
            let r = row("stable", true, bounded);
            assert_eq!(r.observed(), "stable", "{bounded:?}");
            assert_eq!(r.agrees(), Some(true), "{bounded:?}");
        }
        assert!(row("stable", true, Some(f64::NAN)).energy_growth());
        assert_eq!(
            row("contact-unstable", true, Some(62.6)).agrees(),
            Some(true)
        );
        assert_eq!(
            row("contact-unstable", false, Some(62.6)).agrees(),
            Some(false)
        );
        assert_eq!(row("marginal", true, Some(29.4)).agrees(), Some(true));
        assert_eq!(row("marginal", false, None).agrees(), Some(true));
        assert_eq!(row("beyond bound", true, Some(1.0)).agrees(), None);
        assert_eq!(row("beyond bound", false, None).agrees(), None);
        let caught = row("unstable", false, Some(1e6));
        assert_eq!(caught.observed(), "diverged");
        assert_eq!(caught.agrees(), Some(true));
        assert_eq!(row("unstable", true, Some(1.0)).agrees(), Some(false));
    }

    /// Source of truth: the double-root law at the limit (methods.md §2; [`Growth`]). Proves: a
    /// marginal row agrees when its energy grows within the law, caught or not, and disagrees
    /// when it grows beyond it (a catch at step 72 with x1.434e6) or creates energy without
    /// growth (one rule with the rows below the limit); the observed text of a marginal row says
    /// which.
    #[test]
    fn marginal_rows_are_graded_against_the_double_root_law() {
        let law = |log: &[(usize, f64)], end| Growth::of(log, end);
        let quadratic: Vec<(usize, f64)> = (0..=1000)
            .step_by(10)
            .map(|j| (j, (1.0 + 0.1 * j as f64).powi(2)))
            .collect();
        let mut caught = row("marginal", false, Some(1e6));
        caught.growth = law(&quadratic, Some((1000, 1e6)));
        assert_eq!(caught.agrees(), Some(true), "{caught:?}");
        assert!(
            caught
                .observed()
                .starts_with("diverged; within the n^2 law (p = 1.9"),
            "{}",
            caught.observed()
        );
        let mut exploding = row("marginal", false, Some(1.434e6));
        exploding.growth = law(&[(0, 1.0), (71, 3e5)], Some((72, 1.434e6)));
        assert_eq!(exploding.agrees(), Some(false));
        assert!(exploding.observed().contains("beyond the n^2 law"));
        let mut created = row("marginal", true, Some(1.0));
        created.energy_created = 1.2e-3;
        created.growth = law(&[(0, 1.0), (10, 1.0)], None);
        assert_eq!(created.agrees(), Some(false));
        // Rows away from the limit are not graded by the law, nor does their text show it.
        let mut stable = row("stable", true, Some(1.0));
        stable.growth = exploding.growth;
        assert_eq!(
            (stable.agrees(), stable.observed()),
            (Some(true), "stable".into())
        );
    }

    /// Source of truth: methods.md §7 (unilateral contact). Proves: above the contact limit but
    /// below the contact-free one the closed-contact mode grows, the unilateral contact bounds
    /// it; above both the run is unstable.
    #[test]
    fn contact_verdict_bands() {
        assert_eq!(predicted_contact(0.99, 0.5), "stable");
        assert_eq!(predicted_contact(1.01, 0.5), "contact-unstable");
        assert_eq!(predicted_contact(2.0, 1.1), "unstable");
        assert_eq!(predicted_contact(1.0, 1.0), "marginal");
    }
}
