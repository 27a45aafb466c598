//! Tiled solves of an SPD tridiagonal mass (CMM, AMM) on overlapping windows: `M^-1 r` as
//! independent local solves, so the step can solve each stretch of the bar while its residual is
//! still in cache, and twelve recurrences run side by side in three AVX2 registers.
//!
//! Why a window suffices. The inverse of a banded SPD matrix decays geometrically away from its
//! diagonal (Demko, Moss and Smith, Math. Comp. 43 (1984) 491-499, the positive definite case): for
//! a tridiagonal `S` with spectrum in `[a, b]`, `kappa = b/a`,
//!
//! ```text
//!   |(S^-1)_ij| <= C q^|i-j|,   q = (sqrt(kappa) - 1)/(sqrt(kappa) + 1),
//!   C = max(1/a, (1 + sqrt(kappa))^2/(2b))
//! ```
//!
//! Scaled by the lumped mass `A` (`S = A^-1/2 M A^-1/2`), the element masses
//! `(1 - beta) CMM + beta LMM` have Rayleigh quotients `v.M_e v / v.A_e v` between their two
//! eigenvalue ratios, 1 (the rigid mode) and `(1 + 2 beta)/3` (the antisymmetric one), so the
//! assembled `S` has its spectrum in `[min, max]` of those whatever the mesh grading:
//! `kappa = 3` for CMM (`q = 2 - sqrt(3) = 0.268`, the uniform mesh's exact decay), 1.5 for
//! AMM(1/2) (`q = 0.101`). Fixed nodes are decoupled rows; they only cut the matrix into
//! blocks, each with the same bound.
//!
//! A tile of `T` rows (344 to 1024, as [`tile_rows`] fits them to the bar) is solved on a window of
//! `T + 2H` rows, `H` (the halo) more on each side, shifted inward at the bar's ends. The window's
//! solution differs from the whole solution by the response to the two couplings it cuts, at least
//! `H` rows from any row of the tile: `|x_i - x~_i| <= C q^H s sqrt(m_cut/m_i) |x_cut|`,
//! `s = |1 - beta|/3` the largest scaled coupling `M_i,i+1 / sqrt(A_i A_i+1)` and `x_cut` the
//! solution just outside the window. `H` is the least multiple of 4 with `C q^H <= 2^-66`: with
//! `s = 1/3` (CMM) the truncation stays below `2^-13 u |x_cut|` (`u = 2^-53`, the unit round-off)
//! for mass ratios up to 9 across a halo and below `u |x_cut|` up to `9 2^26`: the tiles give the
//! solution to round-off, like the global factor (`crate::mass::partitioned_ldl`), not
//! bit-identical to it. CMM: `H = 36`; AMM(1/2): `H = 24`.
//!
//! Each window is factored once (`L D L^T`, no pivoting: its rows are a principal submatrix of
//! an SPD matrix); a step runs, per window, the forward recurrence `z_k = r_k - l_{k-1} z_{k-1}`
//! and the backward one `x_k = z_k / d_k - l_k x_{k+1}`, each a fused multiply-add (one
//! rounding) per row on a chain of latencies. `WINDOWS_PER_GROUP` (12) windows form a group and run
//! interleaved; the residual rows are transposed in 4 x 4 blocks into group layout (row `k` of
//! the 12 windows side by side) and the solution back into window-major order (`avx2`).
//! The portable loops do the same arithmetic: the same bits with or without AVX2.
//!
//! **Shared factors.** A window's factors depend only on its rows of the matrix. Where every
//! window of a group has the same rows, bit for bit (a bar of uniform element mass `rho A h`,
//! whatever its stiffness), the group uses one set of factors, `2 (T + 2H)` values that stay
//! in cache and are broadcast to every lane; consecutive such groups with the same rows share one
//! set. Other groups keep a block of per-window factors in group layout (row `k`: `l_k` of the
//! 12 windows, then their `1/d_k`). Both give the same bits (the same values enter the same
//! operations); sharing only removes a stream of 16 B per row from every step (measured in
//! `benches/RESULTS.md`).

#[cfg(target_arch = "x86_64")]
mod avx2;
mod group;

pub(crate) use group::WINDOWS_PER_GROUP;

use crate::mass::tridiagonal::Tridiagonal;

