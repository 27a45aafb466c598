//! What a validated scene asks for: node-steps, output values and reference work, estimated
//! from its cases without running anything, and checked against [`super::budget`]'s limits.

use super::budget::{Blame, MAX_NODE_STEPS, MAX_REFERENCE_WORK, SWEEP_PASSES_PER_POINT, refuse};
use super::cases::{Case, Scene};
use super::contact::{ContactCase, StabilitySweep};
use super::dispersion::DispersionCase;
use super::error::{SceneError, Source};
use super::reference::Reference;
use courant_references::Evaluation;

/// The node-steps and output values of a scene, with the case that asks for the most.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Work {
    /// Steps times nodes (or Sturm passes times nodes), summed over the cases.
    pub node_steps: f64,
    /// Numbers recorded and written, summed over the cases.
    pub output_values: f64,
    /// Work of the reference (lattice-node equivalents).
    pub reference: f64,
    /// What the reference is, for messages (e.g. the graded bar's modulus ratio).
    pub reference_detail: String,
    /// The case with the most node-steps, and its node-steps.
    pub largest: Option<(String, f64)>,
}

impl Work {
    fn add(&mut self, case: &str, node_steps: f64, output_values: f64) {
        self.node_steps += node_steps;
        self.output_values += output_values;
        if self.largest.as_ref().is_none_or(|(_, n)| node_steps > *n) {
            self.largest = Some((case.to_string(), node_steps));
        }
    }

    /// What a validated scene asks for (every kind of case it holds).
    pub fn of(scene: &Scene) -> Result<Work, String> {
        let mut work = Work::default();
        for case in &scene.cases {
            work.add_time_stepping(case);
        }
        (work.reference, work.reference_detail) = time_stepping_reference(&scene.cases)?;
        for case in &scene.contact {
            work.add_contact(case);
        }
        for case in &scene.dispersion {
            work.add_dispersion(case);
        }
        for case in &scene.spectra {
            // A dense eigen-solution per mass kind, ~n^3 flops, counted one node-step per flop
            // (an over-count: a node-step is ~2.5 ns).
            let n = case.model.bar().node_count() as f64;
            let values = case.masses.len() as f64 * n * 4.0;
            work.add(&case.name, case.masses.len() as f64 * n.powi(3), values);
        }
        for sweep in &scene.contact_sweeps {
            work.add_sweep(sweep);
        }
        Ok(work)
    }

    fn add_time_stepping(&mut self, case: &Case) {
        let elements = case.model.bar().element_count() as f64;
        let steps = case.plan.steps as f64;
        let request = &case.request;
        let samples = |every: usize| steps / every.max(1) as f64 + 2.0;
        let values = request.profile_steps.len() as f64 * elements * 6.0
            + samples(request.history_every) * request.history_nodes.len() as f64 * 8.0
            + samples(request.energy_every) * 10.0;
        self.add(&case.name, steps * elements, values);
    }

    fn add_contact(&mut self, case: &ContactCase) {
        let steps = case.steps as f64;
        let nodes = case.problem.node_count() as f64;
        let samples = steps / case.history_every.max(1) as f64 + 2.0;
        self.add(&case.name, steps * nodes, samples * 12.0);
    }

    fn add_dispersion(&mut self, case: &DispersionCase) {
        let n = case.elements as f64;
        let node_steps: f64 = case
            .modes
            .iter()
            .map(|&mode| {
                (n / (2.0 * case.courant * mode as f64))
                    .round()
                    .clamp(1.0, 1e5)
                    * n
            })
            .sum();
        self.add(&case.name, node_steps, case.modes.len() as f64 * 8.0);
    }

    fn add_sweep(&mut self, sweep: &StabilitySweep) {
        let points = (sweep.beta_s.len() * sweep.ratios.len()) as f64;
        let passes = points * SWEEP_PASSES_PER_POINT * (sweep.elements + 1) as f64;
        self.add("stability", passes, points * 4.0);
    }

