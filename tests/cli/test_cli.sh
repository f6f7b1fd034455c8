#!/usr/bin/env bash
# The CLI as a user runs it: exit codes, one-line errors that name the key or
# file, outputs written whole or not at all, same seed = same bytes.
# Usage: test_cli.sh SANDPIC_BINARY PROJECT_ROOT with-bullet|without-bullet
set -u
BIN=$1
ROOT=$2
BULLET=${3:-with-bullet}
source "$(dirname "$0")/checks.sh"

# A complete render at quarter scale, with stats and stages.
expect 0 "render" -- "$BIN" render -o "$T/a.png" --scale 0.25 --stats "$T/s.json" --stages "$T/stages"
is_png "$T/a.png"
if [ ! -s "$T/err" ]; then ok; else bad "stderr not quiet off a terminal: $(cat "$T/err")"; fi
for k in '"mode": "lattice"' '"in_picture": 22000' '"total": 22000' '"per_class"' '"simulate_s"' '"total_s"'; do
  if grep -q -- "$k" "$T/s.json"; then ok; else bad "stats lack $k"; fi
done
for f in 1-initialization 2-filled 3-segmentation 4-falling-order 5-picture; do is_png "$T/stages/$f.png"; done

# Same seed, same bytes, at any thread count; another seed, another picture.
expect 0 "render again" -- "$BIN" render -o "$T/b.png" --scale 0.25 --threads 1
if cmp -s "$T/a.png" "$T/b.png"; then ok; else bad "same seed gave other bytes"; fi
expect 0 "other seed" -- "$BIN" render -o "$T/c.png" --scale 0.25 --seed 7

# A key the mode never reads is named (a warning; with --strict exit 2 and
# nothing written), and the picture is the default's; an explicit key wins
# over the one --seed derives.
expect 0 "unread key" -- "$BIN" render -o "$T/u.png" --scale 0.25 --set dem.cycle_steps=20
one_line; err_has "warning: scene key 'dem.cycle_steps' is not read in lattice mode"
if cmp -s "$T/a.png" "$T/u.png"; then ok; else bad "an unread key changed the picture"; fi
expect 2 "unread key strict" -- "$BIN" render -o "$T/u2.png" --scale 0.25 --set dem.cycle_steps=20 --strict
one_line; err_has "dem.cycle_steps"; absent "$T/u2.png"
"$BIN" scene >"$T/every-key.json"
expect 0 "every key at its default" -- "$BIN" render "$T/every-key.json" -o "$T/u3.png" --scale 0.25 --strict
if [ ! -s "$T/err" ]; then ok; else bad "a scene of defaults warned: $(cat "$T/err")"; fi
expect 0 "explicit physics seed" -- "$BIN" render -o "$T/ps1.png" --scale 0.25 --seed 1 --set physics_seed=2
expect 0 "physics seed option" -- "$BIN" render -o "$T/ps2.png" --scale 0.25 --seed 1 --physics-seed 2
if cmp -s "$T/ps1.png" "$T/ps2.png" && ! cmp -s "$T/ps1.png" "$T/a.png"; then ok
else bad "--set physics_seed=2 after --seed 1 was not the picture of physics seed 2"; fi

# compare: JSON with every measure; a picture with itself is identical.
expect 0 "compare" -- "$BIN" compare "$T/a.png" "$T/c.png" --json
for k in '"ssim"' '"scene_slope_deg"' '"heap_angle_deg"' '"psnr_db"' '"silhouette_error"' '"composition_error"' '"composition_error_per_band"' '"ssim_blurred"'; do
  if grep -q -- "$k" "$T/out"; then ok; else bad "compare JSON lacks $k: $(cat "$T/out")"; fi
done
if grep -q '"identical": false' "$T/out"; then ok; else bad "two seeds compared as identical"; fi
expect 0 "compare itself" -- "$BIN" compare "$T/a.png" "$T/b.png" --json
if grep -q '"identical": true' "$T/out" && grep -q '"ssim": 1.0' "$T/out"; then ok; else bad "same picture: $(cat "$T/out")"; fi
expect 2 "compare other sizes" -- "$BIN" compare "$T/a.png" "$ROOT/tests/fixtures/compare/ramp.png"
one_line; err_has "ramp.png"
expect 2 "compare missing" -- "$BIN" compare "$T/a.png" "$T/none.png"
one_line; err_has "none.png"
if ! cmp -s "$T/a.png" "$T/c.png"; then ok; else bad "another seed gave the same picture"; fi
# For scripts: an error picture, and tolerances that exit 1 when passed.
expect 1 "compare beyond tolerance" -- "$BIN" compare "$T/a.png" "$T/c.png" --diff "$T/diff.png" \
  --tolerance silhouette_error=0.0001 --tolerance ssim=0.1
