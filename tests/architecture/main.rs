//! Source of truth: `ARCHITECTURE.md` (the pipeline scene -> run -> results -> compare ->
//! report/check, dependencies pointing one way) and the house rules of the README.
//!
//! ```text
//!   io <- results <- scene <- run      compare      report   check   cli
//!                     ^  ^------------- ^ ^ ---------^ ^ ----- ^ ---- ^
//!   (an arrow: "is used by"; the full table is ALLOWED below)
//! ```
//!
//! Proves, by reading the source (no build needed):
//! 1. no import cycle between file modules in any crate of the workspace (`use crate::…`,
//!    `super::…`, inline `crate::…` paths and paths through declared child modules all count;
//!    a `mod.rs` that re-exports its children and is used by them is a cycle too);
//! 2. the top-level stages of the `courant` crate depend on each other only as ALLOWED says;
//! 3. `courant-references` does not depend on `courant-solver` (references are independent);
//! 4. no source file is longer than [`MAX_LINES`] lines;
//! 5. the top-level modules (folders) of `courant-solver` use only those below them in
//!    [`SOLVER_LAYERS`], so no import cycle runs between them either;
//! 6. each folder of `courant-solver` opens its `mod.rs` with what enters, what leaves and what
//!    it must not know, as the stages of `src/` do.

mod source;

use source::{
    ModPath, child_modules, code_of, expand_use, find_cycle, graph, paths_in, root, rust_files,
    show,
};
use std::collections::{BTreeMap, BTreeSet};

/// Longest source file allowed (the house rule says "about 600").
const MAX_LINES: usize = 600;

/// For each top-level stage of the `courant` crate, the stages it may use.
const ALLOWED: &[(&str, &[&str])] = &[
    ("io", &[]),
    ("results", &["io"]),
    ("scene", &["io"]),
    ("run", &["scene", "results", "io"]),
    ("compare", &["scene", "results", "io"]),
    ("pipeline", &["run", "compare", "scene", "results", "io"]),
    ("report", &["pipeline", "compare", "scene", "results", "io"]),
    ("check", &["pipeline", "compare", "scene", "results", "io"]),
    (
        "cli",
        &[
            "report", "check", "pipeline", "compare", "run", "scene", "results", "io",
        ],
    ),
];

/// The top-level modules of `courant-solver`, lowest first: each may use only itself and the
/// modules before it (ARCHITECTURE.md, "Code map of the other crates").
const SOLVER_LAYERS: &[&str] = &[
    "simd",
    "output",
    "error",
    "model",
    "mass",
    "analysis",
    "kernels",
    "integrator",
    "schemes",
    "contact",
    "fixtures",
    "bench",
];

const CRATES: &[&str] = &["src", "solver/src", "references/src"];

#[test]
fn no_import_cycle_between_modules_in_any_crate() {
    let mut cycles = Vec::new();
    for src in CRATES {
        let g = graph(&root().join(src));
        assert!(g.len() > 3, "{src}: found only {} modules", g.len());
        if let Some(cycle) = find_cycle(&g) {
            let chain: Vec<String> = cycle.iter().map(show).collect();
            cycles.push(format!("{src}: {}", chain.join(" -> ")));
        }
    }
    assert!(
        cycles.is_empty(),
        "import cycles (a module may not use one that uses it back; a mod.rs that re-exports \
         its children must not be used by them: name the sibling file):\n{}",
        cycles.join("\n")
    );
}

#[test]
fn top_level_stages_depend_only_downstream() {
    let g = graph(&root().join("src"));
    let allowed: BTreeMap<&str, &[&str]> = ALLOWED.iter().copied().collect();
    let mut offences = Vec::new();
    for (from, targets) in &g {
        let Some(stage) = from.first() else {
            continue; // the crate root only declares the stages
        };
        let Some(may) = allowed.get(stage.as_str()) else {
            offences.push(format!(
                "{}: top-level module `{stage}` is not a stage of ALLOWED (and ARCHITECTURE.md)",
                show(from)
            ));
            continue;
        };
        for to in targets {
            match to.first() {
                None => offences.push(format!(
                    "{} uses the crate root: name the stage's module instead",
                    show(from)
                )),
                Some(t) if t != stage && !may.contains(&t.as_str()) => offences.push(format!(
                    "{} -> {}: stage `{stage}` may use only {may:?}",
                    show(from),
                    show(to)
                )),
                _ => {}
            }
        }
    }
    assert!(offences.is_empty(), "{}", offences.join("\n"));
}

