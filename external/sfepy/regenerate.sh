#!/usr/bin/env bash
# Regenerate SfePy's results for courant's fig1 and fig1_masses scenes, by default into
# external/sfepy/results/<scene>/ (the committed ones). Arguments go to driver.py, e.g.
#   bash external/sfepy/regenerate.sh                                   # rewrite the committed results
#   bash external/sfepy/regenerate.sh --out /tmp/fresh --compare-with external/sfepy/results
# The venv is $SFEPY_VENV (default target/sfepy-venv, outside git), built from requirements.txt
# when missing or when requirements.txt changed (about 2 minutes: SfePy compiles from source).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
venv="${SFEPY_VENV:-$root/target/sfepy-venv}"
stamp="$venv/.requirements.sha256"
want="$(sha256sum "$here/requirements.txt" | cut -d' ' -f1)"
if [ ! -x "$venv/bin/python" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  echo "== building the SfePy venv in $venv (pinned requirements.txt)"
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$here/requirements.txt"
  echo "$want" > "$stamp"
fi
exec "$venv/bin/python" "$here/driver.py" "$@"