/// The longest tile (rows whose solution a window gives). A bar's tiles are as long as
/// [`tile_rows`] makes them, at most this. Chosen by measurement (CMM steps, ns per node-step;
/// benches/RESULTS.md, heading "... wider windows; where the CMM step's time goes"): tiles of
/// 1024 against 512 took N = 1e6 from 1.06-1.25 to 0.97-1.02 and left N = 1e5 at 0.84-0.86. A
/// group's forward results (`WINDOWS_PER_GROUP (T + 2H)` values: 105 KB for CMM with twelve
/// windows, 70 KB with eight) do not fit a 48 KB L1 (with eight windows 512's did), but the
/// longer, fewer interruptions of the residual sweep and the halo's smaller share (7 % of the
/// rows, 14 % with 512) gain more; 1536-2560 were no faster at 1e6. With twelve windows
/// (heading "... twelve windows per group ...") 768 and 896 were slower at both sizes, and 1280
/// as fast at 1e6 (0.885-0.910 against 0.896-0.917) but slower at 1e5 (0.810 against
/// 0.771-0.778).
pub(crate) const MAX_TILE: usize = 1024;

/// The shortest tile: a matrix shorter than [`WINDOWS_PER_GROUP`] of them keeps the global
/// factor (as fast there): 4096 rows shared by the windows of one group, rounded up to a
/// multiple of [`crate::simd::LANES`] (windows pay from 4096 rows; benches/RESULTS.md, heading
/// "2026-11-27, AMD: shared window factors, constant RMM blocks, the critical step").
const MIN_TILE: usize = 4096usize
    .div_ceil(WINDOWS_PER_GROUP)
    .next_multiple_of(crate::simd::LANES);

/// The tile length for a matrix of order `n`: as many groups of [`WINDOWS_PER_GROUP`] tiles as
/// tiles of [`MAX_TILE`] need, and tiles just long enough (a multiple of [`crate::simd::LANES`])
/// for those groups to cover the rows, so a short last group is not padded with copies of its last
/// window (with a fixed 1024, a bar of 20 000 nodes solved 24 windows for 20 tiles and its CMM step
/// ran 0.97-0.99 ns against 0.87-0.90 with 512; benches/RESULTS.md). Between
/// `WINDOWS_PER_GROUP MIN_TILE` and `WINDOWS_PER_GROUP MAX_TILE` rows it is one group; beyond,
/// between `MAX_TILE / 2` and `MAX_TILE`.
pub(crate) fn tile_rows(n: usize) -> usize {
    let groups = n.div_ceil(WINDOWS_PER_GROUP * MAX_TILE).max(1);
    n.div_ceil(WINDOWS_PER_GROUP * groups)
        .next_multiple_of(crate::simd::LANES)
}

/// The largest halo worth the overlap (a quarter of the longest tile on each side); masses whose
/// inverse decays more slowly (AMM or RMM-like `beta` near `-1/2`) keep the global factor.
const MAX_HALO: usize = MAX_TILE / 4;

/// The truncation bound `C q^H` a halo must reach (see the module docs).
const TRUNCATION: f64 = 1.0 / (1u128 << 66) as f64;

/// The spectral ratio `kappa` of the lumped-scaled mass `A^-1/2 M A^-1/2` for element masses
/// `(1 - beta) CMM + beta LMM` (see the module docs): `max(3/(1 + 2 beta), (1 + 2 beta)/3)`.
pub(crate) fn scaled_spectral_ratio(beta: f64) -> f64 {
    let antisymmetric = (1.0 + 2.0 * beta) / 3.0;
    antisymmetric.max(1.0 / antisymmetric)
}

/// The least multiple of 4 with `C q^H <= 2^-66` for a scaled spectrum `[a, b]` that contains
/// 1 with `kappa = b/a` (module docs), `None` above [`MAX_HALO`].
pub(crate) fn halo_rows(kappa: f64) -> Option<usize> {
    if !(kappa.is_finite() && kappa >= 1.0) {
        return None;
    }
    let root = kappa.sqrt();
    let q = (root - 1.0) / (root + 1.0);
    // Spectrum [a, b] with a <= 1 <= b and b/a = kappa: the largest C over such spectra.
    let constant = kappa.max((1.0 + root).powi(2) / 2.0);
    if q == 0.0 {
        return Some(4);
    }
    let rows = ((TRUNCATION / constant).ln() / q.ln()).ceil().max(1.0) as usize;
    let rows = rows.div_ceil(4) * 4;
    (rows <= MAX_HALO).then_some(rows)
}

