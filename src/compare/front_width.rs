//! The width of a dispersed step front, measured on a stress profile (methods.md §3).
//!
//! Behind a step front lumped central difference at `Co < 1` leaves the Airy profile
//! `sigma/sigma_jump = S((x - ct)/w)`, `S(s) = int_s^inf Ai`, of width
//! `w = (c t h^2 (1 - Co^2)/8)^(1/3)` (methods.md §3, after Whitham 1974, ch. 11). The width
//! measured here is the distance between two features of the profile itself, so that no
//! time-level convention (where the discrete front "is" at `t`) enters:
//!
//! ```text
//!   peak:  the first maximum of S behind the front, at s = a1 = -2.33811 (the first zero of
//!          Ai, S(a1) = 1.27435): the vertex of the parabola through the largest value of
//!          sigma/sigma_jump and its two neighbours;
//!   front: where sigma/sigma_jump crosses S(0) = int_0^inf Ai = 1/3, by linear interpolation
//!          between the two values that straddle 1/3, the crossing nearest the peak;
//!   front_width = |x_front - x_peak|,   = |a1| w = 2.33811 w for the Airy profile.
//! ```
//!
//! `sigma_jump` is the exact value of largest magnitude of the profile's reference (for a single
//! step front, the plateau behind it). Sampled as element averages at element centres `h` apart,
//! the two features move by at most `(0.0974 r + 0.0304 + 0.2588/(8 Ai(1.1 r))) r^2 w` together,
//! `r = h/w` (derived in methods.md §3; checked on sampled Airy profiles below).

/// `|a1|`, the distance from the first zero of Ai to 0 (Abramowitz & Stegun, table 10.13):
/// the Airy front's width in units of `w`, `|s_peak - s_front|`.
pub const AIRY_PEAK_TO_FRONT: f64 = 2.338_107_410_459_767;

/// The level of `sigma/sigma_jump` that marks the front: `S(0) = int_0^inf Ai = 1/3`.
pub const FRONT_LEVEL: f64 = 1.0 / 3.0;

/// Why a profile has no front width.
pub const FRONT_WIDTH_UNDEFINED: &str =
    "undefined: no peak above a third of the jump with a crossing of a third beside it";

/// The front width `|x_front - x_peak|` of a profile (`x` the element centres or points,
/// `stress` their values, `reference` the exact values there), as the module states it; `None`
/// when the profile has no peak above a third of the jump with a neighbour on each side, no
/// crossing of a third of the jump, or the reference is zero.
pub fn front_width(x: &[f64], stress: &[f64], reference: &[f64]) -> Option<f64> {
    let jump = reference
        .iter()
        .copied()
        .fold(0.0_f64, |a, b| if b.abs() > a.abs() { b } else { a });
    if jump == 0.0 || !jump.is_finite() || x.len() != stress.len() || x.len() < 3 {
        return None;
    }
    let p: Vec<f64> = stress.iter().map(|s| s / jump).collect();
    let peak = (0..p.len()).fold(0, |best, i| if p[i] > p[best] { i } else { best });
    if peak == 0
        || peak + 1 >= p.len()
        || p[peak].partial_cmp(&FRONT_LEVEL) != Some(std::cmp::Ordering::Greater)
    {
        return None;
    }
    let x_peak = vertex(
        (x[peak - 1], p[peak - 1]),
        (x[peak], p[peak]),
        (x[peak + 1], p[peak + 1]),
    );
    let crossing = |a: usize, b: usize| x[a] + (x[b] - x[a]) * (p[a] - FRONT_LEVEL) / (p[a] - p[b]);
    // Walking away from the peak, the first value at or below 1/3 ends the walk: the values
    // before it are all above 1/3.
    let ahead = (peak..p.len() - 1)
        .find(|&j| p[j + 1] <= FRONT_LEVEL)
        .map(|j| crossing(j, j + 1));
    let behind = (1..=peak)
        .rev()
        .find(|&j| p[j - 1] <= FRONT_LEVEL)
        .map(|j| crossing(j, j - 1));
    let distance = |front: f64| (front - x_peak).abs();
    let width = match (ahead, behind) {
        (Some(a), Some(b)) => distance(a).min(distance(b)),
        (Some(a), None) => distance(a),
        (None, Some(b)) => distance(b),
        (None, None) => return None,
    };
    width.is_finite().then_some(width)
}

