#!/usr/bin/env bash
# roofsweep simulate / eval / convert: the yardstick's own checks.
source "$(dirname "$0")/lib.sh"
XSD_REL=schemas/citygml-2.0/CityGML-2.0-all.xsd

# A small block: 2 views of 512 px over a few buildings.
SIM="$WORK/sim"
small_block() {
  [[ -d "$SIM" ]] || "$RS" simulate -preset easy -seed 5 -size 512 -gsd 0.15 -strips 1 -views 2 -buildings 4 -o "$SIM" -q
}

test_simulate_writes_a_readable_block() {
  small_block || { fail simulate "exit $?"; return; }
  for f in block.json groundtruth.gml groundtruth_edges.json groundtruth_visibility.json footprints.gpkg simulation.json orientation/opk.txt orientation/camera.yaml; do
    [[ -s "$SIM/$f" ]] || { fail "simulate_writes_$f" "missing"; return; }
  done
  pass simulate_writes_all_files
  expect_ok info_on_simulated info "$SIM" --json || return
  python3 -c "
import json,sys; j=json.load(open(sys.argv[1])); sim=json.load(open(sys.argv[2]))
assert len(j['images'])==2, j['images']
assert j['crs']=='EPSG:25832'
g=sim['gsd_m']  # nominal; attitude noise changes it slightly
assert all(abs(i['gsd_m']-g)/g < 0.02 for i in j['images']), (g, [i['gsd_m'] for i in j['images']])
assert j['overlaps'] and j['overlaps'][0]['fraction'] > 0.5" "$WORK/stdout.txt" "$SIM/simulation.json" \
    && pass simulated_block_geometry || fail simulated_block_geometry "$(head -c 400 "$WORK/stdout.txt")"
}

# footprints.gpkg: one feature per true building, id = the building's id,
# a polygon layer in the block CRS (read here as plain SQLite).
test_simulate_writes_true_footprints() {
  small_block || return
  python3 -c "
import json,re,sqlite3,sys
sim=json.load(open(sys.argv[2]))
ids=sorted(set(re.findall(r'<bldg:Building gml:id=\"([^\"]+)\"', open(sys.argv[3]).read())))
db=sqlite3.connect(sys.argv[1])
rows=db.execute('SELECT id FROM footprints ORDER BY id').fetchall()
assert [r[0] for r in rows]==ids and len(ids)==sim['buildings'], (rows, ids, sim['buildings'])
gt,srs=db.execute(\"SELECT geometry_type_name, srs_id FROM gpkg_geometry_columns WHERE table_name='footprints'\").fetchone()
assert gt=='MULTIPOLYGON' and srs>0, (gt, srs)
assert db.execute('SELECT description FROM gpkg_contents WHERE table_name=?', ('footprints',)).fetchone()[0].startswith('simulated building footprints')
assert 'footprints' not in open(sys.argv[4]).read()" "$SIM/footprints.gpkg" "$SIM/simulation.json" "$SIM/groundtruth.gml" "$SIM/block.json" 2>"$WORK/py.txt" \
    && pass simulate_footprints_one_per_building || fail simulate_footprints_one_per_building "$(tail -3 "$WORK/py.txt")"
}

test_simulate_is_deterministic() {
  small_block || return
  "$RS" simulate -preset easy -seed 5 -size 512 -gsd 0.15 -strips 1 -views 2 -buildings 4 -o "$WORK/again" -q
  if diff -r -q "$SIM/images" "$WORK/again/images" >/dev/null && cmp -s "$SIM/groundtruth.gml" "$WORK/again/groundtruth.gml" &&
    cmp -s "$SIM/block.json" "$WORK/again/block.json" &&
    cmp -s "$SIM/groundtruth_visibility.json" "$WORK/again/groundtruth_visibility.json"; then
    pass same_seed_same_bytes
  else
    fail same_seed_same_bytes "images or ground truth differ"
  fi
}

# -overlap sets the nadir layout: consecutive images of a strip lie
# (1 - forward) image lengths apart, the strips (1 - side) image widths.
test_simulate_overlap() {
  expect_ok simulate_overlap simulate -preset easy -seed 5 -size 512 -gsd 0.15 -strips 2 -views 3 -buildings 4 \
    -overlap 60,30 -o "$WORK/ov" -q || return
  python3 -c "
import json,sys,math
sim=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2]))
assert abs(sim['forward_overlap']-0.6)<1e-12 and abs(sim['side_overlap']-0.3)<1e-12, sim
side=512*0.15
pos={i['name']:i['position'] for i in b['images']}
along=math.dist(pos['s01_i001'][:2],pos['s01_i002'][:2])
across=math.dist(pos['s01_i001'][:2],pos['s02_i003'][:2])
# easy has no position noise; the CRS is not the local frame (mm apart here)
assert abs(along-0.4*side)<0.05, (along, 0.4*side)
assert abs(across-0.7*side)<0.05, (across, 0.7*side)" "$WORK/ov/simulation.json" "$WORK/ov/block.json" 2>"$WORK/py.txt" \
    && pass overlap_sets_the_layout || fail overlap_sets_the_layout "$(tail -3 "$WORK/py.txt")"
}

