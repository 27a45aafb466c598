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
//!    [`SOLVER_LAYERS`], so no import cycle runs between them either.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

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

/// The workspace root.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A module path, e.g. `["scene", "error"]` (empty: the crate root).
type ModPath = Vec<String>;

/// Every `.rs` file under `dir`, recursively, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The module path of a file of a crate whose root directory is `src`.
fn module_of(src: &Path, file: &Path) -> ModPath {
    let rel = file.strip_prefix(src).expect("file under src");
    let mut parts: Vec<String> = rel
        .iter()
        .map(|s| s.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        parts.pop();
    }
    parts
}

/// The text without comments, string literals and `#[cfg(test)]` modules.
fn code_of(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let bytes: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        let next = bytes.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < bytes.len() && bytes[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            i += 2;
            while i + 1 < bytes.len() && !(bytes[i] == '*' && bytes[i + 1] == '/') {
                i += 1;
            }
            i += 2;
        } else if c == '"' {
            // Skip a string literal (escapes honoured); raw strings are rare enough here.
            i += 1;
            while i < bytes.len() && bytes[i] != '"' {
                if bytes[i] == '\\' {
                    i += 1;
                }
                i += 1;
            }
            i += 1;
            out.push_str("\"\"");
        } else if c == '\'' && next.is_some_and(|n| n != '\\') && bytes.get(i + 2) == Some(&'\'') {
            // A char literal such as '{'.
            i += 3;
            out.push_str("' '");
        } else {
            out.push(c);
            i += 1;
        }
    }
    strip_test_modules(&out)
}

/// Remove every `#[cfg(test)] mod name { … }` block (balanced braces).
fn strip_test_modules(code: &str) -> String {
    let mut out = code.to_string();
    while let Some(at) = out.find("#[cfg(test)]") {
        let rest = &out[at..];
        let Some(open) = rest.find('{') else { break };
        let header = &rest[..open];
        if !header.contains("mod ") {
            // `#[cfg(test)]` on something else: drop the attribute only.
            out.replace_range(at..at + "#[cfg(test)]".len(), "");
            continue;
        }
        let mut depth = 0usize;
        let mut end = rest.len();
        for (k, ch) in rest[open..].char_indices() {
            match ch {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = open + k + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        out.replace_range(at..at + end, "");
    }
    out
}

/// Child modules declared in a file (`mod x;` / `pub mod x;` / `pub(crate) mod x;`).
fn child_modules(code: &str) -> Vec<String> {
    let mut children = Vec::new();
    for line in code.lines() {
        let l = line.trim();
        let l = l
            .strip_prefix("pub(crate) ")
            .or_else(|| l.strip_prefix("pub(super) "))
            .or_else(|| l.strip_prefix("pub "))
            .unwrap_or(l);
        if let Some(name) = l.strip_prefix("mod ").and_then(|r| r.strip_suffix(';')) {
            children.push(name.trim().to_string());
        }
    }
    children
}

/// Expand a `use` tree (`a::{b, c::{d, e}}`) into its paths.
fn expand_use(tree: &str) -> Vec<String> {
    let tree = without_renames(tree);
    let Some(open) = tree.find('{') else {
        return vec![tree];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.len().saturating_sub(1)];
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0, 0);
    for (k, ch) in inner.char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..k]);
                start = k + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.is_empty())
        .flat_map(|p| {
            expand_use(p)
                .into_iter()
                .map(|q| {
                    if q == "self" {
                        prefix.trim_end_matches("::").to_string()
                    } else {
                        format!("{prefix}{q}")
                    }
                })
                .collect::<Vec<_>>()
        })
        .collect()
}

/// A `use` tree without whitespace and without its renames (`a::B as C` -> `a::B`).
fn without_renames(tree: &str) -> String {
    let mut out = String::new();
    let mut tokens = tree.split_whitespace();
    while let Some(t) = tokens.next() {
        if t == "as" {
            // Drop the alias, keep the punctuation that follows it (`,` or `}`).
            let alias = tokens.next().unwrap_or("");
            out.extend(
                alias
                    .chars()
                    .filter(|c| !(c.is_alphanumeric() || *c == '_')),
            );
        } else {
            out.push_str(t);
        }
    }
    out
}

