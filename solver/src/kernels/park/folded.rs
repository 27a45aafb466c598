//! The folded step of Park's scheme (module docs of [`crate::kernels::park`], "Folded form") as one
//! sweep over the bar.
//!
//! The step is one sweep over blocks of `BLOCK` = 256 elements (L1-resident): the block's
//! `q_e D_e` (each computed once), its nodes' `u^{n+1}`, the load corrections among them, then
//! step 4 for the nodes whose three `u^{n+1}` are final, one node behind the prediction (no
//! later element reads their `v^n`, `a^n`). The energies are summed in `LANES` = 8 independent
//! partial sums, so they agree with a sequential sum to round-off.

use crate::kernels::energy::StepEnergy;
use crate::simd::LANES;

/// Elements per block of the fused sweep: the block's element terms `w_e = q_e D_e` live in a
/// stack buffer, and the block's slices of every array stay in L1 between its loops (256 was
/// fastest of 128/256/512 at N = 1e5 and 1e6 on the 2-core machines).
const BLOCK: usize = 256;

/// Partial energy sums, one per lane.
#[derive(Debug, Clone, Copy, Default)]
struct Lanes {
    kinetic: [f64; LANES],
    impulse: [f64; LANES],
    strain: [f64; LANES],
}

/// The state and the constants of the folded step: what one step reads and writes. The
/// constants come from [`ParkStep`](super::ParkStep)'s set-up, the load corrections of each
/// step from its loads; the sweep knows neither the model nor the options.
#[derive(Debug, Clone)]
pub(super) struct FoldedStep {
    pub(super) dt: f64,
    /// Blend of the pulled-back and CD predictions.
    pub(super) theta: f64,
    /// `dt_e` per element.
    pub(super) dt_e: Vec<f64>,
    /// `q_e = dt_e^2 beta2 k_e 2/m_e` per element.
    pub(super) pull_stiffness: Vec<f64>,
    /// `A_i` per node (see the module doc of [`crate::kernels::park`]).
    pub(super) pull_acceleration: Vec<f64>,
    pub(super) stiffness: Vec<f64>,
    pub(super) inverse_mass: Vec<f64>,
    pub(super) mass: Vec<f64>,
    /// Nodes that carry a load (the others have zero external force at every time), ascending.
    pub(super) loaded_nodes: Vec<usize>,
    /// Per loaded node: its `u^{n+1}` correction and `F^{n+1}` (filled at each step).
    pub(super) load_change: Vec<f64>,
    pub(super) load_next: Vec<f64>,
    /// 1 at free nodes, 0 at fixed ones (only the two end nodes can be fixed).
    pub(super) free: Vec<f64>,
    pub(super) u: Vec<f64>,
    pub(super) v: Vec<f64>,
    pub(super) a: Vec<f64>,
    pub(super) u_next: Vec<f64>,
}

impl FoldedStep {
    /// One step from `t^n` with the load corrections `load_change`, `load_next` already set:
    /// the new state, and the energies at the new level (kinetic `1/2 v M v`, strain
    /// `1/2 u K u`, staggered kinetic `1/2 v M v - dt^2/8 a M a`).
    #[inline(always)]
    pub(super) fn advance<const INCREMENTAL: bool>(&mut self) -> StepEnergy {
        let lanes = self.fused::<INCREMENTAL>();
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
        let (dt, theta) = (self.dt, self.theta);
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
