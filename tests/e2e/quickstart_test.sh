#!/usr/bin/env bash
# examples/quickstart.sh must run as written.
source "$(dirname "$0")/lib.sh"
ROOT=$(cd "$(dirname "$0")/../.." && pwd)

test_quickstart_runs() {
  if "$ROOT/examples/quickstart.sh" "$RS" "$WORK/q" >"$WORK/out.txt" 2>"$WORK/err.txt"; then
    pass quickstart_exit_0
  else
    fail quickstart_exit_0 "$(tail -5 "$WORK/err.txt")"
    return
  fi
  for f in block.json lines.gpkg lines3d.gpkg buildings.gpkg run.json buildings.gml buildings.city.json \
    truth.fgb overlay.png check.json; do
    [[ -s "$WORK/q/$f" ]] && pass "quickstart_wrote_$f" || fail "quickstart_wrote_$f" "missing"
  done
  grep -q "completeness" "$WORK/out.txt" && pass quickstart_prints_scores || fail quickstart_prints_scores "no table"
  grep -q "<bldg:Building " "$WORK/q/buildings.gml" && pass quickstart_built_buildings \
    || fail quickstart_built_buildings "no building reconstructed"
}

run_tests