#[test]
fn solver_folders_depend_only_on_lower_layers() {
    let g = graph(&root().join("solver/src"));
    let layer = |name: &str| SOLVER_LAYERS.iter().position(|l| *l == name);
    let mut offences = Vec::new();
    for (from, targets) in &g {
        let Some(top) = from.first() else {
            continue; // lib.rs only declares the folders and re-exports
        };
        let Some(here) = layer(top) else {
            offences.push(format!(
                "{}: top-level module `{top}` is not in SOLVER_LAYERS (and ARCHITECTURE.md)",
                show(from)
            ));
            continue;
        };
        for to in targets {
            match to.first() {
                None => offences.push(format!(
                    "{} uses the crate root: name the folder's module instead",
                    show(from)
                )),
                Some(t) if layer(t).is_none_or(|there| there > here) => offences.push(format!(
                    "{} -> {}: `{top}` may use only the layers below it: {:?}",
                    show(from),
                    show(to),
                    &SOLVER_LAYERS[..here]
                )),
                _ => {}
            }
        }
    }
    assert!(offences.is_empty(), "{}", offences.join("\n"));
}

#[test]
fn solver_folders_state_what_enters_leaves_and_is_not_known() {
    let src = root().join("solver/src");
    let mut missing = Vec::new();
    for layer in SOLVER_LAYERS {
        let file = src.join(layer).join("mod.rs");
        let Ok(text) = std::fs::read_to_string(&file) else {
            continue; // a single-file layer (simd, error, output, fixtures, bench)
        };
        let docs: String = text
            .lines()
            .take_while(|l| l.starts_with("//!") || l.trim().is_empty())
            .collect::<Vec<_>>()
            .join("\n");
        let has = |word: &str| docs.contains(word);
        if !(has("Enters") && has("Leaves") && (has("must not") || has("never"))) {
            missing.push(format!("{}", file.display()));
        }
    }
    assert!(
        missing.is_empty(),
        "these folders' mod.rs must open with **Enters:**, **Leaves:** and what they must not \
         know: {}",
        missing.join(", ")
    );
}

#[test]
fn references_do_not_depend_on_the_solver() {
    let manifest = std::fs::read_to_string(root().join("references/Cargo.toml")).unwrap();
    assert!(
        !manifest.contains("courant-solver") && !manifest.contains("courant_solver"),
        "references/Cargo.toml names the solver"
    );
    for file in rust_files(&root().join("references/src")) {
        let text = std::fs::read_to_string(&file).unwrap();
        assert!(
            !code_of(&text).contains("courant_solver"),
            "{} uses courant_solver",
            file.display()
        );
    }
}

#[test]
fn no_source_file_is_longer_than_the_limit() {
    let mut long = Vec::new();
    for dir in [
        "src",
        "solver/src",
        "references/src",
        "tests",
        "solver/tests",
        "references/tests",
        "benches",
    ] {
        for file in rust_files(&root().join(dir)) {
            let lines = std::fs::read_to_string(&file).unwrap().lines().count();
            if lines > MAX_LINES {
                long.push(format!("{} ({lines} lines)", file.display()));
            }
        }
    }
    assert!(
        long.is_empty(),
        "files over {MAX_LINES} lines (split them by concern): {}",
        long.join(", ")
    );
}

/// The checker itself: a two-module cycle through `super::` and a child path is found, and a
/// grouped `use` expands into every path.
#[test]
fn checker_finds_cycles_and_expands_grouped_uses() {
    assert_eq!(
        expand_use("crate::{a::B, c::{d, e::F as G}}"),
        vec!["crate::a::B", "crate::c::d", "crate::c::e::F"]
    );
    let code = code_of(
        "mod x;\n// use crate::z;\nuse super::y;\nfn f() { x::g(); }\n#[cfg(test)]\nmod tests { use crate::q; }\n",
    );
    let children = child_modules(&code);
    assert_eq!(children, vec!["x"]);
    let paths = paths_in(&code, &children);
    assert!(paths.contains(&"super::y".to_string()) && paths.contains(&"x::g".to_string()));
    assert!(!paths.iter().any(|p| p.contains('z') || p.contains('q')));
    let m = |s: &str| -> ModPath { s.split('/').map(String::from).collect() };
    let mut g = BTreeMap::new();
    g.insert(m("a"), BTreeSet::from([m("a/b")]));
    g.insert(m("a/b"), BTreeSet::from([m("a")]));
    assert_eq!(find_cycle(&g), Some(vec![m("a"), m("a/b"), m("a")]));
    g.insert(m("a/b"), BTreeSet::new());
    assert_eq!(find_cycle(&g), None);
}
