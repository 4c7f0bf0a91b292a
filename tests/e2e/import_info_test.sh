#!/usr/bin/env bash
# roofsweep import / info on made-up and real blocks, and bad input.
source "$(dirname "$0")/lib.sh"

# A tiny OPK block: two 64x48 GeoTIFFs, an orthority-style camera file.
make_block() {
  local d=$1
  mkdir -p "$d"
  for n in a b; do
    gdal_create -q -of GTiff -outsize 64 48 -bands 3 -burn 100 "$d/$n.tif"
  done
  cat >"$d/cam.yaml" <<'Y'
test camera:
    type: pinhole
    im_size: [64, 48]
    focal_len: 50.0
    sensor_size: [6.4, 4.8]
    cx: 0.0
    cy: 0.0
Y
  printf 'a 500000.0 5400000.0 1000.0 0.1 0.2 0.3\nb 500100.0 5400000.0 1000.0 0.1 0.2 0.3\n' >"$d/opk.txt"
}

test_import_opk_then_info() {
  local d="$WORK/ok"
  make_block "$d"
  expect_ok import_opk import opk "$d/opk.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -ground 100 -o "$d/block.json" || return
  expect_ok info_text info "$d/block.json" || return
  grep -q "Images: 2" "$WORK/stdout.txt" && pass info_counts_images || fail info_counts_images "$(cat "$WORK/stdout.txt")"
  expect_ok info_json info "$d" --json || return
  python3 -c "import json,sys; j=json.load(open(sys.argv[1])); assert len(j['images'])==2; g=j['images'][0]['gsd_m']; assert 0.5<g<5, g" "$WORK/stdout.txt" \
    && pass info_json_gsd || fail info_json_gsd "$(head -c 300 "$WORK/stdout.txt")"
  expect_fail refuses_existing_output "" "exists|-overwrite" -- import opk "$d/opk.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -o "$d/block.json"
  expect_ok overwrite_allowed import opk "$d/opk.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -o "$d/block.json" -overwrite
}

test_bad_input() {
  local d="$WORK/bad"
  make_block "$d"
  local out="$d/out.json"
  cp "$d/opk.txt" "$d/good.txt"

  printf 'a 500000.0 5400000.0 1000.0 0.1 0.2\n' >"$d/short.txt"
  expect_fail malformed_line "$out" "short.txt:1" -- import opk "$d/short.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -o "$out"

  printf 'a 500000.0 5400000.0 nan 0.1 0.2 0.3\n' >"$d/nan.txt"
  expect_fail nan_value "$out" "nan.txt:1" -- import opk "$d/nan.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -o "$out"

  printf 'a 500000.0 5400000.0 1000 0.1 0.2 0.3\na 500100.0 5400000.0 1000 0.1 0.2 0.3\n' >"$d/dup.txt"
  expect_fail duplicate_image "$out" "dup.txt:2.*(duplicate|twice)" -- import opk "$d/dup.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -o "$out"

  printf 'c 500000.0 5400000.0 1000 0.1 0.2 0.3\n' >"$d/missing.txt"
  expect_fail missing_image "$out" "'?c'?" -- import opk "$d/missing.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -o "$out"

  expect_fail unknown_crs "$out" "EPSG:999999" -- import opk "$d/good.txt" -camera "$d/cam.yaml" -a_srs EPSG:999999 -o "$out"

  sed 's/focal_len: 50.0/focal_len: 0.0/' "$d/cam.yaml" >"$d/zero.yaml"
  expect_fail zero_focal "$out" "focal" -- import opk "$d/good.txt" -camera "$d/zero.yaml" -a_srs EPSG:32632 -o "$out"

  expect_fail unknown_format "$out" "bogus" -- import bogus "$d/good.txt" -o "$out"
  expect_fail missing_output_dir "" "nodir" -- import opk "$d/opk.txt" -camera "$d/cam.yaml" -o "$d/nodir/x.json"

  # Last: it damages a.tif.
  head -c 300 "$d/a.tif" >"$d/trunc.tif" && mv "$d/trunc.tif" "$d/a.tif"
  expect_fail corrupt_image "$out" "a.tif" -- import opk "$d/good.txt" -camera "$d/cam.yaml" -a_srs EPSG:32632 -o "$out"
}

test_usage_errors() {
  local rc=0
  "$RS" info -bogus x >/dev/null 2>"$WORK/err" || rc=$?
  [[ $rc -eq 1 ]] && grep -q "^ERROR 6: Unknown option name '-bogus'" "$WORK/err" && grep -q "^Usage: roofsweep info" "$WORK/err" \
    && pass unknown_option_usage || fail unknown_option_usage "rc=$rc $(cat "$WORK/err")"
  rc=0
  "$RS" info >/dev/null 2>"$WORK/err" || rc=$?
  [[ $rc -eq 1 ]] && grep -q "Missing argument BLOCK" "$WORK/err" && pass missing_argument || fail missing_argument "rc=$rc $(cat "$WORK/err")"
  rc=0
  "$RS" frobnicate >/dev/null 2>"$WORK/err" || rc=$?
  [[ $rc -eq 1 ]] && grep -q "Unknown command 'frobnicate'" "$WORK/err" && pass unknown_command || fail unknown_command "rc=$rc"
  "$RS" --version | grep -q GDAL && pass version || fail version "no GDAL version"
}