test_groundtruth_validates_against_citygml_xsd() {
  small_block || return
  local xsd
  xsd=$(shared_or_skip "$XSD_REL")
  [[ -n "$xsd" ]] || return
  if xmllint --noout --nonet --schema "$xsd" "$SIM/groundtruth.gml" 2>"$WORK/xml.txt"; then
    pass groundtruth_xsd_valid
  else
    fail groundtruth_xsd_valid "$(tail -3 "$WORK/xml.txt")"
  fi
}

test_eval_of_truth_against_itself_is_perfect() {
  small_block || return
  expect_ok eval_self eval "$SIM/groundtruth.gml" "$SIM" --json -lines "$SIM/groundtruth_edges.json" || return
  python3 -c "
import json,sys; j=json.load(open(sys.argv[1]))
rp=j['roof_planes']; g=j['geometry']; b=j['buildings']; l=j['lines3d']
assert rp['completeness']==1 and rp['correctness']==1 and rp['quality']==1, rp
assert g['angle_median_deg'] < 1e-6 and g['vertex_rms_m'] < 1e-6 and g['rmsz_m'] < 1e-6, g
assert b['completeness']==1 and b['correctness']==1, b
assert l['precision']==1 and l['roof_edge_completeness']==1, l
# Every reference plane found in the visibility file, seen or not.
s=j['roof_planes_seen']
assert s['unknown']==0 and s['reference']+s['unseen']==rp['n_reference'] and s['reference']>0, s
assert s['completeness']==1 and s['unseen_true_positive']==s['unseen'], s" "$WORK/stdout.txt" \
    && pass eval_self_perfect || fail eval_self_perfect "$(head -c 600 "$WORK/stdout.txt")"
}

# -vertices: one point per vertex of the matched planes, in the models' CRS,
# as many as the JSON counts; against itself every one lies on the outline.
# A damaged visibility file is refused with its name, not half read.
test_eval_refuses_a_damaged_visibility_file() {
  small_block || return
  rm -rf "$WORK/simvis" && cp -r "$SIM" "$WORK/simvis"
  echo '{"roof_polygons": [{"centroid": ["a", 2, 3], "seen": [1]}]}' >"$WORK/simvis/groundtruth_visibility.json"
  expect_fail eval_bad_visibility "" "groundtruth_visibility.json: roof polygon 0 " -- \
    eval "$SIM/groundtruth.gml" "$WORK/simvis"
}

test_eval_writes_vertices() {
  small_block || return
  expect_ok eval_vertices eval "$SIM/groundtruth.gml" "$SIM" --json -vertices "$WORK/v.gpkg" || return
  python3 - "$WORK/stdout.txt" "$WORK/v.gpkg" <<'PY' 2>"$WORK/py.txt" && pass eval_vertices_layer \
    || fail eval_vertices_layer "$(tail -1 "$WORK/py.txt")"
import json, sqlite3, sys
places = json.load(open(sys.argv[1]))["geometry"]["vertex_places"]
db = sqlite3.connect(sys.argv[2])
rows = db.execute("select place, distance_m, building_id, reference_building_id from vertices").fetchall()
assert len(rows) == sum(p["count"] for p in places.values()) > 8, (len(rows), places)
assert all(p == "on the outline" and d < 1e-6 and b == rb for p, d, b, rb in rows), rows[:3]
srs = db.execute("select srs_id from gpkg_geometry_columns where table_name = 'vertices'").fetchone()[0]
assert srs > 0, srs
PY
}

test_eval_against_empty_model() {
  small_block || return
  cat >"$WORK/empty.city.json" <<'J'
{"type": "CityJSON", "version": "2.0", "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0, 0, 0]},
 "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/25832"}, "CityObjects": {}, "vertices": []}
J
  expect_ok eval_empty eval "$WORK/empty.city.json" "$SIM" --json || return
  python3 -c "
import json,sys; j=json.load(open(sys.argv[1]))
assert j['roof_planes']['completeness']==0, j['roof_planes']
assert j['buildings']['completeness']==0, j['buildings']" "$WORK/stdout.txt" \
    && pass eval_empty_zero || fail eval_empty_zero "$(head -c 400 "$WORK/stdout.txt")"
}

