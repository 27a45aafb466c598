//! Self-tests of the closed-form spectra (`courant_references::spectra`).
//!
//! Source of the formulas: courant's methods.md §5 (mass matrices LMM, CMM, AMM(beta), RMM(beta),
//! the uniform-mesh frequencies Omega(kh), the central-difference limit 2/max Omega and the fully
//! discrete dispersion sin(omega dt/2) = (Co/2) Omega); the CD stability limit after Fried (1972)
//! and Hughes (1987), ch. 9; the reciprocal mass after González et al. (2018) and Tkachuk &
//! Bischoff (2015).
//!
//! What these tests prove, using only the public API and no solver: the sampled continuum modes
//! satisfy `K u = omega^2 M u` (or `M^-1 K u = omega^2 u` for RMM) with hand-assembled dense
//! matrices and the closed-form frequencies, for both end conditions, and the frequencies are
//! distinct, so the closed forms are the complete discrete spectrum; the special cases
//! AMM(0) = CMM, AMM(1) = RMM(1) = LMM hold exactly; LMM lies below and CMM above the continuum;
//! AMM(1/2) is fourth-order accurate in space; the critical Courant numbers equal 2/max Omega
//! on a fine grid; the fourth-order betas make CD fourth order in phase (and plain beta = 1/2 only
//! second order) while staying stable; the phase-speed ratio is undefined exactly above the
//! critical Courant number; invalid parameters are rejected with a named error.

use courant_references::ReferenceError;
use courant_references::spectra::{
    BarEnds, MassKind, UniformBar, critical_courant, dimensionless_frequency,
    fourth_order_beta_averaged, fourth_order_beta_reciprocal, max_dimensionless_frequency,
    phase_speed_ratio,
};
use std::f64::consts::PI;

/// Non-unit bar data so that every scale factor is exercised: L, E, rho, A.
const LENGTH: f64 = 2.5;
const MODULUS: f64 = 7.0;
const DENSITY: f64 = 3.0;
const AREA: f64 = 0.4;

type Matrix = Vec<Vec<f64>>;

fn zeros(n: usize) -> Matrix {
    vec![vec![0.0; n]; n]
}

/// Assembles the 2x2 element matrix `ke` of every element of an N-element chain.
fn assemble(elements: usize, ke: [[f64; 2]; 2]) -> Matrix {
    let mut global = zeros(elements + 1);
    for e in 0..elements {
        for (a, row) in ke.iter().enumerate() {
            for (b, value) in row.iter().enumerate() {
                global[e + a][e + b] += value;
            }
        }
    }
    global
}

fn stiffness(elements: usize, h: f64) -> Matrix {
    let k = MODULUS * AREA / h;
    assemble(elements, [[k, -k], [-k, k]])
}

/// Assembled mass matrix of LMM, CMM or AMM(beta) (methods.md §5).
fn mass(kind: MassKind, elements: usize, h: f64) -> Matrix {
    let m = DENSITY * AREA * h;
    let beta = match kind {
        MassKind::Lumped => 1.0,
        MassKind::Consistent => 0.0,
        MassKind::Averaged { beta } => beta,
        MassKind::Reciprocal { .. } => unreachable!("RMM is assembled as an inverse"),
    };
    let diagonal = (1.0 - beta) * m / 3.0 + beta * m / 2.0;
    let off = (1.0 - beta) * m / 6.0;
    assemble(elements, [[diagonal, off], [off, diagonal]])
}

/// Assembled RMM inverse `A^-1 C A^-1`, A the lumped mass,
/// `C_e = m/(2(1 + 2 beta)) [[2 + beta, beta - 1], [beta - 1, 2 + beta]]` (methods.md §5).
fn inverse_mass_rmm(beta: f64, elements: usize, h: f64) -> Matrix {
    let m = DENSITY * AREA * h;
    let f = m / (2.0 * (1.0 + 2.0 * beta));
    let (d, o) = (f * (2.0 + beta), f * (beta - 1.0));
    let c = assemble(elements, [[d, o], [o, d]]);
    let lumped = assemble(elements, [[m / 2.0, 0.0], [0.0, m / 2.0]]);
    let n = elements + 1;
    let mut inverse = zeros(n);
    for i in 0..n {
        for j in 0..n {
            inverse[i][j] = c[i][j] / (lumped[i][i] * lumped[j][j]);
        }
    }
    inverse
}

