#!/usr/bin/env bash
# Makes the input pictures of examples/ with sandpic itself (paper §10 takes a
# sand picture as the input of another): never downloaded.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${1:-build/sandpic}
# A 1000x350 sand picture, the size of the default initialization region.
"$BIN" render -o examples/inputs/sand-picture.png --seed 11 \
  --set window.height=350 --set region.height=160 --set segment.semi_major_max=110 \
  --set 'grains.colors=["#202020", "#6a6a6a", "#b0b0b0", "#f4f4f4"]' --set 'render.background_color="#d8d8d8"'
# Fig. 14a: the sketch of fig07.json as a picture (ridge lines red, arcs green),
# as a designer would paint it.
"$BIN" sketch examples/fig07.json -o examples/inputs/fig14-sketch.png
# Fig. 14f: a background for the emptied upper part: a pale, far range under a sky.
"$BIN" render -o examples/inputs/fig14-background.png --seed 5 --set region.height=520 \
  --set segment.semi_major_max=260 --set segment.semi_major_min=120 --set physics.friction=0.3 \
  --set 'grains.colors=["#7f93a8", "#97abbe", "#b4c6d6", "#d2dfea"]' --set 'render.background_color="#dcebf6"'