one_line; err_has "silhouette_error"; is_png "$T/diff.png"
if grep -q "ssim" "$T/err"; then bad "ssim was within its bound: $(cat "$T/err")"; else ok; fi
expect 0 "compare within tolerance" -- "$BIN" compare "$T/a.png" "$T/b.png" --tolerance silhouette_error=0 \
  --tolerance psnr_db=60 --diff "$T/same.png"
is_png "$T/same.png"
expect 2 "compare bad tolerance" -- "$BIN" compare "$T/a.png" "$T/c.png" --tolerance ssim --diff "$T/nodiff.png"
one_line; err_has "--tolerance 'ssim'"; absent "$T/nodiff.png"
expect 2 "compare unknown metric" -- "$BIN" compare "$T/a.png" "$T/c.png" --tolerance psnr=30
one_line; err_has "psnr=30"

# Pictures in other colours than the scene's: never zeros, a clear error.
expect 0 "fig16 render" -- "$BIN" render "$ROOT/examples/fig16.json" -o "$T/f16a.png" --scale 0.25
expect 0 "fig16 render, other fall" -- "$BIN" render "$ROOT/examples/fig16.json" -o "$T/f16b.png" --scale 0.25 --physics-seed 2
expect 2 "compare without the scene" -- "$BIN" compare "$T/f16a.png" "$T/f16b.png"
one_line; err_has "f16a.png"; err_has "--scene"
expect 0 "compare with the scene" -- "$BIN" compare "$T/f16a.png" "$T/f16b.png" --scene "$ROOT/examples/fig16.json" --json
if grep -q '"silhouette_error": 0.0,' "$T/out"; then bad "fig16 silhouette error 0: $(cat "$T/out")"; else ok; fi

# Every grain's release point and resting place as CSV, and two
# runs compared grain by grain; bad tables and paths are named, nothing written.
expect 0 "render grains" -- "$BIN" render -o "$T/g1.png" --scale 0.25 --grains "$T/g1.csv"
if [ "$(head -1 "$T/g1.csv")" = "id,class,unit,order,release_x,x,y" ] && [ "$(wc -l <"$T/g1.csv")" = 22001 ]; then ok
else bad "grain table: $(head -2 "$T/g1.csv"), $(wc -l <"$T/g1.csv") lines"; fi
if cmp -s "$T/g1.png" "$T/a.png"; then ok; else bad "--grains changed the picture"; fi
expect 0 "render grains other seed" -- "$BIN" render -o "$T/g2.png" --scale 0.25 --seed 7 --physics-seed 1 --grains "$T/g2.csv"
expect 0 "compare-grains itself" -- "$BIN" compare-grains "$T/g1.csv" "$T/g1.csv" --json
if grep -q '"same_release": true' "$T/out" && grep -q '"travel_distance_px": 0.0' "$T/out" && grep -q '"x": 0.0' "$T/out" &&
  grep -q '"unit_centroid_distance_px": 0.0' "$T/out" && grep -q '"unit_spread_difference_px": 0.0' "$T/out"; then ok
else bad "compare-grains itself: $(head -c 600 "$T/out")"; fi
expect 0 "compare-grains table" -- "$BIN" compare-grains "$T/g1.csv" "$T/g1.csv"
if grep -q "unit spread" "$T/out" && grep -q "^S1 " "$T/out" && grep -q "centroid distance 0.00   spread difference 0.00" "$T/out"; then ok
else bad "compare-grains table: $(cat "$T/out")"; fi
# Another physics seed of the same layout: the same units, their sand a little elsewhere.
expect 0 "render grains other physics seed" -- "$BIN" render -o "$T/gp.png" --scale 0.25 --physics-seed 2 --grains "$T/gp.csv"
expect 0 "compare-grains other physics seed" -- "$BIN" compare-grains "$T/g1.csv" "$T/gp.csv" --json
if grep -q '"same_release": false' "$T/out" && ! grep -q '"unit_centroid_distance_px": 0.0' "$T/out" &&
  grep -q '"unit_centroid_distance_px"' "$T/out"; then ok
