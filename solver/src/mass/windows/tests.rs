//! Tests of the windowed solve: the halo's closed form, the solution against the global factor
//! to round-off (graded, layered and fixed rows, every `beta` with a halo), and the intrinsics
//! against the portable loops bit for bit.

use super::*;
use crate::mass::partitioned_ldl::PartitionedLdl;

/// The assembled mass of element masses `m` with lumped weight `beta`
/// (`(1 - beta) CMM + beta LMM`), rows in `fixed` decoupled.
fn mass(m: &[f64], beta: f64, fixed: &[usize]) -> Tridiagonal {
    let mut t = Tridiagonal {
        diag: vec![0.0; m.len() + 1],
        off: vec![0.0; m.len()],
    };
    for (e, &me) in m.iter().enumerate() {
        let d = (1.0 - beta) * me / 3.0 + beta * me / 2.0;
        t.diag[e] += d;
        t.diag[e + 1] += d;
        t.off[e] = (1.0 - beta) * me / 6.0;
    }
    fixed.iter().for_each(|&i| t.decouple(i));
    t
}

/// Element masses: smoothly graded over three decades, with a hundredfold jump at a third of
/// the bar (a layered bar).
fn graded_masses(elements: usize) -> Vec<f64> {
    (0..elements)
        .map(|e| {
            let x = e as f64 / elements as f64;
            let jump = if 3 * e < elements { 100.0 } else { 1.0 };
            jump * 10f64.powf(3.0 * x) * (1.0 + 0.3 * (40.0 * x).sin())
        })
        .collect()
}

/// A right-hand side with content at every scale: smooth, oscillating node to node, and spikes.
fn right_hand_side(n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            let x = i as f64 / n as f64;
            (7.0 * x).sin() + 0.5 * (-1f64).powi(i as i32) + if i % 997 == 3 { 40.0 } else { 0.0 }
        })
        .collect()
}

#[test]
fn halo_is_the_least_multiple_of_four_meeting_the_decay_bound() {
    // CMM: kappa 3, q = 2 - sqrt(3), C = (1 + sqrt 3)^2 / 2: C q^H <= 2^-66 from H = 35.7.
    assert_eq!(halo_rows(scaled_spectral_ratio(0.0)), Some(36));
    // AMM(1/2): kappa 3/2, q = 0.101: H = 20.4.
    assert_eq!(halo_rows(scaled_spectral_ratio(0.5)), Some(24));
    // LMM: kappa 1, the inverse is diagonal.
    assert_eq!(halo_rows(scaled_spectral_ratio(1.0)), Some(4));
    // beta = -0.49: kappa 150, q = 0.849, H = 307 > MAX_TILE / 4: no tiles.
    assert_eq!(halo_rows(scaled_spectral_ratio(-0.49)), None);
    for kappa in [1.0, 1.5, 3.0, 30.0] {
        let h = halo_rows(kappa).unwrap();
        let root: f64 = kappa.sqrt();
        let q = (root - 1.0) / (root + 1.0);
        let c = kappa.max((1.0 + root).powi(2) / 2.0);
        assert!(c * q.powi(h as i32) <= TRUNCATION, "kappa {kappa}");
        if h > 4 {
            assert!(
                c * q.powi(h as i32 - 4) > TRUNCATION,
                "kappa {kappa}: not the least"
            );
        }
    }
}

#[test]
fn short_matrices_and_slow_decay_keep_the_global_factor() {
    let m = mass(&vec![1.0; WINDOWS_PER_GROUP * MIN_TILE - 2], 0.0, &[]);
    assert!(
        HaloTiles::new(&m, 36, &[]).is_none(),
        "shorter than a group of the shortest tiles"
    );
    let m = mass(&vec![1.0; WINDOWS_PER_GROUP * MIN_TILE], 0.0, &[]);
    let tiles = HaloTiles::new(&m, 36, &[]).unwrap();
    assert_eq!(
        tiles.tile(),
        MIN_TILE + 8,
        "one group, tiles just long enough"
    );
    assert!(
        HaloTiles::new(&m, 34, &[]).is_none(),
        "halo not a multiple of 4"
    );
}

