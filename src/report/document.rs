//! A tiny document model rendered both as Markdown ([`super::markdown`]) and as
//! self-contained HTML ([`super::html`]: inline SVG figures, no network, no scripts), so the
//! report's two forms never drift apart.

use crate::results::table::{Precision, Table};

/// Precision of the report's CSV tables: every number at full round-trip precision (the shown
/// tables round to 4 significant digits, [`super::numbers`]).
pub const STORED: Precision = Precision::RoundTrip;

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

    /// A table shown to 4 significant digits and stored as `csv` at [`STORED`] precision.
    pub fn table(&mut self, table: Table, csv: String) {
        self.files.push((csv.clone(), table.to_csv(STORED)));
        self.blocks.push(Block::Table {
            table,
            csv: Some(csv),
            id: None,
        });
    }

    /// `stored` saved as `csv`, shown as `shown`: the same rows with columns added for the
    /// reader (e.g. times in the unit the figures use).
    pub fn table_shown(&mut self, shown: Table, stored: &Table, csv: String) {
        self.files.push((csv.clone(), stored.to_csv(STORED)));
        self.blocks.push(Block::Table {
            table: shown,
            csv: Some(csv),
            id: None,
        });
    }

    /// As [`Page::table`], with an anchor id others link to.
    pub fn table_with_id(&mut self, table: Table, csv: String, id: String) {
        self.files.push((csv.clone(), table.to_csv(STORED)));
        self.blocks.push(Block::Table {
            table,
            csv: Some(csv),
            id: Some(id),
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

/// A piece of text, possibly a link, possibly a verdict to colour.
#[derive(Debug, Clone, PartialEq)]
pub struct Inline {
    /// The text.
    pub text: String,
    /// Where it links to (`#anchor` or a file).
    pub href: Option<String>,
    /// A verdict the HTML colours: `pass`, `fail`, `finding`.
    pub verdict: Option<&'static str>,
}

impl Inline {
    /// Plain text.
    pub fn text(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            href: None,
            verdict: None,
        }
    }

    /// A link.
    pub fn link(text: impl Into<String>, href: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            href: Some(href.into()),
            verdict: None,
        }
    }

    /// The same text, coloured as `verdict`.
    pub fn verdict(mut self, verdict: &'static str) -> Self {
        self.verdict = Some(verdict);
        self
    }
}

/// One block of a document.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// A heading of level 1 to 4 with an anchor id ([`anchor`]).
    Heading(usize, String),
    /// A paragraph of plain text (`code` spans in backticks are kept).
    Paragraph(String),
    /// A bulleted list of plain-text items.
    List(Vec<String>),
    /// A bulleted list of links.
    Links(Vec<Inline>),
    /// A data table (numbers shown to 4 significant digits, one notation per column), with the
    /// CSV file it is stored in and an optional anchor id.
    Table {
        table: Table,
        csv: Option<String>,
        id: Option<String>,
    },
    /// A small table of links and verdicts (the report's first screen).
    Summary {
        columns: Vec<String>,
        rows: Vec<Vec<Inline>>,
    },
    /// An SVG figure stored as `file`, with a caption.
    Figure {
        svg: String,
        file: String,
        caption: String,
    },
}

/// The anchor id of a heading: lower case, spaces as `-`, only letters, digits, `-` and `_`.
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
