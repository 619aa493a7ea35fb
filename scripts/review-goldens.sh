#!/usr/bin/env bash
# Reviews every golden comparison in one page (docs/app.md, "Reviewing the goldens").
#   scripts/review-goldens.sh [OUT]     (default OUT: <build>/review)
# Runs each demo's (tests/golden/<id>/) and each shipped scene file's (tests/golden/scenes/<name>/) golden
# comparison with its run.args, then writes OUT/index.html: one self-contained page (images inline, no network)
# with a summary table (case, frames, pass/fail, worst pixel fraction, worst SSIM), each failing frame's
# expected, actual and amplified diff side by side with its pixel count and SSIM, and the renderer (GL vendor,
# renderer, version) that made each side. Exit 0 when every case passes, 1 when any fails, 2 on bad usage.
# Environment: PSB_BUILD (build tree, default build), PSB_GOLDENS (golden root, default tests/golden).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PSB_BUILD:-$repo/build}"
goldens="${PSB_GOLDENS:-$repo/tests/golden}"
exe="$build/physics-sandbox"

if [ $# -gt 1 ] || [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
out="${1:-$build/review}"
if [ ! -x "$exe" ]; then
  echo "review-goldens: $exe not found; build first (cmake --build $build --target physics-sandbox) or set PSB_BUILD" >&2
  exit 2
fi
if [ ! -d "$goldens" ]; then
  echo "review-goldens: golden root $goldens is not a directory" >&2
  exit 2
fi
mkdir -p "$out"
out="$(cd "$out" && pwd)"
rm -rf "$out/cases" "$out/index.html"
mkdir -p "$out/cases"

# The cases: every registered demo and every shipped scene file, whether or not it has goldens (a case without
# them fails).
cases=()
while IFS=$'\t' read -r id _; do cases+=("demo:$id"); done < <("$exe" --list)
for f in "$repo"/scenes/*.json; do
  name=${f##*/}
  name=${name%.json}
  case $name in *.schema) continue ;; esac
  cases+=("scene:$name")
done

html_escape() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g' -e 's/"/\&quot;/g'; }
inline_png() { printf 'data:image/png;base64,%s' "$(base64 -w0 "$1")"; }

# One compare.txt frame line -> "name|fraction%|ssim|verdict|pixels" ("-" where the line has no such number;
# pixels: "N of T").
frame_fields() {
  awk -F': ' '{
    name = $1; rest = substr($0, length($1) + 3)
    frac = "-"; ssim = "-"; verdict = "FAIL"; pixels = "-"
    if (rest ~ /^exact/) { frac = "0"; ssim = "1"; verdict = "pass"; pixels = "0" }
    else {
      if (match(rest, /[0-9]+ of [0-9]+ pixels/)) pixels = substr(rest, RSTART, RLENGTH - 7)
      if (match(rest, /\([0-9.]+%\)/)) frac = substr(rest, RSTART + 1, RLENGTH - 3)
      if (match(rest, /SSIM -?[0-9.]+/)) ssim = substr(rest, RSTART + 5, RLENGTH - 5)
      if (rest ~ /: pass on SSIM$/) verdict = "pass on SSIM"
      else if (rest ~ /: pass$/) verdict = "pass"
    }
    printf "%s|%s|%s|%s|%s\n", name, frac, ssim, verdict, pixels
  }'
}

