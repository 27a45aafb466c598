//! The benchmark table of the report's timing section: criterion's medians read from
//! `target/criterion/<group>/<function>/<N>/new/estimates.json` (written by `cargo bench`),
//! in ns per node-step, beside a bandwidth model (bytes of arrays each node-step touches) and
//! the machine's measured reach: the STREAM triad `a = b + s c` at the same N (McCalpin 1995;
//! the `memory_triad` benchmark, 24 B per element), so `fraction_of_triad` = model GB/s over
//! triad GB/s says how close to this machine's limit a step runs.

use crate::results::table::Table;
use std::path::Path;

/// Bytes each node-step reads or writes in the model (8-byte values, every array touched once per
/// pass): the lumped step reads and writes u and v and reads k and dt/m (48 B); with energies it
/// also reads m (56 B); the matrix-mass steps as `courant_solver::kernels::matrix_mass::kernel`'s
/// docs count them: RMM 9 words (72 B), CMM and AMM about 19 (152 B); Park reads u, v, a, dt_e,
/// q_e, A_i, k_e, 1/m and m and writes u, v, a (12 arrays, 96 B; its u^{n+1} block stays in cache);
/// a contact step is two lumped steps with energies plus O(1) contact work (56 B per node); a block
/// of lumped steps (`lumped_cd_block`) passes over the arrays once per sub-block of
/// [`courant_solver::bench::DEPTH`] = 64 steps (48 / 64 and 56 / 64 B).
fn bytes_per_node_step(group: &str, function: &str) -> Option<f64> {
    let depth = courant_solver::bench::DEPTH as f64;
    match (group, function) {
        ("lumped_cd_step", "step") => Some(48.0),
        ("lumped_cd_step", "step_with_energy")
        | ("mass_kind_step", "lmm")
        | ("park_step", "cd")
        | ("contact_step", _) => Some(56.0),
        ("mass_kind_step", f) if f.starts_with("rmm") => Some(72.0),
        ("mass_kind_step", _) => Some(152.0),
        ("park_step", _) => Some(96.0),
        ("lumped_cd_block", f) if f.starts_with("step_with_energy") => Some(56.0 / depth),
        ("lumped_cd_block", _) => Some(48.0 / depth),
        _ => None,
    }
}

/// Time steps one criterion iteration of `group` takes (a block of lumped steps takes
/// [`courant_solver::bench::MAX_BLOCK_STEPS`]).
fn steps_per_iteration(group: &str) -> f64 {
    if group == "lumped_cd_block" {
        courant_solver::bench::MAX_BLOCK_STEPS as f64
    } else {
        1.0
    }
}

/// The benchmark table without rows (what the report writes when `target/criterion` holds no
/// results, so that `timing.benchmarks.csv` is always one of its files).
pub fn empty_bench_table() -> Table {
    Table::new(&[
        "benchmark",
        "N",
        "median_ns_per_iteration",
        "ns_per_node_step",
        "model_bytes_per_node_step",
        "model_GB_per_s",
        "triad_GB_per_s",
        "fraction_of_triad",
    ])
}

/// The STREAM triad benchmark (group, function) and its bytes per element.
const TRIAD: (&str, &str, f64) = ("memory_triad", "triad", 24.0);

