//! `courant list --schemes`: every scheme a scene may name, from the solver's registry (its
//! parameters with defaults, rules and meaning, the masses it runs with, its cost and source),
//! then the contact schemes of `[contact] schemes`.

use courant_solver::contact::CONTACT_SCHEMES;
use courant_solver::integrator::ParameterDefault;
use courant_solver::schemes::REGISTRY;

/// The listing, one block per scheme.
pub fn listing() -> String {
    let mut out = String::from(
        "Time-stepping schemes ([integrator] scheme = [...]; parameters are keys of [integrator], a list of values gives one case each):\n",
    );
    for entry in REGISTRY {
        let aliases = if entry.aliases.is_empty() {
            String::new()
        } else {
            format!(" (also {})", entry.aliases.join(", "))
        };
        out += &format!("\n{}{aliases}\n  {}\n", entry.name, entry.summary);
        out += &format!("  masses: {}\n", entry.masses);
        if entry.parameters.is_empty() {
            out += "  parameters: none\n";
        }
        for p in entry.parameters {
            let default = match p.default {
                ParameterDefault::Number(x) => format!("{x}"),
                ParameterDefault::Text(s) => format!("\"{s}\""),
            };
            out += &format!("  {} = {default} ({}): {}\n", p.key, p.rule, p.meaning);
        }
        out += &format!("  source: {}\n", entry.source);
    }
    out += "\nContact schemes ([contact] schemes = [...]; central difference on the bulk):\n";
    for entry in CONTACT_SCHEMES {
        let parameters = if entry.parameters.is_empty() {
            "none".to_string()
        } else {
            entry.parameters.join(", ")
        };
        out += &format!(
            "\n{}\n  {}\n  parameters: {parameters}\n  source: {}\n",
            entry.name, entry.summary, entry.source
        );
    }
    out
}
