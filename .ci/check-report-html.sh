#!/usr/bin/env bash
# Render the report's index.html in a real headless browser (Debian's chromium) at the widths a
# reviewer uses and check what they see: the first-screen summary is there with a row per scene
# and study, every in-page link lands on an element of the page, every data table sits in a
# scrolling box, nothing makes the page itself wider than the window, and every verdict and run
# status is in view: each table that has one leads with it, each such cell lies within the window
# without scrolling sideways, and only passing words are folded away; and in every SVG figure of
# the report no two legend entries are drawn alike. Screenshots of the
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
# Distinct colours per figure: no two legend entries of a chart drawn alike (same colour and
# same line kind: solid, dashed or points); a curve and its dashed closed form may share a colour.
legend_status=0
python3 - "$report" <<'PY' || legend_status=1
import glob, os, re, sys
def legend(svg):
    i = svg.find('opacity="0.85" fill="#FFFFFF"')
    if i < 0:
        return []
    body = svg[i:]
    texts = [(float(m.group(1)), m.group(2).strip()) for m in
             re.finditer(r'<text x="[\d.]+" y="([\d.]+)"[^>]*>\s*([^<]*)</text>', body)]
    glyphs = {}
    for m in re.finditer(r'<(polyline|circle)([^>]*)/>', body):
        a = m.group(2)
        colour = re.search(r'stroke="(#[0-9A-Fa-f]+)"', a)
        y = re.search(r'points="[\d.]+,([\d.]+)' if m.group(1) == 'polyline' else r'cy="([\d.]+)"', a)
        if not (texts and y):
            continue
        y = float(y.group(1))
        near = min(texts, key=lambda t: abs(t[0] + 6 - y))
        if abs(near[0] + 6 - y) < 9:
            glyphs.setdefault(near[1], []).append((m.group(1), colour.group(1) if colour else None))
    out = []
    for _, name in texts:
        g = glyphs.get(name, [])
        kind = ('dashed' if sum(k == 'polyline' for k, _ in g) > 1
                else 'points' if any(k == 'circle' for k, _ in g) else 'line')
        out.append((name, tuple(sorted({c for _, c in g if c})), kind))
    return out
clashes = []
for f in sorted(glob.glob(os.path.join(sys.argv[1], '**', '*.svg'), recursive=True)):
    seen = {}
    for name, colours, kind in legend(open(f, encoding='utf-8').read()):
        if colours and (colours, kind) in seen:
            clashes.append(f'{os.path.relpath(f, sys.argv[1])}: "{seen[(colours, kind)]}" and "{name}" drawn alike')
        seen.setdefault((colours, kind), name)
print('figures: ' + (', '.join(clashes[:10]) if clashes else 'every legend entry drawn distinctly'))
sys.exit(1 if clashes else 0)
PY
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run
       --disable-background-networking --disable-component-update --disable-sync
       --user-data-dir="$out/profile")
status=$legend_status
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
