//! The points of a work-precision study: what each run cost (elements, steps, wall time) beside
//! the error it bought.

use crate::results::table::Table;
use crate::scene::studies::work_precision::WorkPrecisionStudy;

/// One run of a study.
#[derive(Debug, Clone, PartialEq)]
pub struct WorkPoint {
    /// Scheme or mass label (the case name without its mesh and Courant parts).
    pub method: String,
    /// The Courant setting of its variant ([`CourantVariant::courant`](crate::scene::studies::work_precision::CourantVariant::courant)), when the study has
    /// several.
    pub setting: Option<&'static str>,
    /// Courant number of the run relative to the stiffest element, `c dt / h_min`.
    pub courant: f64,
    /// The critical Courant number of the case's scheme (exact, methods.md §5 and §7).
    pub critical_courant: f64,
    /// Elements.
    pub elements: usize,
    /// Steps.
    pub steps: usize,
    /// Internal-force evaluations `K u` per step of the scheme (central difference 1; Park and
    /// Noh-Bathe 2; a contact scheme 1, its bulk being central difference).
    pub force_evaluations: usize,
    /// Normalised L1 error of the stress.
    pub l1: f64,
    /// Wall time of the integration, in seconds.
    pub wall_time: f64,
}

impl WorkPoint {
    /// Element force evaluations, `N x steps x K u per step`: the work in units of one element's
    /// internal force, whatever the scheme.
    pub fn element_force_evaluations(&self) -> usize {
        self.elements * self.steps * self.force_evaluations
    }

    /// Legend label: the method, with its Courant setting when the study's schemes run at
    /// different ones.
    pub fn label(&self) -> String {
        match self.setting {
            Some(setting) => format!("{} ({setting})", self.method),
            None => self.method.clone(),
        }
    }
}

/// Deterministic table: `method, Co, Co_crit, N, steps, node_steps, l1, force_evals_per_step,
/// element_force_evals` (`Co` relative to the stiffest element, `Co_crit` the exact critical
/// Courant number of the case's scheme).
pub fn table(points: &[WorkPoint]) -> Table {
    let mut t = Table::new(&[
        "method",
        "Co",
        "Co_crit",
        "N",
        "steps",
        "node_steps",
        "l1",
        "force_evals_per_step",
        "element_force_evals",
    ]);
    for p in points {
        t.push(vec![
            p.method.as_str().into(),
            p.courant.into(),
            p.critical_courant.into(),
            p.elements.into(),
            p.steps.into(),
            (p.elements * p.steps).into(),
            p.l1.into(),
            p.force_evaluations.into(),
            p.element_force_evaluations().into(),
        ]);
    }
    t
}

/// The run's wall time over its force-evaluation floor, `wall_time / (element force evaluations
/// x t_f)` with `t_f` the measured seconds of one lumped element force evaluation
/// (`crate::run::force_floor`): how many times the cost of its `K u` products at the fastest
/// kernel's rate the run took. `None` without a floor or a time.
pub fn time_over_floor(p: &WorkPoint, element_force_seconds: Option<f64>) -> Option<f64> {
    let floor = element_force_seconds? * p.element_force_evaluations() as f64;
    (floor > 0.0 && p.wall_time > 0.0).then(|| p.wall_time / floor)
}

/// `study, method, Co, N, steps, l1, wall_time_s, time_over_floor` of every study's runs
/// (machine-dependent; [`time_over_floor`], empty without a floor).
pub fn cpu_table(
    studies: &[WorkPrecisionStudy],
    work: &[Vec<WorkPoint>],
    element_force_seconds: Option<f64>,
) -> Table {
    let mut t = Table::new(&[
        "study",
        "method",
        "Co",
        "N",
        "steps",
        "l1",
        "wall_time_s",
        "time_over_floor",
    ]);
    for (study, points) in studies.iter().zip(work) {
        for p in points {
            t.push(vec![
                study.name.into(),
                p.method.as_str().into(),
                p.courant.into(),
                p.elements.into(),
                p.steps.into(),
                p.l1.into(),
                p.wall_time.into(),
                time_over_floor(p, element_force_seconds).map_or_else(|| "".into(), Into::into),
            ]);
        }
    }
    t
}

