//! [`ParkStep`]: the arithmetic of Park's step on a lumped-mass bar (its stepper, what the time
//! loop drives, is `schemes::park::ParkStepper`; its scheme, with the options, `ParkScheme`).
//! The set-up turns the model, `dt` and the options into the constants of the folded form
//! (module docs of [`crate::kernels::park`]): `alpha_e`, `beta1`, `beta2`, `q_e`, `A_i` and the
//! loads' shares; each step corrects the loaded nodes and runs the folded sweep
//! ([`super::folded`]). As in the lumped CD kernel ([`crate::kernels::lumped::kernel`]), the
//! step runs an AVX2-compiled copy of the same code where the CPU has AVX2 (bit-identical
//! results).

use super::folded::FoldedStep;
use super::options::{ParkOptions, ParkVariant};
use crate::error::InputError;
use crate::kernels::energy::StepEnergy;
use crate::model::Model;
use crate::simd::has_avx2;

/// Per-element constants of the loads' correction (cold: used at loaded nodes only).
#[derive(Debug, Clone, Copy)]
struct ElementLoad {
    dt_e: f64,
    /// `dt_e^2 beta2`.
    pull_at: f64,
    /// `2 / m_e`: the inverse of each node's share of the element LMM.
    inverse_half_mass: f64,
}

/// The arithmetic of Park's step on a lumped-mass bar: its constants and state.
#[derive(Debug, Clone)]
pub struct ParkStep {
    options: ParkOptions,
    /// Per-element constants of the load correction.
    element_loads: Vec<ElementLoad>,
    /// `1/(number of elements at the node)`.
    inverse_count: Vec<f64>,
    /// Share of a nodal load carried by the element on the node's left and right.
    share_left: Vec<f64>,
    share_right: Vec<f64>,
    /// Whether the CPU has AVX2 (the step then runs its AVX2-compiled copy).
    avx2: bool,
    /// The state and the constants of the folded sweep.
    folded: FoldedStep,
}

impl ParkStep {
    /// Set up for `model` with step `dt`; `alpha_e = dt/dt_e > 1` in any element is refused
    /// (the scheme is unstable there), naming the element.
    pub fn new(model: &Model, dt: f64, options: ParkOptions) -> Result<Self, InputError> {
        Self::build(model, dt, options, false)
    }

    /// As [`ParkStep::new`], but `alpha_e = dt/dt_e > 1` is run, not refused: every element
    /// steps with its true `alpha_e` (no clamping to 1) in `beta1`, `beta2`. Above `alpha = 1`
    /// the spectral radius exceeds 1 (methods.md §6): this is for studies of the limit, whose
    /// runs rely on the divergence guard (`StabilityPolicy::allow_unstable`).
    pub fn allowing_unstable(
        model: &Model,
        dt: f64,
        options: ParkOptions,
    ) -> Result<Self, InputError> {
        Self::build(model, dt, options, true)
    }

    /// The largest step with `alpha_e = dt/dt_e <= 1` in every element, `min_e dt_e`: the
    /// stiffest element's transit time `min_e h_e/c_e`, with and without local stepping
    /// (without, every element takes that `dt_e`). Park's stability limit (methods.md §6).
    pub fn limit_step(model: &Model) -> f64 {
        model.bar().stiffest_element().1
    }

