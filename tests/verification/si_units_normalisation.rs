//! Source of truth: methods.md §1 — SI inputs must give the same normalised results as unit
//! data (times in transits T = L/c, stresses over |sigma0|).
//!
//! ```text
//!   unit bar: E = rho = L = A = 1, sigma0 = -1      steel: E = 2.1e11, rho = 7850, A = 1e-4, sigma0 = -1e6
//! ```
//!
//! Proves: every normalised norm of `scenes/fig1_si.toml` equals that of `scenes/fig1.toml` to
//! 1e-9 relative (plus a 1e-12 floor for the exact Co = 1 case), case by case.

use courant::pipeline::evaluate_scene as run_scene;
use courant::scene::builtin::builtin_scene;

#[test]
fn steel_bar_gives_the_unit_bar_normalised_errors() {
    let unit = run_scene(&builtin_scene("fig1").unwrap().unwrap()).unwrap();
    let steel = run_scene(&builtin_scene("fig1_si").unwrap().unwrap()).unwrap();
    assert_eq!(unit.results.len(), steel.results.len());
    for (u, s) in unit.results.iter().zip(&steel.results) {
        assert_eq!(u.run.case, s.run.case);
        assert_eq!(u.run.steps, s.run.steps);
        assert!((u.run.courant - s.run.courant).abs() < 1e-12);
        for (pu, ps) in u.profiles.iter().zip(&s.profiles) {
            let (a, b) = (pu.norms.unwrap(), ps.norms.unwrap());
            for (name, x, y) in [
                ("l1", a.l1, b.l1),
                ("l2", a.l2, b.l2),
                ("linf", a.linf, b.linf),
                ("overshoot", a.overshoot, b.overshoot),
            ] {
                assert!(
                    (x - y).abs() <= 1e-9 * x.abs().max(y.abs()) + 1e-12,
                    "{} {name}: unit {x} vs SI {y}",
                    u.run.case
                );
            }
        }
    }
}
