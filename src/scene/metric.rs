//! The metrics an expectation can bound: their scene-file names, the study each belongs to, and
//! which are errors against the exact answer.

/// A metric an expectation bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Metric {
    /// L1 error of the element stresses, `(1/L) sum_e h_e |sigma_e - sigma_ref,e| / |sigma0|`.
    L1,
    /// L2 error, `sqrt((1/L) sum_e h_e (sigma_e - sigma_ref,e)^2) / |sigma0|`.
    L2,
    /// Max error, `max_e |sigma_e - sigma_ref,e| / |sigma0|`.
    Linf,
    /// Overshoot beyond the exact solution's envelope, as a fraction of the jump |sigma0|.
    Overshoot,
    /// Width of a dispersed step front: the distance from the first peak behind the front to
    /// where the profile crosses a third of the jump, in the bar's length unit
    /// ([`crate::compare::front_width`]; `|a1| w = 2.3381 w` for the Airy front, methods.md §3).
    FrontWidth,
    /// Largest |energy balance error| relative to the energy scale of the run.
    EnergyBalance,
    /// Whether the run diverged.
    Diverged,
    /// Total variation of the profile over the exact one's (1 = no spurious oscillation).
    TvRatio,
    /// Energy the scheme dissipated by the end of the run, relative to the energy scale:
    /// `-(T + U - W)_end / scale` (0 for CD up to round-off; Park dissipates a little).
    EnergyLost,
    /// Spectrum scenes: largest relative deviation of the computed elastic frequencies from the
    /// closed-form discrete spectra (methods.md §5), over every mode and mass kind.
    ClosedFormDeviation,
    /// Dispersion scenes: largest `|measured - closed form|` of the phase-speed ratio.
    DispersionDeviation,
    /// Dispersion scenes: smallest observed order of the phase error between modes `n` and `2n`.
    PhaseErrorOrder,
    /// Contact: largest `|F - F1|/F1` inside the first plateau (10 % to 90 % of it).
    PlateauDeviation,
    /// Contact: `|impulse - exact| / exact`.
    ImpulseError,
    /// Contact: `|duration - exact| / exact` (duration from the half-plateau crossings).
    DurationError,
    /// Contact: L1 norm in time of the force error over the exact impulse.
    ForceL1Error,
    /// Contact: the same L1 norm, away from the jumps of the exact force (`JUMP_EXCLUSION_SAMPLES`).
    ForceL1OffJumps,
    /// Contact: `|t_open - exact| / exact`, the first opening of the contact.
    SeparationError,
    /// Contact: energy of the real masses at the end over the initial energy.
    EnergyRatio,
    /// Contact stability: largest relative deviation of the solver's critical Courant number
    /// from the closed form.
    CourantDeviation,
    /// Contact stability: largest `|Cr - 1|` over the bipenalty curves with `r <= 1`, which
    /// keep the contact-free critical Courant number 1 for every `beta_s` (methods.md §7).
    UnitCourantDeviation,
    /// Contact stability: `|Cr sqrt(beta_s/2) - 1|` of the penalty-only curve at its largest
    /// `beta_s`, the approach to the asymptote `Cr ~ sqrt(2/beta_s)` (methods.md §7).
    PenaltyAsymptoteDeviation,
    /// Contact: largest graded contact force over the run (the seed's `eps_s x penetration` for
    /// the penalty schemes).
    MaxForce,
    /// Contact, against the case `relative_to`: `max_k |F(t_k) - F_ref(t_k)| / F1` over the
    /// common samples, F1 the exact first plateau: how far two force histories differ.
    ForceHistoryDifference,
    /// Time stepping, against the case `relative_to`: the largest stress difference of the two
    /// runs over the peak of the other, at their common profile times
    /// ([`crate::compare::stress_difference`]).
    StressDifference,
    /// Time stepping and contact: the critical Courant number of the case's scheme on its mesh
    /// (CD: `2/omega_max`; Park: `alpha_e <= 1`; contact: the applicable exact limit), in units of
    /// the stiffest element's transit.
    CriticalCourant,
    /// Time stepping: Fried's element bound over the exact critical step,
    /// `dt_crit_element / dt_crit` (at most 1 where the bound is conservative).
    ElementBoundRatio,
    /// Spectrum: `max_n |omega_n(mass) / omega_n(against) - 1|` over the elastic modes, between
    /// two of the case's mass kinds.
    MassDeviation,
    /// Spectrum: `max_n |omega_n(mass)/omega_n - 1| / |omega_n(against)/omega_n - 1|` over the
    /// elastic modes, `omega_n` the continuum (below 1: `mass` closer to the continuum than
    /// `against` on every mode; methods.md §5).
    ModeErrorRatio,
    /// The automatic stability verdict of every case of a stability scene: what the run did
    /// against what theory predicts for its step (not an `[[expect]]` metric; a disagreement is
    /// declared with `[[finding]]`).
    Stability,
    /// A convergence study's order fitted on its finest meshes, against the band theory allows
    /// (automatic, not an `[[expect]]` metric).
    FittedOrder,
    /// A convergence study's largest error over its meshes, where theory says exact (automatic).
    MaxError,
}

