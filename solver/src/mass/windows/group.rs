//! How many windows one group solves side by side: the width of the windowed solve, shared by
//! its portable loop and its AVX2 intrinsics (three registers of four windows).

/// Windows solved side by side (three AVX2 registers of four): the independent recurrences
/// that hide the latency of each row's multiply-add. Chosen by measurement (criterion, ns per
/// node-step; benches/RESULTS.md, heading "... twelve windows per group ..."): twelve against
/// eight took CMM at N = 1e5 from 0.805-0.809 to 0.778-0.796 and at 1e6 from 0.938-0.965 to
/// 0.895-0.908, AMM at 1e6 from 0.922-0.945 to 0.825-0.870; bars of 9000 and 50 000 nodes ran
/// 7-13 % faster, 20 000 nodes 0-9 % slower, CMM on a bar of graded density at 1e6 3-5 %
/// slower. Sixteen in four AVX2 registers ran 0.842-0.848 at 1e5 against twelve's 0.771-0.778
/// and about as fast as twelve at 1e6 (the timing harness, same heading); sixteen in two
/// AVX-512 registers (heading "... wider windows; where the CMM step's time goes") and a
/// group's forward sweep interleaved with the previous group's backward one (heading "... the
/// solve is not latency-bound ...") were no faster than eight.
pub(crate) const WINDOWS_PER_GROUP: usize = 12;

const _: () = assert!(
    WINDOWS_PER_GROUP.is_multiple_of(4),
    "whole AVX2 registers of four windows"
);
