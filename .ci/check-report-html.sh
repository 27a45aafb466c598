#!/usr/bin/env bash
# Render the report's index.html in a real headless browser (Debian's chromium) at the widths a
# reviewer uses and check what they see: the first-screen summary is there with a row per scene
# and study, every in-page link lands on an element of the page, every data table sits in a
# scrolling box, nothing makes the page itself wider than the window, and every verdict and run
# status is in view: each table that has one leads with it, each such cell lies within the window
# without scrolling sideways, and only passing words are folded away. Screenshots of the
# first screen go beside the report copy for a human look.
#
#   .ci/check-report-html.sh REPORT_DIR [OUT_DIR]
#
# Exit status 0 when every check holds at every width, 1 otherwise.
set -euo pipefail
report=${1:?usage: check-report-html.sh REPORT_DIR [OUT_DIR]}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "check-report-html: no chromium; install Debian's package chromium" >&2
  exit 1
fi
page="$(realpath "$report")/_check.html"
trap 'rm -f "$page"' EXIT
# The report with a script that measures the laid-out page and writes the result into it.
python3 - "$report/index.html" "$page" <<'PY'
import sys
html = open(sys.argv[1], encoding="utf-8").read()
probe = """
<script>
window.addEventListener('load', () => {
  const problems = [];
  const summary = document.querySelector('table.summary');
  const rows = summary ? summary.querySelectorAll('tr').length - 1 : 0;
  if (rows < 10) problems.push('summary table has ' + rows + ' rows');
  for (const a of document.querySelectorAll('a[href^="#"]')) {
    const id = decodeURIComponent(a.getAttribute('href').slice(1));
    if (!document.getElementById(id)) problems.push('link to missing #' + id);
  }
  for (const t of document.querySelectorAll('table')) {
    const box = t.parentElement;
    if (!box.classList.contains('table-wrap')) problems.push('table outside a scrolling box');
  }
  // Every verdict in view: a table that states a verdict or status leads with it, and each
  // such cell lies inside the window without scrolling sideways, unless it is folded away, which
  // only a passing word may be.
  const status = ['verdict', 'status', 'agrees'];
  const passing = ['pass', 'yes', 'completed', '-'];
  let verdicts = 0;
  const section = t => {
    let n = t.closest('.table-wrap') || t;
    n = n.closest('details') || n;
    while (n && !/^H[1-4]$/.test(n.tagName)) n = n.previousElementSibling;
    return n ? n.textContent : '?';
  };
  for (const t of document.querySelectorAll('table')) {
    const head = [...(t.rows[0] ? t.rows[0].cells : [])].map(c => c.textContent.trim());
    const columns = head.map((h, i) => status.includes(h) ? i : -1).filter(i => i >= 0);
    if (!columns.length) continue;
    const where = section(t);
    if (!status.includes(head[0])) problems.push('table in ' + where + ' leads with ' + head[0] + ', not its ' + head[columns[0]]);
    for (const row of [...t.rows].slice(1)) {
      for (const i of columns) {
        const cell = row.cells[i];
        if (!cell) continue;
        verdicts++;
        const text = cell.textContent.trim();
        if (cell.closest('details:not([open])')) {
          if (!passing.includes(text)) problems.push('"' + text + '" folded away in ' + where);
          continue;
        }
        const r = cell.getBoundingClientRect();
        if (r.right > window.innerWidth + 1 || r.left < 0)
          problems.push('"' + text + '" off-screen (' + Math.round(r.left) + '-' + Math.round(r.right) + ' px) in ' + where);
      }
    }
  }
  const doc = document.documentElement;
  if (doc.scrollWidth > window.innerWidth + 1)
    problems.push('page ' + doc.scrollWidth + ' px wide in a ' + window.innerWidth + ' px window');
  for (const f of document.querySelectorAll('figure svg')) {
    if (f.getBoundingClientRect().width > doc.clientWidth + 1) problems.push('figure wider than the page');
  }
  const pre = document.createElement('pre');
  pre.id = 'probe-result';
  pre.textContent = JSON.stringify({rows, links: document.querySelectorAll('a[href^="#"]').length,
    tables: document.querySelectorAll('table').length, verdicts, problems: problems.slice(0, 20),
    problem_count: problems.length});
  document.body.appendChild(pre);
});
</script>
"""
open(sys.argv[2], "w", encoding="utf-8").write(html.replace("</body>", probe + "</body>"))
PY
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run
       --disable-background-networking --disable-component-update --disable-sync
       --user-data-dir="$out/profile")
status=0
for width in 1400 1920; do
  dom=$(timeout 120 "$browser" "${flags[@]}" --window-size="$width,1000" \
        --virtual-time-budget=5000 --dump-dom "file://$page" 2>/dev/null)
  result=$(printf '%s' "$dom" | python3 -c '
import sys, re, json, html
m = re.search(r"<pre id=\"probe-result\">(.*?)</pre>", sys.stdin.read(), re.S)
print(html.unescape(m.group(1)) if m else json.dumps({"problems": ["probe did not run"]}))')
  echo "width $width: $result"
  if ! printf '%s' "$result" | python3 -c 'import sys, json; sys.exit(1 if json.load(sys.stdin)["problems"] else 0)'; then
    status=1
  fi
  timeout 120 "$browser" "${flags[@]}" --window-size="$width,1600" \
    --screenshot="$out/first-screen-$width.png" "file://$(realpath "$report")/index.html" \
    >/dev/null 2>&1 || true
done
echo "screenshots: $out/first-screen-*.png"
exit $status