/// Per study and method, the median and the least [`time_over_floor`] over its runs (every
/// mesh; the least is the run a busy machine disturbed least, since preemption only adds time):
/// `study, method, runs, median_time_over_floor, least_time_over_floor`.
pub fn floor_table(
    studies: &[WorkPrecisionStudy],
    work: &[Vec<WorkPoint>],
    element_force_seconds: Option<f64>,
) -> Table {
    let mut t = Table::new(&[
        "study",
        "method",
        "runs",
        "median_time_over_floor",
        "least_time_over_floor",
    ]);
    for (study, points) in studies.iter().zip(work) {
        let mut labels: Vec<String> = Vec::new();
        for p in points {
            if !labels.contains(&p.label()) {
                labels.push(p.label());
            }
        }
        for label in labels {
            let mut ratios: Vec<f64> = points
                .iter()
                .filter(|p| p.label() == label)
                .filter_map(|p| time_over_floor(p, element_force_seconds))
                .collect();
            if ratios.is_empty() {
                continue;
            }
            ratios.sort_by(f64::total_cmp);
            let m = ratios.len();
            let median = 0.5 * (ratios[(m - 1) / 2] + ratios[m / 2]);
            t.push(vec![
                study.name.into(),
                label.into(),
                m.into(),
                median.into(),
                ratios[0].into(),
            ]);
        }
    }
    t
}

/// Two methods of a study compared at equal error ([`equal_error_saving`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Saving<'a> {
    /// The error both reach: the larger of the two methods' smallest errors.
    pub error: f64,
    /// The fast method's cheapest run (fewest element force evaluations) within `error`.
    pub fast: &'a WorkPoint,
    /// The slow method's cheapest run within `error`.
    pub slow: &'a WorkPoint,
}

impl Saving<'_> {
    /// Steps of the slow run over the fast run's.
    pub fn step_ratio(&self) -> f64 {
        self.slow.steps as f64 / self.fast.steps as f64
    }

    /// Element force evaluations of the slow run over the fast run's.
    pub fn evaluation_ratio(&self) -> f64 {
        self.slow.element_force_evaluations() as f64 / self.fast.element_force_evaluations() as f64
    }

    /// Wall time of the slow run over the fast run's (machine-dependent).
    pub fn time_ratio(&self) -> f64 {
        self.slow.wall_time / self.fast.wall_time
    }
}

/// The methods `fast` and `slow` (their [`WorkPoint::method`]) at equal error: the smallest
/// error both reach on the study's meshes, `max(min l1 of fast, min l1 of slow)`, and each
/// method's cheapest run within it. `None` when either method has no point.
pub fn equal_error_saving<'a>(
    points: &'a [WorkPoint],
    fast: &str,
    slow: &str,
) -> Option<Saving<'a>> {
    let of = |method: &str| -> Vec<&'a WorkPoint> {
        points.iter().filter(|p| p.method == method).collect()
    };
    let (fast, slow) = (of(fast), of(slow));
    let best = |runs: &[&WorkPoint]| runs.iter().map(|p| p.l1).reduce(f64::min);
    let error = best(&fast)?.max(best(&slow)?);
    let cheapest = |runs: &[&'a WorkPoint]| {
        runs.iter()
            .copied()
            .filter(|p| p.l1 <= error)
            .min_by_key(|p| p.element_force_evaluations())
    };
    Some(Saving {
        error,
        fast: cheapest(&fast)?,
        slow: cheapest(&slow)?,
    })
}

#[cfg(test)]
mod tests {
    use super::{WorkPoint, equal_error_saving};

    fn point(method: &str, elements: usize, steps: usize, evals: usize, l1: f64) -> WorkPoint {
        WorkPoint {
            method: method.into(),
            setting: None,
            courant: 0.9,
            critical_courant: 1.0,
            elements,
            steps,
            force_evaluations: evals,
            l1,
            wall_time: steps as f64,
        }
    }

    /// Source of truth: the definition of equal error (`equal_error_saving`). Proves: the error
    /// both reach is the larger of the two best errors, each side takes its cheapest run within
    /// it (not its finest), and the ratios are the slow run's work over the fast run's.
    #[test]
    fn equal_error_takes_the_cheapest_run_of_each_within_the_common_error() {
        let points = [
            point("fast", 10, 100, 2, 0.5),
            point("fast", 20, 200, 2, 0.2),
            point("slow", 10, 1000, 1, 0.9),
            point("slow", 20, 2000, 1, 0.4),
            point("slow", 40, 4000, 1, 0.3),
        ];
        let s = equal_error_saving(&points, "fast", "slow").unwrap();
        assert_eq!(s.error, 0.3);
        assert_eq!((s.fast.elements, s.slow.elements), (20, 40));
        assert_eq!(s.step_ratio(), 20.0);
        assert_eq!(s.evaluation_ratio(), (40.0 * 4000.0) / (20.0 * 200.0 * 2.0));
        assert!(equal_error_saving(&points, "fast", "none").is_none());
    }
}
