//! The magnitudes a scene's numbers may take, checked before any numerics.
//!
//! Every dimensional input (lengths, areas, moduli, densities, loads, times, velocities,
//! penalties) and every scale derived from them (element stiffness `E A/h`, nodal mass
//! `rho A h/2`, squared element frequency `4 E/(rho h^2)`, nodal load, penalty stiffness and mass)
//! must be zero (where zero is allowed) or lie within [`MAGNITUDE_MIN`] ..= [`MAGNITUDE_MAX`].
//!
//! Why these bounds: the numerics form products of a few such scales, and each must stay a
//! normal, finite double: Sturm pivots square the stiffness (`k^2 <= 1e100`), energies square
//! displacements that are a load over a stiffness (`(F/k)^2 k = F^2/k <= 1e150`), and errors are
//! divided by the load. Within `1e-50 ..= 1e50` any product or quotient of up to six scales
//! stays inside the normal range of f64 (`1e-308 ..= 1e308`). Outside it (`beta_s = 1e300`, a
//! bar area of 1e300, a load of 5e-324) the Sturm bisection met infinities and NaN and never
//! closed, and results were NaN; such input is refused here with its key and line.

use super::error::{SceneError, Source};
use courant_solver::Model;
use std::ops::Range;

/// Smallest magnitude of a nonzero input or derived scale.
pub const MAGNITUDE_MIN: f64 = 1e-50;
/// Largest magnitude of an input or derived scale.
pub const MAGNITUDE_MAX: f64 = 1e50;

/// True when `x` is zero or a finite number within the magnitude bounds.
pub fn within(x: f64) -> bool {
    x == 0.0 || (MAGNITUDE_MIN..=MAGNITUDE_MAX).contains(&x.abs())
}

/// The rule, for messages.
pub fn rule() -> String {
    format!(
        "numbers and the scales derived from them must be 0 or of magnitude {MAGNITUDE_MIN:e} ..= {MAGNITUDE_MAX:e} (products of a few of them must stay finite doubles)"
    )
}

/// `value` (named `what` in the message) within the bounds, else the error at `key`.
pub fn input(
    src: &Source,
    span: Option<Range<usize>>,
    key: &str,
    what: &str,
    value: f64,
) -> Result<(), SceneError> {
    if within(value) {
        Ok(())
    } else {
        Err(src.error(span, key, format!("{what} = {value:e}: {}", rule())))
    }
}

/// Every value of `values` within the bounds.
pub fn inputs(
    src: &Source,
    span: Option<Range<usize>>,
    key: &str,
    what: &str,
    values: impl IntoIterator<Item = f64>,
) -> Result<(), SceneError> {
    values
        .into_iter()
        .try_for_each(|v| input(src, span.clone(), key, what, v))
}

/// A case's Courant number `Co = c dt/h` (stiffest element) with its square within the bounds:
/// `Co^2` scales every update (`dt^2 K/M`), so a step of Co = 5e49 (allowed unstable) overflowed
/// in its first step. Else the error at `span`/`key` naming the case.
pub fn courant(
    src: &Source,
    span: Option<Range<usize>>,
    key: &str,
    case: &str,
    co: f64,
) -> Result<(), SceneError> {
    if within(co * co) {
        Ok(())
    } else {
        Err(src.error(
            span,
            key,
            format!(
                "case {case}: Courant number {co:e} (c dt/h of the stiffest element): its square scales every step; {}",
                rule()
            ),
        ))
    }
}

/// A scale of an assembled model, for the caller to say which input it blames.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// An element stiffness `E A/h`.
    Stiffness,
    /// A lumped nodal mass `rho A h/2` (summed over the node's elements).
    Mass,
    /// A squared element frequency `k_e/m_i`.
    Frequency,
    /// A nodal load (a traction's stress times the area, or a force).
    Load,
}

/// The scales of an assembled model within the bounds: each element's stiffness `E A/h`, each
/// nodal mass, each squared element frequency `k_e/m_i` and each nodal load magnitude. `blame`
/// gives the key (and span) an out-of-bounds scale is reported at; the message names the scale,
/// the element or node and the inputs it comes from.
pub fn model(
    src: &Source,
    blame: impl Fn(Scale) -> (Option<Range<usize>>, &'static str),
    model: &Model,
) -> Result<(), SceneError> {
    let bar = model.bar();
    let fail = |scale: Scale, what: String, value: f64| {
        let (span, key) = blame(scale);
        Err(src.error(span, key, format!("{what} = {value:e}: {}", rule())))
    };
    let mass = model.nodal_mass();
    for (e, &k) in model.stiffness().iter().enumerate() {
        let (modulus, area, h) = (
            bar.modulus()[e],
            bar.area()[e],
            bar.mesh().element_length(e),
        );
        if !within(k) {
            return fail(
                Scale::Stiffness,
                format!("element {e}: stiffness E A/h (E = {modulus:e}, A = {area:e}, h = {h:e})"),
                k,
            );
        }
        for node in [e, e + 1] {
            if !within(mass[node]) {
                return fail(
                    Scale::Mass,
                    format!(
                        "node {node}: lumped mass (density {:e}, A = {area:e}, h = {h:e})",
                        bar.density()[e]
                    ),
                    mass[node],
                );
            }
            let omega2 = k / mass[node];
            if !within(omega2) {
                return fail(
                    Scale::Frequency,
                    format!("element {e}: squared frequency E A/(h m) at node {node}"),
                    omega2,
                );
            }
        }
    }
    for load in model.loads() {
        if !within(load.magnitude) {
            return fail(
                Scale::Load,
                format!("nodal load at node {} (stress times area)", load.node),
                load.magnitude,
            );
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_and_moderate_numbers_pass_extremes_do_not() {
        for ok in [0.0, 1.0, -2.5e11, 1e-50, 1e50, -1e-50] {
            assert!(within(ok), "{ok}");
        }
        for bad in [
            5e-324,
            1e-300,
            1e300,
            -1e51,
            f64::NAN,
            f64::INFINITY,
            f64::MIN_POSITIVE,
        ] {
            assert!(!within(bad), "{bad}");
        }
    }
}
