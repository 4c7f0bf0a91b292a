#!/usr/bin/env bash
# roofsweep lines: per-image segment layers, overlays, bad input.
source "$(dirname "$0")/lib.sh"

SIM="$WORK/sim"
small_block() {
  [[ -d "$SIM" ]] || "$RS" simulate -preset easy -size 512 -strips 1 -views 2 -buildings 4 -o "$SIM" -q
}

# feature_count FILE LAYER: the layer's feature count, empty when missing.
feature_count() {
  ogrinfo -so -ro "$1" "$2" 2>/dev/null | sed -n 's/^Feature Count: //p'
}

# A copy of the simulated block whose first image is replaced by $2 (a
# command writing the file named by its last argument).
block_with_first_image() {
  local dir="$WORK/$1"
  shift
  rm -rf "$dir"
  cp -r "$SIM" "$dir"
  "$@" "$dir/images/s01_i001.png" >/dev/null 2>&1
  echo "$dir"
}

test_lines_writes_one_layer_per_image() {
  small_block || { fail simulate "exit $?"; return; }
  expect_ok lines_default lines "$SIM" -o "$WORK/lines.gpkg" -png "$WORK/png" -q || return
  for i in 001 002; do
    local n
    n=$(feature_count "$WORK/lines.gpkg" "lines_s01_i$i")
    if [[ -n "$n" && "$n" -gt 5 ]]; then
      pass "layer_lines_s01_i$i ($n features)"
    else
      fail "layer_lines_s01_i$i" "missing or too few features: '$n'"
    fi
  done
  # 2D lines in pixel coordinates inside the 512 x 512 image.
  if ogrinfo -so -ro "$WORK/lines.gpkg" lines_s01_i001 | grep -q '^Geometry: Line String$' &&
    ogrinfo -so -ro "$WORK/lines.gpkg" lines_s01_i001 |
    awk -F'[(), -]+' '/^Extent/ { exit !($2 >= 0 && $3 >= 0 && $4 <= 512 && $5 <= 512) }'; then
    pass lines_pixel_extent
  else
    fail lines_pixel_extent "$(ogrinfo -so -ro "$WORK/lines.gpkg" lines_s01_i001 | grep -E 'Geometry|Extent')"
  fi
  if ogrinfo -ro "$WORK/lines.gpkg" lines_s01_i001 -fid 1 | grep -q 'length_px (Real)' &&
    ogrinfo -ro "$WORK/lines.gpkg" lines_s01_i001 -fid 1 | grep -q 'colour_left (String) = #' &&
    ogrinfo -ro "$WORK/lines.gpkg" lines_s01_i001 -fid 1 | grep -Eq 'texture \(Integer(64)?\) = [01]$'; then
    pass lines_attributes
  else
    fail lines_attributes "fields missing"
  fi
  # The coarse-scale fusion only adds segments (scale 2) to the default ones.
  expect_ok lines_coarse lines "$SIM" -o "$WORK/lines_coarse.gpkg" -coarse_edges -q || return
  local fine coarse only_fine
  fine=$(feature_count "$WORK/lines.gpkg" lines_s01_i001)
  coarse=$(feature_count "$WORK/lines_coarse.gpkg" lines_s01_i001)
  only_fine=$(ogrinfo -ro -q "$WORK/lines_coarse.gpkg" -sql \
    "SELECT COUNT(*) AS n FROM lines_s01_i001 WHERE scale = 1" | sed -n 's/.*n (Integer.*) = //p')
  if [[ -n "$coarse" && "$only_fine" == "$fine" && "$coarse" -ge "$fine" ]]; then
    pass "lines_coarse_adds_only ($fine + $((coarse - fine)))"
  else
    fail lines_coarse_adds_only "default $fine, with -coarse_edges $coarse of which scale 1: '$only_fine'"
  fi
  for i in 001 002; do
    local png="$WORK/png/lines_s01_i$i.png"
    if [[ -s "$png" ]] && gdalinfo "$png" | grep -q 'Size is 512, 512' &&
      [[ $(gdalinfo "$png" | grep -c '^Band ') -eq 3 ]]; then
      pass "overlay_$i"
    else
      fail "overlay_$i" "missing or not a 512 x 512 RGB PNG"
    fi
  done
  # Overlays differ from the input image (the segments are drawn).
  if ! cmp -s "$WORK/png/lines_s01_i001.png" "$SIM/images/s01_i001.png"; then
    pass overlay_has_segments
  else
    fail overlay_has_segments "identical to the input"
  fi
}

