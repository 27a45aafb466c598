//! The report's sources: the methods page and the reference list travel with the report
//! (`methods.md`, `references.md` beside `index.md`, copied from `docs/`), and every
//! `methods.md §N` in the report's text links to section N of its copy (`methods.md#sN`), so a
//! citation resolves wherever the report is written.
//!
//! ```text
//!   "d'Alembert (methods.md §3 and §5)"  ->  "d'Alembert ([methods.md §3](methods.md#s3) and [§5](methods.md#s5))"
//! ```

/// The methods page, as the report carries it.
pub const METHODS_FILE: &str = "methods.md";
/// The reference list, as the report carries it.
pub const REFERENCES_FILE: &str = "references.md";
/// `docs/methods.md`.
pub const METHODS: &str = include_str!("../../docs/methods.md");
/// `docs/references.md`.
pub const REFERENCES: &str = include_str!("../../docs/references.md");

/// `text` cut into plain pieces and linked ones `(text, Some(href))`: each `methods.md §N`
/// and each `§M` chained after it by `, ` or ` and ` links to `methods.md#sN`.
pub fn pieces(text: &str) -> Vec<(&str, Option<String>)> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some(at) = rest.find("methods.md") {
        let after = &rest[at + "methods.md".len()..];
        let Some(first) = section_after(after, " ") else {
            out.push((&rest[..at + "methods.md".len()], None));
            rest = after;
            continue;
        };
        if at > 0 {
            out.push((&rest[..at], None));
        }
        let cited = at + "methods.md".len() + first.len;
        out.push((&rest[at..cited], Some(first.href())));
        rest = &rest[cited..];
        // Further sections chained to the first: "§3 and §5", "§1, §7".
        loop {
            let chained = [", ", " and "]
                .iter()
                .find_map(|sep| section_after(rest, sep).map(|s| (sep.len(), s)));
            let Some((sep, section)) = chained else { break };
            out.push((&rest[..sep], None));
            out.push((&rest[sep..section.len], Some(section.href())));
            rest = &rest[section.len..];
        }
    }
    if !rest.is_empty() {
        out.push((rest, None));
    }
    out
}

/// A section number found after a separator: `len` bytes from the separator's start.
struct Section {
    number: u32,
    len: usize,
}

impl Section {
    fn href(&self) -> String {
        format!("{METHODS_FILE}#s{}", self.number)
    }
}

/// `sep` then `§` then digits at the start of `text`.
fn section_after(text: &str, sep: &str) -> Option<Section> {
    let body = text.strip_prefix(sep)?.strip_prefix('§')?;
    let digits = body.bytes().take_while(u8::is_ascii_digit).count();
    let number = body[..digits].parse().ok()?;
    Some(Section {
        number,
        len: sep.len() + '§'.len_utf8() + digits,
    })
}

/// `text` with its citations as Markdown links.
pub fn markdown(text: &str) -> String {
    pieces(text)
        .into_iter()
        .map(|(t, href)| match href {
            Some(h) => format!("[{t}]({h})"),
            None => t.to_string(),
        })
        .collect()
}

/// Already HTML-escaped `text` with its citations as links (a citation holds no character
/// that escaping changes).
pub fn html(escaped: &str) -> String {
    pieces(escaped)
        .into_iter()
        .map(|(t, href)| match href {
            Some(h) => format!("<a href=\"{h}\">{t}</a>"),
            None => t.to_string(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Source of truth: the citation form of the scene files (`methods.md §N`, chained by
    /// `, ` or ` and `) and the anchors `<a id="sN">` of docs/methods.md. Proves: every form
    /// links to its section and keeps its text, other text is untouched, and every section the
    /// page numbers has its anchor.
    #[test]
    fn citations_link_to_their_sections() {
        assert_eq!(
            markdown("d'Alembert (methods.md §3 and §5); x"),
            "d'Alembert ([methods.md §3](methods.md#s3) and [§5](methods.md#s5)); x"
        );
        assert_eq!(
            markdown("(methods.md §1, §7)"),
            "([methods.md §1](methods.md#s1), [§7](methods.md#s7))"
        );
        assert_eq!(markdown("methods.md warns; §2"), "methods.md warns; §2");
        assert_eq!(
            html("a methods.md §12, b"),
            "a <a href=\"methods.md#s12\">methods.md §12</a>, b"
        );
        for n in 1..=7 {
            assert!(METHODS.contains(&format!("<a id=\"s{n}\"></a>\n## §{n}.")));
        }
    }
}