else bad "compare-grains other physics seed: $(head -c 900 "$T/out")"; fi
expect 2 "compare-grains other layout" -- "$BIN" compare-grains "$T/g1.csv" "$T/g2.csv"
one_line; err_has "g2.csv"
expect 2 "compare-grains not a table" -- "$BIN" compare-grains "$T/g1.csv" "$T/s.json"
one_line; err_has "s.json"
expect 2 "render grains bad path" -- "$BIN" render -o "$T/g3.png" --scale 0.25 --grains "$T/nodir/g.csv"
one_line; err_has "nodir"; absent "$T/g3.png"

# paper Fig. 14c-d: frames of the fall, the last one the picture; a video of them.
expect 0 "frames" -- "$BIN" render -o "$T/fr.png" --scale 0.25 --frames "$T/frames/" --frame-count 12 \
  --video "$T/fall.mp4" --stats "$T/fr.json"
if [ "$(ls "$T/frames" | wc -l)" = 12 ]; then ok; else bad "frames: $(ls "$T/frames")"; fi
is_png "$T/frames/frame-00000.png"
if cmp -s "$T/frames/frame-00011.png" "$T/fr.png"; then ok; else bad "the last frame is not the picture"; fi
if cmp -s "$T/fr.png" "$T/a.png"; then ok; else bad "frames changed the picture"; fi
if [ -s "$T/fall.mp4" ] && [ "$(head -c 8 "$T/fall.mp4" | tail -c 4)" = ftyp ]; then ok; else bad "fall.mp4 is not an MP4"; fi
if grep -q '"frames": 12' "$T/fr.json"; then ok; else bad "stats lack the frames: $(cat "$T/fr.json")"; fi
expect 0 "frames again" -- "$BIN" render -o "$T/fr2.png" --scale 0.25 --frames "$T/frames2" --frame-count 12
if diff -rq "$T/frames" "$T/frames2" >/dev/null; then ok; else bad "same seed gave other frames"; fi
if ls "$T" | grep -q tmp-; then bad "temporaries left: $(ls "$T")"; else ok; fi
echo keep >"$T/framesfile"
expect 2 "frames into a file" -- "$BIN" render -o "$T/e.png" --scale 0.25 --frames "$T/framesfile"
one_line; err_has "--frames"; absent "$T/e.png"
expect 2 "no frames" -- "$BIN" render -o "$T/e.png" --scale 0.25 --frames "$T/f0" --frame-count 0
one_line; err_has "--frame-count"; absent "$T/f0"
expect 2 "video container" -- "$BIN" render -o "$T/e.png" --scale 0.25 --video "$T/fall.nosuch"
one_line; err_has "--video"; absent "$T/e.png"; absent "$T/fall.nosuch"

# The benchmark prints a median per stage.
expect 0 "bench" -- "$BIN" bench --runs 2 --scale 0.2
for k in init_s segment_s simulate_s render_s total_s "grains per second"; do
  if grep -q "$k" "$T/out"; then ok; else bad "bench output lacks $k"; fi
done
# Beside the peer falling-sand automaton: its time and the ratio, every grain at rest.
expect 0 "bench --peer" -- "$BIN" bench --runs 2 --scale 0.2 --peer
for k in peer_s "peer_s / simulate_s" "14000 grains at rest, 0 lost"; do
  if grep -q "$k" "$T/out"; then ok; else bad "bench --peer output lacks $k"; fi
done
expect 2 "bench --peer dem" -- "$BIN" bench --runs 1 --scale 0.2 --peer --mode dem
one_line; err_has "--peer"

# The printed default scene is a complete scene file.
expect 0 "scene" -- "$BIN" scene
cp "$T/out" "$T/default.json"
expect 0 "render printed scene" -- "$BIN" render "$T/default.json" -o "$T/d.png" --scale 0.25
if cmp -s "$T/a.png" "$T/d.png"; then ok; else bad "the printed default scene renders otherwise"; fi

