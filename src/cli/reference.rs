//! `courant reference`: the exact answers of a scene in the exchange format, at its own mesh and
//! output times or at the rows of a query file.

use crate::compare::score::answers::exact_set;
use crate::io::atomic::write_dir_atomically;
use crate::results::exchange::files::read_query;
use crate::results::exchange::writer::set_files;
use crate::scene::builtin::resolve;
use std::path::Path;
use std::process::ExitCode;

/// Write the exact answers of `scene` (at the rows of `at`, if given) to `out/<scene>/`. Exit
/// status 0, or 2 on bad input (nothing is written then).
pub fn reference(scene: &str, at: Option<&Path>, out: &Path) -> ExitCode {
    let scene = match resolve(scene) {
        Ok(scene) => scene,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let query = match at.map(read_query).transpose() {
        Ok(q) => q,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let dir = out.join(&scene.name);
    let set = match exact_set(&scene, query.as_ref(), &dir.display().to_string()) {
        Ok(set) => set,
        Err(e) => {
            errln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let files = set_files(&set);
    if let Err(e) = write_dir_atomically(&dir, &files) {
        errln!("error: {}", super::write_failure(&dir, &e));
        return ExitCode::from(2);
    }
    let references: Vec<&str> = {
        let mut r: Vec<&str> = set
            .cases
            .iter()
            .filter_map(|c| c.reference.as_deref())
            .collect();
        r.dedup();
        r
    };
    outln!(
        "{}: exact answers of {} case(s) ({}) -> {} ({} files)",
        scene.name,
        set.cases.len(),
        references.join(", "),
        dir.display(),
        files.len()
    );
    ExitCode::SUCCESS
}
