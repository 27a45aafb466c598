//! Running the built `courant` binary from an integration test, and the test's scratch
//! directories (included with `#[path = "common/cli.rs"] mod cli;`).
#![allow(dead_code)]

use std::path::PathBuf;
use std::process::{Command, Output};

/// The built `courant` binary run with `args`, its status and output collected.
pub fn courant(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(args)
        .output()
        .unwrap()
}

/// [`courant`] with the environment variables `env` set (e.g. thread counts).
pub fn courant_with_env(args: &[&str], env: &[(&str, &str)]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_courant"))
        .args(args)
        .envs(env.iter().copied())
        .output()
        .unwrap()
}

/// A fresh, empty directory `courant-<test file>-<name>-<pid>` under the system's temporary
/// directory (whatever an earlier run left there removed first).
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "courant-{}-{name}-{}",
        env!("CARGO_CRATE_NAME"),
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