#[test]
fn tiles_fit_the_bar_in_as_many_groups_as_the_longest_tiles_need() {
    // `tile_rows`: a multiple of LANES between MIN_TILE and MAX_TILE from a group of the
    // shortest tiles on; no more groups than tiles of MAX_TILE would take; and the groups' tiles
    // cover the rows with less than LANES rows to spare per tile (a fixed 1024 spares 4576 of
    // 24 576 at n = 20 000: a padded last group).
    let lanes = crate::simd::LANES;
    for n in (WINDOWS_PER_GROUP * MIN_TILE..300_000).step_by(37) {
        let tile = tile_rows(n);
        assert!(tile.is_multiple_of(lanes), "n {n}: {tile}");
        assert!((MIN_TILE..=MAX_TILE).contains(&tile), "n {n}: {tile}");
        let groups = n.div_ceil(tile).div_ceil(WINDOWS_PER_GROUP);
        assert_eq!(
            groups,
            n.div_ceil(WINDOWS_PER_GROUP * MAX_TILE),
            "n {n}: {tile}"
        );
        assert!(
            groups * WINDOWS_PER_GROUP * tile < n + groups * WINDOWS_PER_GROUP * lanes,
            "n {n}: {tile}"
        );
    }
}

#[test]
fn windows_give_the_global_solution_to_round_off() {
    // One whole group of the longest tiles; four groups of shorter ones (792 rows: the rows
    // spread over whole groups) with fixed rows at the left end, on a tile edge and inside a
    // tile; two groups of the shortest tiles two groups can have (520 rows) whose last row is
    // fixed; and the longest tiles again, sixteen groups whose last tile is one fixed row (the
    // seed bar's fixed right end), a fixed row ending a tile.
    let (short, tiled) = (3 * WINDOWS_PER_GROUP * MAX_TILE + 777, 792);
    let single = 16 * WINDOWS_PER_GROUP * MAX_TILE - MAX_TILE;
    assert_eq!(tile_rows(short + 1), tiled);
    assert_eq!(tile_rows(single + 1), MAX_TILE);
    assert_eq!(tile_rows(WINDOWS_PER_GROUP * MAX_TILE + 41), 520);
    for (elements, fixed) in [
        (WINDOWS_PER_GROUP * MAX_TILE - 1, vec![]),
        (short, vec![0, 5 * tiled, 7 * tiled + 100]),
        (
            WINDOWS_PER_GROUP * MAX_TILE + 40,
            vec![WINDOWS_PER_GROUP * MAX_TILE + 40],
        ),
        (single, vec![3 * MAX_TILE - 1, single]),
    ] {
        for (beta, uniform) in [(0.0, true), (0.0, false), (0.5, false), (-0.45, false)] {
            let masses = if uniform {
                vec![0.25; elements]
            } else {
                graded_masses(elements)
            };
            let m = mass(&masses, beta, &fixed);
            let halo = halo_rows(scaled_spectral_ratio(beta)).unwrap();
            let tiles = HaloTiles::new(&m, halo, &fixed).unwrap();
            let n = elements + 1;
            if elements == single {
                assert_eq!(n % tiles.tile(), 1, "the last tile is one row");
            }
            let r = right_hand_side(n);
            let mut exact = r.clone();
            fixed.iter().for_each(|&i| exact[i] = 0.0);
            PartitionedLdl::new(&m).unwrap().solve_in_place(&mut exact);
            let mut x = r.clone();
            tiles.solve_in_place(&mut x);
            // Relative to the solution's scale near the row (masses vary by 1e5 along the bar):
            // x_i against the largest |x| within a halo, a few units of round-off.
            for i in 0..n {
                let near = exact[i.saturating_sub(halo)..(i + halo).min(n)]
                    .iter()
                    .fold(0.0f64, |s, v| s.max(v.abs()));
                assert!(
                    (x[i] - exact[i]).abs() <= 8.0 * f64::EPSILON * near,
                    "beta {beta}, n {n}, row {i}: {} vs {}",
                    x[i],
                    exact[i]
                );
            }
            for &i in &fixed {
                assert_eq!(x[i].to_bits(), 0, "fixed row {i} is +0");
            }
            // One row's own solve: the same bits as the whole solve's.
            for i in (0..n)
                .filter(|i| i % 97 == 0 || i % tiles.tile() < 2 || i + 2 > n || fixed.contains(i))
            {
                assert_eq!(
                    tiles.solution_at(i, &r).to_bits(),
                    x[i].to_bits(),
                    "row {i}"
                );
            }
        }
    }
}

