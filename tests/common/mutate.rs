//! Mutations of scene files for the fuzz harness (`tests/pipeline/fuzz_scenes.rs`): what a hurried user
//! or a corrupted file does to a scene, as edits of its TOML text that mostly keep it parseable
//! (so that the mutants reach validation and the runs, not only the TOML parser).
//!
//! A mutation holds raw indices; it picks its target (the k-th number, string, list or line) and
//! its replacement modulo what the text and the pools hold, so every generated value is valid and
//! shrinking (to smaller indices, fewer mutations) stays meaningful.
#![allow(dead_code)]

use proptest::prelude::*;

/// Number literals put in place of a number: zeros, signs, the magnitude bounds and beyond,
/// subnormals, overflow, non-finite values, huge integers, values near 1.
pub const NUMBERS: &[&str] = &[
    "0",
    "-0.0",
    "1",
    "-1",
    "2",
    "3",
    "0.5",
    "0.999999",
    "1.000001",
    "16",
    "100",
    "1e4",
    "1e-9",
    "1e-50",
    "1e50",
    "1e-51",
    "1e51",
    "1e12",
    "1e-300",
    "5e-324",
    "1e300",
    "1.7976931348623157e308",
    "nan",
    "inf",
    "-inf",
    "1000000",
    "1000001",
    "10000000",
    "9223372036854775807",
    "-9223372036854775808",
];

/// Powers of ten a number is scaled by.
pub const SCALES: &[i32] = &[
    -300, -100, -50, -20, -10, -5, -3, -2, -1, 1, 2, 3, 5, 10, 20, 50, 100, 300,
];

/// Strings put in place of a string value: every keyword of the scene format, and nonsense.
pub const WORDS: &[&str] = &[
    "",
    "x",
    "cd",
    "central-difference",
    "park-lts",
    "park-global",
    "lmm",
    "cmm",
    "amm",
    "rmm",
    "amm(0.25)",
    "rmm(3)",
    "amm(-1)",
    "amm(4th)",
    "rmm(4th)",
    "free",
    "fixed",
    "left",
    "right",
    "traction",
    "force",
    "step",
    "ramp",
    "pulse",
    "table",
    "transit",
    "absolute",
    "critical",
    "exact",
    "stiffest-element",
    "dalembert",
    "graded",
    "layered",
    "none",
    "equal-transit",
    "uniform",
    "incremental",
    "free-free",
    "fixed-free",
    "fixed-fixed",
    "wall",
    "two-bars",
    "cd-penalty",
    "cd-bipenalty",
    "predictor-corrector",
    "lagrange-multiplier",
    "three-level",
    "half-step",
    "l1",
    "linf",
    "overshoot",
    "tv_ratio",
    "energy_balance",
    "diverged",
    "duration_error",
    "energy_ratio",
    "../escape",
    "a/b",
];

/// Lines inserted after a random line: keys of every table, some valid where they land.
pub const LINES: &[&str] = &[
    "history_every = 1",
    "energy_every = 1",
    "end_time = 1000.0",
    "end_time = 1e-9",
    "keep_step = true",
    "allow_unstable = true",
    "courant_unit = \"exact\"",
    "courant_unit = \"critical\"",
    "grading = 1.5",
    "grading = 0.5",
    "spacing = \"equal-transit\"",
    "history_points = [0.0, 0.5, 1.0]",
    "history_points = [2.0]",
    "time_unit = \"transit\"",
    "profile_times = [0.0]",
    "profile_times = []",
    "profile_times = [0.1, 0.2, 0.3, 0.7, 1.3, 2.9]",
    "density = { linear = [1.0, 1e-3] }",
    "modulus = { linear = [1e4, 1.0] }",
    "start = \"three-level\"",
    "theta = 0.0",
    "gap = 0.1",
    "ratio = 0.25",
    "beta_m = 0.0",
    "beta_s = [1e-3, 1e9]",
    "penalty_only = false",
    "blowup_energy_ratio = 1.0",
    "courant = [0.1, 1.0, 1.5]",
    "dt = 1e-3",
    "elements = [1, 2, 3]",
    "mass = [\"lmm\", \"cmm\", \"amm\", \"rmm\"]",
    "scheme = [\"cd\", \"park-lts\", \"park-global\"]",
    "at = 0.5",
    "min = 1e300",
    "max = -1.0",
    "[[expect]]\nmetric = \"l1\"\nmax = 1.0\nsource = \"fuzz\"",
    "[[expect]]\nmetric = \"tv_ratio\"\nmin = 0.0\nsource = \"fuzz\"",
    "[[expect]]\nmetric = \"duration_error\"\nmax = 1.0\nsource = \"fuzz\"",
    "[reference]\nkind = \"graded\"",
    "[reference]\nkind = \"layered\"",
    "[[load]]\nkind = \"force\"\nnode = 3\nvalue = 1.0\ntime = \"pulse\"\nduration = 0.1",
    "[initial]\nvelocity = { linear = [1.0, 0.0] }",
    "layers = [{ thickness = 0.5, modulus = 1.0 }, { thickness = 0.5, modulus = 1e4 }]",
];

