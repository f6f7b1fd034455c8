#!/usr/bin/env bash
# The Bullet DEM against LAMMPS on one scene: every engine (three-layer and
# all-dynamic, both simulating the whole fall from the outlet as LAMMPS does;
# three-layer with the fall analytic down to 4 diameters above the pile:
# "analytic"; LAMMPS) at each friction and physics seed, then each
# picture's scene slope and the silhouette errors between and within the
# engines (each engine's own seed-to-seed floor). Two jobs at once (LAMMPS
# on one core, Bullet on the other). Long: at --scale 0.1 about 30 minutes.
#   scripts/cross-check-lammps.sh OUT [--scale S] [--frictions "0.1 0.4 0.9"] [--seeds "1 2 3"] [-- render options]
set -euo pipefail
out=$1; shift
scale=0.1 frictions="0.1 0.4 0.9" seeds="1 2 3"
while [ $# -gt 0 ]; do
  case "$1" in
    --scale) scale=$2; shift 2 ;;
    --frictions) frictions=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "cross-check-lammps: unknown option $1" >&2; exit 2 ;;
  esac
done
extra=("$@")  # more render options, for every run
sandpic=${SANDPIC:-$(dirname "$0")/../build/sandpic}
mkdir -p "$out"
run() {  # engine friction seed
  local name="$out/$1-mu$2-seed$3"
  [ -f "$name.png" ] && return
  case "$1" in
    analytic) "$sandpic" render --mode dem --set dem.simulated_fall_s=0 --scale "$scale" \
           --set physics.friction="$2" --physics-seed "$3" --threads 1 "${extra[@]}" -o "$name.png" --stats "$name.json" ;;
    lammps) "$sandpic" render --mode lammps --scale "$scale" --set physics.friction="$2" --physics-seed "$3" "${extra[@]}" \
              -o "$name.png" --stats "$name.json" ;;
    *) "$sandpic" render --mode dem --set dem.layers="$1" --scale "$scale" --set physics.friction="$2" \
         --physics-seed "$3" --threads 1 "${extra[@]}" -o "$name.png" --stats "$name.json" ;;
  esac
}
(for mu in $frictions; do for seed in $seeds; do run lammps "$mu" "$seed"; done; done) &
(for mu in $frictions; do for seed in $seeds; do run all-dynamic "$mu" "$seed"; run three "$mu" "$seed"; run analytic "$mu" "$seed"; done; done) &
wait
# The table: mean slope per engine, and errors against all-dynamic over the floors.
python3 - "$out" "$sandpic" "$frictions" "$seeds" <<'PY'
import json, subprocess, sys, itertools, statistics as st
out, sandpic, frictions, seeds = sys.argv[1], sys.argv[2], sys.argv[3].split(), sys.argv[4].split()
def cmp(a, b):
    return json.loads(subprocess.run([sandpic, "compare", "--json", a, b], capture_output=True, text=True, check=True).stdout)
engines = ["lammps", "three", "all-dynamic", "analytic"]
print("| friction | engine | scene slope per seed (mean ± spread) | simulate_s | silhouette floor | silhouette vs LAMMPS (/ own floor, / LAMMPS floor) | composition floor | composition vs LAMMPS |")
print("| --- | --- | --- | --- | --- | --- | --- | --- |")
pairs = list(itertools.combinations(seeds, 2))
for mu in frictions:
    p = lambda e, s: f"{out}/{e}-mu{mu}-seed{s}.png"
    within = {e: [cmp(p(e, a), p(e, b)) for a, b in pairs] for e in engines}
    floor = {e: st.mean(c["silhouette_error"] for c in within[e]) for e in engines}
    for e in engines:
        slopes = [cmp(p(e, s), p(e, s))["scene_slope_deg"][0] for s in seeds]
        times = [json.load(open(p(e, s)[:-4] + ".json"))["timing"]["simulate_s"] for s in seeds]
        comp_floor = st.mean(c["composition_error"] for c in within[e])
        if e == "lammps":
            sil = comp = ""
        else:
            across = [cmp(p(e, a), p("lammps", b)) for a in seeds for b in seeds]
            x = st.mean(c["silhouette_error"] for c in across)
            sil = f"{x:.4f} ({x / floor[e]:.2f}x, {x / floor['lammps']:.2f}x)"
            comp = f"{st.mean(c['composition_error'] for c in across):.4f}"
        spread = st.stdev(slopes) if len(slopes) > 1 else 0
        print(f"| {mu} | {e} | {' / '.join(f'{v:.1f}' for v in slopes)} ({st.mean(slopes):.1f} ± {spread:.1f}) | "
              f"{min(times):.0f}-{max(times):.0f} | {floor[e]:.4f} | {sil} | {comp_floor:.4f} | {comp} |")
PY
