//! Source of truth: the repository's own pages, `docs/methods.md` (sections `<a id="sN">`) and
//! `docs/references.md` (one entry `<a id="...">` per document, listing the parts courant
//! cites). Proves: every document a `source` names resolves inside the repository: each
//! `methods.md §N` to a section of docs/methods.md; each paper or book to its entry in
//! docs/references.md, with every figure, equation, section or chapter cited beside it listed
//! in that entry; each file or module path to a file of the repository. A source that cites a
//! year without a listed author fails, so a new document cannot enter unlisted.
//!
//! The sources read: every `source` of every scene file (scene, `[[expect]]`, `[[finding]]`),
//! and every `source:`/`expected:` string of the app and the solver (scheme registries, study
//! definitions, report rows).

use courant::report::citations;
use std::fs;
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// Documents by the names sources use (first match wins), with their entry in references.md.
const DOCUMENTS: &[(&str, &str)] = &[
    ("Kolman et al. 2016", "kolman-2016"),
    ("Kolman et al. 2017", "kolman-2017"),
    ("Kolman et al.", "kolman-seed"),
    ("seed", "kolman-seed"),
    ("Hughes", "hughes"),
    ("Belytschko", "belytschko-hughes-1983"),
    ("Fried", "fried-1972"),
    ("Kopačka", "kopacka-2018"),
    ("Kopacka", "kopacka-2018"),
    ("González", "gonzalez-2018"),
    ("Gonzalez", "gonzalez-2018"),
    ("Park et al.", "park-2012"),
    ("Tkachuk", "tkachuk-bischoff-2015"),
    ("Noh & Bathe", "noh-bathe-2013"),
    ("Noh and Bathe", "noh-bathe-2013"),
    ("Carpenter", "carpenter-1991"),
    ("Graff", "graff-1975"),
    ("Johnson", "johnson-1972"),
    ("Whitham", "whitham-1974"),
    ("Wilkinson", "wilkinson-1965"),
    ("Parlett", "parlett-1998"),
    ("de Hoog", "de-hoog-1982"),
    ("Abramowitz", "abramowitz-stegun"),
    ("McCalpin", "mccalpin-1995"),
];

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn files(dir: &Path, ext: &str, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files(&path, ext, out);
        } else if path.extension().is_some_and(|e| e == ext) {
            out.push(path);
        }
    }
}

/// Every `source` value of a TOML document.
fn toml_sources(value: &toml::Value, out: &mut Vec<String>) {
    match value {
        toml::Value::Table(t) => t.iter().for_each(|(k, v)| match v {
            toml::Value::String(s) if k == "source" => out.push(s.clone()),
            _ => toml_sources(v, out),
        }),
        toml::Value::Array(a) => a.iter().for_each(|v| toml_sources(v, out)),
        _ => {}
    }
}

/// The string literals after `source: `, `expected: ` or `SOURCE: &str = ` in Rust text,
/// with `\`-newline continuations joined as the compiler joins them.
fn rust_sources(text: &str, out: &mut Vec<String>) {
    for key in ["source: \"", "expected: \"", "SOURCE: &str = \""] {
        let mut rest = text;
        while let Some(at) = rest.find(key) {
            let body = &rest[at + key.len()..];
            let mut literal = String::new();
            let mut chars = body.chars();
            while let Some(c) = chars.next() {
                match c {
                    '"' => break,
                    '\\' => match chars.next() {
                        Some('\n') => {
                            chars = chars.as_str().trim_start().chars();
                        }
                        Some(e) => literal.push(e),
                        None => break,
                    },
                    c => literal.push(c),
                }
            }
            out.push(literal);
            rest = body;
        }
    }
}