# Bad input: exit 2, one line naming the key or file, no output, old file kept.
echo keep >"$T/keep.png"
expect 2 "misspelt key" -- "$BIN" render -o "$T/keep.png" --scale 0.25 --set physics.frictoin=0.3
one_line; err_has "physics.friction"
if [ "$(cat "$T/keep.png")" = keep ]; then ok; else bad "an existing output was overwritten on failure"; fi
expect 2 "bad value" -- "$BIN" render -o "$T/e.png" --set physics.friction=-2
one_line; err_has "physics.friction"; absent "$T/e.png"
expect 2 "missing scene" -- "$BIN" render "$T/none.json" -o "$T/e.png"
one_line; err_has "none.json"; absent "$T/e.png"
printf '{\n "mode": "lattice",\n "seed": 1,,\n}\n' >"$T/broken.json"
expect 2 "malformed scene" -- "$BIN" render "$T/broken.json" -o "$T/e.png"
one_line; err_has "line 3"; absent "$T/e.png"
expect 2 "missing image" -- "$BIN" render -o "$T/e.png" --set init.method=halftone --set init.image=/nope/pic.png
one_line; err_has "/nope/pic.png"; absent "$T/e.png"
expect 2 "no output folder" -- "$BIN" render -o "$T/no/such/dir/e.png"
one_line; err_has "no/such/dir"
expect 2 "negative seed" -- "$BIN" render -o "$T/e.png" --seed -1
one_line; absent "$T/e.png"
mkdir -p "$T/sd/3-segmentation.png"
expect 2 "a stage target is a folder" -- "$BIN" render -o "$T/e.png" --scale 0.25 --stats "$T/e.json" --stages "$T/sd"
one_line; err_has "3-segmentation.png"; absent "$T/e.png"; absent "$T/e.json"
expect 0 "stages folder with a slash" -- "$BIN" render -o "$T/f.png" --scale 0.25 --stages "$T/newstages/"
is_png "$T/newstages/5-picture.png"
expect 2 "not UTF-8" -- "$BIN" render -o "$T/e.png" --set "mode=$(printf 'l\xffx')"
one_line; err_has "mode"; absent "$T/e.png"
head -c 100 "$T/a.png" >"$T/truncated.png"
expect 2 "truncated image" -- "$BIN" render -o "$T/e.png" --set init.method=halftone --set "init.image=$T/truncated.png"
one_line; err_has "truncated.png"; absent "$T/e.png"
expect 2 "no -o" -- "$BIN" render
expect 2 "bad scale" -- "$BIN" render -o "$T/e.png" --scale -1
one_line; absent "$T/e.png"
TINY=(--set window.width=60 --set window.height=60 --set region.height=5 --set segment.semi_major_max=40
      --set segment.semi_major_min=20 --set release.outlet_width_mm=4)