test_convert_round_trip_keeps_scores() {
  small_block || return
  expect_ok to_cityjson convert "$SIM/groundtruth.gml" "$WORK/gt.city.json" -q || return
  expect_ok to_gpkg convert "$WORK/gt.city.json" "$WORK/gt.gpkg" -q || return
  expect_ok to_gml convert "$WORK/gt.gpkg" "$WORK/gt2.gml" -q || return
  expect_ok eval_round_trip eval "$WORK/gt2.gml" "$SIM" --json || return
  python3 -c "
import json,sys; j=json.load(open(sys.argv[1]))
assert j['roof_planes']['quality']==1 and j['geometry']['vertex_rms_m'] < 0.001, j['geometry']" "$WORK/stdout.txt" \
    && pass round_trip_within_1mm || fail round_trip_within_1mm "$(head -c 400 "$WORK/stdout.txt")"
  ogrinfo -ro -so "$WORK/gt.gpkg" roof_surfaces >"$WORK/ogr.txt" 2>&1
  grep -q "Geometry: 3D Multi Polygon" "$WORK/ogr.txt" && grep -q 'ETRS89 / UTM zone 32N' "$WORK/ogr.txt" \
    && pass gpkg_3d_with_crs || fail gpkg_3d_with_crs "$(head -c 600 "$WORK/ogr.txt")"
  expect_fail convert_refuses_existing "" "exists" -- convert "$WORK/gt.city.json" "$WORK/gt.gpkg"
}

test_simulate_from_berlin_tile() {
  local gml xsd
  gml=$(shared_or_skip data/citygml/berlin-lod2/3910_5819.gml)
  xsd=$(shared_or_skip "$XSD_REL")
  [[ -n "$gml" && -n "$xsd" ]] || return
  expect_ok simulate_berlin simulate -citygml "$gml" -aoi 391760,5818980,391900,5819110 -size 768 -o "$WORK/berlin" -q || return
  xmllint --noout --nonet --schema "$xsd" "$WORK/berlin/groundtruth.gml" 2>/dev/null \
    && pass berlin_truth_xsd_valid || fail berlin_truth_xsd_valid "xmllint"
  grep -q 'srsName="EPSG:25833"' "$WORK/berlin/groundtruth.gml" && pass berlin_keeps_crs || fail berlin_keeps_crs "no EPSG:25833"
  # The truth went CRS -> local ENU -> CRS: it must still sit on the source model.
  expect_ok eval_berlin_vs_source eval "$WORK/berlin/groundtruth.gml" "$gml" --json || return
  python3 -c "
import json,sys; j=json.load(open(sys.argv[1]))
assert j['roof_planes']['correctness']==1 and j['geometry']['vertex_rms_m'] < 0.001, (j['roof_planes'], j['geometry'])" "$WORK/stdout.txt" \
    && pass berlin_truth_on_source || fail berlin_truth_on_source "$(head -c 400 "$WORK/stdout.txt")"
}

test_bad_input() {
  expect_fail no_building_fits "$WORK/tiny" "no building fits" -- simulate -preset easy -size 256 -gsd 0.05 -strips 1 -views 2 -o "$WORK/tiny"
  expect_fail unknown_preset "$WORK/x" "preset" -- simulate -preset nonsense -o "$WORK/x"
  expect_fail missing_citygml "$WORK/y" "nope.gml" -- simulate -citygml "$WORK/nope.gml" -o "$WORK/y"
  expect_fail steep_slope "$WORK/s" "terrain slope must be 0..50 %" -- simulate -preset easy -terrain_slope 80 -o "$WORK/s"
  expect_fail slope_on_citygml "$WORK/c" "needs a generated town" -- simulate -citygml "$WORK/nope.gml" -terrain_slope 5 -o "$WORK/c"
  expect_fail negative_relief "$WORK/r" "terrain relief must be 0..50 m" -- simulate -preset easy -terrain_relief -3 -o "$WORK/r"
  expect_fail relief_on_citygml "$WORK/c" "needs a generated town" -- simulate -citygml "$WORK/nope.gml" -terrain_relief 5 -o "$WORK/c"
  expect_fail low_forward_overlap "$WORK/o" "forward overlap must be 50..95 %" -- simulate -preset easy -overlap 40,30 -o "$WORK/o"
  expect_fail overlap_one_value "$WORK/o" "FORWARD,SIDE" -- simulate -preset easy -overlap 60 -o "$WORK/o"
  small_block || return
  expect_fail existing_folder "" "exists" -- simulate -preset easy -o "$SIM"
  expect_fail eval_missing_truth "" "nothere" -- eval "$SIM/groundtruth.gml" "$WORK/nothere.gml"
  printf '<?xml version="1.0"?>\n<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0"><core:cityObjectMember>' >"$WORK/trunc.gml"
  expect_fail convert_truncated "$WORK/t.city.json" "trunc.gml" -- convert "$WORK/trunc.gml" "$WORK/t.city.json"
}

run_tests
