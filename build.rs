//! Compiles the external result sets committed under `external/<code>/results/` into the
//! binary (`results::exchange::committed`): every directory there that holds a `results.toml`
//! is a set, its scene the directory's name, its label the path between `results/` and the
//! scene (`central-difference-as-it-comes`), or the code; every file of the directory is listed,
//! so a set cannot be committed half-listed. A `stated.toml` beside the files holds the
//! findings stated for the set (what courant finds in that code, so that only a change of
//! verdict fails). An `external/<code>/courant_times.csv` holds courant's times on the cases
//! that code ran, measured by its driver together with the code's own (`wall_s` in its sets).

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

fn sets(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<PathBuf> = entries.flatten().map(|e| e.path()).collect();
    paths.sort();
    if paths
        .iter()
        .any(|p| p.file_name().is_some_and(|n| n == "results.toml"))
    {
        out.push(dir.to_path_buf());
        return;
    }
    for p in paths.into_iter().filter(|p| p.is_dir()) {
        sets(&p, out);
    }
}

fn main() {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap());
    let external = root.join("external");
    println!("cargo:rerun-if-changed=external");
    let mut codes: Vec<PathBuf> = fs::read_dir(&external)
        .map(|e| {
            e.flatten()
                .map(|e| e.path())
                .filter(|p| p.is_dir())
                .collect()
        })
        .unwrap_or_default();
    codes.sort();
    let mut text = String::from("&[\n");
    let mut costs = String::from("&[\n");
    for code_dir in codes {
        let code = code_dir.file_name().unwrap().to_string_lossy().into_owned();
        let cost = code_dir.join("courant_times.csv");
        if cost.is_file() {
            let _ = writeln!(
                costs,
                "    ({code:?}, include_str!({:?})),",
                cost.to_string_lossy()
            );
        }
        let results = code_dir.join("results");
        let mut found = Vec::new();
        sets(&results, &mut found);
        for dir in found {
            let rel = dir
                .strip_prefix(&root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            let scene = dir.file_name().unwrap().to_string_lossy().into_owned();
            let inner = dir.parent().unwrap().strip_prefix(&results).unwrap();
            let label = if inner.as_os_str().is_empty() {
                code.clone()
            } else {
                format!("{code} {}", inner.to_string_lossy().replace('\\', "/"))
            };
            let mut files: Vec<PathBuf> = fs::read_dir(&dir)
                .unwrap()
                .flatten()
                .map(|e| e.path())
                .filter(|p| p.is_file())
                .collect();
            files.sort();
            let mut listed = String::new();
            let mut stated = String::from("None");
            for f in files {
                let name = f.file_name().unwrap().to_string_lossy().into_owned();
                let path = format!("{:?}", f.to_string_lossy());
                if name == "stated.toml" {
                    stated = format!("Some(include_str!({path}))");
                } else {
                    let _ = writeln!(listed, "            ({name:?}, include_str!({path})),");
                }
            }
            let _ = writeln!(
                text,
                "    CommittedSet {{\n        code: {code:?},\n        label: {label:?},\n        scene: {scene:?},\n        dir: {rel:?},\n        files: &[\n{listed}        ],\n        stated: {stated},\n    }},"
            );
        }
    }
    text.push(']');
    costs.push(']');
    let out = PathBuf::from(std::env::var("OUT_DIR").unwrap());
    fs::write(out.join("committed_sets.rs"), text).unwrap();
    fs::write(out.join("committed_courant_times.rs"), costs).unwrap();
}
