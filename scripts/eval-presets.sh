#!/usr/bin/env bash
# The figures quoted in the issue notes: simulates blocks (easy, realistic
# seeds 1 and 2, hard, a Berlin LoD2 tile), runs `roofsweep run` on each,
# once from matched lines and once from the simulator's true edges (the
# upper bound of the later stages), and prints one table from `eval -json`.
# A CASE is PRESET-SEED, berlin-SEED or hills-SEED (realistic over 12 m of
# relief, with a DTM).
#   [MATCH_SEEDS="1 2 3"] scripts/eval-presets.sh [BUILD] [OUTDIR] [CASE ...]
# MATCH_SEEDS (default 1) runs the matched lines once per matching seed
# (`-seed`, rows matched1, matched2, ...) and ends with the mean and spread
# of the plane quality over them: one seed cannot show a change of a few
# points (sweep README, "How much the figures move"). Blocks already
# simulated in OUTDIR are reused. Not part of `make test` (about 15
# minutes on two cores, plus 5 per extra seed).
set -euo pipefail
BUILD=${1:-build}
OUT=${2:-out/eval}
shift $(( $# > 2 ? 2 : $# ))
RS="$BUILD/plugin/cli/roofsweep"
SHARED=${ROOFSWEEP_SHARED_DIR:-$(cd "$(dirname "$0")/../.." && pwd)/shared}
CASES=("$@")
read -r -a SEEDS <<<"${MATCH_SEEDS:-1}"
[[ ${#CASES[@]} -gt 0 ]] || CASES=(easy-1 realistic-1 realistic-2 hard-1 berlin-1)
mkdir -p "$OUT"

simulate() {
  local name=$1 preset=${1%-*} seed=${1##*-}
  [[ -f "$OUT/$name/block.json" ]] && return
  if [[ $preset == berlin ]]; then
    "$RS" simulate -preset realistic -seed "$seed" -citygml "$SHARED/data/citygml/berlin-lod2/3910_5819.gml" \
      -aoi 391760,5818980,391900,5819110 -o "$OUT/$name" -q
  elif [[ $preset == hills ]]; then
    "$RS" simulate -preset realistic -seed "$seed" -terrain_relief 12 -o "$OUT/$name" -q
  else
    "$RS" simulate -preset "$preset" -seed "$seed" -o "$OUT/$name" -q
  fi
}

row() {
  python3 - "$@" <<'PY'
import json, sys
name, source, seconds, path = sys.argv[1:5]
d = json.load(open(path))
p, g, b = d["roof_planes"], d["geometry"], d["buildings"]
pct = lambda v: "%5.1f" % (100 * v) if v is not None else "  -  "
num = lambda v, f: (f % v) if v is not None else "-"
print("| %-11s | %-7s | %s | %s | %s | %s | %s | %s | %s | %s | %6s |" % (
    name, source, pct(p["completeness"]), pct(p["correctness"]), pct(p["quality"]),
    num(g.get("angle_median_deg"), "%5.2f"), num(g.get("vertex_rms_gsd"), "%5.1f"),
    num(g.get("rmsz_m"), "%5.2f"), pct(b["completeness"]), pct(b["correctness"]), seconds))
PY
}

echo "| block       | lines   | plane compl % | corr % | quality % | normal median deg | vertex RMS GSD | RMSZ m | bldg compl % | bldg corr % | run s |"
echo "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
runs=()
for c in "${CASES[@]}"; do
  simulate "$c"
  for source in "${SEEDS[@]/#/matched}" truth; do
    extra=()
    label=$source
    if [[ $source == truth ]]; then
      extra=(-lines "$OUT/$c/groundtruth_edges.json")
    else
      extra=(-seed "${source#matched}")
      [[ ${#SEEDS[@]} -gt 1 ]] || label=matched
    fi
    t0=$(date +%s.%N)
    "$RS" run "$OUT/$c" "${extra[@]}" -o "$OUT/$c-$label.gml" -report "$OUT/$c-$label.json" \
      -overwrite -q
    t=$(python3 -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$t0" "$(date +%s.%N)")
    "$RS" eval "$OUT/$c-$label.gml" "$OUT/$c" -json >"$OUT/$c-$label-eval.json" 2>/dev/null
    row "$c" "$label" "$t" "$OUT/$c-$label-eval.json"
    [[ $source == truth ]] || runs+=("$c" "$OUT/$c-$label-eval.json")
  done
done
[[ ${#SEEDS[@]} -gt 1 ]] || exit 0
python3 - "${runs[@]}" <<'PY'
import json, statistics, sys
by = {}
args = sys.argv[1:]
for name, path in zip(args[::2], args[1::2]):
    by.setdefault(name, []).append(100 * json.load(open(path))["roof_planes"]["quality"])
print("\nplane quality from matched lines over the matching seeds: mean, SD, min-max")
for name, q in by.items():
    print("  %-11s %5.1f  %4.1f  %5.1f-%5.1f  (%d seeds)" % (
        name, statistics.mean(q), statistics.pstdev(q), min(q), max(q), len(q)))
PY