/// Every metric, its scene-file name and the study it belongs to.
pub(super) const METRICS: &[(Metric, &str, Study)] = &[
    (Metric::L1, "l1", Study::TimeStepping),
    (Metric::L2, "l2", Study::TimeStepping),
    (Metric::Linf, "linf", Study::TimeStepping),
    (Metric::Overshoot, "overshoot", Study::TimeStepping),
    (Metric::FrontWidth, "front_width", Study::TimeStepping),
    (Metric::TvRatio, "tv_ratio", Study::TimeStepping),
    (Metric::EnergyLost, "energy_lost", Study::TimeStepping),
    (Metric::EnergyBalance, "energy_balance", Study::TimeStepping),
    (Metric::Diverged, "diverged", Study::TimeStepping),
    (
        Metric::StressDifference,
        "stress_difference",
        Study::TimeStepping,
    ),
    (
        Metric::ElementBoundRatio,
        "element_bound_ratio",
        Study::TimeStepping,
    ),
    (
        Metric::CriticalCourant,
        "critical_courant",
        Study::TimeStepping,
    ),
    (
        Metric::ClosedFormDeviation,
        "closed_form_deviation",
        Study::Spectrum,
    ),
    (Metric::MassDeviation, "mass_deviation", Study::Spectrum),
    (Metric::ModeErrorRatio, "mode_error_ratio", Study::Spectrum),
    (
        Metric::DispersionDeviation,
        "dispersion_deviation",
        Study::Dispersion,
    ),
    (
        Metric::PhaseErrorOrder,
        "phase_error_order",
        Study::Dispersion,
    ),
    (
        Metric::PlateauDeviation,
        "plateau_deviation",
        Study::Contact,
    ),
    (Metric::ImpulseError, "impulse_error", Study::Contact),
    (Metric::DurationError, "duration_error", Study::Contact),
    (Metric::ForceL1Error, "force_l1_error", Study::Contact),
    (
        Metric::ForceL1OffJumps,
        "force_l1_off_jumps",
        Study::Contact,
    ),
    (Metric::SeparationError, "separation_error", Study::Contact),
    (Metric::EnergyRatio, "energy_ratio", Study::Contact),
    (Metric::MaxForce, "max_force", Study::Contact),
    (
        Metric::ForceHistoryDifference,
        "force_history_difference",
        Study::Contact,
    ),
    (
        Metric::CourantDeviation,
        "courant_deviation",
        Study::ContactStability,
    ),
    (
        Metric::UnitCourantDeviation,
        "unit_courant_deviation",
        Study::ContactStability,
    ),
    (
        Metric::PenaltyAsymptoteDeviation,
        "penalty_asymptote_deviation",
        Study::ContactStability,
    ),
    (Metric::Stability, "stability", Study::TimeStepping),
    (Metric::FittedOrder, "fitted_order", Study::TimeStepping),
    (Metric::MaxError, "max_error", Study::TimeStepping),
];

/// Metrics whose verdicts courant makes by itself (stability scenes, convergence studies): not
/// for `[[expect]]`.
pub(super) const AUTOMATIC: [Metric; 3] =
    [Metric::Stability, Metric::FittedOrder, Metric::MaxError];

/// The kind of study a scene is; each metric belongs to one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Study {
    /// Time-stepping cases.
    TimeStepping,
    /// Spectra.
    Spectrum,
    /// Single-mode dispersion runs.
    Dispersion,
    /// Contact-impact runs.
    Contact,
    /// Contact stability sweep.
    ContactStability,
}

impl Study {
    /// Name in messages.
    pub fn name(self) -> &'static str {
        match self {
            Study::TimeStepping => "time-stepping",
            Study::Spectrum => "spectrum",
            Study::Dispersion => "dispersion",
            Study::Contact => "contact",
            Study::ContactStability => "contact stability",
        }
    }
}

impl Metric {
    /// Scene-file name.
    pub fn name(self) -> &'static str {
        METRICS.iter().find(|m| m.0 == self).map_or("?", |m| m.1)
    }

    pub(super) fn parse(s: &str) -> Option<Self> {
        METRICS.iter().find(|m| m.1 == s).map(|m| m.0)
    }

    /// True when the metric applies to a scene of `study` (`diverged` and `critical_courant`
    /// apply to time-stepping and contact scenes).
    pub fn applies_to(self, study: Study) -> bool {
        let home = METRICS.iter().find(|m| m.0 == self).map(|m| m.2);
        home == Some(study)
            || (matches!(
                self,
                Metric::Diverged | Metric::CriticalCourant | Metric::Stability
            ) && study == Study::Contact)
    }

    /// True for metrics that compare a case with the case `relative_to` themselves (rather
    /// than the ratio of their two values).
    pub fn compares_cases(self) -> bool {
        matches!(
            self,
            Metric::ForceHistoryDifference | Metric::StressDifference
        )
    }

    /// True for errors against the exact answer: zero when the result is exact, larger when it
    /// is less accurate (so an upper bound on one is met by every more accurate result).
    pub fn is_error(self) -> bool {
        matches!(
            self,
            Metric::L1
                | Metric::L2
                | Metric::Linf
                | Metric::Overshoot
                | Metric::PlateauDeviation
                | Metric::ImpulseError
                | Metric::DurationError
                | Metric::ForceL1Error
                | Metric::ForceL1OffJumps
                | Metric::SeparationError
                | Metric::ClosedFormDeviation
                | Metric::DispersionDeviation
                | Metric::CourantDeviation
                | Metric::UnitCourantDeviation
                | Metric::PenaltyAsymptoteDeviation
        )
    }

    /// True for metrics that compare two of a spectrum case's mass kinds (`mass`, `against`).
    pub fn compares_masses(self) -> bool {
        matches!(self, Metric::MassDeviation | Metric::ModeErrorRatio)
    }

    /// True for metrics measured on profiles (they need a reference).
    pub fn needs_reference(self) -> bool {
        matches!(
            self,
            Metric::L1 | Metric::L2 | Metric::Linf | Metric::Overshoot | Metric::FrontWidth
        )
    }
}