test_real_sets() {
  local s
  s=$(shared_or_skip data/multiview/oxford-vgg/merton1)
  if [[ -n "$s" ]]; then
    expect_ok import_vgg_merton1 import vgg "$s" -o "$WORK/merton1.json" &&
      expect_ok info_merton1 info "$WORK/merton1.json" --json &&
      python3 -c "import json,sys; j=json.load(open(sys.argv[1])); assert len(j['images'])==3; assert all(i['gsd_m']>0 for i in j['images'])" "$WORK/stdout.txt" \
      && pass merton1_three_images || fail merton1_three_images "$(head -c 300 "$WORK/stdout.txt")"
  fi
  s=$(shared_or_skip data/multiview/orthority-ngi-aerial)
  if [[ -n "$s" ]]; then
    expect_ok import_ngi import opk "$s/camera_pos_ori.txt" -camera "$s/ngi_int_param.yaml" -a_srs "$s/ngi_xyz_opk.prj" -dtm "$s/dem.tif" -o "$WORK/ngi.json" &&
      expect_ok info_ngi info "$WORK/ngi.json" --json &&
      python3 -c "
import json,sys; j=json.load(open(sys.argv[1])); im=j['images']
assert len(im)==4, len(im)
# 120 mm lens, 0.144 mm pixels, ~4.5 km above a 150-780 m DEM: GSD about 5 m.
assert all(3 < i['gsd_m'] < 8 for i in im), [i['gsd_m'] for i in im]" "$WORK/stdout.txt" \
      && pass ngi_gsd_plausible || fail ngi_gsd_plausible "$(head -c 600 "$WORK/stdout.txt")"
  fi
  s=$(shared_or_skip data/multiview/opensfm-berlin/reconstruction_example.json)
  if [[ -n "$s" ]]; then
    expect_ok import_opensfm import opensfm "$s" -o "$WORK/berlin.json" &&
      expect_ok info_opensfm info "$WORK/berlin.json" --json &&
      python3 -c "
import json,sys; j=json.load(open(sys.argv[1])); im=j['images']
assert len(im)==3 and j['crs']=='EPSG:32633', j['crs']
# Street-level photos: no ground is claimed, no camera is 'below the ground',
# and the GSD on the facades the cameras converge on is millimetres.
assert not any('below the ground' in w for w in j['warnings']), j['warnings']
assert all(0.0005 < i['gsd_m'] < 0.05 for i in im), [i['gsd_m'] for i in im]" "$WORK/stdout.txt" \
      && pass berlin_street_level_plausible || fail berlin_street_level_plausible "$(head -c 600 "$WORK/stdout.txt")"
  fi
  s=$(shared_or_skip data/multiview/orthority-odm-drone)
  if [[ -n "$s" ]]; then
    expect_ok import_odm_opensfm import opensfm "$s/opensfm/reconstruction.json" -images "$s/images" -dtm "$s/odm_dem/dsm.tif" -o "$WORK/odm.json" &&
      expect_ok info_odm info "$WORK/odm.json" --json &&
      python3 -c "
import json,sys; j=json.load(open(sys.argv[1])); im=j['images']
assert len(im)==4, len(im)
assert all(0.01 < i['gsd_m'] < 0.5 for i in im), [i['gsd_m'] for i in im]
# The set's only elevation model is a DSM: info says so.
assert any('surface model' in w for w in j['warnings']), j['warnings']" "$WORK/stdout.txt" \
      && pass odm_gsd_plausible || fail odm_gsd_plausible "$(head -c 600 "$WORK/stdout.txt")"
    # Given as what it is, the DSM yields a terrain (no surface-model
    # warning), and the manifest keeps the window.
    expect_ok import_odm_dsm import opensfm "$s/opensfm/reconstruction.json" -images "$s/images" -dsm "$s/odm_dem/dsm.tif" -terrain_window 40 -o "$WORK/odm_dsm.json" &&
      expect_ok info_odm_dsm info "$WORK/odm_dsm.json" --json &&
      python3 -c "
import json,sys; j=json.load(open(sys.argv[1]))
assert j['dsm'] and not j['dtm'], (j['dsm'], j['dtm'])
assert not any('surface model' in w for w in j['warnings']), j['warnings']
m=json.load(open(sys.argv[2])); assert m['ground']['terrain_window_m'] == 40, m['ground']" "$WORK/stdout.txt" "$WORK/odm_dsm.json" \
      && pass odm_terrain_from_dsm || fail odm_terrain_from_dsm "$(head -c 600 "$WORK/stdout.txt")"
    expect_fail import_dtm_and_dsm "$WORK/both.json" "exclude each other" -- import opensfm "$s/opensfm/reconstruction.json" -images "$s/images" -dtm "$s/odm_dem/dsm.tif" -dsm "$s/odm_dem/dsm.tif" -o "$WORK/both.json"
  fi
}

run_tests
