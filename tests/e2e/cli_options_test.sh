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
  expect_fail match_t_srs_unknown "$WORK/uk_lines.gpkg" "EPSG:999999" -- match "$SIM" -o "$WORK/uk_lines.gpkg" -t_srs EPSG:999999
}

test_creation_options() {
  small_block || return
  expect_ok convert_lco convert "$SIM/groundtruth.gml" "$WORK/lco.gpkg" -lco FID=myfid -lco SPATIAL_INDEX=NO -dsco VERSION=1.2 -q || return
  ogrinfo -ro -so "$WORK/lco.gpkg" roof_surfaces >"$WORK/ogr.txt" 2>&1
  grep -q '^FID Column = myfid' "$WORK/ogr.txt" && pass lco_fid_column || fail lco_fid_column "$(grep -i fid "$WORK/ogr.txt")"
  ogrinfo -ro -q "$WORK/lco.gpkg" -sql "SELECT COUNT(*) AS n FROM sqlite_master WHERE name LIKE 'rtree_%'" >"$WORK/ogr.txt" 2>&1
  grep -q 'n (Integer) = 0' "$WORK/ogr.txt" && pass lco_no_spatial_index || fail lco_no_spatial_index "$(cat "$WORK/ogr.txt")"
  ogrinfo -ro -q "$WORK/lco.gpkg" -sql "PRAGMA user_version" >"$WORK/ogr.txt" 2>&1
  grep -q '= 10200' "$WORK/ogr.txt" && pass dsco_gpkg_version || fail dsco_gpkg_version "$(cat "$WORK/ogr.txt")"
  expect_ok convert_co_decimals convert "$SIM/groundtruth.gml" "$WORK/d1.gml" -co DECIMALS=1 -q || return
  python3 -c "
import re,sys; t=open(sys.argv[1]).read(); nums=re.findall(r'posList[^>]*>([^<]*)<', t)
assert nums and all(len(x.split('.')[1]) <= 1 for p in nums for x in p.split() if '.' in x), nums[:1]" "$WORK/d1.gml" \
    && pass co_decimals_one || fail co_decimals_one "more than one decimal written"
  expect_ok match_lco match "$SIM" -o "$WORK/m.gpkg" -lco GEOMETRY_NAME=shape -q || return
  ogrinfo -ro -so "$WORK/m.gpkg" lines3d 2>&1 | grep -q '^Geometry Column = shape' && pass match_lco_geometry_name || fail match_lco_geometry_name "no shape column"
  expect_ok lines_lco lines "$SIM" -o "$WORK/l.gpkg" -lco FID=seg -q || return
  ogrinfo -ro -so "$WORK/l.gpkg" "$(ogrinfo -ro -q "$WORK/l.gpkg" | awk -F'[: ]+' 'NR==1{print $2}')" 2>&1 | grep -q '^FID Column = seg' \
    && pass lines_lco_fid || fail lines_lco_fid "no FID column seg"
  expect_fail lco_malformed "$WORK/bad.gpkg" "NAME=VALUE" -- convert "$SIM/groundtruth.gml" "$WORK/bad.gpkg" -lco SPATIAL_INDEX
  grep -q '^Usage: roofsweep convert' "$WORK/stderr.txt" && pass lco_malformed_usage || fail lco_malformed_usage "no usage"
  expect_fail lco_unknown "$WORK/bad.gpkg" "layer creation option 'BOGUS'" -- convert "$SIM/groundtruth.gml" "$WORK/bad.gpkg" -lco BOGUS=1
  expect_fail lco_bad_value "$WORK/bad.gpkg" "SPATIAL_INDEX expects YES or NO" -- match "$SIM" -o "$WORK/bad.gpkg" -lco SPATIAL_INDEX=maybe
  expect_fail dsco_on_cityjson "$WORK/bad.city.json" "-dsco/-lco" -- convert "$SIM/groundtruth.gml" "$WORK/bad.city.json" -dsco VERSION=1.2
  expect_fail co_on_gpkg "$WORK/bad.gpkg" "-co" -- convert "$SIM/groundtruth.gml" "$WORK/bad.gpkg" -co DECIMALS=2
  expect_fail co_unknown_cityjson "$WORK/bad.city.json" "no creation option 'DECIMALS'" -- convert "$SIM/groundtruth.gml" "$WORK/bad.city.json" -co DECIMALS=2
}