    fn build(
        model: &Model,
        dt: f64,
        options: ParkOptions,
        allow_unstable: bool,
    ) -> Result<Self, InputError> {
        if !(0.0..=1.0).contains(&options.theta) {
            return Err(InputError::Parameter {
                field: "theta",
                value: options.theta,
                rule: "must lie in [0, 1]",
            });
        }
        let theta = options.theta;
        let incremental = options.variant == ParkVariant::Incremental;
        let bar = model.bar();
        let n = bar.node_count();
        let (_, stiffest) = bar.stiffest_element();
        let masses = bar.element_mass();
        let mut dt_es = Vec::with_capacity(n - 1);
        let mut pull_stiffness = Vec::with_capacity(n - 1);
        let mut element_loads = Vec::with_capacity(n - 1);
        // Sum over a node's elements of the weight of its own a^n in u_fs: dt_e^2 beta1, plus
        // dt_e^2 beta2 for the incremental variant (a~ = a^n + ...).
        let mut node_pull = vec![0.0; n];
        for (e, (&k, &m)) in model.stiffness().iter().zip(&masses).enumerate() {
            let dt_e = if options.local_stepping {
                bar.element_transit_time(e)
            } else {
                stiffest
            };
            let alpha = dt / dt_e;
            if alpha > 1.0 + crate::analysis::time_step::ROUNDING_SLACK && !allow_unstable {
                return Err(InputError::ParkAlphaAboveOne {
                    element: e,
                    alpha,
                    dt,
                    dt_e,
                });
            }
            // Refusing: alpha within the plan's rounding slack of 1 is 1. Allowing: the true alpha.
            let alpha = if allow_unstable {
                alpha
            } else {
                alpha.min(1.0)
            };
            let beta1 = alpha * (1.0 + 3.0 * alpha - alpha * alpha) / 6.0;
            let beta2 = alpha * (alpha * alpha - 1.0) / 6.0;
            let (pull_a, pull_at) = (dt_e * dt_e * beta1, dt_e * dt_e * beta2);
            let own = if incremental {
                pull_a + pull_at
            } else {
                pull_a
            };
            node_pull[e] += own;
            node_pull[e + 1] += own;
            dt_es.push(dt_e);
            pull_stiffness.push(pull_at * (k * 2.0 / m));
            element_loads.push(ElementLoad {
                dt_e,
                pull_at,
                inverse_half_mass: 2.0 / m,
            });
        }
        let mut inverse_count = vec![0.5; n];
        inverse_count[0] = 1.0;
        inverse_count[n - 1] = 1.0;
        let free: Vec<f64> = (0..n)
            .map(|i| if model.is_fixed(i) { 0.0 } else { 1.0 })
            .collect();
        let pull_acceleration = (0..n)
            .map(|i| {
                free[i] * (theta * inverse_count[i] * node_pull[i] + (1.0 - theta) * 0.5 * dt * dt)
            })
            .collect();
        let loaded_nodes: Vec<usize> = (0..n)
            .filter(|&i| model.loads().iter().any(|l| l.node == i))
            .collect();
        let nodal = model.nodal_mass();
        let share_left: Vec<f64> = (0..n)
            .map(|i| {
                if i > 0 {
                    0.5 * masses[i - 1] / nodal[i]
                } else {
                    0.0
                }
            })
            .collect();
        let share_right: Vec<f64> = (0..n)
            .map(|i| {
                if i + 1 < n {
                    0.5 * masses[i] / nodal[i]
                } else {
                    0.0
                }
            })
            .collect();
        Ok(Self {
            options,
            element_loads,
            inverse_count,
            share_left,
            share_right,
            avx2: has_avx2(),
            folded: FoldedStep {
                dt,
                theta,
                dt_e: dt_es,
                pull_stiffness,
                pull_acceleration,
                stiffness: model.stiffness().to_vec(),
                inverse_mass: model.inverse_mass().to_vec(),
                mass: nodal.to_vec(),
                load_change: vec![0.0; loaded_nodes.len()],
                load_next: vec![0.0; loaded_nodes.len()],
                loaded_nodes,
                free,
                u: model.initial_displacement().to_vec(),
                v: model.initial_velocity().to_vec(),
                a: vec![0.0; n],
                u_next: vec![0.0; n],
            },
        })
    }

    /// Set the starting acceleration `a^0 = M^-1 (F(0) - K u^0)`.
    pub fn start(&mut self, model: &Model) {
        let state = &mut self.folded;
        for i in 0..state.a.len() {
            state.a[i] = model.acceleration_at(&state.u, i, 0.0);
        }
    }

    /// Time step.
    pub fn dt(&self) -> f64 {
        self.folded.dt
    }

    /// Options.
    pub fn options(&self) -> ParkOptions {
        self.options
    }

    /// `u^n`.
    pub fn displacement(&self) -> &[f64] {
        &self.folded.u
    }

    /// `v^n` (full step).
    pub fn velocity(&self) -> &[f64] {
        &self.folded.v
    }

    /// `a^n`.
    pub fn acceleration(&self) -> &[f64] {
        &self.folded.a
    }

    /// Advance from `t^n = t` to `t + dt`. Energies at the new level: kinetic `1/2 v M v`, strain
    /// `1/2 u K u`, and as "staggered" kinetic energy `1/2 v M v - dt^2/8 a M a`, which equals
    /// CD's conserved `1/2 v^{n-1/2} M v^{n+1/2}` when the scheme is CD (theta = 0 or alpha = 1).
    ///
    /// Loads are sparse: the predictor runs load-free and the few loaded (element, node) pairs
    /// are corrected afterwards (the loads enter the prediction linearly).
    pub fn step(&mut self, model: &Model, t: f64) -> StepEnergy {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only when the running CPU reports AVX2 support.
            return unsafe { self.step_avx2(model, t) };
        }
        self.advance(model, t)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn step_avx2(&mut self, model: &Model, t: f64) -> StepEnergy {
        self.advance(model, t)
    }

