#!/usr/bin/env bash
# Paired comparison of two roofsweep builds, or of two sets of `run`
# options, on simulated blocks: how decisions about defaults are made here
# (sweep README, "How much the figures move": one block and one seed cannot
# show a change of a few points).
#
#   scripts/ab-compare.sh OUTDIR RS_A [RS_B]
#
# RS_A, RS_B   roofsweep programs (RS_B defaults to RS_A, to compare options)
# ARGS_A/B     extra `run` options of each side, e.g. ARGS_B="-no_lift_lines"
# LABEL_A/B    result folders under OUTDIR (default A and B). Runs whose
#              evaluation is already there are not run again, so a baseline
#              can be reused: give it a label of its own.
# BLOCKS       simulated blocks, PRESET-SEED, berlin-SEED, slope-SEED (the
#              realistic preset on an 8 % slope falling towards azimuth
#              47 x SEED mod 360, with a DTM) or hills-SEED (the realistic
#              preset over hills spanning up to 12 m, with a DTM),
#              obliques-SEED (the realistic preset with four oblique views
#              beside each nadir one: 40 views, about 5 GB per run),
#              gsd10-SEED (the realistic preset at 10 cm GSD) or
#              overlap60-SEED (the realistic preset flown 60 / 30 %: most
#              ground in two or three views of one strip) (default: the ten
#              below);
#              simulated once into OUTDIR/blocks
# MATCH_SEEDS  matching seeds (default "1 2 3"); the lines are matched once
#              per block and seed by RS_A into OUTDIR/lines, and both sides
#              start from them, so only the later stages are compared
#              (MATCH=each: side B matches with its own program, into
#              OUTDIR/lines-LABEL_B, to compare a change of the matching)
# MATCH_ARGS_A/B extra `match` options of each side (MATCH_ARGS_B needs
#              MATCH=each), e.g. MATCH_ARGS_A="-no_end_check"
# JOBS         runs at a time (default: the number of cores)
#
# Each pair of runs starts from the same lines, once from the lines alone
# and once with the simulator's footprints. The table gives, per figure,
# both means, the mean paired difference B - A with its standard error, and
# how many pairs went up and down. About 15 minutes on two idle cores for
# the default 30 pairs once the lines exist (another 10 to match them).
set -euo pipefail
[[ $# -ge 2 ]] || { sed -n '2,/^set -euo/p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'; exit 2; }
OUT=$1
RS_A=$(realpath "$2")
RS_B=$(realpath "${3:-$2}")
LABEL_A=${LABEL_A:-A}
LABEL_B=${LABEL_B:-B}
[[ $LABEL_A != "$LABEL_B" ]] || { echo "ab-compare: LABEL_A and LABEL_B must differ" >&2; exit 2; }
read -r -a BLOCK_LIST <<<"${BLOCKS:-realistic-1 realistic-2 realistic-3 realistic-7 realistic-11 realistic-13 realistic-17 easy-1 hard-1 berlin-1}"
read -r -a SEEDS <<<"${MATCH_SEEDS:-1 2 3}"
JOBS=${JOBS:-$(nproc)}
SHARED=${ROOFSWEEP_SHARED_DIR:-$(cd "$(dirname "$0")/../.." && pwd)/shared}
mkdir -p "$OUT/blocks" "$OUT/lines" "$OUT/$LABEL_A" "$OUT/$LABEL_B"
export OUT SHARED

simulate() {
  local name=$1 preset=${1%-*} seed=${1##*-} extra=()
  [[ -f "$OUT/blocks/$name/block.json" ]] && return
  # The kinds of block beside the presets: the realistic preset and what
  # makes each different.
  case $preset in
    berlin)
      extra=(-citygml "$SHARED/data/citygml/berlin-lod2/3910_5819.gml"
        -aoi "391760,5818980,391900,5819110") ;;
    slope) extra=(-terrain_slope 8 -terrain_aspect $((47 * seed % 360))) ;;
    hills) extra=(-terrain_relief 12) ;;
    obliques) extra=(-obliques) ;;
    gsd10) extra=(-gsd 0.10) ;;
    overlap60) extra=(-overlap "60,30") ;;
  esac
  if [[ ${#extra[@]} -gt 0 ]]; then preset=realistic; fi
  "$RS_A" simulate -preset "$preset" -seed "$seed" "${extra[@]}" -o "$OUT/blocks/$name" -q
}
export -f simulate
export RS_A
printf '%s\0' "${BLOCK_LIST[@]}" | xargs -0 -P "$JOBS" -n 1 bash -c 'simulate "$@"' _

# Jobs are fed to xargs NUL-separated, so that paths may hold spaces.
# Outputs are written to a temporary name first, so that an interrupted
# comparison does not reuse half a file.
# PROGRAM LINES_DIR ARGS BLOCK SEED
match_job() {
  local rs=$1 dir=$2 args=$3 b=$4 s=$5
  local f="$dir/$b-s$s.gpkg"
  [[ -f $f ]] && return
  # shellcheck disable=SC2086 # ARGS are options, split on purpose
  "$rs" match "$OUT/blocks/$b" -seed "$s" $args -o "$f.tmp.gpkg" -overwrite -q
  mv "$f.tmp.gpkg" "$f"
}
# PROGRAM LINES_DIR LABEL ARGS BLOCK SEED MODE
run_job() {
  local rs=$1 lines=$2 label=$3 args=$4 b=$5 s=$6 mode=$7
  local base="$OUT/$label/$b-s$s-$mode" extra=()
  [[ -f $base-eval.json ]] && return
  [[ $mode == footprints ]] && extra=(-footprints "$OUT/blocks/$b/footprints.gpkg")
  # shellcheck disable=SC2086 # ARGS are options, split on purpose
  "$rs" run "$OUT/blocks/$b" -lines "$lines/$b-s$s.gpkg" "${extra[@]}" $args \
    -o "$base.gpkg" -overwrite -q
  "$rs" eval "$base.gpkg" "$OUT/blocks/$b" -json >"$base-eval.tmp"
  mv "$base-eval.tmp" "$base-eval.json"
}
export -f match_job run_job

LINES_A="$OUT/lines" LINES_B="$OUT/lines"
[[ -z ${MATCH_ARGS_B:-} || ${MATCH:-shared} == each ]] ||
  { echo "ab-compare: MATCH_ARGS_B needs MATCH=each" >&2; exit 2; }
if [[ ${MATCH:-shared} == each ]]; then
  LINES_B="$OUT/lines-$LABEL_B"
  mkdir -p "$LINES_B"
fi
{
  for b in "${BLOCK_LIST[@]}"; do
    for s in "${SEEDS[@]}"; do
      printf '%s\0%s\0%s\0%s\0%s\0' "$RS_A" "$LINES_A" "${MATCH_ARGS_A:-}" "$b" "$s"
      [[ $LINES_B == "$LINES_A" ]] ||
        printf '%s\0%s\0%s\0%s\0%s\0' "$RS_B" "$LINES_B" "${MATCH_ARGS_B:-}" "$b" "$s"
    done
  done
} | xargs -0 -P "$JOBS" -n 5 bash -c 'match_job "$@"' _

jobs_file=$(mktemp)
trap 'rm -f "$jobs_file"' EXIT
for b in "${BLOCK_LIST[@]}"; do
  for s in "${SEEDS[@]}"; do
    for mode in matched footprints; do
      printf '%s\0%s\0%s\0%s\0%s\0%s\0%s\0' "$RS_A" "$LINES_A" "$LABEL_A" "${ARGS_A:-}" "$b" "$s" "$mode"
      printf '%s\0%s\0%s\0%s\0%s\0%s\0%s\0' "$RS_B" "$LINES_B" "$LABEL_B" "${ARGS_B:-}" "$b" "$s" "$mode"
    done
  done
done >"$jobs_file"
xargs -0 -P "$JOBS" -n 7 bash -c 'run_job "$@"' _ <"$jobs_file"

python3 - "$OUT" "$LABEL_A" "$LABEL_B" "${SEEDS[*]}" "${BLOCK_LIST[@]}" <<'PY'
import json, math, sys
out, la, lb, seeds = sys.argv[1:5]
blocks = sys.argv[5:]
figures = [
    ("plane quality", lambda d: d["roof_planes"]["quality"], 100),
    ("plane completeness", lambda d: d["roof_planes"]["completeness"], 100),
    ("plane correctness", lambda d: d["roof_planes"]["correctness"], 100),
    ("vertices within 2 GSD", lambda d: d["geometry"]["vertex_within_2gsd"], 100),
    ("vertex RMS (GSD)", lambda d: d["geometry"]["vertex_rms_gsd"], 1),
    ("RMSZ (m)", lambda d: d["geometry"].get("rmsz_m"), 1),
    ("building quality", lambda d: d["buildings"]["quality"], 100),
    ("building roof tops within 2 m", lambda d: d["buildings"]["top_compared"] and
     (d["buildings"]["top_compared"] - d["buildings"]["top_off"]) / d["buildings"]["top_compared"]
     if "top_compared" in d["buildings"] else None, 100),
    ("roof type agreement", lambda d: d["buildings"].get("roof_type_agreement"), 100),
]
for mode in ("matched", "footprints"):
    print("\n%s (%s): %s against %s, %d blocks x seeds %s" % (
        "from matched lines" if mode == "matched" else "with footprints", mode, lb, la,
        len(blocks), seeds))
    print("| figure | %s mean | %s mean | %s - %s | up / down |" % (la, lb, lb, la))
    print("| --- | ---: | ---: | ---: | ---: |")
    for name, get, scale in figures:
        a, b = [], []
        for bl in blocks:
            for s in seeds.split():
                da = json.load(open("%s/%s/%s-s%s-%s-eval.json" % (out, la, bl, s, mode)))
                db = json.load(open("%s/%s/%s-s%s-%s-eval.json" % (out, lb, bl, s, mode)))
                va, vb = get(da), get(db)
                if va is None or vb is None:
                    continue
                a.append(scale * va)
                b.append(scale * vb)
        if not a:
            print("| %s | n/a | n/a | n/a | |" % name)
            continue
        d = [y - x for x, y in zip(a, b)]
        n = len(d)
        mean = sum(d) / n
        se = math.sqrt(sum((x - mean) ** 2 for x in d) / (n - 1) / n) if n > 1 else float("nan")
        print("| %s | %.2f | %.2f | %+.2f ± %.2f | %d / %d |" % (
            name, sum(a) / n, sum(b) / n, mean, se, sum(x > 1e-9 for x in d),
            sum(x < -1e-9 for x in d)))
PY