/// One edit of a scene's text.
#[derive(Debug, Clone)]
pub enum Mutation {
    /// The `at`-th number literal becomes `NUMBERS[value]`.
    Number { at: usize, value: usize },
    /// The `at`-th number literal is multiplied by `10^SCALES[power]`.
    Scale { at: usize, power: usize },
    /// The `at`-th string value becomes `WORDS[word]`.
    Word { at: usize, word: usize },
    /// The `at`-th list value becomes empty.
    EmptyList { at: usize },
    /// The `at`-th line is deleted.
    DeleteLine { at: usize },
    /// The `at`-th line is written twice.
    DuplicateLine { at: usize },
    /// `LINES[line]` is inserted after the `at`-th line.
    InsertLine { at: usize, line: usize },
    /// The text ends after `at` of every 1000 of its characters.
    Truncate { at: usize },
}

/// A mutation with indices in useful ranges (the edit reduces them modulo what exists).
pub fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (0..64usize, 0..NUMBERS.len()).prop_map(|(at, value)| Mutation::Number { at, value }),
        3 => (0..64usize, 0..SCALES.len()).prop_map(|(at, power)| Mutation::Scale { at, power }),
        2 => (0..32usize, 0..WORDS.len()).prop_map(|(at, word)| Mutation::Word { at, word }),
        1 => (0..16usize).prop_map(|at| Mutation::EmptyList { at }),
        2 => (0..128usize).prop_map(|at| Mutation::DeleteLine { at }),
        1 => (0..128usize).prop_map(|at| Mutation::DuplicateLine { at }),
        2 => (0..128usize, 0..LINES.len()).prop_map(|(at, line)| Mutation::InsertLine { at, line }),
        1 => (0..1000usize).prop_map(|at| Mutation::Truncate { at }),
    ]
}

/// Byte spans of the number literals, string values and list values of a TOML text (outside
/// comments and table headers), found by a small lexer.
#[derive(Debug, Default)]
pub struct Spans {
    pub numbers: Vec<(usize, usize)>,
    pub strings: Vec<(usize, usize)>,
    pub lists: Vec<(usize, usize)>,
}