#[test]
fn intrinsics_and_portable_loops_give_the_same_bits() {
    // Per-window factors (graded masses) and shared ones (uniform masses).
    let elements = 2 * WINDOWS_PER_GROUP * MAX_TILE + 333;
    let fixed = [0, 3 * MAX_TILE + 1];
    for masses in [graded_masses(elements), vec![0.25; elements]] {
        let m = mass(&masses, 0.0, &fixed);
        let intrinsics = HaloTiles::new(&m, 36, &fixed).unwrap();
        if !intrinsics.simd {
            return; // no AVX2 and FMA here: only the portable loops run
        }
        let portable = HaloTiles {
            simd: false,
            ..intrinsics.clone()
        };
        let r = right_hand_side(elements + 1);
        let solve = |tiles: &HaloTiles| {
            let mut x = r.clone();
            tiles.solve_in_place(&mut x);
            x.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        };
        assert_eq!(solve(&portable), solve(&intrinsics));
    }
}

/// Groups whose windows have the same rows share one set of factors: `(shared groups, sets)`.
fn sharing(tiles: &HaloTiles) -> (usize, usize) {
    let shared = tiles
        .group_factors
        .iter()
        .filter(|f| matches!(f, GroupFactors::Shared(_)))
        .count();
    (shared, tiles.shared.len() / (2 * tiles.window))
}

#[test]
fn groups_of_equal_rows_share_their_factors_and_give_the_same_bits() {
    // Uniform element mass: every group but the first (its first window holds row 0) and the
    // last (shifted inward, holding the last row) shares one set. Two uniform layers meeting at
    // a group edge: one set each, the two groups whose windows cross the interface keep their
    // own. Graded: nothing to share. A fixed row inside a group's windows makes that group
    // different; the groups after it share the set of the groups before.
    let groups = 6;
    let elements = groups * WINDOWS_PER_GROUP * MAX_TILE - 100;
    assert_eq!(
        tile_rows(elements + 1),
        MAX_TILE,
        "groups of the longest tiles"
    );
    let layered: Vec<f64> = (0..elements)
        .map(|e| {
            if e < 3 * WINDOWS_PER_GROUP * MAX_TILE {
                0.25
            } else {
                2.0
            }
        })
        .collect();
    for (masses, fixed, expected) in [
        (vec![0.25; elements], vec![], (groups - 2, 1)),
        (layered, vec![], (groups - 4, 2)),
        (graded_masses(elements), vec![], (0, 0)),
        (
            vec![0.25; elements],
            vec![2 * WINDOWS_PER_GROUP * MAX_TILE + 4 * MAX_TILE],
            (groups - 3, 1),
        ),
    ] {
        let m = mass(&masses, 0.0, &fixed);
        let shared = HaloTiles::with_sharing(&m, 36, &fixed, true).unwrap();
        let own = HaloTiles::with_sharing(&m, 36, &fixed, false).unwrap();
        assert_eq!(sharing(&shared), expected, "fixed {fixed:?}");
        assert_eq!(sharing(&own), (0, 0));
        let r = right_hand_side(elements + 1);
        let solve = |tiles: &HaloTiles| {
            let mut x = r.clone();
            tiles.solve_in_place(&mut x);
            x.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        };
        let x = solve(&shared);
        assert_eq!(x, solve(&own), "fixed {fixed:?}");
        for i in (0..=elements).step_by(331) {
            assert_eq!(shared.solution_at(i, &r).to_bits(), x[i], "row {i}");
        }
    }
}