summary_rows=""
details=""
renderers=""  # "golden|actual" per case, for the page's renderer note
failed=0
for c in "${cases[@]}"; do
  kind=${c%%:*}
  name=${c#*:}
  if [ "$kind" = demo ]; then
    dir="$goldens/$name"
    what=(--demo "$name")
  else
    dir="$goldens/scenes/$name"
    what=(--scene "$repo/scenes/$name.json")
  fi
  label="$kind $name"
  run_out="$out/cases/$kind-$name"
  status="pass"
  problem=""
  frames=0
  worst_frac="-"
  worst_ssim="-"
  frame_lines=""
  golden_renderer="unrecorded"
  actual_renderer="-"
  if [ ! -f "$dir/run.args" ]; then
    status="FAIL"
    problem="no goldens: ${dir#"$repo"/}/run.args is missing"
  else
    mapfile -t args < "$dir/run.args"
    set +e
    "$exe" "${what[@]}" "${args[@]}" --compare "$dir" --out "$run_out" --quiet 2> "$out/cases/$kind-$name.stderr"
    code=$?
    set -e
    [ -f "$dir/renderer.txt" ] && golden_renderer=$(head -n 1 "$dir/renderer.txt")
    if [ -f "$run_out/compare.txt" ]; then
      actual_renderer=$(sed -n 's/^renderer: //p' "$run_out/compare.txt" | head -n 1)
      frame_lines=$({ grep -E '^frame_[0-9]+\.png: ' "$run_out/compare.txt" || true; } | frame_fields)
    fi
    if [ "$code" -ne 0 ]; then
      status="FAIL"
      [ "$code" -ne 1 ] && problem="exit $code: $(tail -n 3 "$out/cases/$kind-$name.stderr" | tr '\n' ' ')"
    fi
  fi
  if [ -n "$frame_lines" ]; then
    frames=$(printf '%s\n' "$frame_lines" | wc -l)
    worst_frac=$(printf '%s\n' "$frame_lines" | awk -F'|' '$2 != "-" && (w == "" || $2 + 0 > w + 0) {w = $2} END {print (w == "" ? "-" : w "%")}')
    worst_ssim=$(printf '%s\n' "$frame_lines" | awk -F'|' '$3 != "-" && (w == "" || $3 + 0 < w + 0) {w = $3} END {print (w == "" ? "-" : w)}')
  fi
  [ "$status" = FAIL ] && failed=1
  renderers+="$golden_renderer|$actual_renderer"$'\n'
  esc_label=$(printf '%s' "$label" | html_escape)
  summary_rows+="<tr class=\"case ${status,,}\" data-case=\"$esc_label\"><td><a href=\"#$kind-$name\">$esc_label</a></td>"
  summary_rows+="<td>$frames</td><td class=\"verdict\">$status</td><td>$worst_frac</td><td>$worst_ssim</td></tr>"$'\n'

  [ "$status" = pass ] && continue
  details+="<section class=\"failure\" id=\"$kind-$name\"><h2>$esc_label</h2>"
  details+="<p class=\"renderer\">golden made by: $(printf '%s' "$golden_renderer" | html_escape)<br>"
  details+="actual made by: $(printf '%s' "$actual_renderer" | html_escape)</p>"
  [ -n "$problem" ] && details+="<p class=\"problem\">$(printf '%s' "$problem" | html_escape)</p>"
  while IFS='|' read -r frame frac ssim verdict pixels; do
    [ -n "$frame" ] || continue
    case $verdict in pass*) continue ;; esac
    stem="$run_out/mismatch/${frame%.png}"
    line=$(grep -F "$frame: " "$run_out/compare.txt" | head -n 1 | html_escape)
    details+="<div class=\"frame\"><h3>$frame: $pixels pixels beyond the tolerance ($frac%), SSIM $ssim</h3><p>$line</p><div class=\"row\">"
    for part in expected actual amplified; do
      caption=$part
      [ "$part" = amplified ] && caption="diff (|expected - actual| x 16)"
      if [ -f "$stem.$part.png" ]; then
        details+="<figure class=\"$part\"><img class=\"$part\" alt=\"$frame $part\" src=\"$(inline_png "$stem.$part.png")\"><figcaption>$caption</figcaption></figure>"
      else
        details+="<figure class=\"$part missing\"><figcaption>$caption: not written (no decodable golden)</figcaption></figure>"
      fi
    done
    details+="</div></div>"$'\n'
  done <<< "$frame_lines"
  details+="</section>"$'\n'
done

total=${#cases[@]}
failures=$(printf '%s' "$summary_rows" | grep -c 'class="case fail"' || true)
renderer_note() {  # the distinct renderers of one side (field 1 golden, 2 actual), one list item each
  printf '%s' "$renderers" | cut -d'|' -f"$1" | grep -vx -- '-' | sort -u | html_escape | sed 's|.*|<li>&</li>|'
}
{
  cat <<EOF
<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>Golden review: $failures of $total cases fail</title>
<style>
body { font-family: sans-serif; margin: 1.5em; }
table { border-collapse: collapse; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: left; }
tr.fail td.verdict { color: #b00; font-weight: bold; }
tr.pass td.verdict { color: #070; }
.row { display: flex; gap: 1em; flex-wrap: wrap; }
figure { margin: 0; }
img { max-width: 30vw; border: 1px solid #888; image-rendering: pixelated; }
.renderer, .problem { font-family: monospace; }
</style>
</head>
<body>
<h1>Golden review</h1>
<p id="verdict">$failures of $total cases fail. Build: $(printf '%s' "$build" | html_escape); goldens: $(printf '%s' "$goldens" | html_escape).
Pixel fraction: pixels with a channel beyond the tolerance; SSIM: luminance, 8x8 windows (docs/app.md).</p>
<div id="renderers"><p>Goldens made by (renderer.txt beside them):</p><ul>
$(renderer_note 1)
</ul><p>This run's frames made by:</p><ul>
$(renderer_note 2)
</ul></div>
<table id="summary">
<thead><tr><th>case</th><th>frames</th><th>result</th><th>worst pixel fraction</th><th>worst SSIM</th></tr></thead>
<tbody>
$summary_rows</tbody>
</table>
$details
</body>
</html>
EOF
} > "$out/index.html"
echo "review-goldens: $failures of $total cases fail; see $out/index.html"
exit $failed
