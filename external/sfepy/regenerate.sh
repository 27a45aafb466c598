#!/usr/bin/env bash
# Regenerate SfePy's results for courant's bar scenes and fig6's spectra, by default into
# external/sfepy/results/ (the committed ones). Arguments go to driver.py, e.g.
#   bash external/sfepy/regenerate.sh                                   # rewrite the committed results
#   bash external/sfepy/regenerate.sh --out /tmp/fresh --compare-with external/sfepy/results
#   bash external/sfepy/regenerate.sh --can-run                         # can this machine regenerate? (builds nothing)
# The venv is $SFEPY_VENV (default sfepy-venv in $CARGO_TARGET_DIR or target/, outside git), built from requirements.txt
# when missing or when requirements.txt changed (about 2 minutes: SfePy compiles from source).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
venv="${SFEPY_VENV:-${CARGO_TARGET_DIR:-$root/target}/sfepy-venv}"
stamp="$venv/.requirements.sha256"
want="$(sha256sum "$here/requirements.txt" | cut -d' ' -f1)"

# --can-run: say whether this machine can regenerate (a built venv, or python3 >= 3.11 with
# the compiler and headers SfePy's build needs), build nothing, exit 0 or 1.
if [ "${1:-}" = "--can-run" ]; then
  if [ -x "$venv/bin/python" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
    echo "SfePy venv ready in $venv"; exit 0
  fi
  if ! python3 -c 'import sys; sys.exit(sys.version_info < (3, 11))' >/dev/null 2>&1; then
    echo "no python3 >= 3.11 on PATH (SfePy's driver needs tomllib)"; exit 1
  fi
  headers="$(python3 -c 'import sysconfig; print(sysconfig.get_paths()["include"])')"
  if ! command -v gcc >/dev/null 2>&1 || [ ! -f "$headers/Python.h" ]; then
    echo "SfePy 2026.3 compiles from source: needs gcc and the Python headers ($headers/Python.h; apt-get install gcc python3-dev)"; exit 1
  fi
  echo "python3 $(python3 -c 'import platform; print(platform.python_version())'), gcc and the Python headers found: the venv can be built"; exit 0
fi
if [ ! -x "$venv/bin/python" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  echo "== building the SfePy venv in $venv (pinned requirements.txt)"
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$here/requirements.txt"
  echo "$want" > "$stamp"
fi
# The driver takes each case's mesh, times and step from courant's exact answers.
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
exec "$venv/bin/python" "$here/driver.py" --courant "${CARGO_TARGET_DIR:-$root/target}/release/courant" "$@"
