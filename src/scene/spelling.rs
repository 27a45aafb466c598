//! "Did you mean": the nearest of a list of names to a misspelt one, for scene names and metrics.
//!
//! Enters: a word and the names it may have meant. Leaves: the nearest name within a small edit
//! distance. Must not know: what the names are for.

/// Edit distance with adjacent transpositions (the optimal string alignment distance of Damerau,
/// 1964: insertions, deletions, substitutions and swaps of two neighbours each cost 1), so that
/// `fgi1` is one edit from `fig1`.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut best = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                best = best.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = best;
        }
    }
    d[a.len()][b.len()]
}

/// The name nearest to `word` (compared in lower case), when it is at most 2 edits away and
/// fewer edits than half the word (so a short unrelated word gets no suggestion); the first of
/// equally near names.
pub fn closest<'a>(word: &str, names: &[&'a str]) -> Option<&'a str> {
    let word = word.to_lowercase();
    names
        .iter()
        .map(|n| (edit_distance(&word, n), *n))
        .filter(|&(d, _)| d <= 2 && 2 * d < word.chars().count())
        .min_by_key(|&(d, _)| d)
        .map(|(_, n)| n)
}

/// `did you mean NAME? ` for the [`closest`] name, or nothing.
pub fn hint(word: &str, names: &[&str]) -> String {
    closest(word, names)
        .map(|n| format!("did you mean {n}? "))
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Source of truth: Damerau's edit distance (transpositions count 1). Proves: swapped,
    /// dropped and doubled letters find their name; an unrelated word finds none.
    #[test]
    fn near_misses_find_their_name() {
        assert_eq!(edit_distance("fgi1", "fig1"), 1);
        assert_eq!(edit_distance("fig_1", "fig1"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        let names = ["fig1", "fig2", "l1", "linf", "overshoot"];
        assert_eq!(closest("fgi1", &names), Some("fig1"));
        assert_eq!(closest("ovreshoot", &names), Some("overshoot"));
        assert_eq!(closest("lnif", &names), Some("linf"));
        assert_eq!(closest("banana", &names), None);
    }
}