if [ "$BULLET" = with-bullet ]; then
  expect 0 "dem" -- "$BIN" render -o "$T/dem.png" --mode dem "${TINY[@]}" --stats "$T/dem.json" --stages "$T/dst"
  is_png "$T/dem.png"; is_png "$T/dst/6-layers.png"; is_png "$T/dst/7-layers-end.png"
  expect 0 "dem immovable statics" -- "$BIN" render -o "$T/demb.png" --mode dem "${TINY[@]}" --set dem.static_bodies=false \
    --stages "$T/dstb" --frames "$T/dfb" --frame-count 3
  is_png "$T/demb.png"; is_png "$T/dstb/6-layers.png"; is_png "$T/dfb/frame-00002.png"
  # Static grains out of the flow's reach rest as spheres: the layer pictures
  # and the grain count still see them where they are.
  expect 0 "dem static reach" -- "$BIN" render -o "$T/demr.png" --mode dem "${TINY[@]}" \
    --set dem.static_reach_diameters=1 --stats "$T/demr.json" --stages "$T/dstr"
  is_png "$T/dstr/7-layers-end.png"
  if grep -q '"in_picture": 300' "$T/demr.json" && grep -q '"static_sleeps": [1-9]' "$T/demr.json"; then ok
  else bad "dem static reach stats: $(cat "$T/demr.json")"; fi
  if grep -q '"in_picture": 300' "$T/dem.json"; then ok; else bad "dem stats: $(cat "$T/dem.json")"; fi
  echo keep >"$T/keep.png"
  expect 3 "dem divergence" -- "$BIN" render -o "$T/keep.png" --mode dem "${TINY[@]}" --set dem.step_diameters=1 --set dem.max_overlap=0.1 --set dem.max_substeps=1 \
    --frames "$T/dfr" --video "$T/dfr.mp4"
  one_line; err_has "overlap"; err_has "physics seed"; absent "$T/dfr"; absent "$T/dfr.mp4"
  if ls "$T" | grep -q tmp-; then bad "a diverged run left temporaries: $(ls "$T")"; else ok; fi
  # Both modes release a grain at the same point for one scene and seed.
  expect 0 "dem grains" -- "$BIN" render -o "$T/dg.png" --mode dem "${TINY[@]}" --grains "$T/dg.csv"
  expect 0 "lattice grains" -- "$BIN" render -o "$T/lg.png" "${TINY[@]}" --grains "$T/lg.csv"
  expect 0 "compare-grains modes" -- "$BIN" compare-grains "$T/lg.csv" "$T/dg.csv" --json
  if grep -q '"same_release": true' "$T/out"; then ok; else bad "lattice and DEM released elsewhere: $(head -c 400 "$T/out")"; fi
  expect 0 "dem frames" -- "$BIN" render -o "$T/dem2.png" --mode dem "${TINY[@]}" --frames "$T/dfr" --frame-count 5
  if [ "$(ls "$T/dfr" | wc -l)" = 5 ] && cmp -s "$T/dfr/frame-00004.png" "$T/dem2.png"; then ok; else bad "dem frames: $(ls "$T/dfr")"; fi
  if [ "$(cat "$T/keep.png")" = keep ]; then ok; else bad "a diverged run overwrote the output"; fi
  # verify-dem: single grains against closed forms; a bad case id is refused.
  expect 0 "verify-dem" -- "$BIN" verify-dem --out "$T/vd" --only restitution,incline
  if grep -q '"pass": true' "$T/vd/report.json" && grep -q "<svg" "$T/vd/report.html"; then ok; else bad "verify-dem report: $(head -c 400 "$T/vd/report.json")"; fi
  expect 2 "verify-dem bad case" -- "$BIN" verify-dem --out "$T/vd2" --only nonsense
  one_line; err_has "nonsense"; absent "$T/vd2"
  expect 2 "verify-dem --quick of a full-run case" -- "$BIN" verify-dem --quick --out "$T/vd2" --only restitution,engine-piles
  one_line; err_has "engine-piles"; absent "$T/vd2"
  # --set: a scene key on every pile run, never one the cases vary, checked before anything runs.
  expect 2 "verify-dem --set of a varied key" -- "$BIN" verify-dem --out "$T/vd3" --only heap --set physics.friction=0.2
  err_has "vary 'physics.friction'"
  expect 2 "verify-dem --set of no key" -- "$BIN" verify-dem --out "$T/vd3" --only heap --set dem.nope=1
  err_has "dem.nope"
  absent "$T/vd3"
  expect 2 "verify-dem --layers of no model" -- "$BIN" verify-dem --out "$T/vd3" --only layers --layers three,sand
  one_line; err_has "sand"; absent "$T/vd3"
  expect 2 "verify-dem layers case with no model to compare" -- "$BIN" verify-dem --out "$T/vd3" --only layers --layers all-dynamic
  one_line; err_has "layers"; absent "$T/vd3"
  # paper Fig. 12: the layer models side by side, as a table, CSV and plot.
  expect 0 "bench-layers" -- "$BIN" bench-layers "${TINY[@]}" --grains 100,200 --seeds 1,2 --all-dynamic-max 100 \
    --csv "$T/fig12.csv" --plot "$T/fig12.png"
  is_png "$T/fig12.png"
  if [ "$(wc -l <"$T/fig12.csv")" = 12 ]; then ok; else bad "fig12.csv: $(cat "$T/fig12.csv")"; fi
  if grep -q "all-dyn/three" "$T/out" && [ "$(wc -l <"$T/out")" = 3 ]; then ok; else bad "bench-layers table: $(cat "$T/out")"; fi
  expect 2 "bench-layers bad count" -- "$BIN" bench-layers --grains 100,x --csv "$T/g.csv"
  one_line; err_has "--grains"; absent "$T/g.csv"
  expect 2 "bench-layers bad model" -- "$BIN" bench-layers --layers three,four
  one_line; err_has "four"
  # paper Fig. 9: the pile's slope against friction.
  expect 0 "bench-friction" -- "$BIN" bench-friction --scale 0.25 --friction 0.1,0.9 --seeds 1 --layers three \
    --csv "$T/fig9.csv" --pictures "$T/fig9"
  is_png "$T/fig9/three-friction0.90-seed1.png"
  if [ "$(wc -l <"$T/fig9.csv")" = 3 ] && grep -q "three: the mean angle" "$T/out"; then ok; else bad "bench-friction: $(cat "$T/out")"; fi
  err_has "heap angle"  # each run's line: a heap's angle (a picture of many mountains: its scene slope)
  expect 2 "bench-friction bad friction" -- "$BIN" bench-friction --friction 0.4,abc --csv "$T/f.csv"
  one_line; err_has "--friction"; absent "$T/f.csv"
  # calibrate writes a file a scene names; validate refuses a thin noise floor.
  expect 0 "calibrate" -- "$BIN" calibrate "${TINY[@]}" --grains 300 --scenes 1 --out "$T/cal.json"
  if grep -q '"repose_deg"' "$T/cal.json" && grep -q '"bulk"' "$T/cal.json"; then ok; else bad "cal.json: $(cat "$T/cal.json")"; fi
  expect 0 "render calibrated" -- "$BIN" render "${TINY[@]}" --set lattice.calibration="$T/cal.json" -o "$T/cal.png" --stats "$T/cal-stats.json"
  if grep -q '"calibration"' "$T/cal-stats.json"; then ok; else bad "calibrated stats: $(cat "$T/cal-stats.json")"; fi
  expect 2 "calibrate too few grains" -- "$BIN" calibrate --grains 100 --out "$T/c2.json"
  one_line; err_has "--grains"; absent "$T/c2.json"
  # Two sizes fit the surface layer; --runs keeps the DEM piles and a second fit reuses them.
  expect 0 "calibrate two sizes" -- "$BIN" calibrate "${TINY[@]}" --grains 300,700 --scenes 1 --runs "$T/calruns" --out "$T/cal2.json"
  if grep -q '"surface_px"' "$T/cal2.json" && [ "$(ls "$T/calruns" | grep -c '\.classes\.png$')" = 4 ]; then ok; else bad "cal2: $(ls "$T/calruns")"; fi
  expect 0 "calibrate kept runs" -- "$BIN" calibrate "${TINY[@]}" --grains 300,700 --scenes 1 --runs "$T/calruns" --out "$T/cal3.json"
  if cmp -s "$T/cal2.json" "$T/cal3.json"; then ok; else bad "a refit from kept runs differs"; fi
  # --spot also fits how long a landing spot stays busy (reusing the kept piles).
  expect 0 "calibrate spot" -- "$BIN" calibrate "${TINY[@]}" --grains 300,700 --scenes 1 --runs "$T/calruns" --spot --out "$T/cal4.json"
  if grep -q '"spot_busy_s"' "$T/cal4.json" && grep -q "spot_busy_s" "$T/out"; then ok; else bad "cal4: $(cat "$T/cal4.json")"; fi
  # --fit names keys with a fit grid in the registry; another is refused before any run.
  expect 2 "calibrate --fit of a key without a grid" -- "$BIN" calibrate "${TINY[@]}" --fit lattice.bulk --out "$T/cal5.json"
  one_line; err_has "lattice.bulk"; absent "$T/cal5.json"
  # --shares also fits how much of the picture small grains take where they mix (lattice.picture_share).
  expect 0 "calibrate shares" -- "$BIN" calibrate "${TINY[@]}" --grains 300,700 --scenes 1 --runs "$T/calruns" --shares --out "$T/cal5.json"
  # (Recovering a known share is CalibrateFit.PictureSharesAreFittedToTheComposition's job.)
  if grep -Eq "^picture_share 1\.000 1\.000 ([0-9.]+) \1: composition error" "$T/out" &&
     grep -q '"picture_share"' "$T/cal5.json" && grep -q '"dem_composition_floor"' "$T/cal5.json"; then ok; else bad "cal5: $(cat "$T/out")"; fi
  expect 2 "calibrate bad size list" -- "$BIN" calibrate --grains 8000,x --out "$T/c3.json"
  one_line; err_has "--grains"; absent "$T/c3.json"
  expect 2 "validate few seeds" -- "$BIN" validate "${TINY[@]}" --seeds 3 --out "$T/val"
  one_line; err_has "--seeds"; absent "$T/val/report.html"
  # --runs: the DEM runs go to a folder of their own, and a second report reuses them.
  expect 0 "validate kept runs" -- "$BIN" validate "${TINY[@]}" --sweep none --runs "$T/vruns" --out "$T/val1"
  if [ "$(ls "$T/vruns" | grep -c '\.classes\.png$')" = 5 ] && [ ! -e "$T/val1/runs" ]; then ok; else bad "vruns: $(ls "$T/vruns")"; fi
  expect 0 "validate reuses runs" -- "$BIN" validate "${TINY[@]}" --sweep none --runs "$T/vruns" --out "$T/val2"
  if [ -s "$T/val2/report.html" ] && [ -z "$(find "$T/vruns" -newer "$T/val1/report.json")" ]; then ok; else bad "DEM runs were redone"; fi
  # --lattice-seeds: the lattice scored over several physics seeds, with its own seed-to-seed spread.
  expect 0 "validate lattice seeds" -- "$BIN" validate "${TINY[@]}" --sweep none --runs "$T/vruns" --lattice-seeds 3 --out "$T/val3"
  if grep -q '"lattice_seeds": 3' "$T/val3/report.json" && grep -q '"lattice_seed_to_seed"' "$T/val3/report.json" &&
     grep -q "lattice seed to seed" "$T/val3/report.html" && grep -q "means over 3 physics seeds" "$T/out"; then ok
  else bad "val3: $(cat "$T/out")"; fi
  expect 2 "validate no lattice seed" -- "$BIN" validate "${TINY[@]}" --lattice-seeds 0 --out "$T/val4"
  one_line; err_has "--lattice-seeds"; absent "$T/val4/report.html"
