//! The stability-at-the-extremes section: every case of the stability scenes, predicted against
//! observed (the rows are `compare::stability`'s), and the contact closed forms at large beta_s.

use super::document::{Block, Page};
use crate::compare::contact_closed_forms::{CONTACT_CLOSED_FORMS_TEXT, contact_closed_form_table};
use crate::compare::stability::{ENERGY_BAND, StabilityRow, stability_table};
use crate::scene::studies::STABILITY_SCENES;

/// The section, from the rows of every stability scene.
///
/// # Errors
/// A contact closed form refuses its parameters (it cannot for the fixed, valid values used).
pub fn section(stability: &[StabilityRow]) -> Result<Page, String> {
    let mut page = Page::default();
    let agreeing = stability
        .iter()
        .filter(|r| r.agrees() == Some(true))
        .count();
    let predicted_rows = stability.iter().filter(|r| r.agrees().is_some()).count();
    let listed = |verdict: Option<bool>| -> Vec<String> {
        stability
            .iter()
            .filter(|r| r.agrees() == verdict)
            .map(|r| format!("{}/{} ({}, {})", r.scene, r.case, r.predicted, r.observed()))
            .collect()
    };
    let disagreeing = listed(Some(false));
    let unpredicted = listed(None);
    page.push(Block::Heading(2, "Stability at the extremes".into()));
    page.push(Block::Paragraph(format!(
        "Every time-stepping case of the stability scenes ({}): the step against the exact limit of its \
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
         time stepping: largest T + U over the largest energy supplied) exceeds {} is observed as `energy \
         growth`, and disagrees where stability was predicted. Of {} rows, {} carry a prediction: {agreeing} agree \
         with it and {} disagree{}; {} {}. The contact stability sweep of the solver's eigenvalues against the \
         closed forms (beta_s up to 1e8) is in the fig3 section; the closed forms themselves up to beta_s = 1e12 \
         are in the last table below.",
        STABILITY_SCENES.join(", "),
        ENERGY_BAND,
        stability.len(),
        predicted_rows,
        disagreeing.len(),
        if disagreeing.is_empty() {
            String::new()
        } else {
            format!(": {}", disagreeing.join("; "))
        },
        unpredicted.len(),
        if unpredicted.is_empty() {
            "run beyond a sufficient bound".to_string()
        } else {
            format!(
                "ran beyond a sufficient bound, where nothing is predicted: {}",
                unpredicted.join("; ")
            )
        }
    )));
    page.table(stability_table(stability), "stability/extremes.csv".into());
    page.push(Block::Paragraph(CONTACT_CLOSED_FORMS_TEXT.into()));
    let table = contact_closed_form_table().map_err(|e| format!("contact closed forms: {e}"))?;
    page.table(table, "stability/contact_closed_forms.csv".into());
    Ok(page)
}
