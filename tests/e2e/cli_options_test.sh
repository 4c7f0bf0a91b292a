#!/usr/bin/env bash
# Options every output command shares: -t_srs/-a_srs, -co/-lco/-dsco,
# -options FILE.json, and the wrong-usage contract (one ERROR line, the
# usage, exit 1).
source "$(dirname "$0")/lib.sh"

SIM="$WORK/sim"
small_block() {
  [[ -d "$SIM" ]] || "$RS" simulate -preset easy -seed 5 -size 512 -gsd 0.15 -strips 1 -views 2 -buildings 4 -o "$SIM" -q
}

# First vertex of a CityJSON file, decoded with its transform.
first_vertex() {
  python3 -c "
import json,sys; j=json.load(open(sys.argv[1])); t=j['transform']; v=j['vertices'][0]
print(*['%.9f' % (v[i]*t['scale'][i]+t['translate'][i]) for i in range(3)])" "$1"
}

test_convert_t_srs_reprojects() {
  small_block || { fail simulate "exit $?"; return; }
  expect_ok convert_same_crs convert "$SIM/groundtruth.gml" "$WORK/utm32.city.json" -q || return
  expect_ok convert_t_srs convert "$SIM/groundtruth.gml" "$WORK/wgs84.city.json" -t_srs EPSG:4979 -q || return
  grep -q '"referenceSystem":"https://www.opengis.net/def/crs/EPSG/0/4979"' "$WORK/wgs84.city.json" \
    && pass t_srs_written_crs || fail t_srs_written_crs "$(grep -o '"referenceSystem":"[^"]*"' "$WORK/wgs84.city.json")"
  # The same vertex through PROJ's own command-line tool.
  local want got
  want=$(first_vertex "$WORK/utm32.city.json" | cs2cs -d 9 EPSG:25832 EPSG:4979 | awk '{print $2, $1, $3}')
  got=$(first_vertex "$WORK/wgs84.city.json")
  python3 -c "
import sys; w=list(map(float,sys.argv[1].split())); g=list(map(float,sys.argv[2].split()))
assert abs(w[0]-g[0])<2e-8 and abs(w[1]-g[1])<2e-8 and abs(w[2]-g[2])<2e-3, (w,g)
assert 11 < g[0] < 12 and 48 < g[1] < 49, g" "$want" "$got" \
    && pass t_srs_matches_cs2cs || fail t_srs_matches_cs2cs "cs2cs: $want, roofsweep: $got"
  grep -q '"roofsweep_validity":"valid"' "$WORK/wgs84.city.json" \
    && pass t_srs_checks_in_metres || fail t_srs_checks_in_metres "solid checks run on degrees"
  expect_ok convert_t_srs_gpkg convert "$WORK/utm32.city.json" "$WORK/utm33.gpkg" -t_srs EPSG:25833 -q || return
  ogrinfo -ro -so "$WORK/utm33.gpkg" roof_surfaces >"$WORK/ogr.txt" 2>&1
  grep -q 'UTM zone 33N' "$WORK/ogr.txt" && grep -qE 'Extent: \(24[0-9]{4}\.' "$WORK/ogr.txt" \
    && pass t_srs_gpkg_utm33 || fail t_srs_gpkg_utm33 "$(grep -E 'Extent|PROJCRS' "$WORK/ogr.txt")"
  expect_ok convert_a_srs convert "$WORK/utm32.city.json" "$WORK/relabelled.gpkg" -a_srs EPSG:25833 -q || return
  ogrinfo -ro -so "$WORK/relabelled.gpkg" roof_surfaces >"$WORK/ogr.txt" 2>&1
  grep -q 'UTM zone 33N' "$WORK/ogr.txt" && grep -qE 'Extent: \(69[0-9]{4}\.' "$WORK/ogr.txt" \
    && pass a_srs_keeps_coordinates || fail a_srs_keeps_coordinates "$(grep -E 'Extent|PROJCRS' "$WORK/ogr.txt")"
  expect_fail t_srs_ballpark_refused "$WORK/bp.gpkg" "ballpark" -- convert "$WORK/utm32.city.json" "$WORK/bp.gpkg" -t_srs EPSG:25832+7837
  expect_fail t_srs_unknown_crs "$WORK/uk.gpkg" "EPSG:999999" -- convert "$WORK/utm32.city.json" "$WORK/uk.gpkg" -t_srs EPSG:999999
  expect_fail t_srs_with_a_srs "$WORK/both.gpkg" "exclude" -- convert "$WORK/utm32.city.json" "$WORK/both.gpkg" -t_srs EPSG:4326 -a_srs EPSG:25832
}

test_match_t_srs_reprojects_lines() {
  small_block || return
  expect_ok match_t_srs match "$SIM" -o "$WORK/lines_wgs84.gpkg" -t_srs EPSG:4979 -q || return
  ogrinfo -ro -so "$WORK/lines_wgs84.gpkg" lines3d >"$WORK/ogr.txt" 2>&1
  grep -q 'GEOGCRS\["WGS 84"' "$WORK/ogr.txt" && grep -qE 'Extent: \(11\.56[0-9]*, 48\.1' "$WORK/ogr.txt" \
    && pass match_t_srs_degrees || fail match_t_srs_degrees "$(grep -E 'Extent|CRS' "$WORK/ogr.txt")"
  expect_fail match_t_srs_unknown "$WORK/l.gpkg" "EPSG:999999" -- match "$SIM" -o "$WORK/l.gpkg" -t_srs EPSG:999999
}

run_tests
