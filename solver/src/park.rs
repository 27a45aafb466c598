//! Park's explicit scheme with local time stepping and pull-back interpolation (seed §3.1, as
//! corrected in methods.md §6; Park et al., the seed's refs. [11-13]).
//!
//! Per step `n -> n+1` with the global `dt`; element `e` has its own critical step
//! `dt_e = h_e/c_e` and `alpha_e = dt/dt_e <= 1`:
//!
//! ```text
//!   1. push forward each element alone to t^n + dt_e (element LMM M_e = m_e/2 I):
//!        u~_e = u_e^n + dt_e v_e^n + dt_e^2/2 a_e^n
//!        a~_e = M_e^-1 (f_e - K_e u~_e)                                  (variant "free")
//!        a~_e = a_e^n + M_e^-1 (df_e - K_e (u~_e - u_e^n))                (variant "incremental")
//!   2. pull back to t^{n+1} by cubic interpolation in time:
//!        u_fs,e = u_e^n + dt v_e^n + dt_e^2 (beta1 a_e^n + beta2 a~_e),
//!        beta1 = alpha (1 + 3 alpha - alpha^2)/6,  beta2 = alpha (alpha^2 - 1)/6
//!   3. u_fs = plain average of the element predictions at each node
//!   4. u_cd = u^n + dt v^n + dt^2/2 a^n;   u^{n+1} = theta u_fs + (1 - theta) u_cd
//!      a^{n+1} = M^-1 (f^{n+1} - K u^{n+1});   v^{n+1} = v^n + dt/2 (a^n + a^{n+1})
//! ```
//!
//! The seed prints `dt_e v` in step 2 and drops `dt` in the velocity update: both misprints
//! (methods.md §6). `theta = 0` is central difference; at `alpha = 1` every theta is. `theta = 1/2`
//! cancels the leading phase error `(2 theta - 1)(1 - alpha^2)(kh)^2/24`. A nodal load is shared
//! between the two elements of its node in proportion to their share of the nodal mass, so the
//! element problems see the same acceleration as the assembled one under a uniform state.
//! "Without local stepping" uses one common `dt_e` (the stiffest element's) for every element.
//!
//! # Folded form (what [`ParkScheme::step`] computes)
//!
//! Steps 1-4 are linear in the state, so they are evaluated in an equivalent folded form (the
//! same mathematics, reassociated: results agree with the element-by-element form to round-off).
//! With `k_e`, `m_e` the element's stiffness and mass, `S_e = 2 k_e/m_e` (element acceleration
//! per unit stretch, from `M_e = m_e/2 I`), `c_i = 1/(number of elements at node i)` (1 at the
//! ends, 1/2 inside) and `free_i` = 0 at a fixed node, 1 otherwise:
//!
//! ```text
//!   stretch of element e = (i, j = i+1) under the push forward, load-free:
//!        D_e = (u_j - u_i) + dt_e (v_j - v_i) + dt_e^2/2 (a_j - a_i)      (free)
//!        D_e =               dt_e (v_j - v_i) + dt_e^2/2 (a_j - a_i)      (incremental)
//!   a~ = +-S_e D_e (free) or a^n +- S_e D_e (incremental), so with q_e = dt_e^2 beta2 S_e:
//!   u^{n+1}_i = free_i (u_i + dt v_i) + A_i a_i + free_i theta c_i (q_e D_e - q_{e-1} D_{e-1})
//!        A_i = free_i (theta c_i sum_{e at i} P_e + (1 - theta) dt^2/2),
//!        P_e = dt_e^2 beta1 (free),  dt_e^2 (beta1 + beta2) (incremental)
//! ```
//!
//! (`e` is the element on the node's right and `e-1` the one on its left; a missing element
//! contributes nothing.) Nodal loads are added afterwards at the loaded nodes only: element `e`
//! of loaded node `i` adds `free_i theta c_i dt_e^2 beta2 (2/m_e) share_e F` to `u^{n+1}_i`, with
//! `F = F_i(t^n + dt_e)` (free) or `F_i(t^n + dt_e) - F_i(t^n)` (incremental). The acceleration,
//! velocity and energies of step 4 are unchanged.
//!
//! The step is one sweep over blocks of `BLOCK` = 256 elements (L1-resident): the block's
//! `q_e D_e` (each computed once), its nodes' `u^{n+1}`, the load corrections among them, then
//! step 4 for the nodes whose three `u^{n+1}` are final, one node behind the prediction (no
//! later element reads their `v^n`, `a^n`). The energies are summed in `LANES` = 8 independent
//! partial sums, so they agree with a sequential sum to round-off. As in the CD kernel
//! (kernel.rs), the step runs an AVX2-compiled copy of the same code where the CPU has AVX2
//! (bit-identical results).

