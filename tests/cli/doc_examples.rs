//! Source of truth: the README and the guide (`docs/guide/*.md`): every command they show is run
//! here against the built binary, so a documented example cannot rot.
//!
//! Proves: each ```` ```console ```` block's `$ courant ...` lines exit with the status the block
//! states (`? N` after the command; 0 when none) and print each expected line (every line after
//! the command, whitespace collapsed, found in order as part of an output line; `...` skips).
//! A fenced block with `file=PATH` in its info string (```` ```toml file=my_bar.toml ````) is
//! written to PATH before the document's first command, so the examples run on the files the
//! text shows. Each document runs in
//! a fresh directory holding links to `scenes/`, `benches/` and `external/`. Commands in other
//! blocks (```` ```sh ````) are allowed only when they take minutes or a machine's timing
//! ([`NOT_RUN`], each with its reason); and the README's first block is the two commands that do
//! everything, both of which `.ci/run` runs.

use std::path::{Path, PathBuf};
use std::process::Command;

/// Commands of `sh` blocks that the tests do not run, with why: each is minutes of work, a
/// timing of the machine, or this test suite itself. Matched as a prefix of the command line.
const NOT_RUN: &[(&str, &str)] = &[
    (
        "cargo run --release -- report",
        ".ci/run runs it (about 15 s, every scene)",
    ),
    ("cargo test", "the test suite itself"),
    ("cargo bench", "minutes of timing"),
    ("cargo install", "installs"),
    ("cargo insta", "interactive"),
    ("COURANT_FUZZ_CASES=", "a ten-minute soak"),
    ("bash benches/c_reference/run.sh", "a timing of the machine"),
    (
        "courant bench",
        "a timing of the machine (tests/cli/bench_command.rs runs a small one)",
    ),
    ("CC=", "a timing of the machine"),
    ("/usr/bin/time", "a 10^7-element run (about 1 GB)"),
    (
        "courant run benches/",
        "a --large run of 10^6 elements or more",
    ),
    (
        "courant check --baseline reports",
        ".ci/run runs it (every scene)",
    ),
    (
        "courant run --out baseline/",
        "every scene, on a reference commit",
    ),
    (
        "courant check --baseline baseline/",
        "every scene, against that commit",
    ),
    ("courant check [", "a synopsis, not a command"),
    ("courant reference <scene>", "a synopsis, not a command"),
    ("courant score <scene>", "a synopsis, not a command"),
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The documents whose examples run: the README and every chapter of the guide.
fn documents() -> Vec<PathBuf> {
    let mut docs = vec![root().join("README.md")];
    let mut guide: Vec<PathBuf> = std::fs::read_dir(root().join("docs/guide"))
        .expect("docs/guide exists")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    guide.sort();
    docs.extend(guide);
    docs
}

/// A fenced block: its info string, first line number and lines.
struct Block {
    info: String,
    line: usize,
    lines: Vec<String>,
}

fn blocks(text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut current: Option<(String, usize, Vec<String>, usize)> = None;
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        let indent = line.len() - trimmed.len();
        match &mut current {
            None if trimmed.starts_with("```") => {
                current = Some((trimmed[3..].trim().to_string(), i + 1, Vec::new(), indent));
            }
            Some((info, at, lines, _)) if trimmed.starts_with("```") => {
                out.push(Block {
                    info: std::mem::take(info),
                    line: *at,
                    lines: std::mem::take(lines),
                });
                current = None;
            }
            Some((_, _, lines, indent)) => {
                lines.push(line.get(*indent..).unwrap_or(line.trim_start()).to_string());
            }
            None => {}
        }
    }
    out
}

/// Words of a command line, with single and double quotes.
fn words(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut word = String::new();
    let mut quote: Option<char> = None;
    let mut any = false;
    for c in line.chars() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), c) => word.push(c),
            (None, '\'' | '"') => {
                quote = Some(c);
                any = true;
            }
            (None, c) if c.is_whitespace() => {
                if any || !word.is_empty() {
                    out.push(std::mem::take(&mut word));
                }
                any = false;
            }
            (None, c) => word.push(c),
        }
    }
    if any || !word.is_empty() {
        out.push(word);
    }
    out
}

