//! Figures that stay legible: a scene's cases split into figures of at most [`MAX_CASES`]
//! (grouped by scheme and mass kind), numbered titles and file names of the parts, captions that
//! name every case not drawn and why.

use super::plot::{Axes, PlotError, Series, line_chart};

/// At most this many cases per figure: with the exact solution they keep distinct colours of
/// the 8-colour palette and a legend that fits the chart. A scene with more cases gets several
/// figures (see [`split`]); no case is left out without the caption saying so.
pub const MAX_CASES: usize = 6;

/// Split `items` (each with a group key: scheme, mass kind, …) into figures of at most `max`:
/// items of one key stay together (a group larger than `max` is cut into near-equal parts),
/// groups keep the order of their first item, consecutive groups share a figure, and the figures
/// are as few as possible and as even as the groups allow. Every item lands in exactly one
/// figure.
pub fn split<T>(items: Vec<(String, T)>, max: usize) -> Vec<Vec<T>> {
    let max = max.max(1);
    let mut groups: Vec<(String, Vec<T>)> = Vec::new();
    for (key, item) in items {
        match groups.iter_mut().find(|g| g.0 == key) {
            Some(g) => g.1.push(item),
            None => groups.push((key, vec![item])),
        }
    }
    // Cut oversized groups into ceil(n/max) near-equal chunks.
    let mut chunks: Vec<Vec<T>> = Vec::new();
    for (_, group) in groups {
        let n = group.len();
        let pieces = n.div_ceil(max);
        let mut rest = group.into_iter();
        for p in 0..pieces {
            let size = n / pieces + usize::from(p < n % pieces);
            chunks.push(rest.by_ref().take(size).collect());
        }
    }
    let total: usize = chunks.iter().map(Vec::len).sum();
    if total == 0 {
        return Vec::new();
    }
    let largest = chunks.iter().map(Vec::len).max().unwrap_or(0);
    let sizes: Vec<usize> = chunks.iter().map(Vec::len).collect();
    // The fewest figures k for which greedy packing with capacity max(largest, ceil(total/k))
    // needs at most k figures (k = number of chunks always works).
    let capacity = (total.div_ceil(max)..=chunks.len())
        .map(|k| (k, largest.max(total.div_ceil(k))))
        .find(|&(k, cap)| pack(&sizes, cap).len() <= k)
        .map_or(max, |(_, cap)| cap);
    let mut figures: Vec<Vec<T>> = Vec::new();
    let mut chunks = chunks.into_iter();
    for count in pack(&sizes, capacity) {
        figures.push(chunks.by_ref().take(count).flatten().collect());
    }
    figures
}

/// Greedy packing of consecutive chunk sizes into bins of `capacity`: the number of chunks in
/// each bin.
fn pack(sizes: &[usize], capacity: usize) -> Vec<usize> {
    let mut bins: Vec<(usize, usize)> = Vec::new(); // (chunks, items)
    for &size in sizes {
        match bins.last_mut() {
            Some(bin) if bin.1 + size <= capacity => {
                bin.0 += 1;
                bin.1 += size;
            }
            _ => bins.push((1, size)),
        }
    }
    bins.into_iter().map(|b| b.0).collect()
}

/// `stem.svg`, or `stem_<j+1>.svg` when the figure is one of several.
pub fn part_file(stem: &str, j: usize, parts: usize) -> String {
    if parts > 1 {
        format!("{stem}_{}.svg", j + 1)
    } else {
        format!("{stem}.svg")
    }
}

/// `title (j/n)` when a figure is one of several.
pub fn numbered(title: &str, j: usize, parts: usize) -> String {
    if parts > 1 {
        format!("{title} ({}/{parts})", j + 1)
    } else {
        title.to_string()
    }
}

/// The caption of a figure: its title, the cases it shows when the cases drawn are spread over
/// several figures (`shown` drawn of the scene's `total`), and the notes (cases not shown and
/// why).
pub fn caption<'a, T>(
    title: &str,
    cases: impl Iterator<Item = &'a str>,
    parts: &[Vec<T>],
    total: usize,
    notes: &[String],
) -> String {
    let mut caption = title.to_string();
    if parts.len() > 1 {
        let shown: usize = parts.iter().map(Vec::len).sum();
        let of = if shown < total {
            format!("{shown} of {total}")
        } else {
            format!("all {total}")
        };
        caption += &format!(
            "; {of} cases drawn in {} figures, this one: {}",
            parts.len(),
            names(cases)
        );
    }
    for note in notes {
        caption += "; ";
        caption += note;
    }
    caption
}

/// Comma-separated names.
pub fn names<'a>(names: impl Iterator<Item = &'a str>) -> String {
    names.collect::<Vec<_>>().join(", ")
}

/// Draw `cases` and then `extra` (references): a case series with no drawable point is left
/// out and named in `notes` rather than losing the whole figure; `None` when nothing can be
/// drawn.
pub fn chart_naming_omissions(
    axes: &Axes,
    mut cases: Vec<Series>,
    extra: Vec<Series>,
    notes: &mut Vec<String>,
) -> Option<String> {
    loop {
        let all: Vec<Series> = cases.iter().chain(&extra).cloned().collect();
        match line_chart(axes, &all) {
            Ok(svg) => return Some(svg),
            Err(PlotError::NoPlottableData { series, .. }) => {
                let i = cases.iter().position(|c| c.name == series)?;
                cases.remove(i);
                notes.push(format!("not shown, no drawable point: {series}"));
            }
            Err(_) => return None,
        }
    }
}