    #[inline(always)]
    fn advance(&mut self, model: &Model, t: f64) -> StepEnergy {
        self.prepare_loads(model, t);
        match self.options.variant {
            ParkVariant::Free => self.folded.advance::<false>(),
            ParkVariant::Incremental => self.folded.advance::<true>(),
        }
    }

    /// Loads on the element problems: a~ gains `2/m_e share F` (free, `F` at `t + dt_e`) or
    /// `2/m_e share dF` (incremental, `dF = F(t + dt_e) - F(t)`), so u_fs gains `dt_e^2 beta2`
    /// times that and `u^{n+1}` `free theta/count` times the u_fs change. Also `F^{n+1}`.
    fn prepare_loads(&mut self, model: &Model, t: f64) {
        let state = &mut self.folded;
        let n = state.u.len();
        let incremental = self.options.variant == ParkVariant::Incremental;
        for (index, &node) in state.loaded_nodes.iter().enumerate() {
            let now = model.external_force_at(node, t);
            let mut change = 0.0;
            for (e, share) in [
                (node.checked_sub(1), self.share_left[node]),
                (Some(node).filter(|&k| k + 1 < n), self.share_right[node]),
            ] {
                let Some(e) = e else { continue };
                let el = &self.element_loads[e];
                let push = model.external_force_at(node, t + el.dt_e);
                let force = if incremental { push - now } else { push };
                change += el.pull_at * el.inverse_half_mass * share * force;
            }
            state.load_change[index] =
                state.free[node] * self.options.theta * self.inverse_count[node] * change;
            state.load_next[index] = model.external_force_at(node, t + state.dt);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::graded_seed_bar;

    /// The unfolded step, element by element as in steps 1-4 of the module doc of
    /// [`crate::kernels::park`]. `clamp`: alpha limited to 1 (as [`ParkStep::new`] does), else the
    /// true alpha (as [`ParkStep::allowing_unstable`]).
    fn reference_step(
        model: &Model,
        scheme: &ParkStep,
        u: &mut Vec<f64>,
        v: &mut [f64],
        a: &mut [f64],
        t: f64,
        clamp: bool,
    ) -> StepEnergy {
        let (dt, options) = (scheme.dt(), scheme.options());
        let theta = options.theta;
        let incremental = options.variant == ParkVariant::Incremental;
        let bar = model.bar();
        let n = u.len();
        let masses = bar.element_mass();
        let nodal = model.nodal_mass();
        let mut u_fs = vec![0.0; n];
        for e in 0..n - 1 {
            let dt_e = if options.local_stepping {
                bar.element_transit_time(e)
            } else {
                bar.stiffest_element().1
            };
            let alpha = if clamp {
                (dt / dt_e).min(1.0)
            } else {
                dt / dt_e
            };
            let beta1 = alpha * (1.0 + 3.0 * alpha - alpha * alpha) / 6.0;
            let beta2 = alpha * (alpha * alpha - 1.0) / 6.0;
            let m_e = 0.5 * masses[e];
            let force = |node: usize, share: f64| {
                let push = model.external_force_at(node, t + dt_e);
                share
                    * if incremental {
                        push - model.external_force_at(node, t)
                    } else {
                        push
                    }
            };
            let (fi, fj) = (
                force(e, 0.5 * masses[e] / nodal[e]),
                force(e + 1, 0.5 * masses[e] / nodal[e + 1]),
            );
            let k = model.stiffness()[e];
            let ut = [e, e + 1].map(|i| u[i] + dt_e * v[i] + 0.5 * dt_e * dt_e * a[i]);
            let stretch = ut[1] - ut[0];
            let at = if incremental {
                let d = stretch - (u[e + 1] - u[e]);
                [a[e] + (fi + k * d) / m_e, a[e + 1] + (fj - k * d) / m_e]
            } else {
                [(fi + k * stretch) / m_e, (fj - k * stretch) / m_e]
            };
            for (s, i) in [e, e + 1].into_iter().enumerate() {
                u_fs[i] += u[i] + dt * v[i] + dt_e * dt_e * (beta1 * a[i] + beta2 * at[s]);
            }
        }
        for i in 0..n {
            let count = if i == 0 || i == n - 1 { 1.0 } else { 2.0 };
            let u_cd = u[i] + dt * v[i] + 0.5 * dt * dt * a[i];
            let free = if model.is_fixed(i) { 0.0 } else { 1.0 };
            u_fs[i] = free * (theta * u_fs[i] / count + (1.0 - theta) * u_cd);
        }
        *u = u_fs;
        let (mut kinetic, mut impulse) = (0.0, 0.0);
        for i in 0..n {
            let a_next = model.acceleration_at(u, i, t + dt);
            v[i] += 0.5 * dt * (a[i] + a_next);
            a[i] = a_next;
            kinetic += nodal[i] * v[i] * v[i];
            impulse += nodal[i] * a_next * a_next;
        }
        StepEnergy {
            kinetic_staggered: 0.5 * kinetic - 0.125 * dt * dt * impulse,
            kinetic: 0.5 * kinetic,
            strain: model.strain_energy(u),
        }
    }

    fn close(a: f64, b: f64, scale: f64) -> bool {
        (a - b).abs() <= 1e-12 * scale
    }

    #[test]
    fn folded_step_matches_the_element_by_element_formulas() {
        // Graded bar (free left end loaded by a Heaviside force, fixed right end) at 103
        // elements: blocks, sweeps and their remainders all run; the odd count leaves a tail.
        for elements in [1, 2, 103, 1500] {
            let model = graded_seed_bar(elements).unwrap();
            let dt = 0.5 * model.bar().stiffest_element().1;
            for (theta, variant, local_stepping) in [
                (0.5, ParkVariant::Free, true),
                (0.5, ParkVariant::Free, false),
                (0.8, ParkVariant::Incremental, true),
                (0.3, ParkVariant::Incremental, false),
                (0.0, ParkVariant::Free, true),
            ] {
                let options = ParkOptions {
                    theta,
                    variant,
                    local_stepping,
                };
                let mut scheme = ParkStep::new(&model, dt, options).unwrap();
                let mut portable = scheme.clone();
                portable.avx2 = false;
                scheme.start(&model);
                portable.start(&model);
                let (mut u, mut v, mut a) = (
                    scheme.displacement().to_vec(),
                    scheme.velocity().to_vec(),
                    scheme.acceleration().to_vec(),
                );
                for step in 0..60 {
                    let t = step as f64 * dt;
                    let fast = scheme.step(&model, t);
                    let slow = portable.step(&model, t);
                    let reference =
                        reference_step(&model, &scheme, &mut u, &mut v, &mut a, t, true);
                    let scale_u = u.iter().fold(1e-300f64, |m, x| m.max(x.abs()));
                    let scale_v = v.iter().fold(1e-300f64, |m, x| m.max(x.abs()));
                    let scale_a = a.iter().fold(1e-300f64, |m, x| m.max(x.abs()));
                    for i in 0..u.len() {
                        assert!(
                            close(scheme.displacement()[i], u[i], scale_u),
                            "{options:?} u[{i}]"
                        );
                        assert!(
                            close(scheme.velocity()[i], v[i], scale_v),
                            "{options:?} v[{i}]"
                        );
                        assert!(
                            close(scheme.acceleration()[i], a[i], scale_a),
                            "{options:?} a[{i}]"
                        );
                    }
                    let energy = reference.kinetic + reference.strain;
                    for (x, y) in [
                        (fast.kinetic, reference.kinetic),
                        (fast.kinetic_staggered, reference.kinetic_staggered),
                        (fast.strain, reference.strain),
                    ] {
                        assert!(close(x, y, energy), "{options:?}: {x} vs {y}");
                    }
                    // The AVX2 copy does the same IEEE operations in the same order.
                    assert_eq!(fast, slow);
                    assert_eq!(scheme.displacement(), portable.displacement());
                }
            }
        }
    }

    /// Source of truth: the element-by-element formulas of the module doc with the true
    /// `alpha_e = dt/dt_e`. Proves: [`ParkStep::allowing_unstable`] runs alpha > 1 without
    /// clamping (beta2 > 0), where [`ParkStep::new`] refuses it.
    #[test]
    fn allowing_unstable_steps_with_the_true_alpha() {
        let model = graded_seed_bar(103).unwrap();
        let dt = 1.05 * model.bar().stiffest_element().1;
        for local_stepping in [true, false] {
            let options = ParkOptions {
                local_stepping,
                ..ParkOptions::default()
            };
            assert!(ParkStep::new(&model, dt, options).is_err());
            let mut scheme = ParkStep::allowing_unstable(&model, dt, options).unwrap();
            scheme.start(&model);
            let (mut u, mut v, mut a) = (
                scheme.displacement().to_vec(),
                scheme.velocity().to_vec(),
                scheme.acceleration().to_vec(),
            );
            for step in 0..20 {
                let t = step as f64 * dt;
                scheme.step(&model, t);
                reference_step(&model, &scheme, &mut u, &mut v, &mut a, t, false);
                let scale = u.iter().fold(1e-300f64, |m, x| m.max(x.abs()));
                for (i, (&x, &y)) in scheme.displacement().iter().zip(&u).enumerate() {
                    assert!(close(x, y, scale), "{options:?} u[{i}]");
                }
            }
        }
    }
}
