#!/usr/bin/env bash
# Renders the README's gallery with the tool itself: the default scene, its
# Fig. 2 stages, and every example, into examples/gallery/.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${1:-build/sandpic}
OUT=examples/gallery
mkdir -p "$OUT" "$OUT/stages"
"$BIN" render -o "$OUT/default.png" --stages "$OUT/stages"
for scene in examples/*.json; do
  "$BIN" render "$scene" -o "$OUT/$(basename "$scene" .json).png"
done
for mu in 0.1 0.4 0.9; do
  "$BIN" render examples/three-mountains.json -o "$OUT/friction-$mu.png" --scale 0.5 --set physics.friction=$mu
done
"$BIN" render examples/fig07.json -o "$OUT/fig07-plain.png" --set segment.sketch.narrow=false
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
"$BIN" render examples/fig07.json -o "$TMP/fig07.png" --stages "$TMP"
cp "$TMP/3-segmentation.png" "$OUT/stages/fig07-segmentation.png"
"$BIN" render examples/fig18.json -o "$OUT/fig18-fallen.png" --set render.symmetric=false
for fig in fig17 fig18; do
  "$BIN" render examples/$fig.json -o "$TMP/$fig.png" --stages "$TMP"
  cp "$TMP/3-segmentation.png" "$OUT/stages/$fig-segmentation.png"
done