test_lines_is_deterministic() {
  small_block || return
  "$RS" lines "$SIM" -o "$WORK/a.gpkg" -q && "$RS" lines "$SIM" -o "$WORK/b.gpkg" -q || {
    fail lines_deterministic "lines failed"
    return
  }
  if diff <(ogrinfo -ro -al "$WORK/a.gpkg" | grep -v 'a.gpkg') \
    <(ogrinfo -ro -al "$WORK/b.gpkg" | grep -v 'b.gpkg') >/dev/null; then
    pass lines_deterministic
  else
    fail lines_deterministic "two runs differ"
  fi
}

test_lines_methods_and_options() {
  small_block || return
  expect_ok lines_dizenzo lines "$SIM" -o "$WORK/dz.gpkg" --method dizenzo --min-length 30 -q || return
  local n_long n_default
  n_long=$(feature_count "$WORK/dz.gpkg" lines_s01_i001)
  "$RS" lines "$SIM" -o "$WORK/dz15.gpkg" -method dizenzo -q
  n_default=$(feature_count "$WORK/dz15.gpkg" lines_s01_i001)
  if [[ -n "$n_long" && -n "$n_default" && "$n_long" -lt "$n_default" ]]; then
    pass min_length_drops_short_segments
  else
    fail min_length_drops_short_segments "30 px: '$n_long', 15 px: '$n_default'"
  fi
  expect_ok lines_grey lines "$SIM" -o "$WORK/grey.gpkg" -method grey -q
  expect_fail unknown_method "$WORK/bad.gpkg" "max, dizenzo or grey" -- lines "$SIM" -o "$WORK/bad.gpkg" -method sobel
  expect_fail existing_output "" "exists" -- lines "$SIM" -o "$WORK/dz.gpkg"
  expect_ok overwrite lines "$SIM" -o "$WORK/dz.gpkg" -overwrite -q
  expect_fail missing_block "$WORK/none.gpkg" "no such" -- lines "$WORK/nothing" -o "$WORK/none.gpkg"
}

test_lines_bad_images() {
  small_block || return
  local b
  b=$(block_with_first_image missing rm -f)
  expect_fail missing_image "$WORK/m.gpkg" "s01_i001" -- lines "$b" -o "$WORK/m.gpkg"
  b=$(block_with_first_image corrupt sh -c 'head -c 300 /dev/urandom > "$0"')
  expect_fail corrupt_image "$WORK/c.gpkg" "s01_i001" -- lines "$b" -o "$WORK/c.gpkg" -png "$WORK/cpng"
  [[ -z "$(ls -A "$WORK/cpng" 2>/dev/null)" ]] && pass corrupt_image_no_overlays ||
    fail corrupt_image_no_overlays "overlays written for a refused block"
  b=$(block_with_first_image tiny sh -c 'gdal_translate -q -outsize 1 1 "'"$SIM"'/images/s01_i001.png" "$0"')
  expect_fail one_pixel_image "$WORK/t.gpkg" "s01_i001" -- lines "$b" -o "$WORK/t.gpkg"
  # Handled, not refused: one band (grey method), 16 bits, all black.
  b=$(block_with_first_image grey sh -c 'gdal_translate -q -b 1 "'"$SIM"'/images/s01_i001.png" "$0"')
  expect_ok one_band_image lines "$b" -o "$WORK/g.gpkg" -q &&
    [[ $(feature_count "$WORK/g.gpkg" lines_s01_i001) -gt 5 ]] && pass one_band_has_segments ||
    fail one_band_has_segments "no segments"
  b=$(block_with_first_image deep sh -c 'gdal_translate -q -ot UInt16 -scale 0 255 0 65535 "'"$SIM"'/images/s01_i001.png" "$0"')
  expect_ok sixteen_bit_image lines "$b" -o "$WORK/d.gpkg" -q &&
    [[ $(feature_count "$WORK/d.gpkg" lines_s01_i001) -gt 5 ]] && pass sixteen_bit_has_segments ||
    fail sixteen_bit_has_segments "no segments"
  b=$(block_with_first_image black sh -c 'gdal_translate -q -scale 0 255 0 0 "'"$SIM"'/images/s01_i001.png" "$0"')
  expect_ok black_image lines "$b" -o "$WORK/k.gpkg" -q &&
    [[ $(feature_count "$WORK/k.gpkg" lines_s01_i001) -eq 0 ]] && pass black_image_empty_layer ||
    fail black_image_empty_layer "expected an empty layer"
}

run_tests
