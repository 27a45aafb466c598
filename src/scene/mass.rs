//! Mass kinds as scene files name them.

use courant_solver::MassKind;

/// Parse a mass label: `lmm`/`lumped`, `cmm`/`consistent`, `amm`/`averaged`, `rmm`/`reciprocal`
/// (beta = 1/2), or `amm(beta)`, `rmm(beta)`.
pub fn parse_mass(label: &str) -> Result<MassKind, String> {
    let label = label.trim();
    let (name, beta) = match label.split_once('(') {
        Some((name, rest)) => {
            let inner = rest
                .strip_suffix(')')
                .ok_or_else(|| format!("\"{label}\": a beta is written amm(0.5)"))?;
            let beta: f64 = inner
                .trim()
                .parse()
                .map_err(|_| format!("\"{label}\": beta \"{inner}\" is not a number"))?;
            (name.trim(), Some(beta))
        }
        None => (label, None),
    };
    let kind = match (name, beta) {
        ("lmm" | "lumped", None) => MassKind::Lumped,
        ("cmm" | "consistent", None) => MassKind::Consistent,
        ("amm" | "averaged", b) => MassKind::Averaged {
            beta: b.unwrap_or(0.5),
        },
        ("rmm" | "reciprocal", b) => MassKind::Reciprocal {
            beta: b.unwrap_or(0.5),
        },
        ("lmm" | "lumped" | "cmm" | "consistent", Some(_)) => {
            return Err(format!("\"{label}\": only amm and rmm take a beta"));
        }
        _ => {
            return Err(format!(
                "\"{label}\" is not a mass kind (lmm, cmm, amm, rmm, amm(beta), rmm(beta))"
            ));
        }
    };
    kind.validate().map_err(|e| format!("\"{label}\": {e}"))?;
    Ok(kind)
}

/// File-name friendly mass name: `lmm`, `cmm`, `amm0.5`, `rmm0.5`.
pub fn mass_name(kind: MassKind) -> String {
    match kind {
        MassKind::Lumped => "lmm".into(),
        MassKind::Consistent => "cmm".into(),
        MassKind::Averaged { beta } => format!("amm{}", super::names::number(beta)),
        MassKind::Reciprocal { beta } => format!("rmm{}", super::names::number(beta)),
    }
}
