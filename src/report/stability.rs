//! The stability-at-the-extremes section: every case of the stability scenes, predicted against
//! observed (the rows are `compare::stability`'s), and the contact closed forms at large beta_s.

use super::document::{Block, Page};
use crate::compare::contact_closed_forms::{CONTACT_CLOSED_FORMS_TEXT, contact_closed_form_table};
use crate::compare::growth::ENERGY_BAND;
use crate::compare::stability::{ENERGY_CREATED, StabilityRow, stability_table};

/// The section, from the rows of every stability scene.
///
/// # Errors
/// A contact closed form refuses its parameters (it cannot for the fixed, valid values used).
pub fn section(stability: &[StabilityRow]) -> Result<Page, String> {
    let mut page = Page::default();
    let mut scenes: Vec<&str> = Vec::new();
    for row in stability {
        if !scenes.contains(&row.scene.as_str()) {
            scenes.push(&row.scene);
        }
    }
    let verdicts: Vec<_> = stability.iter().map(|r| (r, r.verdict())).collect();
    let listed = |keep: fn(&Option<(bool, bool, String)>) -> bool| -> Vec<String> {
        verdicts
            .iter()
            .filter(|(_, v)| keep(v))
            .map(|(r, _)| format!("{}/{} ({}, {})", r.scene, r.case, r.predicted, r.observed()))
            .collect()
    };
    let agreeing = listed(|v| matches!(v, Some((true, false, _))));
    let findings = listed(|v| matches!(v, Some((true, true, _))));
    let failing = listed(|v| matches!(v, Some((false, _, _))));
    let unpredicted = listed(|v| v.is_none());
    page.push(Block::Heading(2, "Stability at the extremes".into()));
    page.push(Block::Paragraph(format!(
        "Every case of the stability scenes: its step against the exact limit of its scheme, the \
         verdict theory predicts and what the run did (at the limit: whether its energy keeps \
         the n^2 law). Of {} rows: {} agree with theory, {} \
         disagree as their scenes state (findings), {} disagree without a stated finding (FAIL), \
         {} ran beyond a sufficient bound, where nothing is predicted. Rows that need a look come \
         first; the columns are explained below the table.",
        stability.len(),
        agreeing.len(),
        findings.len(),
        failing.len(),
        unpredicted.len(),
    )));
    page.table(stability_table(stability), "stability/extremes.csv".into());
    page.push(Block::Paragraph(format!(
        "The stability scenes: {}. Column `limit`: 2/omega_max of the assembled system for \
         central difference with any mass; alpha_e = dt/dt_e <= 1 in every element for Park's \
         scheme, whose runs above it use the true alpha; that bound is the limit on a uniform mesh \
         and only sufficient on a graded one, where a step above it is `beyond bound`, not \
         predicted. `predicted` is marginal within 1e-9 of the limit, where the critical mode's double \
         root lets the energy grow at most like n^2 (methods.md §2): a marginal row's `observed` \
         adds `within` or `beyond the n^2 law` with the growth exponent p = log2(max energy over \
         the second half of the run / max over the first half) and its bound (at most 3.32 for a \
         finely logged run), or, for a run too short to measure p, its energy ratio after n steps \
         against 1.5 + 4 (1 + n)^2; beyond the law disagrees. `guard` is where courant's \
         divergence guard stopped the run. Rows at 0.99, 1.00 and 1.01 of the closed-form critical \
         Courant number (stability_extremes, layered_1e4: 1.00 is a hair below the finite mesh's \
         exact limit, `dt_over_dt_crit` shows by how much) stand beside rows in units of the exact \
         limit with the step kept exactly (stability_exact, stability_park, graded_1e4), where \
         dt/dt_crit reads 0.99, 1.00 and 1.01 to round-off. Contact rows (contact_extremes, beta_s \
         up to 1e8) take the exact critical step of their scheme; between it and the contact-free \
         limit linear theory of the closed contact predicts growth, which the unilateral contact \
         bounds by opening (`contact-unstable`: the run completes). `stable` promises bounded \
         energy: a completed run whose energy_ratio (contact: the energy central difference \
         conserves, 1/2 v^{{n-1/2}} M v^{{n+1/2}} + 1/2 u K u, left in the bars at the end over the \
         initial energy; time stepping: largest T + U over the largest energy supplied) exceeds \
         {ENERGY_BAND} is observed as `energy growth`, and a run whose scheme created more than \
         {ENERGY_CREATED:e} of its energy scale (its balance T + U - W grew) as `energy created`; \
         either disagrees where stability was predicted. A disagreement fails the report and \
         `courant check` unless its scene states it as a finding, with its source (`[[finding]]`).",
        scenes.join(", "),
    )));
    if !(findings.is_empty() && failing.is_empty() && unpredicted.is_empty()) {
        page.push(Block::List(
            [
                ("Findings", &findings),
                ("FAIL", &failing),
                ("Beyond a sufficient bound", &unpredicted),
            ]
            .into_iter()
            .filter(|(_, items)| !items.is_empty())
            .map(|(what, items)| format!("{what}: {}.", items.join("; ")))
            .collect(),
        ));
    }
    page.push(Block::Paragraph(
        "The contact stability sweep of the solver's eigenvalues against the closed forms \
         (beta_s up to 1e8) is in the fig3 section; the closed forms themselves up to beta_s = \
         1e12 are in the last table below."
            .into(),
    ));
    page.push(Block::Paragraph(CONTACT_CLOSED_FORMS_TEXT.into()));
    let table = contact_closed_form_table().map_err(|e| format!("contact closed forms: {e}"))?;
    page.table(table, "stability/contact_closed_forms.csv".into());
    Ok(page)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::html::{FOLD_ROWS, html};

    /// A time-stepping row at `ratio` of its limit, completed or stopped by the guard.
    fn row(case: &str, ratio: f64, completed: bool) -> StabilityRow {
        StabilityRow {
            scene: "s".into(),
            case: case.into(),
            limit: "2/omega_max",
            ratio,
            predicted: crate::compare::stability::predicted(ratio),
            completed,
            caught: (!completed).then(|| "step 3, node 0, Co 1.0".into()),
            steps: 10,
            energy_balance: Some(0.0),
            energy_ratio: Some(1.0),
            energy_created: 0.0,
            growth: None,
            finding: None,
        }
    }

    /// Source of truth: the report contract "the stability table shows its disagreements
    /// unfolded, the agreeing rows may fold; a section opens with a short paragraph". Proves: the
    /// section opens with a paragraph of at most 80 words that counts the rows, the table leads
    /// with its verdict, a predicted-stable run that diverged (FAIL) is in view while the
    /// agreeing rows fold, and the explanation of the columns follows the table.
    #[test]
    fn disagreements_stay_in_view_and_the_section_opens_short() {
        let mut rows: Vec<StabilityRow> = (0..=FOLD_ROWS)
            .map(|i| row(&format!("ok{i}"), 0.5, true))
            .collect();
        rows.push(row("broken", 0.99997, false));
        let page = section(&rows).unwrap();
        let Block::Paragraph(opening) = &page.blocks[1] else {
            panic!("no opening paragraph: {:?}", page.blocks[1]);
        };
        assert!(opening.split_whitespace().count() <= 80, "{opening}");
        assert!(
            opening.contains("Of 32 rows: 31 agree with theory"),
            "{opening}"
        );
        assert!(matches!(page.blocks[2], Block::Table { .. }));
        let h = html("t", &page.blocks);
        let table_start = h.find("<table").unwrap();
        assert!(
            h[table_start..].starts_with("<table class=\"status-first\">\n<tr><th>verdict</th>")
        );
        let (shown, folded) = h.split_once("<details>").unwrap();
        assert!(shown.contains(">broken<") && shown.contains("<td class=\"fail\">FAIL</td>"));
        assert!(
            shown.contains(">0.99997<"),
            "the ratio tells 0.99997 from 1"
        );
        assert!(!shown.contains(">ok0<") && folded.contains(">ok0<"));
        let columns = h.find("Column <code>limit</code>").unwrap();
        assert!(
            columns > table_start,
            "the columns are explained below the table"
        );
    }
}
