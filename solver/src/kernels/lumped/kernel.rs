//! The lumped central-difference step, O(N) with no global matrices.
//!
//! State: `u^n` and the half-step velocity `v^{n+1/2}`. One step (seed eqs. 2-4 in half-step
//! form, methods.md §2):
//!
//! ```text
//!   u^{n+1}   = u^n + dt v^{n+1/2}
//!   a^{n+1}   = M^-1 (F^{n+1} - K u^{n+1}),   (K u)_i = -[k_i (u_{i+1} - u_i) - k_{i-1} (u_i - u_{i-1})]
//!   v^{n+3/2} = v^{n+1/2} + dt a^{n+1}
//! ```
//!
//! Arrays carry one ghost node at each end (index 0 and N+2) with zero stiffness, mass and
//! motion, so every real node runs the same branch-free stencil. Fixed nodes have `M^-1 = 0`.
//! External forces act on a few nodes: the node loop runs in branch-free segments between them.

use crate::kernels::energy::StepEnergy;
use crate::model::Model;
use crate::simd::{LANES, has_avx2};

/// Nodes per block of the fused displacement and velocity sweep (a multiple of [`LANES`]; the
/// five arrays of a block, 20 KB, stay in L1).
const BLOCK: usize = 512;

/// Partial energy sums, one per lane.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Lanes {
    pub(crate) strain: [f64; LANES],
    pub(crate) staggered: [f64; LANES],
    pub(crate) kinetic: [f64; LANES],
}

impl Lanes {
    /// Lane `l` moves to place `(l + LANES - by) % LANES`: after `rotate_left(by)`, a sweep that
    /// adds its first node to lane 0 adds it to what was lane `by`.
    #[inline(always)]
    pub(crate) fn rotate_left(&mut self, by: usize) {
        self.strain.rotate_left(by);
        self.staggered.rotate_left(by);
        self.kinetic.rotate_left(by);
    }

    /// The inverse of [`Self::rotate_left`].
    #[inline(always)]
    pub(crate) fn rotate_right(&mut self, by: usize) {
        self.strain.rotate_right(by);
        self.staggered.rotate_right(by);
        self.kinetic.rotate_right(by);
    }

    /// The step's energies: `1/2 sum(staggered)`, `1/8 sum(kinetic)`, `1/2 sum(strain)`, each
    /// lane sum taken in lane order.
    #[inline(always)]
    pub(crate) fn energy(&self) -> StepEnergy {
        StepEnergy {
            kinetic_staggered: 0.5 * self.staggered.iter().sum::<f64>(),
            kinetic: 0.125 * self.kinetic.iter().sum::<f64>(),
            strain: 0.5 * self.strain.iter().sum::<f64>(),
        }
    }
}

/// Lumped-mass central difference on a ghost-padded node layout.
#[derive(Debug, Clone)]
pub struct LumpedStep {
    pub(crate) dt: f64,
    /// `k[j]`: stiffness between padded nodes j and j+1 (0 for the ghost links); length N+2.
    pub(crate) k: Vec<f64>,
    /// `dt / m_i` (0 at fixed and ghost nodes); length N+3.
    pub(crate) dt_inverse_mass: Vec<f64>,
    /// `m_i` (0 at ghosts); length N+3.
    pub(crate) mass: Vec<f64>,
    /// Padded displacement `u^n`; length N+3.
    pub(crate) u: Vec<f64>,
    /// Padded half-step velocity `v^{n+1/2}`; length N+3.
    pub(crate) v: Vec<f64>,
    /// Whether the CPU has AVX2 (the step then runs its AVX2-compiled copy).
    pub(crate) avx2: bool,
    /// Threads of a block of steps (`advance_block`, `kernels::lumped::pipeline`); single steps use
    /// one.
    pub(crate) threads: usize,
}

impl LumpedStep {
    /// Set up the operators of `model` for step `dt`, with state `u = u^0` and
    /// `v = v^{1/2}` supplied by the caller (see [`crate::integrator::Start`]).
    pub fn new(model: &Model, dt: f64, u0: &[f64], v_half: &[f64]) -> Self {
        Self::with_half_step_velocity(model, dt, u0, v_half.to_vec())
    }

