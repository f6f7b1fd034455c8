#!/usr/bin/env bash
# --mode lammps as a user runs it: a tiny scene (360 grains, seconds)
# through LAMMPS's `lmp`, the deck exported and drawn from its dump, and the
# errors. Skipped (exit 77) where `lmp` is not installed.
# Usage: test_lammps.sh SANDPIC_BINARY
set -u
BIN=$1
command -v lmp >/dev/null || { echo "lmp not installed: skipped"; exit 77; }
source "$(dirname "$0")/checks.sh"
has() { if grep -q -- "$2" "$1"; then ok; else bad "$1 lacks $2"; fi; }
# number FILE KEY: the first number after "KEY": in a stats file.
number() { grep -o "\"$2\": [-0-9.e]*" "$1" | head -1 | awk '{print $2}'; }
TINY=(--scale 0.1 --set window.width=300 --set region.height=120)

# A run: every grain in the picture, settled, contacts within a hundredth of
# a diameter, LAMMPS's version in the stats; its files kept where asked.
expect 0 "lammps render" -- "$BIN" render --mode lammps "${TINY[@]}" -o "$T/a.png" --stats "$T/a.json" --lammps-dir "$T/run"
for k in '"mode": "lammps"' '"total": 360' '"in_picture": 360' '"settled": true' '"lammps_version": "'; do has "$T/a.json" "$k"; done
overlap=$(number "$T/a.json" deepest_overlap_diameters)
if awk -v v="$overlap" 'BEGIN { exit !(v > 0 && v <= 0.01) }'; then ok; else bad "deepest overlap $overlap diameters"; fi
for f in in.sandpic atoms.txt log.lammps final.dump; do
  if [ -s "$T/run/$f" ]; then ok; else bad "--lammps-dir lacks $f"; fi
done

# Same scene, same seed, one rank: the same bytes.
mkdir "$T/tmp"
expect 0 "lammps again" -- env TMPDIR="$T/tmp" "$BIN" render --mode lammps "${TINY[@]}" -o "$T/b.png"
if cmp -s "$T/a.png" "$T/b.png"; then ok; else bad "same seed gave other bytes"; fi
if [ -z "$(ls -A "$T/tmp")" ]; then ok; else bad "a temporary folder was left: $(ls "$T/tmp")"; fi

# The deck exported and run by its own script, drawn from its dump: the
# run's picture, byte for byte.
expect 0 "export-lammps" -- "$BIN" export-lammps "${TINY[@]}" -o "$T/deck"
for f in in.sandpic atoms.txt run.sh scene.json; do
  if [ -s "$T/deck/$f" ]; then ok; else bad "export-lammps lacks $f"; fi
done
if cmp -s "$T/deck/in.sandpic" "$T/run/in.sandpic"; then ok; else bad "the exported deck is not the run's"; fi
if sh "$T/deck/run.sh" >"$T/run.out" 2>&1; then ok; else bad "run.sh failed: $(tail -3 "$T/run.out")"; fi
expect 0 "from dump" -- "$BIN" render "$T/deck/scene.json" --from-dump "$T/deck/final.dump" -o "$T/d.png"
if cmp -s "$T/a.png" "$T/d.png"; then ok; else bad "the dump of run.sh drew another picture"; fi

# Errors: exit 2 (one line, nothing written) for a missing lmp, frames,
# a dump without lammps mode or of another scene; exit 3 when LAMMPS fails.
expect 2 "no lmp" -- "$BIN" render --mode lammps "${TINY[@]}" --lmp /nonexistent/lmp -o "$T/e1.png"
one_line; err_has "mode"; absent "$T/e1.png"
expect 2 "frames" -- "$BIN" render --mode lammps "${TINY[@]}" --frames "$T/frames" -o "$T/e2.png"
one_line; err_has "frames"; absent "$T/e2.png"
expect 2 "dump in lattice mode" -- "$BIN" render "${TINY[@]}" --from-dump "$T/deck/final.dump" -o "$T/e3.png"
one_line; err_has "from-dump"; absent "$T/e3.png"
expect 2 "dump of another scene" -- "$BIN" render --mode lammps --scale 0.1 --set window.width=200 --set region.height=120 \
  --from-dump "$T/deck/final.dump" -o "$T/e4.png"
one_line; err_has "final.dump"; absent "$T/e4.png"
printf '#!/bin/sh\necho "LAMMPS (fake)"\necho "ERROR: Lost atoms: original 360 current 359 (src/thermo.cpp:439)"\nexit 1\n' >"$T/fake-lmp"
chmod +x "$T/fake-lmp"
expect 3 "lammps fails" -- "$BIN" render --mode lammps "${TINY[@]}" --lmp "$T/fake-lmp" --lammps-dir "$T/failed" -o "$T/e5.png"
one_line; err_has "Lost atoms"; absent "$T/e5.png"

# Half the stiffness: every grain still in the picture, settled, the factor in the stats.
expect 0 "half stiffness" -- "$BIN" render --mode lammps "${TINY[@]}" --lammps-stiffness 0.5 -o "$T/h.png" --stats "$T/h.json"
for k in '"in_picture": 360' '"settled": true' '"stiffness_factor": 0.5'; do has "$T/h.json" "$k"; done

# Two ranks: the same grains, all in the picture (the bytes may differ).
expect 0 "two ranks" -- "$BIN" render --mode lammps "${TINY[@]}" --ranks 2 -o "$T/r2.png" --stats "$T/r2.json"
has "$T/r2.json" '"in_picture": 360'
has "$T/r2.json" '"ranks": 2' 

echo "test_lammps: $passed passed, $failed failed"
[ "$failed" = 0 ]