/// The abscissa of the vertex of the parabola through three points (`x0 < x1 < x2`), `x1` if
/// they are collinear: `x1 - (d0^2 (y1 - y2) - d2^2 (y1 - y0)) / (2 (d0 (y1 - y2) - d2 (y1 - y0)))`,
/// `d0 = x1 - x0`, `d2 = x1 - x2`.
fn vertex((x0, y0): (f64, f64), (x1, y1): (f64, f64), (x2, y2): (f64, f64)) -> f64 {
    let (d0, d2) = (x1 - x0, x1 - x2);
    let num = d0 * d0 * (y1 - y2) - d2 * d2 * (y1 - y0);
    let den = d0 * (y1 - y2) - d2 * (y1 - y0);
    if den == 0.0 { x1 } else { x1 - 0.5 * num / den }
}

#[cfg(test)]
mod tests {
    //! Source of truth: the Airy step profile `S(s) = int_s^inf Ai` (methods.md §3), computed
    //! here by integrating `Ai'' = s Ai` from `Ai(0) = 0.355028053887817`,
    //! `Ai'(0) = -0.258819403792807` (Abramowitz & Stegun 10.4.4-10.4.5) with `S' = -Ai`,
    //! `S(0) = 1/3`, and its integral for element averages.

    use super::*;

    /// Ai, S and `F = int_0^s S` on a grid of step `D` from `-16` to `8` (classical RK4).
    struct Airy {
        start: f64,
        /// `(Ai, S, F)` at `start + i D`.
        table: Vec<(f64, f64, f64)>,
    }

    const D: f64 = 1e-3;

    impl Airy {
        fn new() -> Self {
            let f = |s: f64, y: [f64; 4]| [y[1], s * y[0], -y[0], y[2]];
            let run = |end: f64| {
                let steps = (end / D).abs().round() as usize;
                let hs = end / steps as f64;
                let mut y = [
                    0.355_028_053_887_817_2,
                    -0.258_819_403_792_806_8,
                    1.0 / 3.0,
                    0.0,
                ];
                let mut out = vec![y];
                for i in 0..steps {
                    let s = i as f64 * hs;
                    let add =
                        |y: [f64; 4], k: [f64; 4], c: f64| [0, 1, 2, 3].map(|j| y[j] + c * k[j]);
                    let k1 = f(s, y);
                    let k2 = f(s + hs / 2.0, add(y, k1, hs / 2.0));
                    let k3 = f(s + hs / 2.0, add(y, k2, hs / 2.0));
                    let k4 = f(s + hs, add(y, k3, hs));
                    y = [0, 1, 2, 3]
                        .map(|j| y[j] + hs / 6.0 * (k1[j] + 2.0 * (k2[j] + k3[j]) + k4[j]));
                    out.push(y);
                }
                out
            };
            let mut negative = run(-16.0);
            negative.reverse();
            let positive = run(8.0);
            let table = negative
                .iter()
                .chain(&positive[1..])
                .map(|y| (y[0], y[2], y[3]))
                .collect();
            Self {
                start: -16.0,
                table,
            }
        }

        /// `(Ai, S, F)` at `s` (cubic Hermite for F with `F' = S`, linear for Ai and S).
        fn at(&self, s: f64) -> (f64, f64, f64) {
            let u = (s - self.start) / D;
            assert!(
                u >= 0.0 && u <= (self.table.len() - 1) as f64,
                "s = {s} off the table"
            );
            let i = (u.floor() as usize).min(self.table.len() - 2);
            let t = u - i as f64;
            let (a, b) = (self.table[i], self.table[i + 1]);
            let lin = |p: f64, q: f64| p + t * (q - p);
            let h00 = 2.0 * t * t * t - 3.0 * t * t + 1.0;
            let h10 = t * t * t - 2.0 * t * t + t;
            let h01 = -2.0 * t * t * t + 3.0 * t * t;
            let h11 = t * t * t - t * t;
            let f = h00 * a.2 + h10 * D * a.1 + h01 * b.2 + h11 * D * b.1;
            (lin(a.0, b.0), lin(a.1, b.1), f)
        }

        /// Element average of S over `[s - r/2, s + r/2]`.
        fn average(&self, s: f64, r: f64) -> f64 {
            (self.at(s + r / 2.0).2 - self.at(s - r / 2.0).2) / r
        }
    }

    /// The sampling bound of the module (methods.md §3), in units of `w`.
    fn sampling_bound(airy: &Airy, r: f64) -> f64 {
        (0.0974 * r + 0.0304 + 0.2588 / (8.0 * airy.at(1.1 * r).0)) * r * r
    }

