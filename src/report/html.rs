//! The document as self-contained HTML (`index.html`): figures inline, no network, no scripts.
//! A table leads with its verdict or status ([`super::layout`]), which stays in place while a
//! wide table scrolls inside its box; a long table keeps the rows that need a look in view and
//! folds the passing ones (`<details>`); text columns are left-aligned and numbers
//! right-aligned, verdict cells are coloured and a run that did not complete is marked, every
//! section ends with a link back to the top, and the page reads in light and dark mode.

use super::citations;
use super::document::{Block, Inline, anchor};
use super::layout::{column_order, has_status, is_status, needs_a_look, reordered};
use super::numbers::shown;
use crate::results::table::{Cell, Table};

/// Tables with more rows than this fold behind a `<details>` summary.
pub const FOLD_ROWS: usize = 30;

const STYLE: &str = "\
body { font-family: sans-serif; max-width: 80rem; margin: 2rem auto; padding: 0 1rem; line-height: 1.45; }
.table-wrap { overflow-x: auto; max-width: 100%; margin: 0.5rem 0 1rem; }
table { border-collapse: collapse; font-size: 0.85rem; }
td, th { border: 1px solid #bbb; padding: 0.2rem 0.4rem; white-space: nowrap; }
th { background: #eee; position: sticky; top: 0; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
td.text { text-align: left; }
td.long { text-align: left; white-space: normal; min-width: 16rem; }
table.status-first td:first-child, table.status-first th:first-child { position: sticky; left: 0; z-index: 1; }
table.status-first th:first-child { z-index: 2; }
table.status-first td.text:first-child { background: #fff; }
table.summary td.pass, table.summary td.finding, table.summary td.fail { text-align: right; }
td.pass, td.yes { background: #dff3e3; }
td.fail, td.no { background: #f8d7da; font-weight: bold; }
td.finding, td.halted { background: #fff0c2; }
figure { margin: 1rem 0; }
figure svg { max-width: 100%; height: auto; background: #fff; border-radius: 4px; }
details > summary { cursor: pointer; color: #0550ae; }
a.top { font-size: 0.8rem; float: right; }
@media (prefers-color-scheme: dark) {
  body { background: #16181b; color: #ddd; }
  a { color: #8ab4f8; }
  th { background: #2a2d31; }
  td, th { border-color: #555; }
  td.pass, td.yes { background: #1f3d27; }
  td.fail, td.no { background: #5a1d22; }
  td.finding, td.halted { background: #4d4014; }
  table.status-first td.text:first-child { background: #16181b; }
  details > summary { color: #8ab4f8; }
}
";

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Inline `code` spans of already-escaped text.
fn code_spans(text: &str) -> String {
    let escaped = escape(text);
    let mut out = String::new();
    for (i, part) in escaped.split('`').enumerate() {
        if i % 2 == 1 {
            out += &format!("<code>{part}</code>");
        } else {
            out += &citations::html(part);
        }
    }
    out
}

/// A piece of inline text as HTML.
fn inline(i: &Inline) -> String {
    match &i.href {
        Some(href) => format!("<a href=\"{}\">{}</a>", escape(href), escape(&i.text)),
        None => escape(&i.text),
    }
}

/// The class of a data cell: a verdict colour where the column holds verdicts, a run that did
/// not complete marked in its status column, else `num` for numbers and `text` for text.
fn cell_class(column: &str, cell: &Cell, shown: &str) -> &'static str {
    if matches!(column, "verdict" | "agrees") {
        return match shown {
            "pass" => "pass",
            "FAIL" => "fail",
            "finding" => "finding",
            "yes" => "yes",
            "no" => "no",
            _ => "text",
        };
    }
    if column == "status" {
        return if shown == "completed" {
            "text"
        } else {
            "halted"
        };
    }
    match cell {
        Cell::Num(_) | Cell::Int(_) | Cell::Empty => "num",
        Cell::Text(t) if t.chars().count() > 40 => "long",
        Cell::Text(_) => "text",
    }
}

/// Rows of a table as HTML, columns in `order`.
fn rows_html(table: &Table, rows: &[(usize, Vec<String>)], order: &[usize]) -> String {
    let mut out = String::new();
    for (r, texts) in rows {
        out += "<tr>";
        for &c in order {
            let column = &table.columns[c];
            out += &format!(
                "<td class=\"{}\">{}</td>",
                cell_class(column, &table.rows[*r][c], &texts[c]),
                citations::html(&escape(&texts[c]))
            );
        }
        out += "</tr>\n";
    }
    out
}

/// One data table: verdict or status first; a long table keeps the rows that need a look (a
/// status that is not a passing word) in view and folds the others behind a `<details>`.
fn table_html(table: &Table, csv: Option<&str>, id: Option<&str>) -> String {
    let id = id
        .map(|id| format!(" id=\"{}\"", escape(id)))
        .unwrap_or_default();
    let link = csv
        .map(|csv| format!("<a href=\"{0}\"><code>{0}</code></a>", escape(csv)))
        .unwrap_or_default();
    let order = column_order(&table.columns);
    let status_first = order.first().is_some_and(|&c| is_status(&table.columns[c]));
    let class = if status_first {
        " class=\"status-first\""
    } else {
        ""
    };
    let head = format!(
        "<div class=\"table-wrap\">\n<table{class}>\n<tr>{}</tr>\n",
        reordered(&table.columns, &order)
            .iter()
            .map(|c| format!("<th>{}</th>", escape(c)))
            .collect::<String>()
    );
    let rows: Vec<(usize, Vec<String>)> = shown(table).into_iter().enumerate().collect();
    let mut out = format!("<p{id}>{link}</p>\n");
    if rows.len() <= FOLD_ROWS {
        return out + &head + &rows_html(table, &rows, &order) + "</table>\n</div>\n";
    }
    let (look, rest): (Vec<_>, Vec<_>) = if has_status(table) {
        rows.into_iter()
            .partition(|(_, texts)| needs_a_look(&table.columns, texts))
    } else {
        (Vec::new(), rows)
    };
    if !look.is_empty() {
        out += &format!(
            "<p>{} of {} rows need a look (a verdict or status other than pass, yes, completed):</p>\n",
            look.len(),
            look.len() + rest.len()
        );
        out += &head;
        out += &rows_html(table, &look, &order);
        out += "</table>\n</div>\n";
    }
    let what = if has_status(table) && !look.is_empty() {
        format!("{} more rows, each passing: show them", rest.len())
    } else if has_status(table) {
        format!("{} rows, each passing: show the table", rest.len())
    } else {
        format!("{} rows: show the table", rest.len())
    };
    out += &format!("<details>\n<summary>{what}</summary>\n");
    out += &head;
    out += &rows_html(table, &rest, &order);
    out + "</table>\n</div>\n</details>\n"
}

/// Self-contained HTML rendering (figures inline).
pub fn html(title: &str, blocks: &[Block]) -> String {
    let mut out = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n\
         <meta name=\"color-scheme\" content=\"light dark\"/>\n<title>{}</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n",
        escape(title)
    );
    let mut sections = 0;
    for b in blocks {
        match b {
            Block::Heading(level, text) => {
                let level = (*level).clamp(1, 6);
                if level == 2 {
                    if sections > 0 {
                        out += "<p><a class=\"top\" href=\"#top\">back to top</a></p>\n";
                    }
                    sections += 1;
                }
                let id = if level == 1 {
                    "top".to_string()
                } else {
                    anchor(text)
                };
                out += &format!("<h{level} id=\"{id}\">{}</h{level}>\n", escape(text));
            }
            Block::Paragraph(text) => out += &format!("<p>{}</p>\n", code_spans(text)),
            Block::List(items) => {
                out += "<ul>\n";
                items
                    .iter()
                    .for_each(|i| out += &format!("<li>{}</li>\n", code_spans(i)));
                out += "</ul>\n";
            }
            Block::Links(links) => {
                out += "<ul>\n";
                links
                    .iter()
                    .for_each(|l| out += &format!("<li>{}</li>\n", inline(l)));
                out += "</ul>\n";
            }
            Block::Table { table, csv, id } => {
                out += &table_html(table, csv.as_deref(), id.as_deref());
            }
            Block::Summary { columns, rows } => {
                out += "<div class=\"table-wrap\">\n<table class=\"summary\">\n<tr>";
                columns
                    .iter()
                    .for_each(|c| out += &format!("<th>{}</th>", escape(c)));
                out += "</tr>\n";
                for row in rows {
                    out += "<tr>";
                    for (k, cell) in row.iter().enumerate() {
                        let class = cell.verdict.unwrap_or(if k == 0 { "text" } else { "num" });
                        out += &format!("<td class=\"{class}\">{}</td>", inline(cell));
                    }
                    out += "</tr>\n";
                }
                out += "</table>\n</div>\n";
            }
            Block::Figure { svg, caption, .. } => {
                let body = svg.trim_start_matches(|c: char| c != '<');
                let body = if body.starts_with("<?xml") {
                    &body[body.find("?>").map_or(0, |i| i + 2)..]
                } else {
                    body
                };
                out += &format!(
                    "<figure>\n{}\n<figcaption>{}</figcaption>\n</figure>\n",
                    body.trim(),
                    citations::html(&escape(caption))
                );
            }
        }
    }
    out += "<p><a class=\"top\" href=\"#top\">back to top</a></p>\n</body>\n</html>\n";
    out
}

#[cfg(test)]
mod tests {
    use super::super::markdown::markdown;
    use super::*;
    use crate::results::table::Table;

    /// Source of truth: the report contract (one content, two renderings). Proves: a heading,
    /// inline code, a table (numbers shown to 4 significant digits, text left, number right,
    /// verdicts coloured) and a link come out in both forms; long tables fold; sections link
    /// back to the top.
    #[test]
    fn both_renderings_carry_the_same_content() {
        let mut t = Table::new(&["a", "verdict"]);
        t.push(vec![Cell::Num(1.5), Cell::Text("FAIL".into())]);
        let mut long = Table::new(&["n"]);
        for i in 0..=FOLD_ROWS {
            long.push(vec![Cell::Int(i as u64)]);
        }
        let blocks = vec![
            Block::Heading(1, "Report".into()),
            Block::Heading(2, "Fig. 1 <x>".into()),
            Block::Paragraph("see `index.md` & more".into()),
            Block::Table {
                table: t,
                csv: Some("x.csv".into()),
                id: Some("fig1-expectations".into()),
            },
            Block::Links(vec![Inline::link("fig1", "#fig1")]),
            Block::Heading(2, "Long".into()),
            Block::Table {
                table: long,
                csv: None,
                id: None,
            },
        ];
        let md = markdown(&blocks);
        assert!(
            md.contains("## Fig. 1 <x>")
                && md.contains("| verdict | a |\n|---|---|\n| FAIL | 1.500 |"),
            "{md}"
        );
        assert!(md.contains("- [fig1](#fig1)"), "{md}");
        let h = html("t", &blocks);
        assert!(h.contains("<h1 id=\"top\">Report</h1>"));
        assert!(h.contains("<h2 id=\"fig-1-x\">Fig. 1 &lt;x&gt;</h2>"));
        assert!(h.contains("<code>index.md</code> &amp; more"));
        assert!(h.contains("<td class=\"fail\">FAIL</td><td class=\"num\">1.500</td>"));
        assert!(h.contains("<table class=\"status-first\">\n<tr><th>verdict</th><th>a</th>"));
        assert!(h.contains("<p id=\"fig1-expectations\">"));
        assert!(h.contains("<li><a href=\"#fig1\">fig1</a></li>"));
        assert!(h.contains("<details>\n<summary>31 rows: show the table</summary>"));
        assert_eq!(h.matches("href=\"#top\"").count(), 2);
    }

    /// Source of truth: the report contract "a verdict is never hidden": a long table keeps the
    /// rows whose verdict or status is not a passing word in view and folds only the passing
    /// ones; a run that did not complete is marked in its status column.
    #[test]
    fn long_tables_fold_only_passing_rows() {
        let mut t = Table::new(&["case", "l1", "status", "verdict"]);
        for i in 0..=FOLD_ROWS {
            t.push(vec![
                Cell::Text(format!("c{i}")),
                Cell::Num(0.5),
                Cell::Text("completed".into()),
                Cell::Text("pass".into()),
            ]);
        }
        t.push(vec![
            Cell::Text("bad".into()),
            Cell::Num(0.0),
            Cell::Text("diverged at step 1".into()),
            Cell::Text("finding".into()),
        ]);
        let h = html(
            "t",
            &[Block::Table {
                table: t,
                csv: None,
                id: None,
            }],
        );
        let (shown, folded) = h.split_once("<details>").unwrap();
        assert!(shown.contains("1 of 32 rows need a look"), "{shown}");
        assert!(shown.contains(
            "<td class=\"finding\">finding</td><td class=\"halted\">diverged at step 1</td><td class=\"text\">bad</td>"
        ));
        assert!(!shown.contains(">c0<"));
        assert!(
            folded.contains("31 more rows, each passing: show them") && folded.contains(">c0<")
        );
        assert!(!folded.contains(">bad<"));
    }
}