/// Every path a file's code names that starts with `crate`, `super`, `self` or a child module.
fn paths_in(code: &str, children: &[String]) -> Vec<String> {
    let mut paths = Vec::new();
    // `use` trees (they may span lines and group with braces).
    let mut rest = code;
    while let Some(at) = find_word(rest, "use") {
        let after = &rest[at + 3..];
        let Some(end) = after.find(';') else { break };
        paths.extend(expand_use(&after[..end]));
        rest = &after[end..];
    }
    // Inline paths: `crate::a::b`, `super::x`, `child::y`.
    let chars: Vec<char> = code.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let boundary = i == 0 || !(chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        if boundary && (chars[i].is_alphabetic() || chars[i] == '_') {
            let start = i;
            while i < chars.len()
                && (chars[i].is_alphanumeric() || chars[i] == '_' || chars[i] == ':')
            {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            let head = word.split("::").next().unwrap_or("");
            if word.contains("::")
                && (["crate", "super", "self"].contains(&head)
                    || children.iter().any(|c| c == head))
            {
                paths.push(word.trim_end_matches(':').to_string());
            }
        } else {
            i += 1;
        }
    }
    paths
}

/// The byte offset of `word` as a whole word in `text`.
fn find_word(text: &str, word: &str) -> Option<usize> {
    let mut from = 0;
    while let Some(k) = text[from..].find(word) {
        let at = from + k;
        let before = text[..at].chars().last();
        let after = text[at + word.len()..].chars().next();
        let is_ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
        if !is_ident(before) && !is_ident(after) {
            return Some(at);
        }
        from = at + word.len();
    }
    None
}

/// The deepest module of `modules` that `path` (written in module `here`) names.
fn resolve(
    path: &str,
    here: &ModPath,
    children: &[String],
    modules: &BTreeSet<ModPath>,
) -> Option<ModPath> {
    let segments: Vec<&str> = path.split("::").filter(|s| !s.is_empty()).collect();
    let mut base: ModPath;
    let mut k = 0;
    match segments.first() {
        Some(&"crate") => {
            base = Vec::new();
            k = 1;
        }
        Some(&"super") | Some(&"self") => {
            base = here.clone();
            while k < segments.len() && (segments[k] == "super" || segments[k] == "self") {
                if segments[k] == "super" {
                    base.pop();
                }
                k += 1;
            }
        }
        Some(head) if children.iter().any(|c| c == head) => base = here.clone(),
        _ => return None,
    }
    for s in &segments[k..] {
        let mut deeper = base.clone();
        deeper.push(s.to_string());
        if modules.contains(&deeper) {
            base = deeper;
        } else {
            break;
        }
    }
    Some(base)
}

/// The module graph of the crate whose root directory is `src`: module -> modules it uses.
fn graph(src: &Path) -> BTreeMap<ModPath, BTreeSet<ModPath>> {
    let files = rust_files(src);
    let modules: BTreeSet<ModPath> = files.iter().map(|f| module_of(src, f)).collect();
    let mut edges = BTreeMap::new();
    for file in &files {
        let here = module_of(src, file);
        let code = code_of(&std::fs::read_to_string(file).expect("readable source"));
        let children = child_modules(&code);
        let targets: BTreeSet<ModPath> = paths_in(&code, &children)
            .iter()
            .filter_map(|p| resolve(p, &here, &children, &modules))
            .filter(|t| *t != here)
            .collect();
        edges.insert(here, targets);
    }
    edges
}

fn show(m: &ModPath) -> String {
    if m.is_empty() {
        "crate".into()
    } else {
        m.join("::")
    }
}

/// One cycle of the graph, if there is any (depth-first search, colours).
fn find_cycle(g: &BTreeMap<ModPath, BTreeSet<ModPath>>) -> Option<Vec<ModPath>> {
    #[derive(Clone, Copy, PartialEq)]
    enum Colour {
        White,
        Grey,
        Black,
    }
    fn visit(
        n: &ModPath,
        g: &BTreeMap<ModPath, BTreeSet<ModPath>>,
        colour: &mut BTreeMap<ModPath, Colour>,
        stack: &mut Vec<ModPath>,
    ) -> Option<Vec<ModPath>> {
        colour.insert(n.clone(), Colour::Grey);
        stack.push(n.clone());
        for m in g.get(n).into_iter().flatten() {
            match colour.get(m).copied().unwrap_or(Colour::White) {
                Colour::Grey => {
                    let from = stack.iter().position(|x| x == m).unwrap_or(0);
                    let mut cycle = stack[from..].to_vec();
                    cycle.push(m.clone());
                    return Some(cycle);
                }
                Colour::White => {
                    if let Some(c) = visit(m, g, colour, stack) {
                        return Some(c);
                    }
                }
                Colour::Black => {}
            }
        }
        stack.pop();
        colour.insert(n.clone(), Colour::Black);
        None
    }
    let mut colour = BTreeMap::new();
    for n in g.keys() {
        if colour.get(n).copied().unwrap_or(Colour::White) == Colour::White {
            let mut stack = Vec::new();
            if let Some(c) = visit(n, g, &mut colour, &mut stack) {
                return Some(c);
            }
        }
    }
    None
}

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
