//! One section per scene: its description and source of truth, its figures, its tables (those a
//! report baseline compares) and its expectation verdicts.

use super::document::{Block, Page};
use super::figures::scene_figures;
use super::summary::expectations_anchor;
use crate::compare::files::{report_tables, scene_tables};
use crate::compare::outcome::SceneOutcome;
use crate::results::table::{Cell, Table};
use crate::scene::cases::Scene;

/// The column of times in transits, named as the figures' titles write them (`t = 0.5000 T`).
pub const TIME_IN_TRANSITS: &str = "t / T";

/// A table with a time column `t` of a scene whose figures give times in transit times `T`, as
/// shown: `t / T` beside `t`, row by row from the row's case (`None` when no case of the scene
/// counts its times in transits, or the table has no `t` and `case`).
pub fn in_transits(scene: &Scene, table: &Table) -> Option<Table> {
    let t = table.columns.iter().position(|c| c == "t")?;
    let case = table.columns.iter().position(|c| c == "case")?;
    if !scene.cases.iter().any(|c| c.times_in_transits) {
        return None;
    }
    let mut columns = table.columns.clone();
    columns.insert(t, TIME_IN_TRANSITS.into());
    let rows = table
        .rows
        .iter()
        .map(|row| {
            let transit = match &row[case] {
                Cell::Text(name) => scene
                    .cases
                    .iter()
                    .find(|c| &c.name == name && c.times_in_transits)
                    .map(|c| c.transit_time),
                _ => None,
            };
            let mut row = row.clone();
            let scaled = match (&row[t], transit) {
                (Cell::Num(time), Some(tt)) => Cell::Num(time / tt),
                _ => Cell::Empty,
            };
            row.insert(t, scaled);
            row
        })
        .collect();
    Some(Table { columns, rows })
}

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
        } else if let Some(shown) = in_transits(scene, &table) {
            page.table_shown(shown, &table, csv);
        } else {
            page.table(table, csv);
        }
    }
    page
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::builtin::builtin_scene;

    /// Source of truth: fig2's figure titles give profile times in transit times of its bar
    /// (`t = 0.5000 T`, `scenes/fig2.toml`: `time_unit = "transit"`). Proves: its norms table
    /// shows `t / T` beside the absolute `t`, each row divided by its case's transit time, so
    /// the table reads in the figures' unit; the stored table is left as it is.
    #[test]
    fn norms_read_in_the_unit_of_the_figures() {
        let scene = builtin_scene("fig2").unwrap().unwrap();
        let case = &scene.cases[0];
        assert!(case.times_in_transits);
        let mut table = Table::new(&["case", "t", "l1"]);
        table.push(vec![
            case.name.as_str().into(),
            Cell::Num(0.5 * case.transit_time),
            Cell::Num(0.1),
        ]);
        let shown = in_transits(&scene, &table).unwrap();
        assert_eq!(shown.columns, ["case", TIME_IN_TRANSITS, "t", "l1"]);
        let Cell::Num(t) = shown.rows[0][1] else {
            panic!("{:?}", shown.rows[0]);
        };
        assert!((t - 0.5).abs() < 1e-12, "{t}");
        assert_eq!(table.columns, ["case", "t", "l1"]);
        // fig5 has no time-stepping case counted in transits: its tables stay as they are.
        let plain = builtin_scene("fig5").unwrap().unwrap();
        assert!(in_transits(&plain, &table).is_none());
    }
}