/// The windows and their factors (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct HaloTiles {
    /// Order of the matrix.
    n: usize,
    /// Rows of a tile ([`tile_rows`]).
    tile: usize,
    /// Rows of a window, `tile + 2 H`.
    window: usize,
    /// First row of each window, [`WINDOWS_PER_GROUP`] per group (the last group padded with copies
    /// of the last window).
    starts: Vec<usize>,
    /// Per group, where its factors are (`l` is 0 at a window's last row).
    group_factors: Vec<GroupFactors>,
    /// Factor sets shared by all windows of a group, each `[l_k, 1/d_k]` for `k < window`.
    shared: Vec<f64>,
    /// Per-window factors of the other groups, each block row-major by window row `k`: `l_k`
    /// of the [`WINDOWS_PER_GROUP`] windows, then their `1/d_k`.
    lanes: Vec<f64>,
    /// Per group, the lowest window row whose solution a tile of the group uses (a multiple of
    /// 4): the backward sweep stops there.
    lowest: Vec<usize>,
    /// Fixed (decoupled) rows, ascending: their solution is `+0`.
    fixed: Vec<usize>,
    /// Whether the CPU has AVX2 and FMA (what the intrinsics need); always false elsewhere.
    simd: bool,
}

/// Where a group's factors are (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
enum GroupFactors {
    /// One set for every window of the group: offset in `HaloTiles::shared`.
    Shared(usize),
    /// One per window, in group layout: offset in `HaloTiles::lanes`.
    Lanes(usize),
}

/// A group's factors as the solve reads them: `l_k` of window `c` is `Shared(f)[2 k]` or
/// `Lanes(f)[2 k WINDOWS_PER_GROUP + c]`, `1/d_k` the next value or the next row of the block.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Factors<'f> {
    Shared(&'f [f64]),
    Lanes(&'f [f64]),
}

impl Factors<'_> {
    /// `(l_k, 1/d_k)` of window `c`.
    #[inline(always)]
    fn row(self, k: usize, c: usize) -> (f64, f64) {
        match self {
            Factors::Shared(f) => (f[2 * k], f[2 * k + 1]),
            Factors::Lanes(f) => (
                f[2 * k * WINDOWS_PER_GROUP + c],
                f[(2 * k + 1) * WINDOWS_PER_GROUP + c],
            ),
        }
    }
}

/// The work arrays of one group's solve: the rows in group layout and the solution by window.
#[derive(Debug, Clone, Default)]
pub(crate) struct GroupBuffers {
    /// `window x WINDOWS_PER_GROUP`: row `k` of window `c` at `k * WINDOWS_PER_GROUP + c`.
    rows: Vec<f64>,
    /// `WINDOWS_PER_GROUP x window`: row `k` of window `c` at `c * window + k`.
    solution: Vec<f64>,
}

impl HaloTiles {
    /// Tiles for `m` (fixed rows decoupled: unit diagonal, zero couplings, listed in `fixed`)
    /// with halo `halo` (a multiple of 4 up to `MAX_TILE / 4`, from `halo_rows`); `None` for any
    /// other halo, when the matrix is shorter than a group of windows (the global factor is as
    /// fast there) or when it is not positive definite (a pivot of its `L D L^T` factorisation
    /// is not positive: the caller's global factor then reports it).
    pub fn new(m: &Tridiagonal, halo: usize, fixed: &[usize]) -> Option<Self> {
        Self::with_sharing(m, halo, fixed, true)
    }

