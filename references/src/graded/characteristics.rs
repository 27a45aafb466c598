//! Route (b) to the graded bar's field: characteristics in `(xi, eta) = (t - tau, t + tau)`
//! with tracked fronts.
//!
//! The characteristic system of the bar (module docs of `bar`, "Characteristics and the
//! transport of jumps") is integrated on a lattice of characteristics `xi = t - tau = const`,
//! `eta = t + tau = const` that contains the fronts (`xi = 2kT`, `eta = 2(k+1)T`) and the
//! target point as lattice lines; it is 2T-periodic and piecewise uniform, and each node keeps
//! the values on both sides of a front through it (the jumps are the constant `[p]`, `[m]` of
//! the jump law). The trapezoidal rule along both families (a 2x2 solve per node) is second
//! order with an error expansion in even powers of the mesh size; four levels of Richardson
//! extrapolation give about 1e-13. It never uses Bessel functions or transforms.

use super::bar::{FieldPoint, GradedBar};

/// Lattice cells per transit on the coarsest level of route (b).
pub const CHARACTERISTIC_CELLS: usize = 16;
/// Number of levels (each halving the cells) combined by Richardson extrapolation.
pub const CHARACTERISTIC_LEVELS: usize = 4;
/// Route (b) declines (returns NaN) beyond this many transits: its cost grows like t.
pub const CHARACTERISTIC_TRANSITS_MAX: f64 = 1000.0;
/// Largest number of levels accepted by [`GradedBar::state_characteristics_with`].
pub const CHARACTERISTIC_LEVELS_MAX: usize = 8;

/// Per-period layout of the characteristic lattice: line positions within `[0, 2T)` and the
/// index of each breakpoint.
struct Lattice {
    period: f64,
    breaks: Vec<f64>,
    offsets: Vec<usize>,
    within: Vec<f64>,
    tol: f64,
}

impl Lattice {
    /// Lines per period.
    fn lines(&self) -> usize {
        self.within.len()
    }

    fn theta(&self, k: usize) -> f64 {
        let lines = self.lines();
        (k / lines) as f64 * self.period + self.within[k % lines]
    }

    /// `v` reduced to `[0, 2T)`, snapped to 0 within the tolerance.
    fn reduce(period: f64, tol: f64, v: f64) -> f64 {
        let r = v - period * (v / period).floor();
        if r < tol || period - r < tol { 0.0 } else { r }
    }

    /// Index of the lattice line at value v (a breakpoint by construction).
    fn locate(&self, v: f64) -> Option<usize> {
        let periods = ((v + self.tol) / self.period).floor();
        let r = Self::reduce(self.period, self.tol, v);
        let bi = self.breaks.iter().position(|&b| (b - r).abs() < self.tol)?;
        Some(periods as usize * self.lines() + self.offsets[bi])
    }
}

impl GradedBar {
    /// Default coarsest resolution of route (b): [`CHARACTERISTIC_CELLS`] per transit, more
    /// for strong gradings so that `kappa_max h <= 0.1`.
    #[must_use]
    pub fn characteristic_cells(&self) -> usize {
        let needed = (10.0 * self.kappa_max() * self.transit_time()).ceil();
        CHARACTERISTIC_CELLS.max(needed.min(1e6) as usize)
    }

    /// Route (b) with the default resolution ([`Self::characteristic_cells`] per transit,
    /// [`CHARACTERISTIC_LEVELS`] levels): about 1e-13 |sigma0|.
    #[must_use]
    pub fn state_characteristics(&self, x: f64, t: f64) -> FieldPoint {
        self.state_characteristics_with(x, t, self.characteristic_cells(), CHARACTERISTIC_LEVELS)
    }

    /// Route (b): method of characteristics in the travel-time coordinate with the fronts as
    /// lattice lines (module documentation), `cells_per_transit` cells per transit on the
    /// coarsest of `levels` lattices, combined by Richardson extrapolation in `h^2`
    /// (`levels = 1`: the plain second-order result). Right-continuous in t.
    ///
    /// Cost grows like `t/T (cells 2^levels)^2`. NaN for x outside `[0, L]`, non-finite input,
    /// `cells_per_transit = 0`, `levels` not in `1..=8`, or `t > 1000 T`
    /// ([`CHARACTERISTIC_TRANSITS_MAX`]).
    #[must_use]
    pub fn state_characteristics_with(
        &self,
        x: f64,
        t: f64,
        cells_per_transit: usize,
        levels: usize,
    ) -> FieldPoint {
        if !self.in_bar(x)
            || !t.is_finite()
            || cells_per_transit == 0
            || !(1..=CHARACTERISTIC_LEVELS_MAX).contains(&levels)
        {
            return FieldPoint::NAN;
        }
        let tau = self
            .travel_time(x.clamp(0.0, self.length()))
            .min(self.transit_time());
        let tol = self.time_tolerance(t);
        if t - tau < -tol {
            return FieldPoint::ZERO;
        }
        if t > CHARACTERISTIC_TRANSITS_MAX * self.transit_time() {
            return FieldPoint::NAN;
        }
        let sqrt_z = self.impedance_at_travel_time(tau).sqrt();
        let mut table = Vec::with_capacity(levels);
        for level in 0..levels {
            let Some((p, m)) = self.characteristics_once(tau, t, cells_per_transit, 1 << level)
            else {
                return FieldPoint::NAN;
            };
            table.push([sqrt_z * (p + m), (m - p) / sqrt_z]);
        }
        let mut factor = 4.0;
        while table.len() > 1 {
            table = table
                .windows(2)
                .map(|w| [0, 1].map(|i| (factor * w[1][i] - w[0][i]) / (factor - 1.0)))
                .collect();
            factor *= 4.0;
        }
        FieldPoint {
            stress: table[0][0],
            velocity: table[0][1],
        }
    }