/// Every source string with the file it comes from.
fn sources() -> Vec<(PathBuf, String)> {
    let mut out = Vec::new();
    let mut scenes = Vec::new();
    files(&Path::new(ROOT).join("scenes"), "toml", &mut scenes);
    for path in scenes {
        let value: toml::Value = toml::from_str(&read(&path)).unwrap();
        let mut found = Vec::new();
        toml_sources(&value, &mut found);
        out.extend(found.into_iter().map(|s| (path.clone(), s)));
    }
    let mut code = Vec::new();
    files(&Path::new(ROOT).join("src"), "rs", &mut code);
    files(&Path::new(ROOT).join("solver/src"), "rs", &mut code);
    for path in code {
        let mut found = Vec::new();
        rust_sources(&read(&path), &mut found);
        out.extend(found.into_iter().map(|s| (path.clone(), s)));
    }
    out
}

/// The text of a references.md entry: from its anchor to the next one.
fn entry<'a>(references: &'a str, anchor: &str) -> Option<&'a str> {
    let start = references.find(&format!("<a id=\"{anchor}\"></a>"))?;
    let body = &references[start + 1..];
    Some(&body[..body.find("<a id=").unwrap_or(body.len())])
}

/// The parts cited right after a document's name, up to the end of its clause (`;`, `:`, the
/// next `methods.md` or the next document's name): `§3.2`, `Fig. 2c-d`, `eqs. 2-4`, `ch. 2`.
fn cited_parts(clause: &str) -> Vec<(String, u32, u32)> {
    let mut parts = Vec::new();
    for (kind, prefixes) in [
        ("§", &["§"][..]),
        ("Fig.", &["Figs. ", "Fig. "][..]),
        ("eq.", &["eqs. ", "eq. "][..]),
        ("ch.", &["ch. "][..]),
        ("§", &["Sec. "][..]),
    ] {
        for prefix in prefixes {
            let mut rest = clause;
            while let Some(at) = rest.find(prefix) {
                let body = &rest[at + prefix.len()..];
                let number: String = body
                    .chars()
                    .take_while(|c| c.is_ascii_digit() || *c == '.')
                    .collect();
                let number = number.trim_end_matches('.').to_string();
                rest = &body[number.len().min(body.len())..];
                if number.is_empty() {
                    continue;
                }
                // A range "4-5" or "2c-d" (letters are panels of one figure).
                let tail = rest.trim_start_matches(|c: char| c.is_ascii_lowercase());
                let last = tail
                    .strip_prefix('-')
                    .map(|t| {
                        t.chars()
                            .take_while(char::is_ascii_digit)
                            .collect::<String>()
                    })
                    .filter(|t| !t.is_empty());
                if kind == "§" {
                    parts.push((format!("§{number}"), 0, 0));
                } else {
                    let first: u32 = number.split('.').next().unwrap().parse().unwrap();
                    let last = last.map_or(first, |l| l.parse().unwrap());
                    parts.push((kind.to_string(), first, last));
                }
            }
        }
    }
    parts
}

/// Whether an entry lists a cited part: `§x` literally; a figure, equation or chapter number
/// either singly (`Fig. 3`) or inside a listed range (`Figs. 4-5`, `eqs. 6-13`).
fn lists(entry: &str, part: &(String, u32, u32)) -> bool {
    let (kind, first, last) = part;
    if kind.starts_with('§') {
        return entry.contains(&format!("{kind} ")) || entry.contains(&format!("{kind},"));
    }
    let (single, plural) = match kind.as_str() {
        "Fig." => ("Fig. ", "Figs. "),
        "eq." => ("eq. ", "eqs. "),
        _ => ("ch. ", "chs. "),
    };
    (*first..=*last).all(|n| {
        let single_hit = entry.match_indices(single).any(|(i, _)| {
            let digits: String = entry[i + single.len()..]
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            digits == n.to_string()
        });
        let range_hit = entry.match_indices(plural).any(|(i, _)| {
            let range: String = entry[i + plural.len()..]
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '-')
                .collect();
            let mut ends = range.split('-').filter_map(|x| x.parse::<u32>().ok());
            match (ends.next(), ends.next()) {
                (Some(a), Some(b)) => (a..=b).contains(&n),
                (Some(a), None) => a == n,
                _ => false,
            }
        });
        single_hit || range_hit
    })
}