/// Lex `text` for [`Spans`].
pub fn spans(text: &str) -> Spans {
    let bytes = text.as_bytes();
    let mut spans = Spans::default();
    let mut open_lists: Vec<usize> = Vec::new();
    let (mut i, mut after_equals) = (0, false);
    while i < bytes.len() {
        let c = bytes[i];
        match c {
            b'#' => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            b'\n' => after_equals = false,
            b'=' => after_equals = true,
            b'"' => {
                let start = i;
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' && bytes[i] != b'\n' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                if after_equals {
                    spans.strings.push((start, (i + 1).min(bytes.len())));
                }
            }
            b'[' if after_equals => open_lists.push(i),
            b']' if after_equals => {
                if let Some(start) = open_lists.pop() {
                    spans.lists.push((start, i + 1));
                }
            }
            b'0'..=b'9' | b'+' | b'-' | b'i' | b'n' if after_equals => {
                let start = i;
                let word =
                    |b: u8| b.is_ascii_alphanumeric() || matches!(b, b'.' | b'+' | b'-' | b'_');
                while i < bytes.len() && word(bytes[i]) {
                    i += 1;
                }
                let token = &text[start..i];
                let numeric = token.trim_start_matches(['+', '-']);
                if numeric.starts_with(|c: char| c.is_ascii_digit())
                    || numeric == "inf"
                    || numeric == "nan"
                {
                    spans.numbers.push((start, i));
                }
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    spans
}

/// `literal` times `10^power`, as a TOML literal (integers stay integers while they fit).
fn scaled(literal: &str, power: i32) -> String {
    let clean = literal.replace('_', "");
    if let Ok(n) = clean.parse::<i64>()
        && let Some(m) = (power > 0 && power < 19)
            .then(|| n.checked_mul(10_i64.pow(power as u32)))
            .flatten()
    {
        return m.to_string();
    }
    match clean.parse::<f64>() {
        Ok(x) => {
            let y = x * 10f64.powi(power);
            if y.is_nan() {
                "nan".into()
            } else if y.is_infinite() {
                if y > 0.0 { "inf".into() } else { "-inf".into() }
            } else {
                format!("{y:e}")
            }
        }
        Err(_) => literal.to_string(),
    }
}

/// `text` with `mutation` applied (unchanged when there is nothing to mutate).
pub fn apply(text: &str, mutation: &Mutation) -> String {
    let replace = |(start, end): (usize, usize), with: &str| {
        format!("{}{with}{}", &text[..start], &text[end..])
    };
    let pick =
        |list: &[(usize, usize)], at: usize| (!list.is_empty()).then(|| list[at % list.len()]);
    let lines: Vec<&str> = text.lines().collect();
    let rejoin = |lines: Vec<&str>| {
        let mut joined = lines.join("\n");
        joined.push('\n');
        joined
    };
    let s = spans(text);
    match *mutation {
        Mutation::Number { at, value } => pick(&s.numbers, at)
            .map_or_else(|| text.to_string(), |span| replace(span, NUMBERS[value])),
        Mutation::Scale { at, power } => pick(&s.numbers, at).map_or_else(
            || text.to_string(),
            |span| replace(span, &scaled(&text[span.0..span.1], SCALES[power])),
        ),
        Mutation::Word { at, word } => pick(&s.strings, at).map_or_else(
            || text.to_string(),
            |span| replace(span, &format!("\"{}\"", WORDS[word])),
        ),
        Mutation::EmptyList { at } => {
            pick(&s.lists, at).map_or_else(|| text.to_string(), |span| replace(span, "[]"))
        }
        Mutation::DeleteLine { at } if !lines.is_empty() => {
            let mut lines = lines;
            lines.remove(at % lines.len());
            rejoin(lines)
        }
        Mutation::DuplicateLine { at } if !lines.is_empty() => {
            let mut lines = lines;
            let k = at % lines.len();
            lines.insert(k, lines[k]);
            rejoin(lines)
        }
        Mutation::InsertLine { at, line } => {
            let mut lines = lines;
            let k = if lines.is_empty() {
                0
            } else {
                at % (lines.len() + 1)
            };
            lines.insert(k, LINES[line]);
            rejoin(lines)
        }
        Mutation::Truncate { at } => {
            let mut cut = text.len() * at / 1000;
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
            text[..cut].to_string()
        }
        _ => text.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lexer_finds_values_not_comments_or_headers() {
        let text =
            "# 1.0 in a comment\n[mesh]\nelements = [10, 20] # 30\nname = \"a\"\nx = -1e-3\n";
        let s = spans(text);
        let numbers: Vec<&str> = s.numbers.iter().map(|&(a, b)| &text[a..b]).collect();
        assert_eq!(numbers, ["10", "20", "-1e-3"]);
        assert_eq!(s.strings.len(), 1);
        assert_eq!(&text[s.lists[0].0..s.lists[0].1], "[10, 20]");
    }
}
