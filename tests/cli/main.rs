//! The command line as a user meets it: `run`, `check`, `bench`, output directories, atomic
//! replacement and thread-count determinism.
//!
//! One test binary; each module opens with its source of truth and what it proves.

#[path = "../common/cli.rs"]
mod cli;
#[path = "../common/xml.rs"]
mod xml;

mod bench_command;
mod check_command;
mod cli_conventions;
mod cli_first_contact;
mod cli_run;
mod doc_examples;
mod output_directory_safety;
mod report_atomic_replacement;
mod thread_count_bit_identity;