else
  expect 2 "dem without Bullet" -- "$BIN" render -o "$T/e.png" --mode dem
  one_line; err_has "Bullet"; absent "$T/e.png"
  expect 2 "bench-layers without Bullet" -- "$BIN" bench-layers --grains 100 --csv "$T/g.csv"
  one_line; err_has "Bullet"; absent "$T/g.csv"
  expect 2 "bench-friction without Bullet" -- "$BIN" bench-friction --csv "$T/f.csv"
  one_line; err_has "Bullet"; absent "$T/f.csv"
  expect 2 "validate without Bullet" -- "$BIN" validate --out "$T/val"
  one_line; err_has "validate needs the DEM mode"; absent "$T/val/report.html"
  expect 2 "calibrate without Bullet" -- "$BIN" calibrate --out "$T/c.json"
  one_line; err_has "calibrate needs the DEM mode"; absent "$T/c.json"
  expect 2 "verify-dem without Bullet" -- "$BIN" verify-dem --out "$T/vd"
  one_line; err_has "Bullet"; absent "$T/vd"
fi
expect 2 "missing calibration" -- "$BIN" render -o "$T/e.png" --set lattice.calibration="$T/nothing.json"
one_line; err_has "lattice.calibration"; absent "$T/e.png"
# A busy landing spot makes grains wait (counted in the stats); a negative time is a bad scene.
expect 0 "busy spots" -- "$BIN" render --scale 0.2 --set lattice.spot_busy_s=0.01 -o "$T/spot.png" --stats "$T/spot.json"
if grep -Eq '"grains_waited": [1-9]' "$T/spot.json"; then ok; else bad "spot stats: $(grep -o '"grains_waited": [0-9]*' "$T/spot.json")"; fi
expect 2 "negative spot time" -- "$BIN" render -o "$T/e.png" --set lattice.spot_busy_s=-1
one_line; err_has "lattice.spot_busy_s"; absent "$T/e.png"
# lattice.picture_share redraws mixed columns only: the silhouette stays, the small classes show more.
expect 0 "picture shares" -- "$BIN" render --scale 0.2 --set 'lattice.picture_share=[1,1,2,2]' -o "$T/share.png"
expect 0 "picture shares off" -- "$BIN" render --scale 0.2 -o "$T/noshare.png"
expect 0 "picture shares compared" -- "$BIN" compare "$T/noshare.png" "$T/share.png" --json
if grep -q '"silhouette_error": 0\.0,' "$T/out" && ! grep -q '"composition_error": 0\.0,' "$T/out"; then ok; else bad "picture shares: $(cat "$T/out")"; fi
expect 2 "bad picture share" -- "$BIN" render -o "$T/e.png" --set 'lattice.picture_share=[1,1,0,1]'
one_line; err_has "lattice.picture_share"; absent "$T/e.png"

