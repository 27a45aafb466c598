//! Grading results files of any code: the exchange format, `courant score`, its diagnostics, fair-
//! grading rules, the committed sets of other codes and the fuzz of result files.
//!
//! One test binary; each module opens with its source of truth and what it proves.

#[path = "../common/cli.rs"]
mod cli;
#[path = "../common/exchange.rs"]
mod exchange;
#[path = "../common/mutate_csv.rs"]
mod mutate_csv;
#[path = "../common/xml.rs"]
mod xml;

mod fuzz_exchange;
mod other_codes_committed;
mod score_and_io_regressions;
mod score_command;
mod score_diagnostics;
mod score_fair_grading;
mod score_round_trip;