test_options_file() {
  small_block || return
  printf '{"min_length": 40, "lco": ["FID=zz"], "overwrite": true}\n' >"$WORK/opts.json"
  expect_ok options_file match "$SIM" -o "$WORK/o40.gpkg" -options "$WORK/opts.json" -q || return
  expect_ok options_cli_wins match "$SIM" -o "$WORK/o15.gpkg" -options "$WORK/opts.json" -min_length 15 -q || return
  local n40 n15
  n40=$(ogrinfo -ro -so "$WORK/o40.gpkg" lines3d | awk '/Feature Count/{print $3}')
  n15=$(ogrinfo -ro -so "$WORK/o15.gpkg" lines3d | awk '/Feature Count/{print $3}')
  ogrinfo -ro -so "$WORK/o40.gpkg" lines3d | grep -q '^FID Column = zz' && [[ $n40 -gt 0 && $n40 -lt $n15 ]] \
    && pass options_file_applied || fail options_file_applied "40 px: $n40 lines, 15 px: $n15 lines"
  printf '{"min_length": 20,\n "bogus": 1}\n' >"$WORK/unknown.json"
  expect_fail options_unknown_key "$WORK/u.gpkg" "unknown.json: /bogus: unknown option" -- match "$SIM" -o "$WORK/u.gpkg" -options "$WORK/unknown.json"
  printf '{"min_length": "long"}\n' >"$WORK/type.json"
  expect_fail options_wrong_type "$WORK/u.gpkg" "type.json: /min_length: expects a number" -- match "$SIM" -o "$WORK/u.gpkg" -options "$WORK/type.json"
  printf '{"overwrite": true,\n "min_length": }\n' >"$WORK/broken.json"
  expect_fail options_malformed "$WORK/u.gpkg" "broken.json:2: malformed JSON" -- match "$SIM" -o "$WORK/u.gpkg" -options "$WORK/broken.json"
  grep -q '^Usage: roofsweep match' "$WORK/stderr.txt" && pass options_malformed_usage || fail options_malformed_usage "no usage"
}

# expect_usage NAME CMD PATTERN -- roofsweep args...: exit 1, one ERROR line
# matching PATTERN, the command's usage on stderr, nothing on stdout.
expect_usage() {
  local name=$1 cmd=$2 pattern=$3
  shift 4
  local rc=0 nerr
  "$RS" "$@" >"$WORK/stdout.txt" 2>"$WORK/stderr.txt" || rc=$?
  nerr=$(grep -c '^ERROR' "$WORK/stderr.txt" || true)
  if [[ $rc -ne 1 ]]; then
    fail "$name" "exit $rc (expected 1): $(head -c 300 "$WORK/stderr.txt")"
  elif [[ $nerr -ne 1 ]] || ! grep -qE -- "^ERROR.*$pattern" "$WORK/stderr.txt"; then
    fail "$name" "expected one ERROR line matching /$pattern/: $(head -c 400 "$WORK/stderr.txt")"
  elif ! grep -q "^Usage: roofsweep $cmd " "$WORK/stderr.txt"; then
    fail "$name" "no usage of $cmd: $(head -c 400 "$WORK/stderr.txt")"
  elif [[ -s "$WORK/stdout.txt" ]]; then
    fail "$name" "stdout not empty: $(head -c 200 "$WORK/stdout.txt")"
  else
    pass "$name"
  fi
}