# paper §5.2: a sketch drawn as a picture, painted over, read back as the sketch.
expect 0 "sketch" -- "$BIN" sketch "$ROOT/examples/fig07.json" -o "$T/sketch.png"
is_png "$T/sketch.png"
expect 0 "render from the sketch picture" -- "$BIN" render -o "$T/sk.png" --scale 0.3 --stages "$T/sk" \
  --set segment.method=sketch "segment.sketch.image=\"$T/sketch.png\""
is_png "$T/sk/3-segmentation.png"
expect 2 "sketch of a scene without one" -- "$BIN" sketch -o "$T/none.png"
one_line; err_has "segment.sketch.ridges"; absent "$T/none.png"
expect 2 "sketch with no crossing" -- "$BIN" render -o "$T/nc.png" --set segment.method=sketch \
  'segment.sketch.ridges=[[[10, 300], [10, 0]]]' 'segment.sketch.arcs=[[[100, 100], [200, 100]]]'
one_line; err_has "no arc-like curve crosses a ridge line"; absent "$T/nc.png"
expect 2 "sketch picture missing" -- "$BIN" render -o "$T/nc.png" --set segment.method=sketch \
  "segment.sketch.image=\"$T/nothing.png\""
one_line; err_has "segment.sketch.image"; absent "$T/nc.png"