use crate::error::InputError;
use crate::kernel::StepEnergy;
use crate::model::Model;

/// The element acceleration of step 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ParkVariant {
    /// `a~_e = M_e^-1 (f_e - K_e u~_e)`: the seed's literal formula.
    #[default]
    Free,
    /// `a~_e = a_e^n + M_e^-1 (df_e - K_e (u~_e - u_e^n))`: interface forces frozen at `t^n`;
    /// keeps a static state static on heterogeneous meshes.
    Incremental,
}

impl ParkVariant {
    /// Name in outputs.
    pub fn name(self) -> &'static str {
        match self {
            ParkVariant::Free => "free",
            ParkVariant::Incremental => "incremental",
        }
    }
}

/// Parameters of Park's scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParkOptions {
    /// Blend of the pulled-back and CD predictions, `0 <= theta <= 1` (default 1/2).
    pub theta: f64,
    /// Element acceleration variant (default `free`).
    pub variant: ParkVariant,
    /// Each element steps with its own `dt_e` (default); otherwise all use the stiffest one's.
    pub local_stepping: bool,
}

impl Default for ParkOptions {
    fn default() -> Self {
        Self {
            theta: 0.5,
            variant: ParkVariant::Free,
            local_stepping: true,
        }
    }
}

impl ParkOptions {
    /// Short name, e.g. `park-lts-free`.
    pub fn label(&self) -> String {
        format!(
            "park-{}-{}",
            if self.local_stepping { "lts" } else { "global" },
            self.variant.name()
        )
    }
}

/// Elements per block of the fused sweep: the block's element terms `w_e = q_e D_e` live in a
/// stack buffer, and the block's slices of every array stay in L1 between its loops (256 was
/// fastest of 128/256/512 at N = 1e5 and 1e6 on the 2-core machines).
const BLOCK: usize = 256;

/// Independent partial sums per energy (kept in vector registers; fixed order, deterministic).
const LANES: usize = 8;

/// Per-element constants of the loads' correction (cold: used at loaded nodes only).
#[derive(Debug, Clone, Copy)]
struct ElementLoad {
    dt_e: f64,
    /// `dt_e^2 beta2`.
    pull_at: f64,
    /// `2 / m_e`: the inverse of each node's share of the element LMM.
    inverse_half_mass: f64,
}

/// Partial energy sums, one per lane.
#[derive(Debug, Clone, Copy, Default)]
struct Lanes {
    kinetic: [f64; LANES],
    impulse: [f64; LANES],
    strain: [f64; LANES],
}