/// Deletes row and column `node` (a Dirichlet node).
fn delete(matrix: &Matrix, node: usize) -> Matrix {
    matrix
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != node)
        .map(|(_, row)| {
            row.iter()
                .enumerate()
                .filter(|&(j, _)| j != node)
                .map(|(_, &v)| v)
                .collect()
        })
        .collect()
}

fn mul(matrix: &Matrix, v: &[f64]) -> Vec<f64> {
    matrix
        .iter()
        .map(|row| row.iter().zip(v).map(|(a, b)| a * b).sum())
        .collect()
}

fn norm_inf(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |acc, x| acc.max(x.abs()))
}

fn matrix_norm_inf(matrix: &Matrix) -> f64 {
    matrix
        .iter()
        .map(|row| row.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

fn kinds_for_residuals() -> Vec<MassKind> {
    let mut kinds = vec![MassKind::Lumped, MassKind::Consistent];
    for beta in [0.0, 0.5, 1.0] {
        kinds.push(MassKind::Averaged { beta });
        kinds.push(MassKind::Reciprocal { beta });
    }
    kinds
}

fn bar(elements: usize, ends: BarEnds) -> UniformBar {
    UniformBar::new(LENGTH, (MODULUS / DENSITY).sqrt(), elements, ends).unwrap()
}

/// Relative residual of the sampled continuum mode n of `bar` as an eigenvector of the
/// hand-assembled problem with the closed-form frequency.
fn mode_residual(bar: &UniformBar, kind: MassKind, n: usize) -> f64 {
    let (elements, h) = (bar.elements, bar.element_length());
    let k_n = bar.wavenumber(n);
    let omega2 = bar.discrete_frequency(kind, n).powi(2);
    let mut u: Vec<f64> = (0..=elements).map(|j| (k_n * j as f64 * h).cos()).collect();
    let mut k = stiffness(elements, h);
    let mut m = match kind {
        MassKind::Reciprocal { beta } => inverse_mass_rmm(beta, elements, h),
        _ => mass(kind, elements, h),
    };
    if bar.ends == BarEnds::FixedFree {
        // Node N at x = L is fixed; the sampled mode vanishes there.
        assert!(u[elements].abs() < 1e-12);
        u.pop();
        k = delete(&k, elements);
        m = delete(&m, elements);
    }
    let ku = mul(&k, &u);
    let (residual, scale) = match kind {
        MassKind::Reciprocal { .. } => {
            let minv_ku = mul(&m, &ku);
            let r: Vec<f64> = minv_ku
                .iter()
                .zip(&u)
                .map(|(a, b)| a - omega2 * b)
                .collect();
            // ||M^-1 K|| <= ||M^-1|| ||K||.
            (r, matrix_norm_inf(&m) * matrix_norm_inf(&k) * norm_inf(&u))
        }
        _ => {
            let mu = mul(&m, &u);
            let r: Vec<f64> = ku.iter().zip(&mu).map(|(a, b)| a - omega2 * b).collect();
            (r, matrix_norm_inf(&k) * norm_inf(&u))
        }
    };
    norm_inf(&residual) / scale
}

#[test]
fn closed_forms_are_the_complete_spectrum_of_hand_assembled_uniform_meshes() {
    for ends in [BarEnds::FreeFree, BarEnds::FixedFree] {
        for elements in [7, 20] {
            let bar = bar(elements, ends);
            for kind in kinds_for_residuals() {
                let spectrum = bar.discrete_frequencies(kind);
                let expected_count = match ends {
                    BarEnds::FreeFree => elements + 1,
                    BarEnds::FixedFree => elements,
                };
                // One frequency per degree of freedom of the (reduced) mesh ...
                assert_eq!(spectrum.len(), expected_count);
                // ... all distinct, so the eigenvectors below are independent and complete.
                assert!(spectrum.windows(2).all(|w| w[1] > w[0]), "{}", kind.label());
                for n in bar.modes() {
                    let r = mode_residual(&bar, kind, n);
                    assert!(
                        r < 1e-10,
                        "{ends:?} N={elements} {} n={n}: residual {r:e}",
                        kind.label()
                    );
                }
            }
        }
    }
}

#[test]
fn residual_check_detects_a_wrong_frequency() {
    // Guard against a vacuous residual: CMM frequencies fail the LMM problem and vice versa.
    let bar = bar(7, BarEnds::FixedFree);
    let n = 5;
    let wrong = |kind, other| {
        let mut k = stiffness(7, bar.element_length());
        let mut m = mass(kind, 7, bar.element_length());
        k = delete(&k, 7);
        m = delete(&m, 7);
        let u: Vec<f64> = (0..7)
            .map(|j| (bar.wavenumber(n) * j as f64 * bar.element_length()).cos())
            .collect();
        let omega2 = bar.discrete_frequency(other, n).powi(2);
        let (ku, mu) = (mul(&k, &u), mul(&m, &u));
        let r: Vec<f64> = ku.iter().zip(&mu).map(|(a, b)| a - omega2 * b).collect();
        norm_inf(&r) / (matrix_norm_inf(&k) * norm_inf(&u))
    };
    assert!(wrong(MassKind::Lumped, MassKind::Consistent) > 1e-2);
    assert!(wrong(MassKind::Consistent, MassKind::Lumped) > 1e-2);
}

#[test]
fn rmm_one_and_amm_one_equal_lmm_and_amm_zero_equals_cmm_exactly() {
    for i in 0..=1000 {
        let kh = PI * i as f64 / 1000.0;
        let lumped = dimensionless_frequency(MassKind::Lumped, kh);
        let consistent = dimensionless_frequency(MassKind::Consistent, kh);
        assert_eq!(
            dimensionless_frequency(MassKind::Reciprocal { beta: 1.0 }, kh),
            lumped
        );
        assert_eq!(
            dimensionless_frequency(MassKind::Averaged { beta: 1.0 }, kh),
            lumped
        );
        assert_eq!(
            dimensionless_frequency(MassKind::Averaged { beta: 0.0 }, kh),
            consistent
        );
    }
    let bar = bar(20, BarEnds::FixedFree);
    let lumped = bar.discrete_frequencies(MassKind::Lumped);
    assert_eq!(
        bar.discrete_frequencies(MassKind::Reciprocal { beta: 1.0 }),
        lumped
    );
    assert_eq!(
        bar.discrete_frequencies(MassKind::Averaged { beta: 1.0 }),
        lumped
    );
    assert_eq!(
        bar.discrete_frequencies(MassKind::Averaged { beta: 0.0 }),
        bar.discrete_frequencies(MassKind::Consistent)
    );
    assert_eq!(critical_courant(MassKind::Reciprocal { beta: 1.0 }), 1.0);
    assert_eq!(critical_courant(MassKind::Averaged { beta: 1.0 }), 1.0);
}

#[test]
fn lmm_is_below_and_cmm_above_the_continuum_for_every_elastic_mode() {
    for ends in [BarEnds::FreeFree, BarEnds::FixedFree] {
        for elements in [7, 20] {
            let bar = bar(elements, ends);
            for n in bar.modes() {
                let exact = bar.continuum_frequency(n);
                let lumped = bar.discrete_frequency(MassKind::Lumped, n);
                let consistent = bar.discrete_frequency(MassKind::Consistent, n);
                if n == 0 {
                    // Free-free rigid mode: zero for every kind.
                    assert_eq!(exact, 0.0);
                    for kind in kinds_for_residuals() {
                        assert_eq!(bar.discrete_frequency(kind, 0), 0.0);
                    }
                } else {
                    assert!(lumped < exact && exact < consistent, "{ends:?} n={n}");
                }
            }
        }
    }
}

#[test]
fn wavenumbers_and_mode_counts_follow_the_end_conditions() {
    let free = bar(7, BarEnds::FreeFree);
    let fixed = bar(7, BarEnds::FixedFree);
    assert_eq!(free.modes(), 0..=7);
    assert_eq!(fixed.modes(), 1..=7);
    assert_eq!(free.continuum_frequencies().len(), 8);
    assert_eq!(fixed.continuum_frequencies().len(), 7);
    assert!(fixed.wavenumber(0).is_nan());
    assert!(fixed.discrete_frequency(MassKind::Lumped, 8).is_nan());
    let c = (MODULUS / DENSITY).sqrt();
    for n in 1..=7 {
        // Free-free: sin(k L) = 0; fixed-free: cos(k L) = 0 (fixed at x = L).
        assert!((free.wavenumber(n) * LENGTH).sin().abs() < 1e-14);
        assert!((fixed.wavenumber(n) * LENGTH).cos().abs() < 1e-14);
        assert!((free.continuum_frequency(n) - c * n as f64 * PI / LENGTH).abs() < 1e-12);
    }
}

#[test]
fn amm_one_half_is_fourth_order_in_space_while_lmm_and_cmm_are_second_order() {
    let error = |kind, theta: f64| (dimensionless_frequency(kind, theta) / theta - 1.0).abs();
    for theta in [0.2, 0.1] {
        let ratio = |kind| error(kind, theta) / error(kind, theta / 2.0);
        let amm = ratio(MassKind::Averaged { beta: 0.5 });
        assert!((15.0..17.0).contains(&amm), "AMM(1/2) ratio {amm}");
        for kind in [MassKind::Lumped, MassKind::Consistent] {
            let r = ratio(kind);
            assert!((3.9..4.1).contains(&r), "{} ratio {r}", kind.label());
        }
    }
}

#[test]
fn critical_courant_equals_two_over_max_omega_on_a_fine_grid() {
    let kinds = [
        MassKind::Lumped,
        MassKind::Consistent,
        MassKind::Averaged { beta: -0.4 },
        MassKind::Averaged { beta: 0.0 },
        MassKind::Averaged { beta: 0.5 },
        MassKind::Averaged { beta: 1.0 },
        MassKind::Averaged { beta: 3.0 },
        MassKind::Reciprocal { beta: -0.4 },
        MassKind::Reciprocal { beta: 0.0 },
        MassKind::Reciprocal { beta: 0.5 },
        MassKind::Reciprocal { beta: 1.0 },
        MassKind::Reciprocal { beta: 2.5 },
        // Beyond beta = 5/2 the RMM maximum is interior.
        MassKind::Reciprocal { beta: 3.0 },
        MassKind::Reciprocal { beta: 10.0 },
    ];
    let points = 200_000;
    for kind in kinds {
        let grid_max = (0..=points)
            .map(|i| dimensionless_frequency(kind, PI * i as f64 / points as f64))
            .fold(0.0, f64::max);
        let co = critical_courant(kind);
        assert!(
            (co - 2.0 / grid_max).abs() <= 1e-9 * co,
            "{}: {co} vs {}",
            kind.label(),
            2.0 / grid_max
        );
        assert!((max_dimensionless_frequency(kind) - grid_max).abs() <= 1e-9 * grid_max);
    }
    // methods.md §5 values.
    assert_eq!(critical_courant(MassKind::Lumped), 1.0);
    assert!((critical_courant(MassKind::Consistent) - 1.0 / 3.0_f64.sqrt()).abs() < 1e-15);
    for beta in [0.0_f64, 0.25, 0.5, 0.75, 1.0, 2.0] {
        let expected = ((1.0 + 2.0 * beta) / 3.0).sqrt();
        for kind in [MassKind::Averaged { beta }, MassKind::Reciprocal { beta }] {
            assert!((critical_courant(kind) - expected).abs() < 1e-15);
        }
    }
}

/// |phase-speed ratio - 1| of CD at `kh` and `co`.
fn phase_error(kind: MassKind, kh: f64, co: f64) -> f64 {
    (phase_speed_ratio(kind, kh, co).unwrap() - 1.0).abs()
}

#[test]
fn fourth_order_betas_make_cd_fourth_order_in_phase_and_one_half_only_second_order() {
    for co in [0.2, 0.5, 0.8] {
        let tuned = [
            MassKind::Averaged {
                beta: fourth_order_beta_averaged(co).unwrap(),
            },
            MassKind::Reciprocal {
                beta: fourth_order_beta_reciprocal(co).unwrap(),
            },
        ];
        for kind in tuned {
            let ratio = phase_error(kind, 0.1, co) / phase_error(kind, 0.05, co);
            assert!(
                (14.0..18.0).contains(&ratio),
                "Co={co} {}: {ratio}",
                kind.label()
            );
        }
        for kind in [
            MassKind::Averaged { beta: 0.5 },
            MassKind::Reciprocal { beta: 0.5 },
        ] {
            let ratio = phase_error(kind, 0.1, co) / phase_error(kind, 0.05, co);
            assert!(
                (3.5..4.5).contains(&ratio),
                "Co={co} {}: {ratio}",
                kind.label()
            );
        }
    }
}

#[test]
fn fourth_order_betas_match_the_series_and_reach_lmm_at_courant_one() {
    // Hand values: AMM (1 + Co^2)/2, RMM (5 + Co^2)/(8 - 2 Co^2).
    assert_eq!(fourth_order_beta_averaged(0.0).unwrap(), 0.5);
    assert_eq!(fourth_order_beta_reciprocal(0.0).unwrap(), 0.625);
    assert_eq!(fourth_order_beta_averaged(1.0).unwrap(), 1.0);
    assert_eq!(fourth_order_beta_reciprocal(1.0).unwrap(), 1.0);
    assert!((fourth_order_beta_reciprocal(0.5).unwrap() - 5.25 / 7.5).abs() < 1e-15);
    // At Co = 1 the tuned scheme is LMM + CD at Co = 1: exact for every resolved wave.
    for i in 1..=100 {
        let kh = PI * i as f64 / 100.0;
        assert!(phase_error(MassKind::Lumped, kh, 1.0) < 1e-14);
    }
}

#[test]
fn fourth_order_betas_stay_within_the_stability_limit_up_to_courant_one() {
    for i in 1..=1000 {
        let co = i as f64 / 1000.0;
        let kinds = [
            MassKind::averaged(fourth_order_beta_averaged(co).unwrap()).unwrap(),
            MassKind::reciprocal(fourth_order_beta_reciprocal(co).unwrap()).unwrap(),
        ];
        for kind in kinds {
            assert!(
                co <= critical_courant(kind) + 1e-15,
                "Co={co} {}",
                kind.label()
            );
            // The shortest mode is still resolved (the ratio exists at kh = pi).
            assert!(phase_speed_ratio(kind, PI, co).is_some());
        }
    }
}

#[test]
fn phase_speed_ratio_is_none_exactly_above_the_critical_courant_number() {
    let kinds = [
        MassKind::Lumped,
        MassKind::Consistent,
        MassKind::Averaged { beta: 0.5 },
        MassKind::Averaged { beta: 0.8 },
        MassKind::Reciprocal { beta: 0.0 },
        MassKind::Reciprocal { beta: 0.5 },
    ];
    for kind in kinds {
        let critical = critical_courant(kind);
        assert!(phase_speed_ratio(kind, PI, critical).is_some());
        assert!(phase_speed_ratio(kind, PI, critical * (1.0 - 1e-9)).is_some());
        assert!(phase_speed_ratio(kind, PI, critical * (1.0 + 1e-9)).is_none());
        // Below the limit every wavenumber has a real frequency.
        for i in 0..=100 {
            let kh = PI * i as f64 / 100.0;
            assert!(phase_speed_ratio(kind, kh, critical * 0.999).is_some());
        }
    }
}

#[test]
fn phase_speed_ratio_tends_to_one_for_long_waves() {
    for kind in kinds_for_residuals() {
        for co in [0.0, 0.3, 0.5] {
            assert_eq!(phase_speed_ratio(kind, 0.0, co), Some(1.0));
            let ratio = phase_speed_ratio(kind, 1e-4, co).unwrap();
            assert!(
                (ratio - 1.0).abs() < 1e-8,
                "{} Co={co}: {ratio}",
                kind.label()
            );
        }
        // Co = 0 is the semi-discrete ratio Omega/kh.
        let kh = 0.7;
        assert_eq!(
            phase_speed_ratio(kind, kh, 0.0),
            Some(dimensionless_frequency(kind, kh) / kh)
        );
    }
}

#[test]
fn labels_name_the_kind_and_its_parameter() {
    assert_eq!(MassKind::Lumped.label(), "lmm");
    assert_eq!(MassKind::Consistent.label(), "cmm");
    assert_eq!(MassKind::Averaged { beta: 0.5 }.label(), "amm(0.5)");
    assert_eq!(MassKind::Reciprocal { beta: 0.5 }.label(), "rmm(0.5)");
}

#[test]
fn invalid_beta_courant_number_and_bar_data_give_the_typed_error() {
    for beta in [-0.5, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for kind in [MassKind::Averaged { beta }, MassKind::Reciprocal { beta }] {
            match kind.validate() {
                Err(ReferenceError::InvalidParameter { name, value, .. }) => {
                    assert_eq!(name, "beta");
                    assert!(value.to_bits() == beta.to_bits());
                }
                other => panic!("{kind:?} accepted: {other:?}"),
            }
            assert!(dimensionless_frequency(kind, 1.0).is_nan());
            assert!(critical_courant(kind).is_nan());
            assert!(phase_speed_ratio(kind, 1.0, 0.1).is_none());
        }
        assert!(MassKind::averaged(beta).is_err());
        assert!(MassKind::reciprocal(beta).is_err());
    }
    assert_eq!(
        MassKind::averaged(-0.49),
        Ok(MassKind::Averaged { beta: -0.49 })
    );
    assert_eq!(
        MassKind::reciprocal(7.0),
        Ok(MassKind::Reciprocal { beta: 7.0 })
    );
    for co in [-0.1, 1.01, f64::NAN] {
        for result in [
            fourth_order_beta_averaged(co),
            fourth_order_beta_reciprocal(co),
        ] {
            assert!(matches!(
                result,
                Err(ReferenceError::InvalidParameter { name: "co", .. })
            ));
        }
    }
    assert!(phase_speed_ratio(MassKind::Lumped, 1.0, -0.5).is_none());
    assert!(phase_speed_ratio(MassKind::Lumped, f64::NAN, 0.5).is_none());
    let c = 1.0;
    assert!(matches!(
        UniformBar::new(0.0, c, 4, BarEnds::FreeFree),
        Err(ReferenceError::InvalidParameter { name: "length", .. })
    ));
    assert!(matches!(
        UniformBar::new(1.0, f64::NAN, 4, BarEnds::FreeFree),
        Err(ReferenceError::InvalidParameter {
            name: "wave_speed",
            ..
        })
    ));
    assert!(matches!(
        UniformBar::new(1.0, c, 0, BarEnds::FixedFree),
        Err(ReferenceError::InvalidParameter {
            name: "elements",
            ..
        })
    ));
}
