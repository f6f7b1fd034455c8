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
# A polygon of 40 corners around (x, y) with radius r, as JSON.
circle() {
  awk -v x="$1" -v y="$2" -v r="$3" 'BEGIN { printf "["; for (i = 0; i < 40; i++) {
    a = i * 3.14159265358979 / 20; printf "%s[%.1f, %.1f]", (i ? ", " : ""), x + r * cos(a), y + r * sin(a) }
    printf "]" }'
}
# Fig. 17b: a night sky for the mountains and clouds: dark sand strata filling
# most of the window and mirrored over the rest (render.symmetric), a few
# light grains as stars, and a bright moon as a figure (drawn in C1/C2, here
# set to the moon's colours).
"$BIN" render -o examples/inputs/fig17-moon.png --seed 3 --set region.height=560 \
  --set init.dominant_share=0.996 --set render.symmetric=true \
  --set 'grains.diameter_mm=[0.2, 0.2, 0.2, 0.2]' --set 'grains.proportions=[0, 0, 0.5, 0.5]' \
  --set init.tessellation=strips --set init.row_height_min=10 --set init.row_height_max=40 \
  --set segment.semi_major_min=200 --set segment.semi_major_max=300 \
  --set segment.eccentricity_min=0.97 --set segment.eccentricity_max=0.99 \
  --set 'grains.colors=["#fbf6dc", "#e8dfb0", "#141c33", "#22304f"]' --set 'render.background_color="#0d1326"' \
  --set "render.figures=[{\"polygon\": $(circle 780 130 48)}]"
# Fig. 15c: a sunset for the mountains in sunset: warm strata mirrored over
# the window and a low sun as a figure.
"$BIN" render -o examples/inputs/fig15-sunset.png --seed 4 --set region.height=560 \
  --set init.dominant_share=0.9 --set render.symmetric=true \
  --set 'grains.diameter_mm=[0.2, 0.2, 0.2, 0.2]' --set 'grains.proportions=[0, 0, 0.5, 0.5]' \
  --set init.tessellation=strips --set init.row_height_min=14 --set init.row_height_max=50 \
  --set segment.semi_major_min=250 --set segment.semi_major_max=400 \
  --set segment.eccentricity_min=0.98 --set segment.eccentricity_max=0.99 \
  --set 'grains.colors=["#fff1b8", "#ffd36e", "#e9744a", "#f4a259"]' --set 'render.background_color="#f7c59f"' \
  --set "render.figures=[{\"polygon\": $(circle 500 190 80)}]"