    /// [`Self::new`] taking `v^{1/2}` by value: it becomes the kernel's padded velocity in place
    /// (grown by its two ghosts before the other arrays are made), so a run never holds two
    /// copies of it. The same values as [`Self::new`].
    pub fn with_half_step_velocity(model: &Model, dt: f64, u0: &[f64], v_half: Vec<f64>) -> Self {
        let n = model.bar().node_count();
        let mut v = v_half;
        v.reserve_exact(2);
        v.insert(0, 0.0);
        v.push(0.0);
        let pad = |inner: &mut dyn Iterator<Item = f64>| -> Vec<f64> {
            std::iter::once(0.0)
                .chain(inner)
                .chain(std::iter::once(0.0))
                .collect()
        };
        let k = pad(&mut model.stiffness().iter().copied());
        let dt_inverse_mass = pad(&mut model.inverse_mass().iter().map(|m| dt * m));
        let mass = pad(&mut model.nodal_mass().iter().copied());
        let u = pad(&mut u0.iter().copied());
        debug_assert_eq!(u.len(), n + 2);
        debug_assert_eq!(v.len(), n + 2);
        Self {
            dt,
            k,
            dt_inverse_mass,
            mass,
            u,
            v,
            avx2: has_avx2(),
            threads: 1,
        }
    }

    /// The time step.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// The threads a block of steps runs on (`advance_block`): 1 unless set (a run sets the
    /// count its [`crate::integrator::Integration`] resolves). The results do not depend on it.
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// Run blocks of steps on `threads` threads (at least 1; at most one per tile is used).
    pub fn set_threads(&mut self, threads: usize) {
        self.threads = threads.max(1);
    }

    /// Displacements `u^n` of the real nodes.
    pub fn displacement(&self) -> &[f64] {
        &self.u[1..self.u.len() - 1]
    }

    /// Half-step velocities `v^{n+1/2}` of the real nodes.
    pub fn half_step_velocity(&self) -> &[f64] {
        &self.v[1..self.v.len() - 1]
    }

    /// Advance one step. `forces` lists `(node, F_node^{n+1})`, sorted by node, each node once.
    #[inline]
    pub fn step(&mut self, forces: &[(usize, f64)]) {
        self.dispatch::<false>(forces);
    }

    /// Advance one step and return the energies at the new level (same arithmetic as
    /// [`Self::step`], so both give bit-identical states).
    #[inline]
    pub fn step_with_energy(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        self.dispatch::<true>(forces)
    }

    /// Run the step compiled for AVX2 where the CPU has it. The arithmetic is the same
    /// element-wise IEEE operations in the same order (Rust never contracts to FMA on its own,
    /// and the energy sums use explicit lanes), so both paths give bit-identical results.
    #[inline(always)]
    fn dispatch<const ENERGY: bool>(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only when the running CPU reports AVX2 support.
            return unsafe { self.advance_avx2::<ENERGY>(forces) };
        }
        self.advance::<ENERGY, false>(forces)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn advance_avx2<const ENERGY: bool>(&mut self, forces: &[(usize, f64)]) -> StepEnergy {
        self.advance::<ENERGY, true>(forces)
    }

    /// One step; `AVX2`: the energy sweep runs its AVX2 intrinsics
    /// ([`crate::kernels::lumped::avx2`]), which only an AVX2-compiled caller may ask for.
    #[inline(always)]
    fn advance<const ENERGY: bool, const AVX2: bool>(
        &mut self,
        forces: &[(usize, f64)],
    ) -> StepEnergy {
        let mut lanes = Lanes::default();
        let real_nodes = self.u.len() - 2;
        let mut u_done = 0; // padded u[..u_done] already hold u^{n+1}
        let mut next = 1; // padded index of the next node to update
        for &(node, force) in forces {
            let p = node + 1;
            self.blocked_sweep::<ENERGY, AVX2>(next, p, &mut u_done, &mut lanes);
            self.advance_displacement(&mut u_done, p + 2);
            self.update_node::<ENERGY>(p, force, &mut lanes);
            next = p + 1;
        }
        self.blocked_sweep::<ENERGY, AVX2>(next, real_nodes + 1, &mut u_done, &mut lanes);
        self.advance_displacement(&mut u_done, real_nodes + 2);
        if ENERGY {
            // Each node adds the strain energy of the link on its right: the real links 1..=N
            // of the padded layout are the right links of the real nodes 1..=N; the last real
            // node's right link is a ghost with k = 0.
            lanes.energy()
        } else {
            StepEnergy::default()
        }
    }

