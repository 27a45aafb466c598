//! One section per scene: its description and source of truth, its figures, its tables (those a
//! report baseline compares) and its expectation verdicts.

use super::document::{Block, Page};
use super::figures::scene_figures;
use super::summary::expectations_anchor;
use crate::compare::files::{report_tables, scene_tables};
use crate::compare::outcome::SceneOutcome;
use crate::scene::cases::Scene;

/// The section of one scene.
pub fn section(scene: &Scene, outcome: &SceneOutcome) -> Page {
    let mut page = Page::default();
    page.push(Block::Heading(2, scene.name.clone()));
    let stop = if scene.description.ends_with(['.', '!', '?']) {
        ""
    } else {
        "."
    };
    page.push(Block::Paragraph(format!(
        "{}{stop} Source of truth: {}.",
        scene.description, scene.source
    )));
    for (svg_name, caption, svg) in scene_figures(scene, outcome) {
        page.figure(format!("{}/{svg_name}", scene.name), svg, caption);
    }
    for (file, table) in scene_tables(outcome) {
        let csv = format!("{}/{file}", scene.name);
        if file == report_tables::EXPECTATIONS {
            page.table_with_id(table, csv, expectations_anchor(&scene.name));
        } else {
            page.table(table, csv);
        }
    }
    page
}
