#!/usr/bin/env bash
# The figures quoted in the issue notes: simulates blocks (easy, realistic
# seeds 1 and 2, hard, a Berlin LoD2 tile), runs `roofsweep run` on each,
# once from matched lines and once from the simulator's true edges (the
# upper bound of the later stages), and prints one table from `eval -json`.
#   scripts/eval-presets.sh [BUILD] [OUTDIR] [CASE ...]
# Blocks already simulated in OUTDIR are reused. Not part of `make test`
# (about 15 minutes on two cores).
set -euo pipefail
BUILD=${1:-build}
OUT=${2:-out/eval}
shift $(( $# > 2 ? 2 : $# ))
RS="$BUILD/plugin/cli/roofsweep"
SHARED=${ROOFSWEEP_SHARED_DIR:-$(cd "$(dirname "$0")/../.." && pwd)/shared}
CASES=("$@")
[[ ${#CASES[@]} -gt 0 ]] || CASES=(easy-1 realistic-1 realistic-2 hard-1 berlin-1)
mkdir -p "$OUT"

simulate() {
  local name=$1 preset=${1%-*} seed=${1##*-}
  [[ -f "$OUT/$name/block.json" ]] && return
  if [[ $preset == berlin ]]; then
    "$RS" simulate -preset realistic -seed "$seed" -citygml "$SHARED/data/citygml/berlin-lod2/3910_5819.gml" \
      -aoi 391760,5818980,391900,5819110 -o "$OUT/$name" -q
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
for c in "${CASES[@]}"; do
  simulate "$c"
  for source in matched truth; do
    extra=()
    [[ $source == truth ]] && extra=(-lines "$OUT/$c/groundtruth_edges.json")
    t0=$(date +%s.%N)
    "$RS" run "$OUT/$c" "${extra[@]}" -o "$OUT/$c-$source.gml" -report "$OUT/$c-$source.json" \
      -overwrite -q
    t=$(python3 -c "import sys; print('%.1f' % (float(sys.argv[2]) - float(sys.argv[1])))" "$t0" "$(date +%s.%N)")
    "$RS" eval "$OUT/$c-$source.gml" "$OUT/$c" -json >"$OUT/$c-$source-eval.json" 2>/dev/null
    row "$c" "$source" "$t" "$OUT/$c-$source-eval.json"
  done
done
