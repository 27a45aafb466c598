//! A tiny document model rendered both as Markdown and as self-contained HTML (inline SVG
//! figures, no network, no scripts), so the report's two forms never drift apart.

use crate::results::table::{Cell, Precision, Table};

/// Display precision of the report's Markdown and HTML tables (values below 1e-12, round-off,
/// shown as 0).
pub const SHOWN: Precision = Precision::Significant {
    digits: 4,
    floor: 1e-12,
};

/// Precision of the report's CSV tables: 10 significant digits, round-off below 1e-12 as 0, so
/// the committed report does not change with the last bits of a platform.
pub const STORED: Precision = Precision::Significant {
    digits: 10,
    floor: 1e-12,
};

/// A part of a document: its blocks and the files stored beside them (CSV tables, SVG figures),
/// by path relative to the document.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Page {
    /// The blocks, in order.
    pub blocks: Vec<Block>,
    /// `(relative path, contents)` of the files the blocks refer to.
    pub files: Vec<(String, String)>,
}

impl Page {
    /// Append a block.
    pub fn push(&mut self, block: Block) {
        self.blocks.push(block);
    }

    /// A table shown at [`SHOWN`] precision and stored as `csv` at [`STORED`] precision.
    pub fn table(&mut self, table: Table, csv: String) {
        self.files.push((csv.clone(), table.to_csv(STORED)));
        self.blocks.push(Block::Table {
            table,
            precision: SHOWN,
            csv: Some(csv),
        });
    }

    /// A figure stored as `file`.
    pub fn figure(&mut self, file: String, svg: String, caption: String) {
        self.files.push((file.clone(), svg.clone()));
        self.blocks.push(Block::Figure { svg, file, caption });
    }

    /// Append another page.
    pub fn extend(&mut self, other: Page) {
        self.blocks.extend(other.blocks);
        self.files.extend(other.files);
    }
}

/// One block of a document.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// A heading of level 1 to 4 with an anchor id.
    Heading(usize, String),
    /// A paragraph of plain text (`code` spans in backticks are kept).
    Paragraph(String),
    /// A bulleted list of plain-text items.
    List(Vec<String>),
    /// A table, numbers shown at the given precision, with the CSV file it is stored in.
    Table {
        table: Table,
        precision: Precision,
        csv: Option<String>,
    },
    /// An SVG figure stored as `file`, with a caption.
    Figure {
        svg: String,
        file: String,
        caption: String,
    },
}

/// The anchor id of a heading.
pub fn anchor(text: &str) -> String {
    text.to_lowercase()
        .chars()
        .filter_map(|c| {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                Some(c)
            } else if c == ' ' {
                Some('-')
            } else {
                None
            }
        })
        .collect()
}

/// Markdown rendering.
pub fn markdown(blocks: &[Block]) -> String {
    let mut out = String::new();
    for b in blocks {
        match b {
            Block::Heading(level, text) => out += &format!("{} {text}\n\n", "#".repeat(*level)),
            Block::Paragraph(text) => out += &format!("{text}\n\n"),
            Block::List(items) => {
                items.iter().for_each(|i| out += &format!("- {i}\n"));
                out += "\n";
            }
            Block::Table {
                table,
                precision,
                csv,
            } => {
                if let Some(csv) = csv {
                    out += &format!("[`{csv}`]({csv})\n\n");
                }
                out += &table.to_markdown(*precision);
                out += "\n";
            }
            Block::Figure { file, caption, .. } => out += &format!("![{caption}]({file})\n\n"),
        }
    }
    out
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Inline `code` spans of already-escaped text.
fn inline(text: &str) -> String {
    let escaped = escape(text);
    let mut out = String::new();
    for (i, part) in escaped.split('`').enumerate() {
        if i % 2 == 1 {
            out += &format!("<code>{part}</code>");
        } else {
            out += part;
        }
    }
    out
}

/// Self-contained HTML rendering (figures inline).
pub fn html(title: &str, blocks: &[Block]) -> String {
    let mut out = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<title>{}</title>\n<style>\n\
         body {{ font-family: sans-serif; max-width: 72rem; margin: 2rem auto; padding: 0 1rem; }}\n\
         table {{ border-collapse: collapse; font-size: 0.85rem; margin: 0.5rem 0 1rem; }}\n\
         td, th {{ border: 1px solid #bbb; padding: 0.2rem 0.4rem; text-align: right; }}\n\
         th {{ background: #eee; }}\n\
         figure {{ margin: 1rem 0; }}\n\
         </style>\n</head>\n<body>\n",
        escape(title)
    );
    for b in blocks {
        match b {
            Block::Heading(level, text) => {
                let level = (*level).clamp(1, 6);
                out += &format!(
                    "<h{level} id=\"{}\">{}</h{level}>\n",
                    anchor(text),
                    escape(text)
                );
            }
            Block::Paragraph(text) => out += &format!("<p>{}</p>\n", inline(text)),
            Block::List(items) => {
                out += "<ul>\n";
                items
                    .iter()
                    .for_each(|i| out += &format!("<li>{}</li>\n", inline(i)));
                out += "</ul>\n";
            }
            Block::Table {
                table,
                precision,
                csv,
            } => {
                if let Some(csv) = csv {
                    out += &format!("<p><a href=\"{0}\"><code>{0}</code></a></p>\n", escape(csv));
                }
                out += "<table>\n<tr>";
                table
                    .columns
                    .iter()
                    .for_each(|c| out += &format!("<th>{}</th>", escape(c)));
                out += "</tr>\n";
                for row in &table.rows {
                    out += "<tr>";
                    for cell in row {
                        let text = match cell {
                            Cell::Num(x) => precision.format(*x),
                            Cell::Int(i) => i.to_string(),
                            Cell::Text(s) => s.clone(),
                            Cell::Empty => "-".into(),
                        };
                        out += &format!("<td>{}</td>", escape(&text));
                    }
                    out += "</tr>\n";
                }
                out += "</table>\n";
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
                    escape(caption)
                );
            }
        }
    }
    out += "</body>\n</html>\n";
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_renderings_carry_the_same_content() {
        let mut t = Table::new(&["a"]);
        t.push(vec![Cell::Num(1.5)]);
        let blocks = vec![
            Block::Heading(2, "Fig. 1 <x>".into()),
            Block::Paragraph("see `index.md` & more".into()),
            Block::Table {
                table: t,
                precision: Precision::Significant {
                    digits: 3,
                    floor: 0.0,
                },
                csv: Some("x.csv".into()),
            },
        ];
        let md = markdown(&blocks);
        assert!(md.contains("## Fig. 1 <x>") && md.contains("| 1.50 |"));
        let h = html("t", &blocks);
        assert!(h.contains("<h2 id=\"fig-1-x\">Fig. 1 &lt;x&gt;</h2>"));
        assert!(h.contains("<code>index.md</code> &amp; more"));
        assert!(h.contains("<td>1.50</td>"));
    }
}
