//! The ratio of two mass kinds' relative frequency errors, mode by mode (methods.md §5, "error
//! ratio"), computed from the closed-form spectra `Omega(kh)` of `courant_references::spectra`:
//!
//! ```text
//!   rho_X(kh) = |Omega_X(kh)/kh - 1| / |Omega_LMM(kh)/kh - 1|,   0 < kh <= pi.
//! ```
//!
//! Source of truth: the closed forms of methods.md §5 and their expansions in `kh` (LMM
//! `-(kh)^2/24 + (kh)^4/1920`, CMM `+(kh)^2/24 + (kh)^4/1920`, AMM(1/2) `-(kh)^4/480`,
//! RMM(1/2) `+(kh)^2/48`). What these tests prove: on a grid of 10^5 wavenumbers, the supremum
//! of `rho` over the band is `(pi - sqrt 6)/(pi - 2) = 0.60626` at `kh = pi` for both AMM(1/2)
//! and RMM(1/2) (where both have `Omega = sqrt 6`), so both are closer to the continuum than
//! LMM on every mode of any uniform mesh; its limits as `kh -> 0` are `(kh)^2/20 -> 0` (AMM)
//! and `1/2` (RMM); CMM's exceeds 1 below `kh = 1.982` and peaks at 1.03063 (`kh = 1.4706`);
//! and the top mode of each case of scene `fig6` reaches the lower bounds its rows state.

use courant_references::spectra::{BarEnds, MassKind, dimensionless_frequency};
use std::f64::consts::PI;

const AMM: MassKind = MassKind::Averaged { beta: 0.5 };
const RMM: MassKind = MassKind::Reciprocal { beta: 0.5 };

/// `Omega(kh)/kh - 1`, the relative error of a mode against the continuum.
fn error(kind: MassKind, kh: f64) -> f64 {
    dimensionless_frequency(kind, kh) / kh - 1.0
}

fn ratio(kind: MassKind, kh: f64) -> f64 {
    error(kind, kh).abs() / error(MassKind::Lumped, kh).abs()
}

/// The largest ratio on `kh = pi i / 10^5`, `i = 1 ... 10^5`, and where it is.
fn supremum(kind: MassKind) -> (f64, f64) {
    const STEPS: usize = 100_000;
    (1..=STEPS)
        .map(|i| PI * i as f64 / STEPS as f64)
        .map(|kh| (ratio(kind, kh), kh))
        .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a })
}

#[test]
fn amm_and_rmm_at_one_half_have_the_error_ratio_supremum_pi_minus_sqrt6_over_pi_minus_2() {
    let closed = (PI - 6.0_f64.sqrt()) / (PI - 2.0);
    assert!((closed - 0.606_260_830_980_529).abs() < 1e-14);
    for kind in [AMM, RMM] {
        let (sup, at) = supremum(kind);
        assert_eq!(at, PI, "{}: the largest ratio is at kh = pi", kind.label());
        assert!((sup - closed).abs() < 1e-12, "{}: {sup}", kind.label());
        assert!(sup < 1.0);
    }
}

#[test]
fn the_error_ratios_tend_to_their_leading_coefficients_as_kh_tends_to_zero() {
    // AMM(1/2): -(kh)^4/480 over (kh)^2/24 = (kh)^2/20; RMM(1/2): (kh)^2/48 over (kh)^2/24.
    for kh in [0.01, 0.02] {
        let amm = ratio(AMM, kh) / (kh * kh);
        assert!((amm - 1.0 / 20.0).abs() < 1e-4, "kh = {kh}: {amm}");
        assert!((ratio(RMM, kh) - 0.5).abs() < 1e-4, "kh = {kh}");
        assert!(error(AMM, kh) < 0.0 && error(RMM, kh) > 0.0);
    }
}

#[test]
fn rmm_at_one_half_is_exact_once_in_the_band_and_below_one_half_before() {
    // RMM(1/2) leads at low kh and lags at kh = pi (Omega = sqrt 6 < pi): one exact wavenumber.
    let exact = 1.715_669_095;
    assert!(error(RMM, exact - 1e-6) > 0.0 && error(RMM, exact + 1e-6) < 0.0);
    let below = (1..1000)
        .map(|i| exact * i as f64 / 1000.0)
        .map(|kh| ratio(RMM, kh))
        .fold(0.0, f64::max);
    assert!(below < 0.5 + 1e-6, "{below}");
}

#[test]
fn cmm_is_not_closer_than_lmm_on_every_mode() {
    let (sup, at) = supremum(MassKind::Consistent);
    assert!((sup - 1.030_626_283_5).abs() < 1e-9, "{sup}");
    assert!((at - 1.4706).abs() < 1e-3, "{at}");
    assert!(ratio(MassKind::Consistent, 1.98) > 1.0);
    assert!(ratio(MassKind::Consistent, 1.99) < 1.0);
    assert!(ratio(MassKind::Consistent, 1e-2) > 1.0);
}

#[test]
fn the_top_modes_of_scene_fig6_reach_the_lower_bounds_of_its_rows() {
    // fig6's mode_error_ratio rows: min 0.5789 (AMM), 0.5786 (RMM), 1.0304 (CMM), each below
    // the largest closed-form ratio over the modes of every case.
    for ends in [BarEnds::FreeFree, BarEnds::FixedFree] {
        for n in [20, 100] {
            let largest = |kind| {
                ends.modes(n)
                    .filter(|&m| m > 0)
                    .map(|m| ratio(kind, ends.wavenumber(m, 1.0) / n as f64))
                    .fold(0.0, f64::max)
            };
            assert!(largest(AMM) >= 0.5789, "{ends:?} N = {n}");
            assert!(largest(RMM) >= 0.5786, "{ends:?} N = {n}");
            assert!(largest(MassKind::Consistent) >= 1.0304, "{ends:?} N = {n}");
        }
    }
}