fn collapse(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// One `$ command` with its expected status and lines.
struct Example {
    command: String,
    status: i32,
    expected: Vec<String>,
}

fn examples(block: &Block) -> Vec<Example> {
    let mut out: Vec<Example> = Vec::new();
    for line in &block.lines {
        if let Some(command) = line.strip_prefix("$ ") {
            out.push(Example {
                command: command.to_string(),
                status: 0,
                expected: Vec::new(),
            });
        } else if let Some(last) = out.last_mut() {
            if let Some(status) = line.strip_prefix("? ") {
                last.status = status.trim().parse().expect("`? N` is a number");
            } else if !line.trim().is_empty() {
                last.expected.push(line.clone());
            }
        } else {
            panic!("line {:?} of a console block before any `$ `", line);
        }
    }
    out
}

fn run(dir: &Path, example: &Example, at: &str) {
    let mut words = words(&example.command);
    let mut env = Vec::new();
    while words
        .first()
        .is_some_and(|w| w.contains('=') && !w.starts_with('-'))
    {
        let w = words.remove(0);
        let (k, v) = w.split_once('=').unwrap();
        env.push((k.to_string(), v.to_string()));
    }
    assert_eq!(
        words.first().map(String::as_str),
        Some("courant"),
        "{at}: a console example runs `courant`: {}",
        example.command
    );
    let output = Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(&words[1..])
        .envs(env)
        .current_dir(dir)
        .output()
        .unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert_eq!(
        output.status.code(),
        Some(example.status),
        "{at}: `{}` exit status\n{text}",
        example.command
    );
    let lines: Vec<String> = text.lines().map(collapse).collect();
    let mut from = 0;
    for want in &example.expected {
        if want.trim() == "..." {
            continue;
        }
        let want = collapse(want);
        match lines[from..].iter().position(|l| l.contains(&want)) {
            Some(i) => from += i + 1,
            None => panic!(
                "{at}: `{}` does not print {want:?} (in order)\n{text}",
                example.command
            ),
        }
    }
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("doc-examples-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for linked in ["scenes", "benches", "external"] {
        #[cfg(unix)]
        std::os::unix::fs::symlink(root().join(linked), dir.join(linked)).unwrap();
    }
    dir
}

#[test]
fn every_console_example_of_the_readme_and_the_guide_runs_as_shown() {
    let mut ran = 0;
    for doc in documents() {
        let name = doc.strip_prefix(root()).unwrap().display().to_string();
        let dir = scratch(&name.replace('/', "_"));
        let text = std::fs::read_to_string(&doc).unwrap();
        let blocks = blocks(&text);
        // Every file a document shows is there before its first command (a text may show a
        // command first and the file it reads below it).
        for block in &blocks {
            if let Some(path) = block
                .info
                .split_whitespace()
                .find_map(|w| w.strip_prefix("file="))
            {
                let file = dir.join(path);
                std::fs::create_dir_all(file.parent().unwrap()).unwrap();
                std::fs::write(&file, block.lines.join("\n") + "\n").unwrap();
            }
        }
        for block in &blocks {
            let at = format!("{name}:{}", block.line);
            if block.info.contains("file=") {
                continue;
            } else if block.info == "console" {
                for example in examples(block) {
                    run(&dir, &example, &at);
                    ran += 1;
                }
            } else {
                for line in &block.lines {
                    let command = line.trim();
                    let runs_courant = command.starts_with("courant ")
                        || command.starts_with("cargo ")
                        || command.contains(" courant ");
                    if block.info == "sh" && runs_courant {
                        assert!(
                            NOT_RUN
                                .iter()
                                .any(|(prefix, _)| command.starts_with(prefix)),
                            "{at}: `{command}` is in a `sh` block: put it in a `console` block \
                             (run by this test) or, if it takes minutes, in NOT_RUN with why"
                        );
                    }
                }
            }
        }
    }
    assert!(ran >= 10, "only {ran} examples ran");
}

#[test]
fn the_readme_opens_with_the_two_commands_that_ci_runs() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let first = &blocks(&readme)[0];
    let commands: Vec<String> = first
        .lines
        .iter()
        .map(|l| l.split('#').next().unwrap().trim().to_string())
        .collect();
    assert_eq!(
        commands,
        ["cargo run --release -- report", "cargo test --workspace"]
    );
    let ci = std::fs::read_to_string(root().join(".ci/run")).unwrap();
    assert!(
        ci.contains("\ncargo test --workspace\n"),
        ".ci/run runs the tests"
    );
    assert!(
        ci.contains("\ncargo run --release -- report "),
        ".ci/run regenerates the report"
    );
    assert!(
        readme.lines().count() <= 250,
        "the README stays within 250 lines"
    );
}

#[test]
fn the_tree_links_resolve_from_the_readme_and_the_guide() {
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).unwrap();
        let base = doc.parent().unwrap();
        for (i, _) in text.match_indices("](") {
            let rest = &text[i + 2..];
            let target = &rest[..rest.find(')').unwrap()];
            if target.starts_with("http") || target.starts_with('#') {
                continue;
            }
            let path = target.split('#').next().unwrap();
            // docs/methods.md and docs/references.md are written alongside; their absence
            // here is not a broken example.
            if path.ends_with("methods.md") || path.ends_with("references.md") {
                continue;
            }
            assert!(
                base.join(path).exists(),
                "{}: link {target} does not resolve",
                doc.display()
            );
        }
    }
}