/// Park's scheme on a lumped-mass bar.
#[derive(Debug, Clone)]
pub struct ParkScheme {
    dt: f64,
    options: ParkOptions,
    /// `dt_e` per element.
    dt_e: Vec<f64>,
    /// `q_e = dt_e^2 beta2 k_e 2/m_e` per element.
    pull_stiffness: Vec<f64>,
    /// `A_i` per node (see the module doc).
    pull_acceleration: Vec<f64>,
    /// Per-element constants of the load correction.
    element_loads: Vec<ElementLoad>,
    /// `1/(number of elements at the node)`.
    inverse_count: Vec<f64>,
    /// Share of a nodal load carried by the element on the node's left and right.
    share_left: Vec<f64>,
    share_right: Vec<f64>,
    stiffness: Vec<f64>,
    inverse_mass: Vec<f64>,
    mass: Vec<f64>,
    /// Nodes that carry a load (the others have zero external force at every time), ascending.
    loaded_nodes: Vec<usize>,
    /// Per loaded node: its `u^{n+1}` correction and `F^{n+1}` (filled at each step).
    load_change: Vec<f64>,
    load_next: Vec<f64>,
    /// 1 at free nodes, 0 at fixed ones (only the two end nodes can be fixed).
    free: Vec<f64>,
    u: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    u_next: Vec<f64>,
    /// Whether the CPU has AVX2 (the step then runs its AVX2-compiled copy).
    avx2: bool,
}

impl ParkScheme {
    /// Set up for `model` with step `dt`; `alpha_e = dt/dt_e > 1` in any element is refused
    /// (the scheme is unstable there), naming the element.
    pub fn new(model: &Model, dt: f64, options: ParkOptions) -> Result<Self, InputError> {
        Self::build(model, dt, options, false)
    }

