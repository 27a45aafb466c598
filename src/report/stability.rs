//! The stability-at-the-extremes section: every case of the stability scenes, predicted against
//! observed (the rows are `compare::stability`'s), and the contact closed forms at large beta_s.

use super::document::{Block, Page};
use crate::compare::contact_closed_forms::{CONTACT_CLOSED_FORMS_TEXT, contact_closed_form_table};
use crate::compare::stability::{ENERGY_BAND, ENERGY_CREATED, StabilityRow, stability_table};

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
    let list = |items: &[String]| {
        if items.is_empty() {
            String::new()
        } else {
            format!(": {}", items.join("; "))
        }
    };
    page.push(Block::Heading(2, "Stability at the extremes".into()));
    page.push(Block::Paragraph(format!(
        "Every case of the stability scenes ({}): the step against the exact limit of its \
         scheme (column `limit`: 2/omega_max of the assembled system for central difference with any mass; \
         alpha_e = dt/dt_e <= 1 in every element for Park's scheme, whose runs above it use the true alpha; \
         that bound is the limit on a uniform mesh and only sufficient on a graded one, where a step above it \
         is `beyond bound`, not predicted), \
         the verdict theory predicts (marginal within 1e-9 of the limit), what the run did, and where \
         courant's divergence guard stopped it. Rows at 0.99, 1.00 and 1.01 of the closed-form critical Courant \
         number (stability_extremes, layered_1e4: 1.00 is a hair below the finite mesh's exact limit) stand \
         beside rows in units of the exact limit with the step kept exactly (stability_exact, stability_park, \
         graded_1e4), where dt/dt_crit reads 0.99, 1.00 and 1.01 to round-off. Contact rows \
         (contact_extremes, beta_s up to 1e8) take the exact critical step of their scheme; between it and the \
         contact-free limit linear theory of the closed contact predicts growth, which the unilateral contact \
         bounds by opening (`contact-unstable`: the run completes). `stable` promises bounded energy: a \
         completed run whose energy_ratio (contact: the energy central difference conserves, 1/2 v^{{n-1/2}} M v^{{n+1/2}} + 1/2 u K u, left in the bars at the end over the initial energy; \
         time stepping: largest T + U over the largest energy supplied) exceeds {ENERGY_BAND} is observed as `energy \
         growth`, and a run whose scheme created more than {ENERGY_CREATED:e} of its energy scale (its balance \
         T + U - W grew) as `energy created`; either disagrees where stability was predicted. A disagreement \
         fails the report and `courant check` unless its scene states it as a finding, with its source \
         (`[[finding]]`). Of {} rows: {} agree with theory{}; {} disagree as their scenes state (findings){}; \
         {} disagree without a stated finding (FAIL){}; {} ran beyond a sufficient bound, where nothing is \
         predicted{}. The contact stability sweep of the solver's eigenvalues against the closed forms \
         (beta_s up to 1e8) is in the fig3 section; the closed forms themselves up to beta_s = 1e12 are in the \
         last table below.",
        scenes.join(", "),
        stability.len(),
        agreeing.len(),
        "",
        findings.len(),
        list(&findings),
        failing.len(),
        list(&failing),
        unpredicted.len(),
        list(&unpredicted),
    )));
    page.table(stability_table(stability), "stability/extremes.csv".into());
    page.push(Block::Paragraph(CONTACT_CLOSED_FORMS_TEXT.into()));
    let table = contact_closed_form_table().map_err(|e| format!("contact closed forms: {e}"))?;
    page.table(table, "stability/contact_closed_forms.csv".into());
    Ok(page)
}