    /// One lattice solve; returns the wave amplitudes (p, m) at the target after every front
    /// through it. `refine` multiplies the cells of every segment (uniform refinement of one
    /// piecewise-uniform lattice, so that the Richardson expansion holds).
    fn characteristics_once(
        &self,
        tau: f64,
        t: f64,
        cells: usize,
        refine: usize,
    ) -> Option<(f64, f64)> {
        let transit = self.transit_time();
        let period = 2.0 * transit;
        let tol = self.time_tolerance(t);
        let (xi, eta) = ((t - tau).max(0.0), t + tau);
        let mut breaks = vec![0.0];
        for v in [xi, eta].map(|v| Lattice::reduce(period, tol, v)) {
            if breaks.iter().all(|&b| (b - v).abs() >= tol) {
                breaks.push(v);
            }
        }
        breaks.sort_by(f64::total_cmp);
        let h = transit / cells as f64;
        let (mut within, mut offsets) = (Vec::new(), Vec::new());
        for (i, &b0) in breaks.iter().enumerate() {
            let b1 = breaks.get(i + 1).copied().unwrap_or(period);
            let n = ((b1 - b0) / h).ceil().max(1.0) as usize * refine;
            offsets.push(within.len());
            within.extend((0..n).map(|j| b0 + (b1 - b0) * j as f64 / n as f64));
        }
        let lattice = Lattice {
            period,
            breaks,
            offsets,
            within,
            tol,
        };
        let lines = lattice.lines();
        let (jx, je) = (lattice.locate(xi)?, lattice.locate(eta)?);
        if je < jx || je - jx > lines {
            return None;
        }
        // Boundary value of p + m and the constant jump [p] of pass n (sign (-1)^n).
        let p_bc = self.sigma0() / self.z1().sqrt();
        let jump = |n: usize| if n.is_multiple_of(2) { p_bc } else { -p_bc };
        // Per xi-line j, at its last node: p before any front, m after, kappa.
        let mut line_p = vec![0.0; jx + 1];
        let mut line_m = vec![0.0; jx + 1];
        let mut line_kappa = vec![0.0; jx + 1];
        let mut result = None;
        for k in 0..=je {
            let eta_k = lattice.theta(k);
            let deta = if k > 0 {
                eta_k - lattice.theta(k - 1)
            } else {
                0.0
            };
            // Along eta-line k, at the previous node: m before, p after, kappa, xi.
            let (mut prev_m, mut prev_p, mut prev_kappa, mut prev_xi) = (0.0, 0.0, 0.0, 0.0);
            for j in k.saturating_sub(lines)..=k.min(jx) {
                let xi_j = lattice.theta(j);
                let kappa = self.kappa(0.5 * (eta_k - xi_j));
                let dxi = xi_j - prev_xi;
                let (p, m) = if j == 0 {
                    // On the first front: ahead of it everything is at rest.
                    (0.0, 0.0)
                } else if j == k {
                    // Loaded end: p + m = p_bc.
                    let m = (prev_m + 0.25 * dxi * (prev_kappa * prev_p + kappa * p_bc))
                        / (1.0 + 0.25 * dxi * kappa);
                    (p_bc - m, m)
                } else if k - j == lines {
                    // Fixed end: m = p.
                    let p = (line_p[j] - 0.25 * deta * line_kappa[j] * line_m[j])
                        / (1.0 + 0.25 * deta * kappa);
                    (p, p)
                } else {
                    let (aa, bb) = (0.25 * deta * kappa, 0.25 * dxi * kappa);
                    let p1 = line_p[j] - 0.25 * deta * line_kappa[j] * line_m[j];
                    let m1 = prev_m + 0.25 * dxi * prev_kappa * prev_p;
                    let p = (p1 - aa * m1) / (1.0 + aa * bb);
                    (p, m1 + bb * p)
                };
                let p_after = if j.is_multiple_of(lines) {
                    p + jump(j / lines)
                } else {
                    p
                };
                let m_after = if k.is_multiple_of(lines) && k >= lines {
                    m + jump(k / lines - 1)
                } else {
                    m
                };
                line_p[j] = p;
                line_m[j] = m_after;
                line_kappa[j] = kappa;
                (prev_m, prev_p, prev_kappa, prev_xi) = (m, p_after, kappa, xi_j);
                if j == jx && k == je {
                    result = Some((p_after, m_after));
                }
            }
        }
        result
    }
}
