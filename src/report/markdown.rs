//! The document as Markdown (`index.md`): headings, paragraphs, lists, pipe tables with numbers
//! shown as [`super::numbers`] does and columns in [`super::layout`]'s order, figures as image links to their SVG files.

use super::citations;
use super::document::{Block, Inline};
use super::layout::{column_order, reordered};
use super::numbers::shown;

/// A piece of inline text as Markdown: a link where it has one.
fn inline(i: &Inline) -> String {
    let text = i.text.replace('|', "\\|");
    match &i.href {
        Some(href) => format!("[{text}]({href})"),
        None => text,
    }
}

/// A pipe table.
fn pipe_table(columns: &[String], rows: &[Vec<String>]) -> String {
    let mut out = format!("| {} |\n", columns.join(" | "));
    out += &format!("|{}\n", "---|".repeat(columns.len()));
    for row in rows {
        let cells: Vec<String> = row
            .iter()
            .map(|c| citations::markdown(&c.replace('|', "\\|")))
            .collect();
        out += &format!("| {} |\n", cells.join(" | "));
    }
    out
}

/// Markdown rendering.
pub fn markdown(blocks: &[Block]) -> String {
    let mut out = String::new();
    for b in blocks {
        match b {
            Block::Heading(level, text) => out += &format!("{} {text}\n\n", "#".repeat(*level)),
            Block::Paragraph(text) => out += &format!("{}\n\n", citations::markdown(text)),
            Block::List(items) => {
                items
                    .iter()
                    .for_each(|i| out += &format!("- {}\n", citations::markdown(i)));
                out += "\n";
            }
            Block::Links(links) => {
                links
                    .iter()
                    .for_each(|l| out += &format!("- {}\n", inline(l)));
                out += "\n";
            }
            Block::Table { table, csv, .. } => {
                if let Some(csv) = csv {
                    out += &format!("[`{csv}`]({csv})\n\n");
                }
                let order = column_order(&table.columns);
                let rows: Vec<Vec<String>> = shown(table)
                    .iter()
                    .map(|row| reordered(row, &order))
                    .collect();
                out += &pipe_table(&reordered(&table.columns, &order), &rows);
                out += "\n";
            }
            Block::Summary { columns, rows } => {
                let rows: Vec<Vec<String>> = rows
                    .iter()
                    .map(|r| r.iter().map(|c| inline(c).replace("\\|", "|")).collect())
                    .collect();
                out += &pipe_table(columns, &rows);
                out += "\n";
            }
            Block::Figure { file, caption, .. } => out += &format!("![{caption}]({file})\n\n"),
        }
    }
    out
}
