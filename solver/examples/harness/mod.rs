//! The timing harnesses' common arguments (`step_pair`, `run_timing`, `scheme_timing`):
//! `N STEPS MASS [FOURTH]`, each with the harness's own default.

use courant_solver::MassKind;

/// Stop with `error: {message}` (exit status 2), as a command does on an argument it cannot read.
pub fn fail(message: &str) -> ! {
    eprintln!("error: {message}");
    std::process::exit(2)
}

/// A whole number, or [`fail`] naming the argument.
pub fn whole_number(name: &str, s: &str) -> usize {
    s.parse()
        .unwrap_or_else(|_| fail(&format!("{name}: {s} is not a whole number")))
}

/// `N`, `STEPS`, `MASS` (cmm | amm | rmm | lmm; amm and rmm with beta = 1/2) and the fourth
/// argument, if any; defaults `n` and `steps`, CMM. Stops ([`fail`]) with a message naming the
/// argument on a value it cannot read.
pub fn arguments(n: usize, steps: usize) -> (usize, usize, MassKind, Option<String>) {
    let args: Vec<String> = std::env::args().collect();
    let arg = |i: usize| args.get(i).map(String::as_str);
    let number =
        |i: usize, name: &str, default: usize| arg(i).map_or(default, |s| whole_number(name, s));
    let kind = match arg(3) {
        Some("rmm") => MassKind::Reciprocal { beta: 0.5 },
        Some("amm") => MassKind::Averaged { beta: 0.5 },
        Some("lmm") => MassKind::Lumped,
        Some("cmm") | None => MassKind::Consistent,
        Some(other) => fail(&format!("MASS: {other} is not one of cmm, amm, rmm, lmm")),
    };
    let fourth = arg(4).map(str::to_string);
    (number(1, "N", n), number(2, "STEPS", steps), kind, fourth)
}
