//! The thread count of the runs that take blocks of steps (lumped central difference on bars
//! of 1e5 nodes or more): the `COURANT_THREADS` setting, read and checked once when the command
//! line is read ([`crate::run::threads::set`] from `main`), and carried into each run's
//! [`Integration`] ([`with_setting`]). Unset, or never set (a library caller), every core the
//! process may use. The records do not depend on it: only how long a run takes does.

use courant_solver::Integration;
use std::sync::OnceLock;

/// The setting, once read: `Some(count)` from `COURANT_THREADS`, `None` when it is unset.
static SETTING: OnceLock<Option<usize>> = OnceLock::new();

/// Keep the thread count for every later run of the process (the first call wins: the
/// command line is read once).
pub fn set(threads: Option<usize>) {
    let _ = SETTING.set(threads.map(|t| t.max(1)));
}

/// The thread count set by [`set`] (`None`: every core).
pub fn setting() -> Option<usize> {
    SETTING.get().copied().flatten()
}

/// `integration` with the process's thread setting.
pub fn with_setting(integration: &Integration) -> Integration {
    Integration {
        threads: setting(),
        ..integration.clone()
    }
}

/// `COURANT_THREADS` as a thread count: `None` when unset; an error naming the variable, the
/// value and the rule when it is set but not a positive integer (rather than every core
/// without a word).
///
/// # Errors
/// The message to print; the caller exits with status 2.
pub fn from_environment() -> Result<Option<usize>, String> {
    match std::env::var("COURANT_THREADS") {
        Err(std::env::VarError::NotPresent) => Ok(None),
        Ok(text) => match text.trim().parse::<usize>() {
            Ok(threads) if threads > 0 => Ok(Some(threads)),
            _ => Err(format!(
                "COURANT_THREADS: {text:?} must be a positive integer (the threads of a central-difference run of 1e5 nodes or more; unset: every core)"
            )),
        },
        Err(std::env::VarError::NotUnicode(_)) => {
            Err("COURANT_THREADS: not valid Unicode; it must be a positive integer".to_string())
        }
    }
}