    /// Within [`MAX_NODE_STEPS`], the limits' output values (`src.limits`) and [`MAX_REFERENCE_WORK`], else the
    /// error saying what the scene asks for and the limit, at the key that `blame` names for
    /// each (`[node-steps, output values, reference]`).
    pub fn check(&self, src: &Source, blame: [&Blame; 3]) -> Result<(), SceneError> {
        let [steps_blame, output_blame, reference_blame] = blame;
        if self.node_steps > MAX_NODE_STEPS {
            let largest = self
                .largest
                .as_ref()
                .map(|(c, n)| format!("; the largest, case {c}, {n:.2e}"))
                .unwrap_or_default();
            return Err(refuse(
                src,
                steps_blame,
                format!(
                    "the scene asks for {:.2e} node-steps in all{largest}, more than the {MAX_NODE_STEPS:.0e} a scene may ask for \
                     (about 4 minutes for lumped central difference at 2.5 ns per node-step, up to about 12 for Noh-Bathe with matrix masses at ~7 ns); coarsen the meshes, raise the steps, shorten the runs or use \
                     fewer cases",
                    self.node_steps
                ),
            ));
        }
        if self.output_values > src.limits.output_values {
            return Err(refuse(
                src,
                output_blame,
                format!(
                    "the scene would record {:.2e} numbers (profiles, histories, energy logs, force histories; about {:.0} MB \
                     in memory), more than the {:.0e} a scene may record; record fewer samples \
                     (history_every, energy_every), fewer profile times or fewer history points{}",
                    self.output_values,
                    self.output_values * 30.0 / 1e6,
                    src.limits.output_values,
                    src.limits.hint()
                ),
            ));
        }
        if self.reference > MAX_REFERENCE_WORK {
            return Err(refuse(
                src,
                reference_blame,
                format!(
                    "evaluating the reference{} would take {:.2e} units of work (lattice nodes of the graded bar's \
                     characteristics, ~7 ns each; the work grows with the modulus ratio and the time), more than the \
                     {MAX_REFERENCE_WORK:.0e} a scene may ask for; use a milder grading, earlier times, fewer profile times \
                     and history samples, or no reference",
                    self.reference_detail, self.reference
                ),
            ));
        }
        Ok(())
    }
}

/// The work of evaluating the time-stepping cases' references (module docs): exact profiles
/// once per reference, mesh and time (as `compare`'s cache does), history references per
/// sample. `Err` when a reference cannot reach a case's end time at all.
fn time_stepping_reference(cases: &[Case]) -> Result<(f64, String), String> {
    // Distinct references (a scene has one per mesh at most) and the latest time each reaches.
    let mut references: Vec<(&Reference, f64)> = Vec::new();
    for case in cases {
        if let Some(r) = &case.reference {
            let end = case.plan.steps as f64 * case.plan.dt;
            match references.iter_mut().find(|(known, _)| *known == r) {
                Some((_, latest)) => *latest = latest.max(end),
                None => references.push((r, end)),
            }
        }
    }
    // Per reference, the work of one evaluation at its latest time (an upper bound for every
    // earlier one): graded, lattice nodes; layered, its waves to that time.
    let per_evaluation = references
        .iter()
        .map(|&(r, end)| {
            r.exact().evaluation_work(end).map_err(|e| {
                format!(
                    "the {} reference cannot reach the scene's end time {end:e}: {e}",
                    r.name()
                )
            })
        })
        .collect::<Result<Vec<f64>, String>>()?;
    let mut seen = std::collections::HashSet::new();
    let mut work = 0.0;
    for case in cases {
        let Some(reference) = &case.reference else {
            continue;
        };
        let r = references
            .iter()
            .position(|(known, _)| *known == reference)
            .unwrap_or_default();
        let (dt, request) = (case.plan.dt, &case.request);
        let history = (case.plan.steps as f64 / request.history_every.max(1) as f64 + 2.0)
            * request.history_nodes.len() as f64;
        work += history * per_evaluation[r];
        let elements = case.model.bar().element_count();
        for t in request.profile_steps.iter().map(|&s| s as f64 * dt) {
            if !seen.insert((r, elements, t.to_bits())) {
                continue;
            }
            // The averages on this mesh and the field's extreme: each evaluation's work at t
            // where the reference knows it up front, else the bound at the latest time.
            let exact = reference.exact();
            let mesh = case.model.bar().mesh();
            let nodes: Vec<f64> = mesh.nodes().iter().map(|x| x - mesh.start()).collect();
            let evaluations = exact.evaluations(Evaluation::Averages(&nodes), t)
                + exact.evaluations(Evaluation::Extreme, t);
            let one = if exact.work_known_up_front() {
                exact.evaluation_work(t).unwrap_or(per_evaluation[r])
            } else {
                per_evaluation[r]
            };
            work += evaluations as f64 * one;
        }
    }
    let detail = references
        .iter()
        .map(|(r, _)| r.exact().cost_detail())
        .find(|d| !d.is_empty())
        .unwrap_or_default();
    Ok((work, detail))
}