    /// As [`ParkScheme::new`], but `alpha_e = dt/dt_e > 1` is run, not refused: every element
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
            if alpha > 1.0 + crate::time_step::ROUNDING_SLACK && !allow_unstable {
                return Err(InputError::Other(format!(
                    "Park's scheme needs alpha_e = dt/dt_e <= 1 in every element; element {e} has alpha = {alpha:.6} \
                     (dt = {dt:e}, dt_e = {dt_e:e}): lower the Courant number"
                )));
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
            dt,
            options,
            dt_e: dt_es,
            pull_stiffness,
            pull_acceleration,
            element_loads,
            inverse_count,
            share_left,
            share_right,
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
            avx2: has_avx2(),
        })
    }

    /// Set the starting acceleration `a^0 = M^-1 (F(0) - K u^0)`.
    pub fn start(&mut self, model: &Model) {
        for i in 0..self.a.len() {
            self.a[i] = model.acceleration_at(&self.u, i, 0.0);
        }
    }

    /// Time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Options.
    pub fn options(&self) -> ParkOptions {
        self.options
    }

    /// `u^n`.
    pub fn displacement(&self) -> &[f64] {
        &self.u
    }

    /// `v^n` (full step).
    pub fn velocity(&self) -> &[f64] {
        &self.v
    }

    /// `a^n`.
    pub fn acceleration(&self) -> &[f64] {
        &self.a
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
        let lanes = match self.options.variant {
            ParkVariant::Free => self.fused::<false>(),
            ParkVariant::Incremental => self.fused::<true>(),
        };
        std::mem::swap(&mut self.u, &mut self.u_next);
        let (kinetic, impulse, strain) = (
            lanes.kinetic.iter().sum::<f64>(),
            lanes.impulse.iter().sum::<f64>(),
            lanes.strain.iter().sum::<f64>(),
        );
        let dt = self.dt;
        // T - dt^2/8 a M a: with full-step velocities this is CD's conserved kinetic part
        // 1/2 v^{n-1/2} M v^{n+1/2}, so the energy balance of the CD limits is round-off.
        StepEnergy {
            kinetic_staggered: 0.5 * kinetic - 0.125 * dt * dt * impulse,
            kinetic: 0.5 * kinetic,
            strain: 0.5 * strain,
        }
    }

    /// Loads on the element problems: a~ gains `2/m_e share F` (free, `F` at `t + dt_e`) or
    /// `2/m_e share dF` (incremental, `dF = F(t + dt_e) - F(t)`), so u_fs gains `dt_e^2 beta2`
    /// times that and `u^{n+1}` `free theta/count` times the u_fs change. Also `F^{n+1}`.
    fn prepare_loads(&mut self, model: &Model, t: f64) {
        let n = self.u.len();
        let incremental = self.options.variant == ParkVariant::Incremental;
        for (index, &node) in self.loaded_nodes.iter().enumerate() {
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
            self.load_change[index] =
                self.free[node] * self.options.theta * self.inverse_count[node] * change;
            self.load_next[index] = model.external_force_at(node, t + self.dt);
        }
    }

    /// Block by block: the load-free prediction of the block's nodes into `u_next`, the load
    /// corrections among them, then step 4 for the nodes whose neighbours are all predicted
    /// (one node behind; the next block reads only `v^n`, `a^n` of nodes not yet finished).
    #[inline(always)]
    fn fused<const INCREMENTAL: bool>(&mut self) -> Lanes {
        let n = self.u.len();
        let elements = n - 1;
        let mut lanes = Lanes::default();
        // w[0] holds w_{e0-1}, w[1..=len] hold w_{e0..e0+len}.
        let mut w = [0.0f64; BLOCK + 1];
        let (mut corrected, mut finished_loads, mut done) = (0, 0, 0);
        let mut e0 = 0;
        while e0 < elements {
            let len = BLOCK.min(elements - e0);
            let last = e0 + len == elements;
            self.predict_block::<INCREMENTAL>(e0, len, last, &mut w);
            let predicted = if last { n } else { e0 + len };
            while corrected < self.loaded_nodes.len() && self.loaded_nodes[corrected] < predicted {
                self.u_next[self.loaded_nodes[corrected]] += self.load_change[corrected];
                corrected += 1;
            }
            let limit = if last { n } else { predicted - 1 };
            self.finish(done, limit, &mut finished_loads, &mut lanes);
            done = limit;
            w[0] = w[len];
            e0 += len;
        }
        lanes
    }

    /// `u^{n+1}` without loads of the nodes `e0..e0+len` (and node `n-1` when `last`) into
    /// `u_next`, in the folded form of the module doc; `w[0]` must hold `w_{e0-1}`.
    #[inline(always)]
    fn predict_block<const INCREMENTAL: bool>(
        &mut self,
        e0: usize,
        len: usize,
        last: bool,
        w: &mut [f64; BLOCK + 1],
    ) {
        let n = self.u.len();
        let (dt, theta) = (self.dt, self.options.theta);
        let half_theta = 0.5 * theta;
        let (u, v, a) = (&self.u[..], &self.v[..], &self.a[..]);
        let pull = &self.pull_acceleration[..];
        let out = &mut self.u_next[..];
        {
            let (uu, vv, aa) = (&u[e0..=e0 + len], &v[e0..=e0 + len], &a[e0..=e0 + len]);
            let (dd, qq) = (&self.dt_e[e0..e0 + len], &self.pull_stiffness[e0..e0 + len]);
            let ww = &mut w[1..=len];
            for k in 0..len {
                let d = dd[k];
                let stretch = d * (vv[k + 1] - vv[k]) + 0.5 * d * d * (aa[k + 1] - aa[k]);
                let stretch = if INCREMENTAL {
                    stretch
                } else {
                    (uu[k + 1] - uu[k]) + stretch
                };
                ww[k] = qq[k] * stretch;
            }
        }
        // Interior nodes i in max(e0, 1)..e0+len: w_{i-1} = w[i-e0], w_i = w[i-e0+1].
        let from = e0.max(1);
        let to = e0 + len;
        if from < to {
            let skip = from - e0;
            let m = to - from;
            let (uu, vv, aa, pp) = (&u[from..to], &v[from..to], &a[from..to], &pull[from..to]);
            let ww = &w[skip..=skip + m];
            let oo = &mut out[from..to];
            for k in 0..m {
                oo[k] = (uu[k] + dt * vv[k]) + pp[k] * aa[k] + half_theta * (ww[k + 1] - ww[k]);
            }
        }
        // End nodes: one element each, inverse count 1, possibly fixed.
        let free = &self.free;
        let end =
            |i: usize, jump: f64| free[i] * ((u[i] + dt * v[i]) + theta * jump) + pull[i] * a[i];
        if e0 == 0 {
            out[0] = end(0, w[1]);
        }
        if last {
            out[n - 1] = end(n - 1, -w[len]);
        }
    }

    /// Step 4 for the nodes `from..to` (`u_next` final at `from-1..=to`): new accelerations
    /// `a^{n+1} = M^-1 (F^{n+1} - K u^{n+1})`, trapezoidal velocities and the energies; the end
    /// and loaded nodes one by one, the rest in vectorisable sweeps. `load` indexes the first
    /// loaded node not yet finished.
    #[inline(always)]
    fn finish(&mut self, from: usize, to: usize, load: &mut usize, lanes: &mut Lanes) {
        let n = self.u.len();
        let mut next = from;
        while next < to {
            let force = match self.loaded_nodes.get(*load) {
                Some(&node) if node == next => {
                    *load += 1;
                    Some(self.load_next[*load - 1])
                }
                _ => None,
            };
            if force.is_some() || next == 0 || next == n - 1 {
                self.update_node(next, force.unwrap_or(0.0), lanes);
                next += 1;
                continue;
            }
            let stop = match self.loaded_nodes.get(*load) {
                Some(&node) if node < to => node,
                _ => to,
            }
            .min(n - 1);
            self.sweep(next, stop, lanes);
            next = stop;
        }
    }

    /// Step 4 for nodes `from..to`, all interior (`1 <= from`, `to <= n-1`) and load-free: the
    /// updates in one element-wise loop, then the energy sums in a second loop over the (L1-hot)
    /// block; one fused loop with the sums does not vectorise as well.
    #[inline(always)]
    fn sweep(&mut self, from: usize, to: usize, lanes: &mut Lanes) {
        if from >= to {
            return;
        }
        let half_dt = 0.5 * self.dt;
        let m = to - from;
        let u = &self.u_next[from - 1..=to];
        let k = &self.stiffness[from - 1..to];
        let (im, mass) = (&self.inverse_mass[from..to], &self.mass[from..to]);
        let (v, a) = (&mut self.v[from..to], &mut self.a[from..to]);
        // The updates first (element-wise, vectorisable), then the energy sums over the block,
        // still in L1.
        for i in 0..m {
            let du = u[i + 2] - u[i + 1];
            let right = k[i + 1] * du;
            let left = k[i] * (u[i + 1] - u[i]);
            let a_next = im[i] * (right - left);
            v[i] += half_dt * (a[i] + a_next);
            a[i] = a_next;
        }
        let (v, a) = (&*v, &*a);
        let Lanes {
            mut kinetic,
            mut impulse,
            mut strain,
        } = *lanes;
        let whole = m / LANES * LANES;
        for base in (0..whole).step_by(LANES) {
            let uu: &[f64; LANES + 1] = u[base + 1..base + LANES + 2]
                .try_into()
                .expect("fixed-size window");
            let kk: &[f64; LANES] = k[base + 1..base + LANES + 1]
                .try_into()
                .expect("fixed-size window");
            let mm: &[f64; LANES] = mass[base..base + LANES]
                .try_into()
                .expect("fixed-size window");
            let vv: &[f64; LANES] = v[base..base + LANES].try_into().expect("fixed-size window");
            let aa: &[f64; LANES] = a[base..base + LANES].try_into().expect("fixed-size window");
            for l in 0..LANES {
                let du = uu[l + 1] - uu[l];
                kinetic[l] += mm[l] * vv[l] * vv[l];
                impulse[l] += mm[l] * aa[l] * aa[l];
                strain[l] += kk[l] * du * du;
            }
        }
        for i in whole..m {
            let l = i % LANES;
            let du = u[i + 2] - u[i + 1];
            kinetic[l] += mass[i] * v[i] * v[i];
            impulse[l] += mass[i] * a[i] * a[i];
            strain[l] += k[i + 1] * du * du;
        }
        *lanes = Lanes {
            kinetic,
            impulse,
            strain,
        };
    }

    /// One node `i` (any, end or loaded) with external force `force`.
    #[inline(always)]
    fn update_node(&mut self, i: usize, force: f64, lanes: &mut Lanes) {
        let n = self.u.len();
        let u = &self.u_next;
        let (right, du) = if i + 1 < n {
            let du = u[i + 1] - u[i];
            (self.stiffness[i] * du, du)
        } else {
            (0.0, 0.0)
        };
        let left = if i > 0 {
            self.stiffness[i - 1] * (u[i] - u[i - 1])
        } else {
            0.0
        };
        let a_next = self.inverse_mass[i] * (force + right - left);
        let v_next = self.v[i] + 0.5 * self.dt * (self.a[i] + a_next);
        self.v[i] = v_next;
        self.a[i] = a_next;
        lanes.kinetic[0] += self.mass[i] * v_next * v_next;
        lanes.impulse[0] += self.mass[i] * a_next * a_next;
        lanes.strain[0] += right * du;
    }
}

