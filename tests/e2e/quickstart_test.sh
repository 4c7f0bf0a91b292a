#!/usr/bin/env bash
# examples/quickstart.sh and examples/tiles.sh must run as written.
source "$(dirname "$0")/lib.sh"
ROOT=$(cd "$(dirname "$0")/../.." && pwd)

# run_example NAME SCRIPT DIR: runs examples/SCRIPT into $WORK/DIR, output
# in $WORK/NAME.out.
run_example() {
  if "$ROOT/examples/$2" "$RS" "$WORK/$3" >"$WORK/$1.out" 2>"$WORK/$1.err"; then
    pass "${1}_exit_0"
  else
    fail "${1}_exit_0" "$(tail -5 "$WORK/$1.err")"
    return 1
  fi
}

test_quickstart_runs() {
  run_example quickstart quickstart.sh q || return
  cp "$WORK/quickstart.out" "$WORK/out.txt"
  for f in block.json lines.gpkg lines3d.gpkg buildings.gpkg run.json buildings.gml buildings.city.json \
    truth.fgb overlay.png check.json; do
    [[ -s "$WORK/q/$f" ]] && pass "quickstart_wrote_$f" || fail "quickstart_wrote_$f" "missing"
  done
  grep -q "completeness" "$WORK/out.txt" && pass quickstart_prints_scores || fail quickstart_prints_scores "no table"
  grep -q "<bldg:Building " "$WORK/q/buildings.gml" && pass quickstart_built_buildings \
    || fail quickstart_built_buildings "no building reconstructed"
}

test_tiles_example_runs() {
  run_example tiles tiles.sh t || return
  cp "$WORK/tiles.out" "$WORK/tout.txt"
  grep -Eq "^[0-9]+ tiles of 60 m" "$WORK/tout.txt" && pass tiles_grid || fail tiles_grid "$(head -3 "$WORK/tout.txt")"
  # info -tiles: whole 60 m cells on multiples of 60, each once.
  python3 - "$WORK/t/tiles.txt" <<'PY' && pass tiles_aligned || fail tiles_aligned "$(head -3 "$WORK/t/tiles.txt")"
import sys
cells = [tuple(map(float, l.split(","))) for l in open(sys.argv[1])]
assert cells and len(set(cells)) == len(cells)
assert all(c[2] - c[0] == 60 and c[3] - c[1] == 60 and c[0] % 60 == 0 and c[1] % 60 == 0 for c in cells)
PY
  expect_fail tiles_bad_size "" "positive tile size" -- info "$WORK/t/sim" -tiles 0
  # Every building of the gathered model comes from one tile: the ids say which.
  python3 - "$WORK/t/city.gml" <<'PY' && pass tiles_gathered || fail tiles_gathered "$(grep -c "<bldg:Building " "$WORK/t/city.gml")"
import re, sys
ids = re.findall(r'<bldg:Building gml:id="([^"]+)"', open(sys.argv[1]).read())
assert ids and len(set(ids)) == len(ids), ids
assert all(re.match(r"t-?[0-9.]+_-?[0-9.]+_rs_b[0-9]+$", i) for i in ids), ids
PY
  grep -q "completeness" "$WORK/tout.txt" && pass tiles_prints_scores || fail tiles_prints_scores "no table"
}

run_tests
