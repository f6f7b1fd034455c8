#!/usr/bin/env bash
# Renders every example scene at full size (or --scale F) in the lattice
# mode, the DEM mode or both, with stats, into one folder:
#   scripts/render-examples.sh [--mode lattice|dem|both] [--scale F] [--out DIR] [-- RENDER OPTIONS]
# At full size a DEM render is ~350,000 grains: hours each (README, DEM mode).
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${BIN:-build/sandpic}
MODE=both SCALE=1 OUT=renders
while [ $# -gt 0 ]; do
  case "$1" in
    --mode) MODE=$2; shift 2 ;;
    --scale) SCALE=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "render-examples: unknown option '$1'" >&2; exit 2 ;;
  esac
done
case "$MODE" in
  both) MODES="lattice dem" ;;
  lattice|dem) MODES=$MODE ;;
  *) echo "render-examples: --mode must be lattice, dem or both, got '$MODE'" >&2; exit 2 ;;
esac
mkdir -p "$OUT"
status=0
for scene in examples/*.json; do
  name=$(basename "$scene" .json)
  for mode in $MODES; do
    start=$(date +%s)
    if "$BIN" render "$scene" --mode "$mode" --scale "$SCALE" -o "$OUT/$name-$mode.png" \
        --stats "$OUT/$name-$mode.json" "$@"; then
      echo "$name $mode: $(( $(date +%s) - start )) s"
    else
      rc=$?
      echo "$name $mode: FAILED (exit $rc)"
      status=1
    fi
  done
done
exit $status
