#!/usr/bin/env bash
# Build and run the C reference of one lumped central-difference step (see README.md).
#
#   bash benches/c_reference/run.sh                  # gcc -O3 -march=native, default sizes
#   bash benches/c_reference/run.sh 5e7 9 1000       # node-steps per repetition, repetitions, N...
#   CFLAGS="-O3" bash benches/c_reference/run.sh     # same code at the x86-64 baseline ISA
#                                                    # (what a default `cargo bench` targets)
#
# The binary goes to target/c_reference/ (git-ignored); nothing here is part of the cargo build.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
out="$root/target/c_reference"
mkdir -p "$out"
cc="${CC:-gcc}"
cflags="${CFLAGS:--O3 -march=native}"
"$cc" $cflags -Wall -Wextra -o "$out/cd_step" "$here/cd_step.c" -lm
echo "compiler: $("$cc" --version | head -n 1)"
echo "flags:    $cflags"
echo "cpu:      $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//') ($(nproc) cores)"
exec "$out/cd_step" "$@"