fn has_avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::graded_seed_bar;

    /// The unfolded step, element by element as in the module doc's steps 1-4.
    /// `clamp`: alpha limited to 1 (as [`ParkScheme::new`] does), else the true alpha (as
    /// [`ParkScheme::allowing_unstable`]).
    fn reference_step(
        model: &Model,
        scheme: &ParkScheme,
        u: &mut Vec<f64>,
        v: &mut [f64],
        a: &mut [f64],
        t: f64,
        clamp: bool,
    ) -> StepEnergy {
        let (dt, options) = (scheme.dt, scheme.options);
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
                let mut scheme = ParkScheme::new(&model, dt, options).unwrap();
                let mut portable = scheme.clone();
                portable.avx2 = false;
                scheme.start(&model);
                portable.start(&model);
                let (mut u, mut v, mut a) = (scheme.u.clone(), scheme.v.clone(), scheme.a.clone());
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
                        assert!(close(scheme.u[i], u[i], scale_u), "{options:?} u[{i}]");
                        assert!(close(scheme.v[i], v[i], scale_v), "{options:?} v[{i}]");
                        assert!(close(scheme.a[i], a[i], scale_a), "{options:?} a[{i}]");
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
                    assert_eq!(scheme.u, portable.u);
                }
            }
        }
    }

    /// Source of truth: the element-by-element formulas of the module doc with the true
    /// `alpha_e = dt/dt_e`. Proves: [`ParkScheme::allowing_unstable`] runs alpha > 1 without
    /// clamping (beta2 > 0), where [`ParkScheme::new`] refuses it.
    #[test]
    fn allowing_unstable_steps_with_the_true_alpha() {
        let model = graded_seed_bar(103).unwrap();
        let dt = 1.05 * model.bar().stiffest_element().1;
        for local_stepping in [true, false] {
            let options = ParkOptions {
                local_stepping,
                ..ParkOptions::default()
            };
            assert!(ParkScheme::new(&model, dt, options).is_err());
            let mut scheme = ParkScheme::allowing_unstable(&model, dt, options).unwrap();
            scheme.start(&model);
            let (mut u, mut v, mut a) = (scheme.u.clone(), scheme.v.clone(), scheme.a.clone());
            for step in 0..20 {
                let t = step as f64 * dt;
                scheme.step(&model, t);
                reference_step(&model, &scheme, &mut u, &mut v, &mut a, t, false);
                let scale = u.iter().fold(1e-300f64, |m, x| m.max(x.abs()));
                for (i, (&x, &y)) in scheme.u.iter().zip(&u).enumerate() {
                    assert!(close(x, y, scale), "{options:?} u[{i}]");
                }
            }
        }
    }
}