# A scene past the memory or time limit is refused before it starts.
expect 2 "memory limit" -- "$BIN" render -o "$T/keep.png" --max-memory-gb 0.05
one_line; err_has "--max-memory-gb"; err_has "350000 grains"
if [ "$(cat "$T/keep.png")" = keep ]; then ok; else bad "a refused scene overwrote the output"; fi
if [ "$BULLET" = with-bullet ]; then
  expect 2 "time limit" -- "$BIN" render -o "$T/e.png" --mode dem --max-hours 0.01
  one_line; err_has "--max-hours"; absent "$T/e.png"
fi
printf '{"physics": {"friction": 1e999}}\n' >"$T/huge.json"
expect 2 "number past a double" -- "$BIN" render "$T/huge.json" -o "$T/e.png"
one_line; err_has "physics.friction"; err_has "line 1"; absent "$T/e.png"

# The stress catalogue, a few cases of each kind (the whole quick
# catalogue is a test of its own).
expect 0 "stress" -- "$BIN" stress --quick --threads 2 --out "$T/stress" --only json-nan,image-16bit,region-1px
for f in stress.md stress.json; do if [ -s "$T/stress/$f" ]; then ok; else bad "stress wrote no $f"; fi; done
if grep -q '| image-16bit | lattice | picture |' "$T/stress/stress.md"; then ok; else bad "stress.md lacks image-16bit"; fi
if grep -q '"failed": 0' "$T/stress/stress.json"; then ok; else bad "stress.json reports failures"; fi
# Two runs at a time, the rows still in the catalogue's order.
rows=$(grep -o '^| [a-z0-9-]* | [a-z]* |' "$T/stress/stress.md" | tr -d '| ' | tr '\n' ' ')
want="casemode region-1pxlattice region-1pxdem image-16bitlattice image-16bitdem json-nanlattice "
# A build without Bullet has no DEM rows.
[ "$BULLET" = with-bullet ] || want="casemode region-1pxlattice image-16bitlattice json-nanlattice "
if [ "$rows" = "$want" ]; then ok
else bad "stress rows out of the catalogue's order: $rows"; fi
expect 2 "stress unknown case" -- "$BIN" stress --quick --out "$T/stress" --only no-such-case
one_line; err_has "no-such-case"

# paper §10, Fig. 16: figures; a missing mask is named.
expect 2 "figure mask missing" -- "$BIN" render -o "$T/fg.png" --set \
  "render.figures=[{\"mask\": \"$T/nothing.png\"}]"
one_line; err_has "render.figures\[0\].mask"; absent "$T/fg.png"

# sandpic studio. A bad starting scene is refused before it listens;
# a good one prints its loopback address and serves the page there.
printf '{"physics": {"friction": -1}}\n' >"$T/bad-studio.json"
expect 2 "studio bad scene" -- "$BIN" studio "$T/bad-studio.json" --port 0
one_line; err_has "physics.friction"
"$BIN" studio --port 0 --renders "$T/studio-renders" >"$T/studio.out" 2>"$T/studio.err" &
studio_pid=$!
for _ in $(seq 50); do grep -q http "$T/studio.out" 2>/dev/null && break; sleep 0.1; done
url=$(grep -o 'http://127.0.0.1:[0-9]*/' "$T/studio.out")
if [ -n "$url" ]; then ok; else bad "studio printed no loopback address: $(cat "$T/studio.out" "$T/studio.err")"; fi
if command -v curl >/dev/null && [ -n "$url" ]; then
  if curl -s "$url" | grep -q "sandpic studio"; then ok; else bad "studio page not served at $url"; fi
fi
kill "$studio_pid" 2>/dev/null
wait "$studio_pid" 2>/dev/null

# Every example renders (scaled down).
for scene in "$ROOT"/examples/*.json; do
  expect 0 "example $(basename "$scene")" -- "$BIN" render "$scene" -o "$T/ex.png" --scale 0.3
done

echo "cli: $passed passed, $failed failed"
[ "$failed" = 0 ]