    /// `u^{n+1} = u^n + dt v^{n+1/2}` for padded nodes `*done..to` (none when `to <= *done`);
    /// `*done` becomes `to`.
    #[inline(always)]
    fn advance_displacement(&mut self, done: &mut usize, to: usize) {
        let to = to.min(self.u.len());
        if *done >= to {
            return;
        }
        let dt = self.dt;
        for (u, v) in self.u[*done..to].iter_mut().zip(&self.v[*done..to]) {
            *u += dt * v;
        }
        *done = to;
    }

    /// The velocity update of padded nodes `from..to` (no external force), in blocks of
    /// [`BLOCK`] nodes, each preceded by the displacement update it reads (up to its right
    /// neighbour): the block's `u` and `v` are still in L1 for the sweep, so a step streams each
    /// array once instead of reading `u` and `v` twice. Every value is computed as in two whole
    /// passes (`u` of node `j` is updated before any velocity that reads it and after nothing
    /// writes `v_j`), and blocks start at multiples of [`LANES`] from `from`, so every node adds
    /// to the same energy lane: bit-identical to the unblocked step.
    #[inline(always)]
    fn blocked_sweep<const ENERGY: bool, const AVX2: bool>(
        &mut self,
        from: usize,
        to: usize,
        u_done: &mut usize,
        lanes: &mut Lanes,
    ) {
        let mut start = from;
        while start < to {
            let end = (start + BLOCK).min(to);
            self.advance_displacement(u_done, end + 1);
            self.sweep::<ENERGY, AVX2>(start, end, lanes);
            start = end;
        }
    }

    /// Velocity update of padded nodes `from..to` (no external force), lanes counted from
    /// `from`.
    #[inline(always)]
    pub(crate) fn sweep<const ENERGY: bool, const AVX2: bool>(
        &mut self,
        from: usize,
        to: usize,
        lanes: &mut Lanes,
    ) {
        if from >= to {
            return;
        }
        sweep_nodes::<ENERGY, AVX2>(
            &self.u[from - 1..=to],
            &self.k[from - 1..to],
            &mut self.v[from..to],
            &self.dt_inverse_mass[from..to],
            &self.mass[from..to],
            lanes,
        );
    }

    /// Velocity update of one padded node `p` carrying an external force.
    #[inline(always)]
    pub(crate) fn update_node<const ENERGY: bool>(
        &mut self,
        p: usize,
        force: f64,
        lanes: &mut Lanes,
    ) {
        let u = [self.u[p - 1], self.u[p], self.u[p + 1]];
        let (k, dt_over_m, m) = (
            [self.k[p - 1], self.k[p]],
            self.dt_inverse_mass[p],
            self.mass[p],
        );
        update_one_node::<ENERGY>(u, k, Some(force), &mut self.v[p], [dt_over_m, m], lanes, 0);
    }
}

