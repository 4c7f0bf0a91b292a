#!/usr/bin/env bash
# roofsweep overlay: a model drawn over the block's images, the share of its
# roof edges on an image edge, any CRS, bad input.
source "$(dirname "$0")/lib.sh"

SIM="$WORK/sim"
small_block() {
  [[ -d "$SIM" ]] || "$RS" simulate -preset easy -size 512 -strips 1 -views 2 -buildings 4 -o "$SIM" -q
}

# supported FILE: the report's overall supported fraction.
supported() {
  python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["total"]["supported_fraction"])' "$1"
}

# expect_fraction NAME REPORT OP VALUE: the report's overall supported
# fraction compared with VALUE by OP (a Python comparison, e.g. ">=").
expect_fraction() {
  local f
  f=$(supported "$2")
  if python3 -c "import sys; sys.exit(not (float(sys.argv[1]) $3 float(sys.argv[2])))" "$f" "$4"; then
    pass "$1 ($f)"
  else
    fail "$1" "supported fraction $f, expected $3 $4"
  fi
}

# A copy of the true model as CityJSON moved by DX, DY metres.
shifted_truth() {
  "$RS" convert "$SIM/groundtruth.gml" "$WORK/truth.city.json" -q -overwrite &&
    python3 - "$WORK/truth.city.json" "$1" "$2" "$3" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["transform"]["translate"][0] += float(sys.argv[3])
d["transform"]["translate"][1] += float(sys.argv[4])
json.dump(d, open(sys.argv[2], "w"))
PY
}

test_overlay_of_the_true_model() {
  small_block || { fail simulate "exit $?"; return; }
  expect_ok overlay_truth overlay "$SIM" "$SIM/groundtruth.gml" -o "$WORK/ov" \
    -report "$WORK/ov.json" || return
  for v in s01_i001 s01_i002; do
    local png="$WORK/ov/$v.png"
    if [[ -s "$png" ]] && gdalinfo "$png" | grep -q 'Size is 512, 512' &&
      [[ $(gdalinfo "$png" | grep -c '^Band ') -eq 3 ]]; then
      pass "overlay_png_$v"
    else
      fail "overlay_png_$v" "missing or not a 512 x 512 RGB PNG"
    fi
  done
  if grep -q 'all views' "$WORK/stdout.txt" && grep -q 'on edge' "$WORK/stdout.txt"; then
    pass overlay_table
  else
    fail overlay_table "$(head -c 400 "$WORK/stdout.txt")"
  fi
  # The true roof outline lies on the rendered image edges.
  expect_fraction overlay_truth_supported "$WORK/ov.json" ">=" 0.9
  # Each building with where it stands (the block's CRS, UTM metres here).
  python3 -c '
import json, sys
b = json.load(open(sys.argv[1]))["buildings"]
assert b and all(isinstance(x["x"], float) and x["x"] > 1e5 and x["y"] > 1e6 for x in b), b
' "$WORK/ov.json" && pass overlay_building_places || fail overlay_building_places "x/y missing"
  # The same model 1 m (20 GSD) off is not.
  shifted_truth "$WORK/shifted.city.json" 1 1 || { fail shift "could not write the model"; return; }
  expect_ok overlay_shifted overlay "$SIM" "$WORK/shifted.city.json" -o "$WORK/ov_shifted" \
    -report "$WORK/ov_shifted.json" -q || return
  expect_fraction overlay_shifted_unsupported "$WORK/ov_shifted.json" "<" 0.5
}

test_overlay_reprojects_the_model() {
  small_block || { fail simulate "exit $?"; return; }
  "$RS" convert "$SIM/groundtruth.gml" "$WORK/geo.city.json" -t_srs EPSG:4979 -q -overwrite ||
    { fail convert "exit $?"; return; }
  expect_ok overlay_geographic overlay "$SIM" "$WORK/geo.city.json" -o "$WORK/ov_geo" \
    -report "$WORK/ov_geo.json" -view s01_i002 || return
  if grep -q 'reprojected from EPSG:4979' "$WORK/stdout.txt" && [[ -s "$WORK/ov_geo/s01_i002.png" ]] &&
    [[ ! -e "$WORK/ov_geo/s01_i001.png" ]]; then
    pass overlay_one_view_reprojected
  else
    fail overlay_one_view_reprojected "$(head -c 400 "$WORK/stdout.txt"; ls "$WORK/ov_geo")"
  fi
  expect_fraction overlay_geographic_supported "$WORK/ov_geo.json" ">=" 0.9
}

test_overlay_bad_input() {
  small_block || { fail simulate "exit $?"; return; }
  mkdir -p "$WORK/exists"
  touch "$WORK/exists/s01_i002.png"
  expect_fail overlay_existing_png "$WORK/exists/s01_i001.png" "exists" -- \
    overlay "$SIM" "$SIM/groundtruth.gml" -o "$WORK/exists"
  expect_fail overlay_unknown_view "$WORK/uv/s01_i001.png" "no view named 'nope'" -- \
    overlay "$SIM" "$SIM/groundtruth.gml" -o "$WORK/uv" -view nope
  expect_fail overlay_missing_model "$WORK/mm/s01_i001.png" "none.gml" -- \
    overlay "$SIM" "$WORK/none.gml" -o "$WORK/mm"
  expect_fail overlay_no_output "" "-o DIR" -- overlay "$SIM" "$SIM/groundtruth.gml"
  expect_fail overlay_bad_angle "" "max_angle" -- \
    overlay "$SIM" "$SIM/groundtruth.gml" -o "$WORK/ba" -max_angle 120
  local b="$WORK/corrupt"
  rm -rf "$b" && cp -r "$SIM" "$b" && head -c 300 "$SIM/images/s01_i001.png" >"$b/images/s01_i001.png"
  expect_fail overlay_corrupt_image "$WORK/ci/s01_i002.png" "s01_i001" -- \
    overlay "$b" "$SIM/groundtruth.gml" -o "$WORK/ci"
}

run_tests