/// The clause after a document's name.
fn clause(after: &str) -> &str {
    let mut end = after.len();
    let names = DOCUMENTS.iter().map(|(name, _)| *name);
    for stop in [";", ":", "methods.md"].into_iter().chain(names) {
        if let Some(i) = after.find(stop) {
            end = end.min(i);
        }
    }
    &after[..end]
}

#[test]
fn every_methods_section_a_source_cites_exists() {
    let methods = read(&Path::new(ROOT).join("docs/methods.md"));
    let mut cited = 0;
    for (path, source) in sources() {
        for (_, href) in citations::pieces(&source) {
            let Some(href) = href else { continue };
            let anchor = href.split('#').nth(1).unwrap();
            assert!(
                methods.contains(&format!("<a id=\"{anchor}\"></a>")),
                "{}: `{source}` cites {href}, which docs/methods.md does not have",
                path.display()
            );
            cited += 1;
        }
    }
    assert!(cited > 100, "only {cited} methods.md citations found");
}

#[test]
fn every_document_a_source_names_is_listed_with_the_parts_it_cites() {
    let references = read(&Path::new(ROOT).join("docs/references.md"));
    for (_, anchor) in DOCUMENTS {
        assert!(entry(&references, anchor).is_some(), "no entry {anchor}");
    }
    let all = sources();
    assert!(all.len() > 150, "only {} sources found", all.len());
    for (path, source) in &all {
        for (name, anchor) in DOCUMENTS {
            let mut from = 0;
            while let Some(i) = source[from..].find(name) {
                let at = from + i + name.len();
                from = at;
                // "seed" inside "seed's": the name still cites the seed.
                let entry = entry(&references, anchor).unwrap();
                for part in cited_parts(clause(&source[at..])) {
                    assert!(
                        lists(entry, &part),
                        "{}: `{source}` cites {name} {part:?}, which docs/references.md#{anchor} does not list",
                        path.display()
                    );
                }
            }
        }
        // A year names a document: one of the listed names must stand before it.
        let bytes = source.as_bytes();
        for i in 0..bytes.len().saturating_sub(3) {
            let Some(year) = source.get(i..i + 4) else {
                continue;
            };
            let is_year = year.chars().all(|c| c.is_ascii_digit())
                && (year.starts_with("19") || year.starts_with("20"))
                && (i == 0 || !(bytes[i - 1].is_ascii_digit() || bytes[i - 1] == b'.'))
                && bytes
                    .get(i + 4)
                    .is_none_or(|b| !(b.is_ascii_digit() || *b == b'.' || *b == b'-'));
            if !is_year {
                continue;
            }
            let before = &source[source.floor_char_boundary(i.saturating_sub(60))..i];
            assert!(
                DOCUMENTS.iter().any(|(name, _)| before.contains(name)),
                "{}: `{source}` cites a document of {year} that docs/references.md does not list",
                path.display()
            );
        }
    }
}

#[test]
fn every_file_or_module_a_source_names_exists() {
    let root = Path::new(ROOT);
    for (path, source) in sources() {
        for word in source.split(|c: char| c.is_whitespace() || "(),;`'\"".contains(c)) {
            let word = word.trim_end_matches(['.', ':']);
            if let Some(module) = word.strip_prefix("courant_solver::") {
                let base = root.join("solver/src").join(module.replace("::", "/"));
                assert!(
                    base.with_extension("rs").is_file() || base.join("mod.rs").is_file(),
                    "{}: `{source}` names {word}, which is not a module of the solver",
                    path.display()
                );
            } else if word.contains('/')
                && [".rs", ".md", ".toml", ".csv"]
                    .iter()
                    .any(|e| word.ends_with(e))
            {
                assert!(
                    root.join(word).is_file(),
                    "{}: `{source}` names {word}, which is not a file of the repository",
                    path.display()
                );
            }
        }
    }
}