/// The velocity update of one node from `u = [u_{j-1}, u_j, u_{j+1}]`, `k = [k_{j-1}, k_j]`,
/// its external force `F_j` if loaded and `[dt/m_j, m_j]`, adding its energy terms to `lane`:
///
/// ```text
///   r = k_j (u_{j+1} - u_j) - k_{j-1} (u_j - u_{j-1}) [+ F_j],   v' = v + dt/m_j r,
///   strain += k_j (u_{j+1} - u_j)^2,  staggered += m_j v v',  kinetic += m_j (v + v')^2,
/// ```
///
/// the operations of [`sweep_nodes`] for an unloaded node (no `+ 0.0`: it would turn a `-0.0`
/// into `+0.0`).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn update_one_node<const ENERGY: bool>(
    u: [f64; 3],
    k: [f64; 2],
    force: Option<f64>,
    v: &mut f64,
    [dt_over_m, m]: [f64; 2],
    lanes: &mut Lanes,
    lane: usize,
) {
    let right = u[2] - u[1];
    let r = k[1] * right - k[0] * (u[1] - u[0]);
    let r = match force {
        Some(force) => r + force,
        None => r,
    };
    let old = *v;
    let new = old + dt_over_m * r;
    *v = new;
    if ENERGY {
        lanes.strain[lane] += k[1] * right * right;
        lanes.staggered[lane] += m * old * new;
        lanes.kinetic[lane] += m * (old + new) * (old + new);
    }
}

/// Velocity update of the nodes of `v` (no external force), node `i` of the slice adding to
/// lane `i % LANES`: `u` and `k` start one node to the left (`u.len() = v.len() + 2`,
/// `k.len() = v.len() + 1`), `s` = `dt/m`, `m` the masses.
#[inline(always)]
pub(crate) fn sweep_nodes<const ENERGY: bool, const AVX2: bool>(
    u: &[f64],
    k: &[f64],
    v: &mut [f64],
    s: &[f64],
    m: &[f64],
    lanes: &mut Lanes,
) {
    if ENERGY {
        // Node i adds to lane i % LANES: independent partial sums the compiler can keep
        // in vector registers; fixed order, so the result is deterministic.
        let (mut strain, mut staggered, mut kinetic) =
            (lanes.strain, lanes.staggered, lanes.kinetic);
        #[cfg(target_arch = "x86_64")]
        let avx2_done = if AVX2 {
            // SAFETY: `AVX2` is true only in functions compiled with AVX2 and called only when
            // the CPU has it (`advance_avx2`, the tiled kernel's AVX2 copies).
            Some(unsafe {
                crate::kernels::lumped::avx2::sweep_with_energy(
                    u,
                    k,
                    v,
                    s,
                    m,
                    &mut strain,
                    &mut staggered,
                    &mut kinetic,
                )
            })
        } else {
            None
        };
        #[cfg(not(target_arch = "x86_64"))]
        let avx2_done: Option<usize> = None;
        let whole = v.len() / LANES * LANES;
        let portable_from = avx2_done.unwrap_or(0);
        for base in (portable_from..whole).step_by(LANES) {
            let uu: &[f64; LANES + 2] = u[base..base + LANES + 2]
                .try_into()
                .expect("fixed-size window");
            let kk: &[f64; LANES + 1] = k[base..base + LANES + 1]
                .try_into()
                .expect("fixed-size window");
            let ss: &[f64; LANES] = s[base..base + LANES].try_into().expect("fixed-size window");
            let mm: &[f64; LANES] = m[base..base + LANES].try_into().expect("fixed-size window");
            let vv: &mut [f64; LANES] = (&mut v[base..base + LANES])
                .try_into()
                .expect("fixed-size window");
            for l in 0..LANES {
                let right = uu[l + 2] - uu[l + 1];
                let r = kk[l + 1] * right - kk[l] * (uu[l + 1] - uu[l]);
                let old = vv[l];
                let new = old + ss[l] * r;
                vv[l] = new;
                strain[l] += kk[l + 1] * right * right;
                staggered[l] += mm[l] * old * new;
                kinetic[l] += mm[l] * (old + new) * (old + new);
            }
        }
        for i in whole..v.len() {
            let (l, right) = (i % LANES, u[i + 2] - u[i + 1]);
            let r = k[i + 1] * right - k[i] * (u[i + 1] - u[i]);
            let old = v[i];
            let new = old + s[i] * r;
            v[i] = new;
            strain[l] += k[i + 1] * right * right;
            staggered[l] += m[i] * old * new;
            kinetic[l] += m[i] * (old + new) * (old + new);
        }
        *lanes = Lanes {
            strain,
            staggered,
            kinetic,
        };
    } else {
        for i in 0..v.len() {
            let r = k[i + 1] * (u[i + 2] - u[i + 1]) - k[i] * (u[i + 1] - u[i]);
            v[i] += s[i] * r;
        }
    }
}

