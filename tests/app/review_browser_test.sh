#!/usr/bin/env bash
# The golden review page (scripts/review-goldens.sh) in a real browser: Debian's headless Chromium. With one
# golden forced to mismatch (ch15's frame 30 replaced by another 640x480 frame), the review must exit 1; the page
# must load with no console message, its summary must list every demo and scene file with only the forced case
# failing, and that case must show its expected, actual and amplified-diff images decoded at 640x480. The
# screenshot stays in WORK/screenshot.png. Exit 77 (skipped) when Chromium is not installed.
# Usage: review_browser_test.sh REPO BUILD WORK
set -uo pipefail
repo=$1
build=$2
work=$3

chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
  echo "review.browser: skipped: Chromium is not installed (Debian package chromium, scripts/install-deps.sh)"
  exit 77
fi
fail() {
  echo "review.browser: FAIL: $*"
  exit 1
}

rm -rf "$work"
mkdir -p "$work"
cp -r "$repo/tests/golden" "$work/goldens"
cp "$work/goldens/ch14/frame_00060.png" "$work/goldens/ch15/frame_00030.png"  # the forced mismatch

PSB_BUILD=$build PSB_GOLDENS=$work/goldens bash "$repo/scripts/review-goldens.sh" "$work/report" > "$work/review.log" 2>&1
code=$?
[ "$code" -eq 1 ] || fail "review-goldens.sh exited $code, expected 1 (a forced mismatch): $(tail -n 5 "$work/review.log")"
[ -s "$work/report/index.html" ] || fail "no $work/report/index.html"

flags=(--headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update
  --disable-sync --no-first-run "--user-data-dir=$work/profile" --enable-logging=stderr --v=0
  --virtual-time-budget=5000)

# 1. The page itself: a screenshot, and no console message of any level while it loads.
timeout 120 "$chromium" "${flags[@]}" --window-size=1400,2400 "--screenshot=$work/screenshot.png" \
  "file://$work/report/index.html" > /dev/null 2> "$work/chromium-page.log" || fail "chromium exited $? on the page"
[ -s "$work/screenshot.png" ] || fail "no screenshot"
if grep -E ':CONSOLE' "$work/chromium-page.log"; then fail "console messages while loading the page"; fi

# 2. Its DOM once loaded, with tests/app/review_check.js appended to a copy (not part of the report): each image
#    of a failing case as "<case id> <role> <decoded width>x<height> whole|partial|empty".
{
  sed -e 's|</body>||' -e 's|</html>||' "$work/report/index.html"
  printf '<script>\n'
  cat "$(dirname "$0")/review_check.js"
  printf '</script>\n</body>\n</html>\n'
} > "$work/report/check.html"
timeout 120 "$chromium" "${flags[@]}" --dump-dom "file://$work/report/check.html" > "$work/dom.html" \
  2> "$work/chromium-dom.log" || fail "chromium exited $? dumping the DOM"
if grep -E ':CONSOLE' "$work/chromium-dom.log"; then fail "console messages while checking the images"; fi

cases=()
while IFS=$'\t' read -r id _; do cases+=("demo $id"); done < <("$build/physics-sandbox" --list)
for f in "$repo"/scenes/*.json; do
  name=${f##*/}
  name=${name%.json}
  case $name in *.schema) continue ;; esac
  cases+=("scene $name")
done
[ ${#cases[@]} -ge 10 ] || fail "only ${#cases[@]} cases listed"
for c in "${cases[@]}"; do
  want="pass"
  [ "$c" = "demo ch15" ] && want="fail"
  grep -qF "<tr class=\"case $want\" data-case=\"$c\">" "$work/dom.html" || fail "summary: no $want row for '$c'"
done
rows=$(grep -c '<tr class="case ' "$work/dom.html")
[ "$rows" -eq ${#cases[@]} ] || fail "summary has $rows rows for ${#cases[@]} cases"

images=$(sed -n '/<pre id="image-check">/,/<\/pre>/p' "$work/dom.html" | sed -e 's/<[^>]*>//g' | grep -v '^$')
expected=$'demo-ch15 expected 640x480 whole\ndemo-ch15 actual 640x480 whole\ndemo-ch15 amplified 640x480 whole'
[ "$images" = "$expected" ] || fail "images of the failing case: got '$images', expected '$expected'"
echo "review.browser: ${#cases[@]} cases listed, the forced mismatch shows its 3 images; screenshot $work/screenshot.png"