    #[test]
    fn the_integrated_airy_profile_has_its_tabulated_peak_and_front() {
        // A & S 10.4.4-5 and table 10.13: S(a1) = 1 + 0.27435 (methods.md §3), S(0) = 1/3,
        // Ai(a1) = 0.
        let airy = Airy::new();
        let (ai, s, _) = airy.at(-AIRY_PEAK_TO_FRONT);
        assert!(ai.abs() < 1e-6, "Ai(a1) = {ai}");
        assert!((s - 1.274_35).abs() < 1e-5, "S(a1) = {s}");
        assert!(airy.at(8.0).1 < 1e-6);
    }

    #[test]
    fn an_airy_front_sampled_by_element_averages_measures_a1_w_within_the_sampling_bound() {
        // methods.md §3: element averages of sigma_jump S((x - ct)/w) at centres h apart, at the
        // h/w of fig1_airy's cases (0.27 to 0.60) and 40 offsets of the mesh against the front,
        // give a width within the derived sampling bound of |a1| w; compressive jump, front
        // running towards +x.
        let airy = Airy::new();
        let (w, ct, jump) = (0.02, 0.5, -1.0);
        for r in [0.27, 0.3, 0.34, 0.38, 0.45, 0.55, 0.6] {
            let h = r * w;
            let bound = sampling_bound(&airy, r);
            for k in 0..40 {
                let offset = k as f64 / 40.0 * h;
                let x: Vec<f64> = (0..(20.0 / r) as usize)
                    .map(|e| ct - 14.0 * w + (e as f64 + 0.5) * h + offset)
                    .collect();
                let s = |x: f64| (x - ct) / w;
                let stress: Vec<f64> = x.iter().map(|&x| jump * airy.average(s(x), r)).collect();
                let reference: Vec<f64> =
                    x.iter().map(|&x| if x < ct { jump } else { 0.0 }).collect();
                let width = front_width(&x, &stress, &reference).unwrap();
                let error = width / w - AIRY_PEAK_TO_FRONT;
                assert!(
                    error.abs() <= bound,
                    "r = {r}, offset {offset}: width {} w, error {error} > bound {bound}",
                    width / w
                );
            }
        }
    }

    #[test]
    fn a_front_running_towards_minus_x_is_measured_the_same() {
        // Mirror image of a sampled Airy front (tensile jump): the width does not depend on the
        // direction or the sign (methods.md §3).
        let airy = Airy::new();
        let (w, r) = (0.02, 0.4);
        let h = r * w;
        let front = 0.9;
        // 21 w of bar: s from -14 to 7 for the front running to +x, 7 to -14 for its mirror
        // (about the point front - 3.5 w).
        let x: Vec<f64> = (0..52)
            .map(|e| front - 14.0 * w + (e as f64 + 0.5) * h)
            .collect();
        let forward: Vec<f64> = x
            .iter()
            .map(|&x| airy.average((x - front) / w, r))
            .collect();
        let mirrored: Vec<f64> = x
            .iter()
            .map(|&x| airy.average((front - 7.0 * w - x) / w, r))
            .collect();
        let ones = vec![1.0; x.len()];
        let a = front_width(&x, &forward, &ones).unwrap();
        let b = front_width(&x, &mirrored, &ones).unwrap();
        assert!((a / w - AIRY_PEAK_TO_FRONT).abs() < sampling_bound(&airy, r));
        assert!((b / w - AIRY_PEAK_TO_FRONT).abs() < sampling_bound(&airy, r));
    }

    #[test]
    fn a_sharp_step_has_no_front_width() {
        // The exact d'Alembert step (methods.md §3) has no peak above its plateau with a
        // neighbour on each side that is not a plateau value: no Airy peak, no width.
        let x: Vec<f64> = (0..10).map(|e| e as f64 + 0.5).collect();
        let step: Vec<f64> = (0..10).map(|e| if e < 5 { -1.0 } else { 0.0 }).collect();
        assert_eq!(front_width(&x, &step, &step), None);
        assert_eq!(front_width(&x, &[0.0; 10], &[0.0; 10]), None);
    }

    #[test]
    fn the_vertex_of_a_parabola_is_found_on_an_uneven_grid() {
        // y = 3 - (x - 0.7)^2 through x = 0, 0.5, 2: vertex 0.7 (closed form).
        let y = |x: f64| 3.0 - (x - 0.7) * (x - 0.7);
        let v = vertex((0.0, y(0.0)), (0.5, y(0.5)), (2.0, y(2.0)));
        assert!((v - 0.7).abs() < 1e-14);
    }
}