/// `benchmark, N, median_ns_per_iteration, ns_per_node_step, model_bytes_per_node_step, model_GB_per_s, triad_GB_per_s, fraction_of_triad`
/// for every criterion result found under `criterion_dir` (the triad columns where the triad was
/// measured at the same N); `None` when there are none (run `cargo bench` first).
pub fn bench_table(criterion_dir: &Path) -> Option<Table> {
    let mut rows: Vec<(String, String, u64, f64)> = Vec::new();
    for group in std::fs::read_dir(criterion_dir).ok()?.flatten() {
        let group_name = group.file_name().to_string_lossy().to_string();
        for function in std::fs::read_dir(group.path())
            .ok()
            .into_iter()
            .flatten()
            .flatten()
        {
            let function_name = function.file_name().to_string_lossy().to_string();
            for size in std::fs::read_dir(function.path())
                .ok()
                .into_iter()
                .flatten()
                .flatten()
            {
                let Ok(n) = size.file_name().to_string_lossy().parse::<u64>() else {
                    continue;
                };
                let Ok(text) = std::fs::read_to_string(size.path().join("new/estimates.json"))
                else {
                    continue;
                };
                let Ok(json) = serde_json::from_str::<serde_json::Value>(&text) else {
                    continue;
                };
                if let Some(median) = json["median"]["point_estimate"].as_f64() {
                    rows.push((group_name.clone(), function_name.clone(), n, median));
                }
            }
        }
    }
    if rows.is_empty() {
        return None;
    }
    rows.sort_by(|a, b| (&a.0, &a.1, a.2).cmp(&(&b.0, &b.1, b.2)));
    // GB/s of the triad at each N (bytes per ns = GB/s).
    let triad = |n: u64| {
        rows.iter()
            .find(|r| r.0 == TRIAD.0 && r.1 == TRIAD.1 && r.2 == n)
            .map(|r| TRIAD.2 * n as f64 / r.3)
    };
    let mut table = empty_bench_table();
    for &(ref group, ref function, n, median) in &rows {
        if (group.as_str(), function.as_str()) == (TRIAD.0, TRIAD.1) {
            table.push(vec![
                format!("{group}/{function}").into(),
                (n as usize).into(),
                median.into(),
                None::<f64>.into(),
                None::<usize>.into(),
                triad(n).into(),
                triad(n).into(),
                Some(1.0).into(),
            ]);
            continue;
        }
        // A dense spectrum benchmark iterates one eigen-solve, not a time step; a contact step
        // advances two bars of N elements each.
        let is_step = group != "spectrum_dense";
        let nodes = if group == "contact_step" { 2 } else { 1 } as f64 * (n as f64 + 1.0);
        let per_node = is_step.then(|| median / (nodes * steps_per_iteration(group)));
        let bytes = bytes_per_node_step(group, function);
        let model = bytes.zip(per_node).map(|(b, t)| b / t);
        table.push(vec![
            format!("{group}/{function}").into(),
            (n as usize).into(),
            median.into(),
            per_node.into(),
            bytes.into(),
            model.into(),
            triad(n).into(),
            model.zip(triad(n)).map(|(m, t)| m / t).into(),
        ]);
    }
    Some(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A synthetic criterion tree: 48 B per node-step at 0.5 ns per node-step must read 96 GB/s;
    /// an empty or missing directory gives no table.
    #[test]
    fn reads_criterion_median_and_applies_bandwidth_model() {
        let dir = std::env::temp_dir().join(format!("courant-bench-table-{}", std::process::id()));
        let median = |bench: &str, ns: f64| {
            let leaf = dir.join(bench).join("new");
            std::fs::create_dir_all(&leaf).unwrap();
            let json = format!(r#"{{"median":{{"point_estimate":{ns}}}}}"#);
            std::fs::write(leaf.join("estimates.json"), json).unwrap();
        };
        median("lumped_cd_step/step/999", 500.0);
        let table = bench_table(&dir).expect("one result");
        let csv = table.to_csv(crate::results::table::Precision::RoundTrip);
        let row = csv.lines().nth(1).unwrap();
        assert_eq!(row, "lumped_cd_step/step,999,500,0.5,48,96,,");
        // A triad of 999 elements in 125 ns moves 24 * 999 / 125 GB/s; the step's 96 GB/s is
        // that fraction of it.
        median("memory_triad/triad/999", 125.0);
        let csv = bench_table(&dir)
            .unwrap()
            .to_csv(crate::results::table::Precision::RoundTrip);
        std::fs::remove_dir_all(&dir).unwrap();
        let triad = 24.0 * 999.0 / 125.0;
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(
            lines[1],
            format!(
                "lumped_cd_step/step,999,500,0.5,48,96,{triad},{}",
                96.0 / triad
            )
        );
        assert_eq!(
            lines[2],
            format!("memory_triad/triad,999,125,,,{triad},{triad},1")
        );
        assert!(bench_table(&dir).is_none());
    }

    /// One criterion iteration of `lumped_cd_block` is a block of 1024 steps: 512 000 ns for
    /// 1000 nodes is 0.5 ns per node-step, and 48 B per node per 64 steps at that rate 1.5 GB/s.
    #[test]
    fn a_block_of_steps_is_counted_per_node_step() {
        let dir = std::env::temp_dir().join(format!("courant-bench-block-{}", std::process::id()));
        let leaf = dir.join("lumped_cd_block/step_t1/999/new");
        std::fs::create_dir_all(&leaf).unwrap();
        std::fs::write(
            leaf.join("estimates.json"),
            r#"{"median":{"point_estimate":512000}}"#,
        )
        .unwrap();
        let csv = bench_table(&dir)
            .unwrap()
            .to_csv(crate::results::table::Precision::RoundTrip);
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(
            csv.lines().nth(1).unwrap(),
            "lumped_cd_block/step_t1,999,512000,0.5,0.75,1.5,,"
        );
    }
}