    /// [`Self::new`], with factors shared between windows of equal rows or not (`share`; the
    /// tests compare both).
    fn with_sharing(m: &Tridiagonal, halo: usize, fixed: &[usize], share: bool) -> Option<Self> {
        let n = m.diag.len();
        let tile = tile_rows(n);
        let window = tile + 2 * halo;
        if !halo.is_multiple_of(4)
            || halo > MAX_HALO
            || n < WINDOWS_PER_GROUP * MIN_TILE
            || n < window
        {
            return None;
        }
        let tiles = n.div_ceil(tile);
        let groups = tiles.div_ceil(WINDOWS_PER_GROUP);
        let start_of = |t: usize| (t * tile).saturating_sub(halo).min(n - window);
        let mut starts = Vec::with_capacity(groups * WINDOWS_PER_GROUP);
        let (mut shared, mut lanes, mut group_factors) = (Vec::new(), Vec::new(), Vec::new());
        // The first row of the window whose factors the last shared set holds.
        let mut shared_from: Option<usize> = None;
        let mut lowest = Vec::with_capacity(groups);
        let (mut lower, mut pivot) = (vec![0.0; n], vec![0.0; n]);
        // Positive definite iff every pivot of the whole factorisation is positive (each window
        // is then positive definite too, as a principal submatrix).
        if !crate::mass::partitioned_ldl::factor_rows(m, 0..n, &mut lower, &mut pivot) {
            return None;
        }
        // Factor the window at `start` into the scratch rows `start..start + window`.
        let factor = |start: usize, lower: &mut [f64], pivot: &mut [f64]| {
            let rows = start..start + window;
            let positive = crate::mass::partitioned_ldl::factor_rows(m, rows, lower, pivot);
            debug_assert!(positive, "a principal submatrix of an SPD matrix is SPD");
        };
        for g in 0..groups {
            let group_starts: [usize; WINDOWS_PER_GROUP] =
                std::array::from_fn(|c| start_of((g * WINDOWS_PER_GROUP + c).min(tiles - 1)));
            let low = (0..WINDOWS_PER_GROUP)
                .map(|c| (g * WINDOWS_PER_GROUP + c).min(tiles - 1) * tile - group_starts[c])
                .min()
                .unwrap_or(window);
            lowest.push(low / 4 * 4);
            starts.extend(group_starts);
            let first = group_starts[0];
            if share && group_starts.iter().all(|&s| same_rows(m, window, first, s)) {
                if !shared_from.is_some_and(|from| same_rows(m, window, from, first)) {
                    shared_from = Some(first);
                    factor(first, &mut lower, &mut pivot);
                    let rows = first..first + window;
                    shared.extend(rows.flat_map(|i| [lower[i], pivot[i]]));
                }
                group_factors.push(GroupFactors::Shared(shared.len() - 2 * window));
            } else {
                let offset = lanes.len();
                lanes.resize(offset + 2 * window * WINDOWS_PER_GROUP, 0.0);
                for (c, &start) in group_starts.iter().enumerate() {
                    factor(start, &mut lower, &mut pivot);
                    for k in 0..window {
                        lanes[offset + 2 * k * WINDOWS_PER_GROUP + c] = lower[start + k];
                        lanes[offset + (2 * k + 1) * WINDOWS_PER_GROUP + c] = pivot[start + k];
                    }
                }
                group_factors.push(GroupFactors::Lanes(offset));
            }
        }
        Some(Self {
            n,
            tile,
            window,
            starts,
            group_factors,
            shared,
            lanes,
            lowest,
            fixed: fixed.to_vec(),
            simd: crate::simd::has_avx2() && crate::simd::has_fma(),
        })
    }

