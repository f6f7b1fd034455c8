#!/usr/bin/env bash
# validate on a small scene, end to end with the DEM, and its
# report opened in headless Chromium (no network): a screenshot, and no
# console errors. A report with a broken picture must log one (so the check
# can fail).
# Usage: test_report_html.sh SANDPIC_BINARY
set -u
BIN=$1
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
CHROMIUM=$(command -v chromium || command -v chromium-browser) || fail "chromium is not installed (scripts/setup.sh installs it)"

"$BIN" validate --scale 0.0845 --sweep both --all-dynamic-max 0 --out "$T/v" >"$T/out" 2>"$T/err" ||
  fail "validate: exit $?: $(cat "$T/err")"
for f in report.html report.json lattice.png difference.png runs/dem-seed-1.png runs/dem-seed-5.png; do
  [ -s "$T/v/$f" ] || fail "validate wrote no $f"
done
for k in '"silhouette_error_ratio"' '"time_ratio"' '"noise_floor"' '"dem.layers=bcre"' '"lattice.resolution=2"' 'all-dynamic skipped'; do
  grep -q -- "$k" "$T/v/report.json" || fail "report.json lacks $k"
done
grep -q "silhouette_error" "$T/out" || fail "no metrics table on stdout: $(cat "$T/out")"
[ -s "$T/err" ] && fail "stderr not quiet off a terminal: $(cat "$T/err")"

# Again in the same folder: the DEM runs are kept, not rerun.
"$BIN" validate --scale 0.0845 --sweep none --out "$T/v" >/dev/null 2>"$T/err" || fail "validate again: $(cat "$T/err")"
[ "$(grep -c '"cached": true' "$T/v/report.json")" = 5 ] || fail "the five DEM runs were not reused"

shoot() {  # shoot PAGE SCREENSHOT LOG
  HOME="$T" timeout 180 "$CHROMIUM" --headless --no-sandbox --disable-gpu --no-first-run --no-default-browser-check \
    --user-data-dir="$T/profile" --window-size=1400,2400 --screenshot="$2" --enable-logging=stderr --v=0 \
    "file://$1" >/dev/null 2>"$3"
}
shoot "$T/v/report.html" "$T/shot.png" "$T/chrome.log" || fail "chromium: exit $?: $(tail -5 "$T/chrome.log")"
[ -s "$T/shot.png" ] || fail "no screenshot"
if grep -q "CONSOLE" "$T/chrome.log"; then fail "console messages: $(grep CONSOLE "$T/chrome.log")"; fi

sed 's|data:image/png;base64,|data:image/png;base64,AAAA|' "$T/v/report.html" >"$T/broken.html"
shoot "$T/broken.html" "$T/broken.png" "$T/broken.log"
grep -q "picture failed" "$T/broken.log" || fail "a broken picture logged nothing: the console check cannot fail"
echo "report: validate, reuse, screenshot and console check passed"