/// Real nodes from which a run's blocks of steps use several threads
/// ([`crate::integrator::Integration::threads`]; below, one thread: each thread's region should
/// hold many tiles for the pipeline to pay).
pub const PARALLEL_FROM_NODES: usize = 100_000;

#[cfg(test)]
mod tests {
    use super::*;

    use crate::fixtures::graded_test_kernel as graded_kernel;

    #[test]
    fn vector_and_portable_paths_and_energy_variant_are_bit_identical() {
        let forces = [(0, 1.0), (57, -0.25)];
        let mut fast = graded_kernel(203);
        let mut portable = graded_kernel(203);
        portable.avx2 = false;
        let mut plain = graded_kernel(203);
        for _ in 0..500 {
            let a = fast.step_with_energy(&forces);
            let b = portable.step_with_energy(&forces);
            plain.step(&forces);
            assert_eq!(a, b);
        }
        assert_eq!(fast.u, portable.u);
        assert_eq!(fast.v, portable.v);
        assert_eq!(fast.u, plain.u);
        assert_eq!(fast.v, plain.v);
    }

    /// The step as two whole passes (all `u`, then every `v` in order, node `i` of a segment
    /// between loaded nodes adding to lane `(i - start) % 8`, a loaded node to lane 0): the
    /// unblocked form of the step.
    fn two_pass_reference(kernel: &mut LumpedStep, forces: &[(usize, f64)]) -> StepEnergy {
        let k = &kernel.k;
        for (u, v) in kernel.u.iter_mut().zip(&kernel.v) {
            *u += kernel.dt * v;
        }
        let u = &kernel.u;
        let mut lanes = Lanes::default();
        let mut start = 1;
        for p in 1..u.len() - 1 {
            let force = forces.iter().find(|f| f.0 + 1 == p).map(|f| f.1);
            let l = if force.is_some() {
                0
            } else {
                (p - start) % LANES
            };
            let right = u[p + 1] - u[p];
            let r = k[p] * right - k[p - 1] * (u[p] - u[p - 1]);
            let r = force.map_or(r, |f| r + f);
            let old = kernel.v[p];
            let new = old + kernel.dt_inverse_mass[p] * r;
            kernel.v[p] = new;
            lanes.strain[l] += k[p] * right * right;
            lanes.staggered[l] += kernel.mass[p] * old * new;
            lanes.kinetic[l] += kernel.mass[p] * (old + new) * (old + new);
            if force.is_some() {
                start = p + 1;
            }
        }
        StepEnergy {
            kinetic_staggered: 0.5 * lanes.staggered.iter().sum::<f64>(),
            kinetic: 0.125 * lanes.kinetic.iter().sum::<f64>(),
            strain: 0.5 * lanes.strain.iter().sum::<f64>(),
        }
    }

    #[test]
    fn blocked_step_is_bit_identical_to_two_whole_passes() {
        // Segments longer than a block, a load inside a block and one at a block edge.
        let forces = [(0, 1.0), (700, -0.25), (1 + 2 * BLOCK, 0.5)];
        for avx2 in [false, has_avx2()] {
            let mut blocked = graded_kernel(3 * BLOCK + 37);
            blocked.avx2 = avx2;
            let mut reference = graded_kernel(3 * BLOCK + 37);
            for _ in 0..200 {
                let a = blocked.step_with_energy(&forces);
                let b = two_pass_reference(&mut reference, &forces);
                assert_eq!(a, b);
            }
            assert_eq!(blocked.u, reference.u);
            assert_eq!(blocked.v, reference.v);
            // The step without energy sums runs the same blocks: the same states.
            let mut plain = graded_kernel(3 * BLOCK + 37);
            plain.avx2 = avx2;
            for _ in 0..200 {
                plain.step(&forces);
            }
            assert_eq!(plain.u, reference.u);
            assert_eq!(plain.v, reference.v);
        }
    }
}