    /// The factors of group `g`.
    fn factors(&self, g: usize) -> Factors<'_> {
        let span = 2 * self.window;
        match self.group_factors[g] {
            GroupFactors::Shared(at) => Factors::Shared(&self.shared[at..at + span]),
            GroupFactors::Lanes(at) => {
                Factors::Lanes(&self.lanes[at..at + span * WINDOWS_PER_GROUP])
            }
        }
    }

    /// Number of groups of [`WINDOWS_PER_GROUP`] windows.
    pub(crate) fn groups(&self) -> usize {
        self.lowest.len()
    }

    /// Rows of a tile.
    #[cfg(test)]
    pub(crate) fn tile(&self) -> usize {
        self.tile
    }

    /// Rows of a window (tile + `2 H`).
    pub fn window(&self) -> usize {
        self.window
    }

    /// One past the last row of the right-hand side that group `g` reads.
    pub(crate) fn rows_read(&self, g: usize) -> usize {
        let starts = &self.starts[g * WINDOWS_PER_GROUP..(g + 1) * WINDOWS_PER_GROUP];
        starts.iter().max().map_or(0, |s| s + self.window)
    }

    /// The tiles of group `g`: `(window index c, tile rows)`.
    pub(crate) fn group_tiles(
        &self,
        g: usize,
    ) -> impl Iterator<Item = (usize, std::ops::Range<usize>)> {
        let (n, first) = (self.n, g * WINDOWS_PER_GROUP);
        let tile = self.tile;
        (first..n.div_ceil(tile).min(first + WINDOWS_PER_GROUP))
            .map(move |t| (t - first, t * tile..((t + 1) * tile).min(n)))
    }

    /// Work arrays for [`Self::solve_group`].
    pub(crate) fn buffers(&self) -> GroupBuffers {
        GroupBuffers {
            rows: vec![0.0; self.window * WINDOWS_PER_GROUP],
            solution: vec![0.0; WINDOWS_PER_GROUP * self.window],
        }
    }

    /// Solve the windows of group `g` for the right-hand side `r` (the whole vector; rows up
    /// to [`Self::rows_read`] are read), with the intrinsics where the CPU has AVX2 and FMA,
    /// the portable loops otherwise: the same bits. Afterwards [`Self::tile_solution`] gives
    /// each tile's rows.
    pub(crate) fn solve_group(&self, g: usize, r: &[f64], buffers: &mut GroupBuffers) {
        self.solve_group_at(g, r, 0, buffers);
    }

    /// The first row of the right-hand side that group `g` reads.
    pub(crate) fn first_row_read(&self, g: usize) -> usize {
        let starts = &self.starts[g * WINDOWS_PER_GROUP..(g + 1) * WINDOWS_PER_GROUP];
        starts.iter().copied().min().unwrap_or(0)
    }

    /// [`Self::solve_group`] with `r` holding the rows from `offset` on (`offset` at most
    /// [`Self::first_row_read`]): the same values enter the same operations, the same bits.
    pub(crate) fn solve_group_at(
        &self,
        g: usize,
        r: &[f64],
        offset: usize,
        buffers: &mut GroupBuffers,
    ) {
        let window = self.window;
        // The AVX2 path reads `r` at `starts[c] + ...` unchecked: an offset past the group's
        // first row would wrap these subtractions (release builds) into an out-of-bounds read.
        assert!(offset <= self.first_row_read(g));
        let starts: [usize; WINDOWS_PER_GROUP] =
            std::array::from_fn(|c| self.starts[g * WINDOWS_PER_GROUP + c] - offset);
        let starts = &starts;
        let factors = self.factors(g);
        let lowest = self.lowest[g];
        assert!(
            r.len() + offset >= self.rows_read(g)
                && buffers.rows.len() == window * WINDOWS_PER_GROUP
        );
        assert!(buffers.solution.len() == WINDOWS_PER_GROUP * window && window.is_multiple_of(4));
        let (input, extent) = ((factors, starts, r), (window, lowest));
        let output = [&mut buffers.rows[..], &mut buffers.solution[..]];
        if self.simd {
            // SAFETY: `simd` is set only when the CPU reports AVX2 and FMA; the lengths are
            // asserted above.
            #[cfg(target_arch = "x86_64")]
            unsafe {
                use avx2::solve_windows;
                match input.0 {
                    Factors::Shared(f) => solve_windows::<true>((f, starts, r), extent, output),
                    Factors::Lanes(f) => solve_windows::<false>((f, starts, r), extent, output),
                }
            };
        } else {
            solve_windows_portable(input, extent, output);
        }
        self.zero_fixed(g, buffers);
    }

    /// The solution at the rows of the tile in window `c` of the last solved group (`rows` from
    /// [`Self::group_tiles`]).
    pub(crate) fn tile_solution<'b>(
        &self,
        g: usize,
        c: usize,
        rows: &std::ops::Range<usize>,
        buffers: &'b mut GroupBuffers,
    ) -> &'b mut [f64] {
        let offset = rows.start - self.starts[g * WINDOWS_PER_GROUP + c];
        let at = c * self.window + offset;
        &mut buffers.solution[at..at + rows.len()]
    }

    /// `x <- M^-1 x` (`+0` at the fixed rows): every group solved from a copy of `x`, the same
    /// arithmetic as the step's (`AVX2` where the CPU has it, the same bits either way).
    pub fn solve_in_place(&self, x: &mut [f64]) {
        assert_eq!(x.len(), self.n, "right-hand side of the wrong length");
        let r = x.to_vec();
        self.solve_into(&r, x, &mut self.buffers());
    }

    /// `x = M^-1 r` (`+0` at the fixed rows) with the work arrays `buffers` (from
    /// [`Self::buffers`]): [`Self::solve_in_place`]'s arithmetic without allocating.
    pub(crate) fn solve_into(&self, r: &[f64], x: &mut [f64], buffers: &mut GroupBuffers) {
        assert!(
            r.len() == self.n && x.len() == self.n,
            "vectors of the wrong length"
        );
        self.for_each_tile(r, buffers, |rows, solution| {
            x[rows].copy_from_slice(solution)
        });
    }

    /// Solve `M x = r` group by group and hand each tile's rows and solution to `f`, in
    /// increasing rows.
    pub(crate) fn for_each_tile(
        &self,
        r: &[f64],
        buffers: &mut GroupBuffers,
        mut f: impl FnMut(std::ops::Range<usize>, &[f64]),
    ) {
        for g in 0..self.groups() {
            self.solve_group(g, r, buffers);
            for (c, rows) in self.group_tiles(g) {
                let solution = self.tile_solution(g, c, &rows, buffers);
                f(rows, solution);
            }
        }
    }

    /// `(M^-1 r)_i` alone: the one window of row `i`'s tile, with the operations of the step's
    /// group solve (so the same bits), the backward sweep stopping at row `i`: O(window) work
    /// and no allocation.
    pub fn solution_at(&self, i: usize, r: &[f64]) -> f64 {
        assert!(i < self.n && r.len() == self.n, "row {i} of {}", self.n);
        if self.fixed.binary_search(&i).is_ok() {
            return 0.0;
        }
        let (tile, window) = (i / self.tile, self.window);
        let (g, c) = (tile / WINDOWS_PER_GROUP, tile % WINDOWS_PER_GROUP);
        let start = self.starts[g * WINDOWS_PER_GROUP + c];
        let factors = self.factors(g);
        let lower = |k: usize| factors.row(k, c).0;
        let pivot = |k: usize| factors.row(k, c).1;
        let mut z = [0.0; MAX_TILE + 2 * MAX_HALO];
        z[0] = r[start];
        for k in 1..window {
            z[k] = (-lower(k - 1)).mul_add(z[k - 1], r[start + k]);
        }
        let mut x = 0.0;
        for k in (i - start..window).rev() {
            x = (-lower(k)).mul_add(x, z[k] * pivot(k));
        }
        x
    }

    /// `+0` at the fixed rows of group `g`'s tiles (a decoupled row's window value is its
    /// right-hand side, not 0).
    fn zero_fixed(&self, g: usize, buffers: &mut GroupBuffers) {
        let rows = g * WINDOWS_PER_GROUP * self.tile
            ..((g + 1) * WINDOWS_PER_GROUP * self.tile).min(self.n);
        let from = self.fixed.partition_point(|&i| i < rows.start);
        for &i in self.fixed[from..].iter().take_while(|&&i| i < rows.end) {
            let c = i / self.tile - g * WINDOWS_PER_GROUP;
            let offset = i - self.starts[g * WINDOWS_PER_GROUP + c];
            buffers.solution[c * self.window + offset] = 0.0;
        }
    }
}