test_wrong_usage() {
  small_block || return
  local gt="$SIM/groundtruth.gml"
  # Unknown option.
  expect_usage usage_unknown_option_convert convert "Unknown option name '-bogus'" -- convert "$gt" "$WORK/u1.gpkg" -bogus
  expect_usage usage_unknown_option_match match "Unknown option name '-frobnicate'" -- match "$SIM" -o "$WORK/u1.gpkg" -frobnicate 3
  # Missing argument, missing option value.
  expect_usage usage_missing_argument convert "Missing argument OUT" -- convert "$gt"
  expect_usage usage_missing_value convert "Option -of needs a value" -- convert "$gt" "$WORK/u1.gpkg" -of
  expect_usage usage_missing_value_lco lines "Option -lco needs a value" -- lines "$SIM" -o "$WORK/u1.gpkg" -lco
  expect_usage usage_missing_output match "Missing option -o" -- match "$SIM"
  expect_usage usage_bad_number match "Option -min_length expects a number" -- match "$SIM" -o "$WORK/u1.gpkg" -min_length ten
  expect_usage usage_negative_seed match "-seed must be 0 or more" -- match "$SIM" -o "$WORK/u1.gpkg" -seed -1
  expect_usage usage_negative_seed_run run "-seed must be 0 or more" -- run "$SIM" -o "$WORK/u1.gml" -seed -1
  # Unknown format.
  expect_usage usage_unknown_format_convert convert "Unknown output format 'Bogus'" -- convert "$gt" "$WORK/u1.xyz" -of Bogus
  expect_usage usage_unknown_extension_convert convert "Cannot tell the format of .*u1.xyz" -- convert "$gt" "$WORK/u1.xyz"
  expect_usage usage_unknown_format_match match "Unknown output format 'Bogus'" -- match "$SIM" -o "$WORK/u1.gpkg" -of Bogus
  expect_usage usage_unknown_format_lines lines "Unknown output format 'Bogus'" -- lines "$SIM" -o "$WORK/u1.gpkg" -of Bogus
  expect_usage usage_unknown_extension_match match "Cannot tell the vector format" -- match "$SIM" -o "$WORK/u1.xyz"
  expect_usage usage_unknown_import_format import "Unknown import format 'bogus'" -- import bogus "$SIM/orientation/opk.txt" -o "$WORK/u1.json"
  for f in u1.gpkg u1.xyz u1.json u1.gml; do [[ -e "$WORK/$f" ]] && fail "usage_left_$f" "output written"; done
  # Output exists without -overwrite: refused before any work, file untouched.
  touch "$WORK/exists.gpkg" "$WORK/exists.json" "$WORK/exists.png"
  mkdir -p "$WORK/exists_dir"
  expect_usage usage_exists_convert convert "exists.gpkg exists; pass -overwrite" -- convert "$gt" "$WORK/exists.gpkg"
  expect_usage usage_exists_match match "exists.gpkg exists; pass -overwrite" -- match "$SIM" -o "$WORK/exists.gpkg"
  expect_usage usage_exists_lines lines "exists.gpkg exists; pass -overwrite" -- lines "$SIM" -o "$WORK/exists.gpkg"
  expect_usage usage_exists_import import "exists.json exists; pass -overwrite" -- import opk "$SIM/orientation/opk.txt" -camera "$SIM/orientation/camera.yaml" -o "$WORK/exists.json"
  expect_usage usage_exists_simulate simulate "exists_dir exists; pass -overwrite" -- simulate -preset easy -o "$WORK/exists_dir"
  expect_usage usage_exists_eval eval "exists.png exists; pass -overwrite" -- eval "$gt" "$SIM" -png "$WORK/exists.png"
  expect_usage usage_exists_eval_vertices eval "exists.gpkg exists; pass -overwrite" -- eval "$gt" "$SIM" -vertices "$WORK/exists.gpkg"
  [[ ! -s "$WORK/exists.gpkg" && ! -s "$WORK/exists.json" ]] && pass usage_exists_untouched || fail usage_exists_untouched "an existing output was changed"
}

# The program runs itself again with malloc advising transparent huge pages
# where the kernel gives them only on advice (heap_policy.h); a user's
# glibc.malloc.hugetlb=0 keeps it from doing so.
test_huge_page_heap() {
  local mode glibc
  mode=$(cat /sys/kernel/mm/transparent_hugepage/enabled 2>/dev/null)
  glibc=$(getconf GNU_LIBC_VERSION 2>/dev/null | awk '{split($2, v, "."); print v[1] * 1000 + v[2]}')
  if [[ "$mode" != *"[madvise]"* || -z "$glibc" || "$glibc" -lt 2035 ]]; then
    echo "SKIP: huge_page_heap: transparent huge pages are '$mode', glibc ${glibc:-unknown}: nothing to advise"
    return
  fi
  env -u GLIBC_TUNABLES "$RS" --debug on run --help >"$WORK/hp.txt" 2>&1
  grep -q 'roofsweep: GLIBC_TUNABLES=glibc.malloc.hugetlb=1$' "$WORK/hp.txt" \
    && pass huge_page_heap || fail huge_page_heap "$(grep -i tunables "$WORK/hp.txt")"
  GLIBC_TUNABLES=glibc.malloc.check=0 "$RS" --debug on run --help >"$WORK/hp.txt" 2>&1
  grep -q 'GLIBC_TUNABLES=glibc.malloc.check=0:glibc.malloc.hugetlb=1$' "$WORK/hp.txt" \
    && pass huge_page_heap_keeps_other_tunables || fail huge_page_heap_keeps_other_tunables "$(grep -i tunables "$WORK/hp.txt")"
  GLIBC_TUNABLES=glibc.malloc.hugetlb=0 "$RS" --debug on run --help >"$WORK/hp.txt" 2>&1
  grep -q 'GLIBC_TUNABLES=glibc.malloc.hugetlb=0$' "$WORK/hp.txt" \
    && pass huge_page_heap_opt_out || fail huge_page_heap_opt_out "$(grep -i tunables "$WORK/hp.txt")"
  # A command that reads no images is not worth the second start.
  env -u GLIBC_TUNABLES "$RS" --debug on info --help >"$WORK/hp.txt" 2>&1
  ! grep -q 'GLIBC_TUNABLES' "$WORK/hp.txt" \
    && pass huge_page_heap_not_for_info || fail huge_page_heap_not_for_info "$(grep -i tunables "$WORK/hp.txt")"
}

run_tests
