#!/usr/bin/env bash
# Regenerate OpenSees' results for courant's scenes, by default into external/opensees/results/
# (the committed ones). Arguments go to driver.py, e.g.
#   bash external/opensees/regenerate.sh                                      # rewrite the committed results
#   bash external/opensees/regenerate.sh --out /tmp/fresh --compare-with external/opensees/results
#   bash external/opensees/regenerate.sh --can-run                            # can this machine regenerate? (builds nothing)
# The venv is $OPENSEES_VENV (default opensees-venv in $CARGO_TARGET_DIR or target/, outside git), built from
# requirements.txt when missing or when requirements.txt changed (about 15 s: one 86 MB wheel).
# OpenSeesPy 3.8 needs Python >= 3.12: $OPENSEES_PYTHON if set, else the first of python3.13,
# python3.12, python3 on PATH and pyenv's 3.12+ versions that is at least 3.12.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
venv="${OPENSEES_VENV:-${CARGO_TARGET_DIR:-$root/target}/opensees-venv}"
stamp="$venv/.requirements.sha256"
want="$(sha256sum "$here/requirements.txt" | cut -d' ' -f1)"

recent_enough() { "$1" -c 'import sys; sys.exit(sys.version_info < (3, 12))' >/dev/null 2>&1; }

find_python() {
  local candidates=()
  [ -n "${OPENSEES_PYTHON:-}" ] && candidates+=("$OPENSEES_PYTHON")
  candidates+=(python3.13 python3.12 python3)
  local pyenv_root="${PYENV_ROOT:-$HOME/.pyenv}"
  for v in "$pyenv_root"/versions/3.1[2-9]*/bin/python3; do
    [ -x "$v" ] && candidates+=("$v")
  done
  for c in "${candidates[@]}"; do
    if command -v "$c" >/dev/null 2>&1 && recent_enough "$c"; then
      echo "$c"
      return 0
    fi
  done
  echo "error: OpenSeesPy 3.8 needs Python >= 3.12; looked for \$OPENSEES_PYTHON, python3.13, python3.12, python3 on PATH and $pyenv_root/versions/3.12+ and found none (install one, or set OPENSEES_PYTHON)" >&2
  return 1
}

# --can-run: say whether this machine can regenerate (a built venv, or a Python >= 3.12), build
# nothing, exit 0 or 1.
if [ "${1:-}" = "--can-run" ]; then
  if [ -x "$venv/bin/python" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$want" ]; then
    echo "OpenSees venv ready in $venv"; exit 0
  fi
  python="$(find_python 2>&1)" || { echo "$python"; exit 1; }
  echo "$python ($("$python" --version 2>&1)) found: the venv can be built"; exit 0
fi

if [ ! -x "$venv/bin/python" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  python="$(find_python)"
  echo "== building the OpenSees venv in $venv with $python ($("$python" --version 2>&1)), pinned requirements.txt"
  rm -rf "$venv"
  "$python" -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$here/requirements.txt"
  echo "$want" > "$stamp"
fi
# The driver takes each case's mesh, times and step from courant's exact answers.
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
exec "$venv/bin/python" "$here/driver.py" --courant "${CARGO_TARGET_DIR:-$root/target}/release/courant" "$@"