/// The group solve without intrinsics: for each window `c` (rows `starts[c]..starts[c] + window` of
/// `r`), the forward recurrence into `rows` (group layout), then the backward one down to row
/// `lowest` into `solution` (window layout), each `a - l b` one fused multiply-add (one rounding);
/// the operations of [`avx2::solve_windows`], one lane at a time.
fn solve_windows_portable(
    (factors, starts, r): (Factors, &[usize; WINDOWS_PER_GROUP], &[f64]),
    (window, lowest): (usize, usize),
    [rows, solution]: [&mut [f64]; 2],
) {
    let lower = |k: usize, c: usize| factors.row(k, c).0;
    let pivot = |k: usize, c: usize| factors.row(k, c).1;
    for (c, &start) in starts.iter().enumerate() {
        let mut z = r[start];
        rows[c] = z;
        for k in 1..window {
            z = (-lower(k - 1, c)).mul_add(z, r[start + k]);
            rows[k * WINDOWS_PER_GROUP + c] = z;
        }
        let mut x = 0.0;
        for k in (lowest..window).rev() {
            x = (-lower(k, c)).mul_add(x, rows[k * WINDOWS_PER_GROUP + c] * pivot(k, c));
            solution[c * window + k] = x;
        }
    }
}

/// Whether the windows starting at rows `a` and `b` have the same rows of `m`, bit for bit (then
/// they have the same factors).
fn same_rows(m: &Tridiagonal, window: usize, a: usize, b: usize) -> bool {
    let bits = |x: &[f64], y: &[f64]| x.iter().zip(y).all(|(x, y)| x.to_bits() == y.to_bits());
    a == b
        || (bits(&m.diag[a..a + window], &m.diag[b..b + window])
            && bits(&m.off[a..a + window - 1], &m.off[b..b + window - 1]))
}

#[cfg(test)]
mod tests;
