#!/usr/bin/env bash
# roofsweep run / sweep: the whole pipeline on a small simulated block.
source "$(dirname "$0")/lib.sh"
XSD_REL=schemas/citygml-2.0/CityGML-2.0-all.xsd

SIM="$WORK/sim"
# Four nadir views (the sweep needs the reference and two more views) of
# three buildings, small enough to run in a few seconds.
small_block() {
  [[ -d "$SIM" ]] || "$RS" simulate -preset easy -seed 3 -size 512 -gsd 0.15 -strips 1 -views 4 \
    -buildings 3 -o "$SIM" -q
}

test_run_writes_valid_closed_lod2() {
  small_block || { fail simulate "exit $?"; return; }
  expect_ok run_gml run "$SIM" -o "$WORK/b.gml" -report "$WORK/report.json" -lines3d "$WORK/l.gpkg" \
    -half_planes "$WORK/hp.gpkg" -planes "$WORK/planes.gpkg"
  grep -q "^half-plane sweep" "$WORK/stdout.txt" || fail run_stage_table "no stage table"
  # One progress line from 0 to 100: a step reporting from a later part of
  # the range before an earlier one makes GDAL's progress start over.
  [[ $(grep -o "0\.\.\.10\.\.\." "$WORK/stdout.txt" | wc -l) -eq 1 ]] \
    && grep -q "100 - done\." "$WORK/stdout.txt" && pass run_progress_once \
    || fail run_progress_once "$(grep -F '...' "$WORK/stdout.txt" | head -c 300)"
  grep -Eq "^near-coplanar planes merged +[0-9]+ pairs proposed, [0-9]+ merged" "$WORK/stdout.txt" \
    && pass run_merge_stage || fail run_merge_stage "$(grep -i coplanar "$WORK/stdout.txt")"
  grep -Eq "^flat planes beyond eaves +[0-9]+ dropped" "$WORK/stdout.txt" \
    && pass run_eave_stage || fail run_eave_stage "$(grep -i eaves "$WORK/stdout.txt")"
  grep -Eq "^faces grown to their eaves +[0-9]+ eaves found below [0-9]+ planes, [0-9]+ patches grown" \
    "$WORK/stdout.txt" && pass run_eave_search_stage \
    || fail run_eave_search_stage "$(grep -i eaves "$WORK/stdout.txt")"
  grep -Eq "^faces cut at their border lines +[0-9]+ of [0-9]+ patches cut" "$WORK/stdout.txt" \
    && pass run_border_clip_stage || fail run_border_clip_stage "$(grep -i border "$WORK/stdout.txt")"
  local n
  n=$(grep -c "<bldg:Building " "$WORK/b.gml" || true)
  [[ $n -gt 0 ]] && pass run_builds_buildings || fail run_builds_buildings "no building in b.gml"
  local xsd
  if xsd=$(shared_or_skip "$XSD_REL"); then
    if xmllint --noout --nonet --schema "$xsd" "$WORK/b.gml" 2>"$WORK/xml.txt"; then
      pass run_citygml_schema_valid
    else
      fail run_citygml_schema_valid "$(head -c 400 "$WORK/xml.txt")"
    fi
  fi
  # Every solid closed, planar within 1 cm and outward: convert re-checks
  # them on reading and counts the failures.
  expect_ok run_convert_gpkg convert "$WORK/b.gml" "$WORK/b.gpkg"
  grep -q "failing the solid checks" "$WORK/stdout.txt" && fail run_solids_valid "$(cat "$WORK/stdout.txt")" \
    || pass run_solids_valid
  python3 - "$WORK/report.json" <<'PY' && pass run_report || fail run_report "report lacks stages or reasons"
import json, sys
r = json.load(open(sys.argv[1]))
names = [s["stage"] for s in r["stages"]]
assert names[:3] == ["read", "segments + 3D lines", "half-plane sweep"], names
assert all(isinstance(x, str) and ": " in x for x in r["rejected"])
PY
  [[ -s "$WORK/l.gpkg" && -s "$WORK/hp.gpkg" ]] && pass run_side_layers || fail run_side_layers "missing"
  # The lines3d layer is the one `match` writes, observations included, so
  # that `run -lines` on it restricts each line's reference views as the
  # run that matched did.
  ogrinfo -ro -al "$WORK/l.gpkg" lines3d 2>/dev/null | grep -Eq '^  observations \(String\) = [^ ]+:[0-9]+ [^ ]+:[0-9]+' \
    && pass run_lines3d_observations || fail run_lines3d_observations "no observations in run -lines3d"
  # Every building carries the image support of its roof edges (a share),
  # and the stage table says how it came out.
  python3 - "$WORK/b.gml" <<'PY' && pass run_edge_support || fail run_edge_support "edge_support missing or out of range"
import re, sys
text = open(sys.argv[1]).read()
n = len(re.findall(r"<bldg:Building ", text))
v = [float(x) for x in re.findall(r'<gen:doubleAttribute name="edge_support">\s*<gen:value>([^<]+)<', text)]
assert n and len(v) == n and all(0 <= x <= 1 for x in v), (n, v)
PY
  python3 -c '
import json, re, sys
st = {s["stage"]: s["result"] for s in json.load(open(sys.argv[1]))["stages"]}
assert re.match(r"median \d+ % of roof edges on image edges, lowest \d+ %", st["edge support"]), st
' "$WORK/report.json" && pass run_edge_support_stage || fail run_edge_support_stage "not in the report"
  # Every verified plane hypothesis is built into a building of the output
  # or carries a reason; the built ones are the planes the run used.
  python3 - "$WORK/planes.gpkg" "$WORK/report.json" "$WORK/b.gml" <<'PY' && pass run_planes_layer \
    || fail run_planes_layer "roof_planes layer incomplete or inconsistent with the run"
import json, re, sqlite3, sys
planes, report, gml = sys.argv[1:]
db = sqlite3.connect(planes)
rows = db.execute("select status, reason, building from roof_planes").fetchall()
assert rows, "no rows"
# The verification's evidence agrees with its verdict (default margins: 0.1
# over the moved planes, the tilt test at 0 + 1 standard error).
checked = 0
for s, r, score, lo, hi, dt, se, hfl in db.execute(
        "select status, reason, score, score_below, score_above, tilt_difference, tilt_se, "
        "height_from_lines from roof_planes where score is not null"):
    if s == "built" and not hfl:
        assert score >= max(lo, hi) + 0.1 - 1e-9 and dt >= -se - 1e-9, (score, lo, hi, dt, se)
        checked += 1
    if r and r.startswith("height not confirmed"):
        assert score < max(lo, hi) + 0.1, (r, score, lo, hi)
assert checked, "no built plane with its evidence"
assert all(s in ("built", "rejected", "not built") for s, _, _ in rows), rows
assert all(r and r != "no reason recorded" for s, r, _ in rows if s != "built"), rows
built = [b for s, _, b in rows if s == "built"]
stage = next(x for x in json.load(open(report))["stages"] if x["stage"] == "LoD2 buildings")
used = int(re.search(r"(\d+) planes used", stage["result"]).group(1))
assert len(built) == used, (len(built), stage)
ids = set(re.findall(r'<bldg:Building gml:id="([^"]+)"', open(gml).read()))
assert built and set(built) <= ids, (set(built) - ids)
PY
  expect_ok run_eval eval "$WORK/b.gml" "$SIM"
  grep -q "Roof planes" "$WORK/stdout.txt" && pass run_eval_table || fail run_eval_table "no table"
  # With the run's plane hypotheses, eval tells every missed reference
  # plane by where it was lost.
  "$RS" eval "$WORK/b.gml" "$SIM" -planes "$WORK/planes.gpkg" -json >"$WORK/eval_planes.json" \
    2>"$WORK/stderr.txt" || fail run_eval_planes "exit $?: $(head -c 300 "$WORK/stderr.txt")"
  python3 - "$WORK/eval_planes.json" <<'PY' && pass run_eval_planes_losses \
    || fail run_eval_planes_losses "missed planes not all accounted for"
import json, sys
d = json.load(open(sys.argv[1]))
p, m = d["roof_planes"], d["missed_roof_planes"]
assert sum(v["count"] for v in m.values()) == p["n_reference"] - p["tp_reference"], (p, m)
# The same planes one by one, with what a person needs to find them.
items = d["missed_roof_plane_list"]
assert len(items) == sum(v["count"] for v in m.values()), (len(items), m)
for stage, v in m.items():
    assert sum(1 for i in items if i["stage"] == stage) == v["count"], (stage, items)
assert len({i["reference_plane"] for i in items}) == len(items), items
for i in items:
    assert i["building_id"] and i["roof_type"] and i["plan_area_m2"] > 0, i
    assert 0 <= i["slope_deg"] < 90, i
PY
  expect_fail run_eval_planes_wrong_layer "$WORK/none" "l\.gpkg: no layer 'roof_planes'" -- \
    eval "$WORK/b.gml" "$SIM" -planes "$WORK/l.gpkg"
}

test_run_is_deterministic() {
  small_block || return
  "$RS" run "$SIM" -o "$WORK/d1.city.json" -q && "$RS" run "$SIM" -o "$WORK/d2.city.json" -q
  cmp -s "$WORK/d1.city.json" "$WORK/d2.city.json" && pass run_deterministic \
    || fail run_deterministic "two runs differ"
}

test_run_reprojects_with_t_srs() {
  small_block || return
  expect_ok run_t_srs run "$SIM" -o "$WORK/w.city.json" -t_srs EPSG:4979 -q
  python3 - "$WORK/w.city.json" <<'PY' && pass run_t_srs_crs || fail run_t_srs_crs "not EPSG:4979 degrees"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["metadata"]["referenceSystem"].endswith("/EPSG/0/4979"), d["metadata"]
x, y = d["transform"]["translate"][:2]
assert -180 <= x <= 180 and -90 <= y <= 90, (x, y)
PY
}

test_sweep_writes_half_planes() {
  small_block || return
  expect_ok sweep_gpkg sweep "$SIM" -o "$WORK/s.gpkg"
  python3 - "$WORK/s.gpkg" <<'PY' && pass sweep_layer || fail sweep_layer "no half_planes rows"
import sqlite3, sys
c = sqlite3.connect(sys.argv[1])
n, acc = c.execute("select count(*), sum(accepted) from half_planes").fetchone()
assert n > 0 and acc is not None, (n, acc)
# Every accepted side is a candidate; every candidate has a swept profile.
bad = c.execute("select count(*) from half_planes where accepted = 1 and candidate = 0").fetchone()[0]
assert bad == 0, bad
cand, unset = c.execute(
    "select sum(candidate), sum(candidate = 1 and not peak_ratio > 0) from half_planes").fetchone()
assert cand >= acc and unset == 0, (cand, acc, unset)
PY
}

# -ncc_window: on this clean block "auto" is the 7 x 7 window, 11 changes
# the similarities and the stage table says which window ran; a window
# without a centre pixel is refused before any work.
test_sweep_window_option() {
  small_block || return
  expect_ok sweep_window_auto sweep "$SIM" -o "$WORK/w_auto.gpkg" || return
  grep -q "7 x 7 px window" "$WORK/stdout.txt" && pass sweep_window_auto_is_7 \
    || fail sweep_window_auto_is_7 "$(grep '^half-plane sweep' "$WORK/stdout.txt")"
  expect_ok sweep_window_7 sweep "$SIM" -o "$WORK/w_7.gpkg" -ncc_window 7 || return
  expect_ok sweep_window_11 sweep "$SIM" -o "$WORK/w_11.gpkg" -ncc_window 11 || return
  grep -q "11 x 11 px window" "$WORK/stdout.txt" && pass sweep_window_11_named \
    || fail sweep_window_11_named "$(grep '^half-plane sweep' "$WORK/stdout.txt")"
  python3 - "$WORK"/w_auto.gpkg "$WORK"/w_7.gpkg "$WORK"/w_11.gpkg <<'PY' 2>"$WORK/py.txt" \
    && pass sweep_window_used || fail sweep_window_used "$(tail -1 "$WORK/py.txt")"
import sqlite3, sys
rows = [sqlite3.connect(f).execute(
    "select line, side, similarity, theta_deg from half_planes order by line, side").fetchall()
    for f in sys.argv[1:]]
assert rows[0] and rows[0] == rows[1], "auto and 7 differ on a clean block"
assert [r[:2] for r in rows[2]] == [r[:2] for r in rows[0]], "11 swept other sides"
assert rows[2] != rows[0], "11 gave the same similarities as 7"
PY
  expect_fail sweep_window_even "$WORK/w_8.gpkg" "ncc_window.*odd" -- sweep "$SIM" -o "$WORK/w_8.gpkg" -ncc_window 8
  expect_fail run_window_word "$WORK/w_x.gpkg" "ncc_window.*'wide'" -- run "$SIM" -o "$WORK/w_x.gpkg" -ncc_window wide
}

# A block on sloping or hilly ground: the simulator writes a DTM and names it
# in the manifest, the truth's wall feet lie on it, and every building run
# builds stands on the lowest DTM height under its ground surface.
# NAME SIMULATE_OPTIONS...
check_run_on_terrain() {
  local name=$1
  shift
  local b="$WORK/$name"
  expect_ok "simulate_$name" simulate -preset easy -seed 3 -size 512 -gsd 0.15 -strips 1 -views 4 \
    -buildings 3 "$@" -o "$b" -q || return
  python3 -c "
import json,sys; m=json.load(open(sys.argv[1]))
assert m['ground']=={'dtm': 'dtm.tif'}, m['ground']" "$b/block.json" 2>"$WORK/py.txt" \
    && pass "${name}_manifest_names_dtm" || fail "${name}_manifest_names_dtm" "$(tail -1 "$WORK/py.txt")"
  # The DTM interpolated bilinearly between its 1 m cell centres (exact on a
  # slope, within a millimetre over these hills): the truth's wall feet lie
  # on it within a centimetre.
  python3 - "$b" <<'PY' 2>"$WORK/py.txt" && pass "${name}_truth_on_dtm" || fail "${name}_truth_on_dtm" "$(tail -1 "$WORK/py.txt")"
import json, math, subprocess, sys
dtm = sys.argv[1] + "/dtm.tif"
segs = [s for s in json.load(open(sys.argv[1] + "/groundtruth_edges.json"))["segments"]
        if s["kind"] == "footprint"]
pts = [p for s in segs for p in (s["a"], s["b"])]
x0, dx, _, y0, _, dy = json.loads(subprocess.run(["gdalinfo", "-json", dtm], capture_output=True,
                                                 text=True, check=True).stdout)["geoTransform"]
corners = []
for p in pts:
    c, r = (p[0] - x0) / dx - 0.5, (p[1] - y0) / dy - 0.5
    c0, r0 = math.floor(c), math.floor(r)
    corners.append((c - c0, r - r0, [(c0 + i, r0 + j) for j in (0, 1) for i in (0, 1)]))
out = subprocess.run(["gdallocationinfo", "-valonly", dtm],
                     input="".join("%d %d\n" % q for _, _, qs in corners for q in qs),
                     capture_output=True, text=True, check=True).stdout.split()
assert len(pts) > 8 and len(out) == 4 * len(pts), (len(pts), len(out))
worst = 0
for k, (fc, fr, _) in enumerate(corners):
    z00, z10, z01, z11 = (float(v) for v in out[4 * k:4 * k + 4])
    z = (1 - fr) * ((1 - fc) * z00 + fc * z10) + fr * ((1 - fc) * z01 + fc * z11)
    worst = max(worst, abs(z - pts[k][2]))
assert worst < 0.01, worst
PY
  expect_ok "run_$name" run "$b" -footprints "$b/footprints.gpkg" -o "$WORK/$name.gpkg" \
    -lines3d "$WORK/${name}_lines.gpkg" || return
  # eval takes the terrain from the block's DTM: 3D lines on the sloping
  # ground lie on a true surface (measured 18 % of the length; 3 % when the
  # terrain was taken as unknown).
  expect_ok "eval_${name}_lines" eval "$WORK/$name.gpkg" "$b" -lines "$WORK/${name}_lines.gpkg" --json &&
    python3 -c "
import json,sys; j=json.load(open(sys.argv[1]))['lines3d']
assert j['on_surface'] > 0.10, j" "$WORK/stdout.txt" 2>"$WORK/py.txt" \
    && pass "${name}_lines_on_terrain" || fail "${name}_lines_on_terrain" "$(tail -1 "$WORK/py.txt")"
  ogrinfo -ro -al -q "$WORK/$name.gpkg" ground_surfaces >"$WORK/ground.txt" 2>&1
  python3 - "$b/dtm.tif" "$WORK/ground.txt" <<'PY' 2>"$WORK/py.txt" && pass "${name}_buildings_on_dtm" \
    || fail "${name}_buildings_on_dtm" "$(tail -1 "$WORK/py.txt")"
import re, subprocess, sys
n = 0
for line in open(sys.argv[2]):
    if "POLYGON" not in line:
        continue
    pts = [tuple(map(float, p.split())) for p in re.findall(r"(-?[\d.]+ -?[\d.]+ -?[\d.]+)", line)]
    out = subprocess.run(["gdallocationinfo", "-valonly", "-geoloc", sys.argv[1]],
                         input="".join("%f %f\n" % (x, y) for x, y, _ in pts),
                         capture_output=True, text=True, check=True).stdout.split()
    dtm = [float(v) for v in out]
    base = min(z for _, _, z in pts)
    assert max(z for _, _, z in pts) - base < 1e-3, "ground surface not level"
    assert abs(base - min(dtm)) < 0.08, (base, min(dtm))
    n += 1
assert n > 0, "no ground surface"
PY
}

test_run_on_a_slope() { check_run_on_terrain slope -terrain_slope 10 -terrain_aspect 60; }

# Hills: the ground under each building is curved, not a plane.
test_run_over_hills() { check_run_on_terrain hills -terrain_relief 12; }

test_run_with_footprints() {
  small_block || return
  # The simulator's footprints, in another CRS than the block: read through
  # OGR, reprojected, and every footprint ends as a building or a reason.
  ogr2ogr -t_srs EPSG:3857 "$WORK/fp3857.gpkg" "$SIM/footprints.gpkg" 2>"$WORK/ogr.txt" \
    || { fail run_fp_input "ogr2ogr: $(head -c 300 "$WORK/ogr.txt")"; return; }
  expect_ok run_fp run "$SIM" -o "$WORK/fp.gpkg" -footprints "$WORK/fp3857.gpkg" \
    -report "$WORK/fp.json"
  grep -q "3 footprints" "$WORK/stdout.txt" && pass run_fp_read || fail run_fp_read "$(head -c 400 "$WORK/stdout.txt")"
  grep -Eq "faces grown along footprints +[0-9]+ strips proposed, [0-9]+ confirmed" "$WORK/stdout.txt" \
    && pass run_fp_growth_stage || fail run_fp_growth_stage "$(grep -i grown "$WORK/stdout.txt")"
  python3 - "$WORK/fp.gpkg" "$SIM/footprints.gpkg" "$WORK/fp.json" <<'PY' && pass run_fp_labels \
    || fail run_fp_labels "buildings not labelled by footprint, or a footprint unaccounted for"
import json, sqlite3, sys
out, fps, report = sys.argv[1:]
ids = {r[0] for r in sqlite3.connect(fps).execute("select id from footprints")}
rows = sqlite3.connect(out).execute("select footprint_id, outline from buildings").fetchall()
assert rows, "no building"
assert all(r[0] in ids for r in rows), rows
assert all(r[1].startswith("footprint") or r[1].startswith("roof planes cut") for r in rows), rows
built = {r[0] for r in rows}
assert len(built) == len(rows), ("one building per footprint", rows)
db = sqlite3.connect(out)
if db.execute("select 1 from gpkg_contents where table_name='building_parts'").fetchone():
    parts = db.execute("select p.footprint_id, b.footprint_id from building_parts p "
                       "join buildings b on p.building_id = b.id").fetchall()
    assert parts and all(p == b for p, b in parts), parts
rejected = json.load(open(report))["rejected"]
for i in ids - built:
    assert any(x.startswith("footprint " + i + ":") for x in rejected), (i, rejected)
PY
  # Footprints named in the block manifest are used without -footprints
  # (a second manifest beside the first, so that its paths stay valid).
  python3 - "$SIM/block.json" "$SIM/block_fp.json" <<'PY' \
    || { fail run_fp_manifest "cannot write the manifest"; return; }
import json, sys
m = json.load(open(sys.argv[1]))
m["footprints"] = {"path": "footprints.gpkg", "layer": "footprints"}
json.dump(m, open(sys.argv[2], "w"), indent=1)
PY
  expect_ok run_fp_manifest run "$SIM/block_fp.json" -o "$WORK/fpm.gpkg" -q
  python3 - "$WORK/fpm.gpkg" <<'PY' && pass run_fp_manifest_labels || fail run_fp_manifest_labels "no footprint_id"
import sqlite3, sys
rows = sqlite3.connect(sys.argv[1]).execute("select footprint_id from buildings").fetchall()
assert rows and all(r[0] for r in rows), rows
PY
  expect_ok run_fp_convert convert "$WORK/fp.gpkg" "$WORK/fp.gml"
  grep -q "failing the solid checks" "$WORK/stdout.txt" && fail run_fp_solids "$(cat "$WORK/stdout.txt")" \
    || pass run_fp_solids
  expect_fail run_fp_missing "$WORK/y.gml" "nofile.gpkg" -- run "$SIM" -o "$WORK/y.gml" \
    -footprints "$WORK/nofile.gpkg"
  # Footprints labelled with the wrong CRS: the neighbouring UTM zone lies
  # far away, degrees cannot hold metres.
  ogr2ogr -a_srs EPSG:25833 "$WORK/far.gpkg" "$SIM/footprints.gpkg" 2>/dev/null
  expect_fail run_fp_elsewhere "$WORK/y.gml" "far.gpkg: no footprint" -- run "$SIM" -o "$WORK/y.gml" \
    -footprints "$WORK/far.gpkg"
  ogr2ogr -a_srs EPSG:4326 "$WORK/deg.gpkg" "$SIM/footprints.gpkg" 2>/dev/null
  expect_fail run_fp_bad_crs "$WORK/y.gml" "deg.gpkg: feature 1: .*cannot transform" -- run "$SIM" \
    -o "$WORK/y.gml" -footprints "$WORK/deg.gpkg"
}

test_run_drops_buildings_the_images_do_not_support() {
  small_block || return
  # No roof outline lies wholly on image edges: every building goes, each
  # with its reason.
  expect_ok run_min_edge_support run "$SIM" -o "$WORK/none.gml" -min_edge_support 1 \
    -report "$WORK/none.json" -planes "$WORK/none_planes.gpkg" || return
  python3 -c '
import json, sqlite3, sys
r = json.load(open(sys.argv[1]))["rejected"]
dropped = [x for x in r if "roof edges on image edges" in x]
assert dropped, r
rows = sqlite3.connect(sys.argv[2]).execute("select status, reason from roof_planes").fetchall()
assert not [x for x in rows if x[0] == "built"], rows
assert [x for x in rows if x[1] and "roof edges on image edges" in x[1]], rows
' "$WORK/none.json" "$WORK/none_planes.gpkg" && ! grep -q "<bldg:Building " "$WORK/none.gml" && pass run_min_edge_support_drops \
    || fail run_min_edge_support_drops "buildings kept or no reason"
}

# A roof no 3D line supports (a roof model over a bare footprint) must show
# min_edge_support_unlined of its outline as image edges: at 1 every such
# building goes, with its reason, and those built on lines stay; at the
# default the models' roofs on this block (97 % on edges) stay.
test_run_drops_unlined_roofs_the_images_do_not_show() {
  small_block || return
  expect_ok run_unlined_lines match "$SIM" -o "$WORK/ul.gpkg" -q || return
  expect_ok run_unlined run "$SIM" -lines "$WORK/ul.gpkg" -footprints "$SIM/footprints.gpkg" \
    -min_edge_support_unlined 1 -o "$WORK/ul.gml" -report "$WORK/ul.json" -q || return
  expect_ok run_unlined_default run "$SIM" -lines "$WORK/ul.gpkg" \
    -footprints "$SIM/footprints.gpkg" -o "$WORK/ud.gml" -report "$WORK/ud.json" -q || return
  python3 - "$WORK/ul.json" "$WORK/ul.gml" "$WORK/ud.json" "$WORK/ud.gml" <<'PY' 2>"$WORK/py.txt" \
    && pass run_unlined_roofs_dropped || fail run_unlined_roofs_dropped "$(tail -1 "$WORK/py.txt")"
import json, re, sys
def buildings(gml):
    t = open(gml).read()
    return re.findall(r'name="supporting_lines">\s*<gen:value>([0-9.]+)<', t)
dropped = [r for r in json.load(open(sys.argv[1]))["rejected"]
           if "no matched line supports its roof" in r]
kept, default = buildings(sys.argv[2]), buildings(sys.argv[4])
assert dropped, "no unlined roof dropped"
assert kept and all(float(x) > 0 for x in kept), kept
assert len(default) == len(kept) + len(dropped), (default, kept, dropped)
assert not [r for r in json.load(open(sys.argv[3]))["rejected"] if "image edges" in r]
PY
}

# With footprints, a footprint whose roof is not reconstructed gets an LoD1
# block at the height of the 3D lines over it: here every LoD2 building is
# dropped (no roof outline lies wholly on image edges), so the footprints
# that have lines over them come back as blocks, valid CityGML, marked in
# the report and scored apart by eval.
test_run_gives_footprints_without_a_roof_lod1_blocks() {
  small_block || return
  expect_ok run_lod1 run "$SIM" -footprints "$SIM/footprints.gpkg" -min_edge_support 1 \
    -o "$WORK/lod1.gml" -report "$WORK/lod1.json" || return
  grep -Eq "^LoD1 blocks +[1-9][0-9]* of [0-9]+ footprints without a roof" "$WORK/stdout.txt" \
    && pass run_lod1_stage || fail run_lod1_stage "$(grep -i lod1 "$WORK/stdout.txt")"
  grep -q "<bldg:lod1Solid>" "$WORK/lod1.gml" && ! grep -q "<bldg:lod2Solid>" "$WORK/lod1.gml" \
    && pass run_lod1_solids || fail run_lod1_solids "no lod1Solid, or an lod2Solid left"
  local xsd
  if xsd=$(shared_or_skip "$XSD_REL"); then
    xmllint --noout --nonet --schema "$xsd" "$WORK/lod1.gml" 2>"$WORK/xml.txt" \
      && pass run_lod1_schema_valid || fail run_lod1_schema_valid "$(head -c 400 "$WORK/xml.txt")"
  fi
  expect_ok eval_lod1 eval "$WORK/lod1.gml" "$SIM" --json || return
  python3 - "$WORK/stdout.txt" "$WORK/lod1.json" "$WORK/lod1.gml" <<'PY' 2>"$WORK/py.txt" \
    && pass eval_lod1_apart || fail eval_lod1_apart "$(tail -1 "$WORK/py.txt")"
import json, sys
e = json.load(open(sys.argv[1]))
rejected = json.load(open(sys.argv[2]))["rejected"]
blocks = open(sys.argv[3]).read().count("<bldg:lod1Solid>")
marked = [r for r in rejected if r.endswith("; a flat block instead (LoD1)")]
assert len(marked) == blocks, (marked, blocks)
assert e["lod1"]["blocks"] == blocks, e["lod1"]
# Blocks are not LoD2: no roof plane and no LoD2 building to score.
assert e["roof_planes"]["n_result"] == 0 and e["buildings"]["n_result"] == 0, e["buildings"]
assert e["lod1"]["found_by_block_only"] == e["lod1"]["found"] > 0, e["lod1"]
PY
  expect_ok run_no_lod1 run "$SIM" -footprints "$SIM/footprints.gpkg" -min_edge_support 1 -no_lod1 \
    -o "$WORK/nolod1.gml" -q
  ! grep -q "<bldg:Building " "$WORK/nolod1.gml" && pass run_no_lod1_none \
    || fail run_no_lod1_none "buildings written with -no_lod1"
}

# match -truth says how much roof edge a true pair could reach at all. One
# strip: its edges along the flight line lie along every pair's epipolar
# lines, so part of the roof edge is out of reach. -truth_edges writes the
# same edge by edge: its sums must give the summary's figures.
test_match_truth_reach() {
  small_block || return
  expect_ok match_truth match "$SIM" -o "$WORK/m.gpkg" -truth "$SIM/groundtruth_edges.json" \
    -truth_edges "$WORK/te.gpkg" || return
  python3 - "$WORK/stdout.txt" "$WORK/te.gpkg" <<'PY' && pass match_truth_reach || fail match_truth_reach "$(grep -i 'roof edges' "$WORK/stdout.txt")"
import re, sqlite3, sys
text = open(sys.argv[1]).read()
roof = ("ridge", "hip", "valley", "break", "eave", "verge", "wall_top", "step", "party", "roof_other")
rows = sqlite3.connect(sys.argv[2]).execute(
    "select kind, reach, length_m, covered_m, stage, views from truth_edges").fetchall()
assert rows, "no true edge written"
by = {}
for kind, reach, length, covered, stage, views in rows:
    assert 0 <= covered <= length + 1e-6 and 0 <= stage <= 7 and views >= 0, (kind, length, covered)
    assert (reach == "within reach") == (stage >= 1), (reach, stage)
    if kind in roof:
        by[reach] = by.get(reach, 0) + length
        by["covered"] = by.get("covered", 0) + covered
roof_m = sum(v for k, v in by.items() if k != "covered")
m = re.search(r"Roof edges within reach of a true pair: ([\d.]+)% of (\d+) m; out of reach: ([\d.]+)% "
              r"along the epipolar lines of every pair that sees them, ([\d.]+)% detected in fewer "
              r"than two views, ([\d.]+)% other", text)
assert m, text
reach, total, along, one, other = (float(x) for x in m.groups())
assert total > 0 and abs(reach + along + one + other - 100) < 0.3, m.groups()
assert along > 0, m.groups()
done = float(re.search(r"roof-edge completeness ([\d.]+)%", text).group(1))
# Lines outside the candidates' reach come only from junction completion.
assert done < reach + along + 1, (done, m.groups())
assert abs(roof_m - total) < 1, (roof_m, total)
for name, printed in (("within reach", reach), ("along the epipolar lines", along),
                      ("in fewer than two views", one), ("other", other)):
    assert abs(100 * by.get(name, 0) / roof_m - printed) < 0.06, (name, by, m.groups())
assert abs(100 * by["covered"] / roof_m - done) < 0.06, (by["covered"], roof_m, done)
PY
  expect_fail match_truth_edges_without_truth "$WORK/te2.gpkg" "-truth_edges needs -truth" -- \
    match "$SIM" -o "$WORK/m2.gpkg" -truth_edges "$WORK/te2.gpkg"
}

# Plan centroids of the top-level buildings of a CityGML file (mean of the
# ground-surface vertices), one "id x y" line each.
centroids() {
  python3 - "$1" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
for chunk in text.split('<bldg:Building gml:id="')[1:]:
    bid = chunk.split('"', 1)[0]
    xs, ys = [], []
    for g in re.findall(r"<bldg:GroundSurface.*?</bldg:GroundSurface>", chunk, re.S):
        for pl in re.findall(r"<gml:posList[^>]*>([^<]+)<", g):
            v = list(map(float, pl.split()))
            xs += v[0::3]
            ys += v[1::3]
    print(bid, sum(xs) / len(xs), sum(ys) / len(ys))
PY
}

# Two tiles of a grid split the block between two buildings: each tile's run
# writes the buildings whose ground centre lies in it, ids prefixed with the
# tile's tag, and together they give the buildings of the whole run, each once.
test_run_tiles() {
  small_block || return
  expect_ok tile_whole run "$SIM" -o "$WORK/whole.gml" -q || return
  centroids "$WORK/whole.gml" >"$WORK/whole.txt"
  # The split runs between the first two buildings across the axis along
  # which they lie farthest apart: a few decimetres of difference between
  # a tile's run and the whole run must not carry a building across it.
  local axis split lo
  read -r axis split lo < <(python3 - "$WORK/whole.txt" <<'PY'
import sys
rows = [tuple(map(float, l.split()[1:3])) for l in open(sys.argv[1])]
if len(rows) >= 2:
    a, b = rows[0], rows[1]
    k = 0 if abs(a[0] - b[0]) >= abs(a[1] - b[1]) else 1
    print(k, "%.3f" % ((a[k] + b[k]) / 2), min(r[1 - k] for r in rows))
PY
  )
  [[ -n "$split" ]] || { fail tile_split "fewer than two buildings: $(cat "$WORK/whole.txt")"; return; }
  # A tile from FROM to TO across the split axis, 1 km wide along the other.
  tile_box() {
    if [[ $axis == 0 ]]; then echo "$1,$(python3 -c "print($lo - 500)"),$2,$(python3 -c "print($lo + 500)")"
    else echo "$(python3 -c "print($lo - 500)"),$1,$(python3 -c "print($lo + 500)"),$2"; fi
  }
  local x0 x1
  x0=$(python3 -c "print($split - 500)"); x1=$(python3 -c "print($split + 500)")
  expect_ok tile_west run "$SIM" -aoi "$(tile_box "$x0" "$split")" -o "$WORK/west.gml" || return
  grep -Eq "^tile: [0-9]+ of 4 views see it and its 30 m buffer; [0-9.]+ of [0-9.]+ megapixels read" \
    "$WORK/stdout.txt" && pass tile_message || fail tile_message "$(grep -i tile "$WORK/stdout.txt")"
  grep -Eq "^tile +[0-9]+ of [0-9]+ buildings in the tile" "$WORK/stdout.txt" \
    && pass tile_stage || fail tile_stage "$(grep -i tile "$WORK/stdout.txt")"
  expect_ok tile_east run "$SIM" -aoi "$(tile_box "$split" "$x1")" -o "$WORK/east.gml" -q || return
  centroids "$WORK/west.gml" >"$WORK/west.txt"
  centroids "$WORK/east.gml" >"$WORK/east.txt"
  python3 - "$WORK/whole.txt" "$WORK/west.txt" "$WORK/east.txt" "$split" "$axis" <<'PY' \
    && pass tile_buildings_once || fail tile_buildings_once "$(cat "$WORK"/{whole,west,east}.txt)"
import sys
read = lambda f: [(l.split()[0], float(l.split()[1]), float(l.split()[2])) for l in open(f)]
whole, west, east, split = read(sys.argv[1]), read(sys.argv[2]), read(sys.argv[3]), float(sys.argv[4])
k = 1 + int(sys.argv[5])
assert west and east, "a tile without buildings"
assert all(r[k] < split for r in west) and all(r[k] >= split for r in east)
ids = [i for i, _, _ in west + east]
assert len(set(ids)) == len(ids), "an id twice"
assert all(i.startswith("t") and "_rs_b" in i for i in ids), ids
# One to one with the whole run's buildings, within a metre.
tiles = west + east
assert len(tiles) == len(whole), (len(tiles), len(whole))
for _, x, y in whole:
    assert min((x - a) ** 2 + (y - b) ** 2 for _, a, b in tiles) < 1.0, (x, y)
PY
  # With footprints, each footprint's own centre decides its tile: no
  # footprint id in both, and the tile's report says why the others went.
  expect_ok tile_fp_west run "$SIM" -aoi "$(tile_box "$x0" "$split")" -footprints "$SIM/footprints.gpkg" \
    -o "$WORK/fw.gml" -report "$WORK/fw.json" -q || return
  expect_ok tile_fp_east run "$SIM" -aoi "$(tile_box "$split" "$x1")" -footprints "$SIM/footprints.gpkg" \
    -o "$WORK/fe.gml" -q || return
  python3 - "$WORK/fw.gml" "$WORK/fe.gml" "$WORK/fw.json" <<'PY' && pass tile_fp_once || fail tile_fp_once "see the tiles"
import json, re, sys
ids = [re.findall(r'name="footprint_id">\s*<gen:value>([^<]+)<', open(f).read()) for f in sys.argv[1:3]]
assert ids[0] and ids[1] and not set(ids[0]) & set(ids[1]), ids
left = [r for r in json.load(open(sys.argv[3]))["rejected"] if "neighbouring tile" in r]
assert left and all("footprint's centre" in r for r in left), left
PY
  # The tiles' outputs gathered into one model: every building once, a
  # valid CityGML file; appending a tile twice is refused.
  expect_ok tile_append_west convert "$WORK/west.gml" "$WORK/city.gml" -append -q || return
  expect_ok tile_append_east convert "$WORK/east.gml" "$WORK/city.gml" -append || return
  grep -q "there before" "$WORK/stdout.txt" && pass tile_append_message \
    || fail tile_append_message "$(cat "$WORK/stdout.txt")"
  [[ $(grep -c "<bldg:Building " "$WORK/city.gml") -eq $(wc -l <"$WORK/whole.txt") ]] \
    && pass tile_append_count || fail tile_append_count "$(grep -c "<bldg:Building " "$WORK/city.gml")"
  local xsd
  if xsd=$(shared_or_skip "$XSD_REL"); then
    xmllint --noout --nonet --schema "$xsd" "$WORK/city.gml" 2>"$WORK/xml.txt" \
      && pass tile_append_schema_valid || fail tile_append_schema_valid "$(head -c 400 "$WORK/xml.txt")"
  fi
  cp "$WORK/city.gml" "$WORK/city_before.gml"
  expect_fail tile_append_twice "" "already" -- convert "$WORK/east.gml" "$WORK/city.gml" -append
  cmp -s "$WORK/city.gml" "$WORK/city_before.gml" && pass tile_append_twice_untouched \
    || fail tile_append_twice_untouched "city.gml changed"
  # A small tile reads a small part of the images.
  local bx by
  read -r _ bx by < <(head -1 "$WORK/west.txt")
  expect_ok tile_small run "$SIM" -aoi "$(python3 -c "print(f'{$bx-3},{$by-3},{$bx+3},{$by+3}')")" \
    -tile_buffer 5 -o "$WORK/small.gml" || return
  python3 - "$WORK/stdout.txt" <<'PY' && pass tile_reads_windows || fail tile_reads_windows "$(grep '^tile' "$WORK/stdout.txt")"
import re, sys
m = re.search(r"^tile: \d+ of 4 views .*; ([0-9.]+) of ([0-9.]+) megapixels read", open(sys.argv[1]).read(), re.M)
assert m and float(m.group(1)) < 0.5 * float(m.group(2)), m and m.groups()
PY
  # match reads the same windows for a tile, and its lines feed run on it.
  local small
  small=$(python3 -c "print(f'{$bx-3},{$by-3},{$bx+3},{$by+3}')")
  expect_ok tile_match match "$SIM" -aoi "$small" -tile_buffer 5 -o "$WORK/small_lines.gpkg" || return
  grep -Eq "^tile: [0-9]+ of 4 views see it and its 5 m buffer" "$WORK/stdout.txt" \
    && pass tile_match_message || fail tile_match_message "$(head -3 "$WORK/stdout.txt")"
  ogrinfo -ro -al -q "$WORK/small_lines.gpkg" lines3d >"$WORK/small_lines.txt" 2>&1
  python3 - "$WORK/small_lines.txt" "$small" <<'PY' && pass tile_match_lines || fail tile_match_lines "$(head -c 600 "$WORK/small_lines.txt")"
import re, sys
text, box = open(sys.argv[1]).read(), [float(v) for v in sys.argv[2].split(",")]
obs = re.findall(r"observations \(String\) = (.*)", text)
assert obs, "no lines in the tile"
# Segment ids of the windows name nothing in the whole images.
assert all(t.endswith(":-1") for o in obs for t in o.split()), obs[:3]
# The lines lie in the tile and its buffer (5 m), give or take the windows'
# margin and a line's run past the region's edge.
points = re.findall(r"([0-9.]+) ([0-9.]+) [0-9.]+", " ".join(re.findall(r"LINESTRING Z \(([^)]*)\)", text)))
assert len(points) == 2 * len(obs), (len(points), len(obs))
for x, y in points:
    assert box[0] - 15 < float(x) < box[2] + 15 and box[1] - 15 < float(y) < box[3] + 15, (x, y, box)
PY
  expect_ok tile_match_run run "$SIM" -aoi "$small" -tile_buffer 5 -lines "$WORK/small_lines.gpkg" \
    -o "$WORK/small_from_lines.gml" -q
  # sweep takes the tile too, and the lines it writes name no segment either.
  expect_ok tile_sweep sweep "$SIM" -aoi "$small" -tile_buffer 5 -o "$WORK/small_hp.gpkg" \
    -lines3d "$WORK/small_sweep_lines.gpkg" || return
  grep -Eq "^tile: [0-9]+ of 4 views see it and its 5 m buffer" "$WORK/stdout.txt" \
    && pass tile_sweep_message || fail tile_sweep_message "$(head -3 "$WORK/stdout.txt")"
  ogrinfo -ro -al -q "$WORK/small_sweep_lines.gpkg" lines3d | grep "observations (String)" >"$WORK/obs.txt"
  [[ -s "$WORK/obs.txt" ]] && ! grep -Eq ":([0-9]|-[02-9])" "$WORK/obs.txt" \
    && pass tile_sweep_lines || fail tile_sweep_lines "$(head -3 "$WORK/obs.txt")"
  # lines reads the same windows, and writes their segments in the whole
  # images' pixels: most of them are those of the whole images (the rest end
  # at a window's border, or were thresholded on the window's statistics).
  expect_ok tile_lines_whole lines "$SIM" -o "$WORK/lines_whole.gpkg" -q || return
  expect_ok tile_lines lines "$SIM" -aoi "$small" -tile_buffer 5 -o "$WORK/lines_tile.gpkg" || return
  grep -Eq "^tile: [0-9]+ of 4 views see it and its 5 m buffer" "$WORK/stdout.txt" \
    && pass tile_lines_message || fail tile_lines_message "$(head -3 "$WORK/stdout.txt")"
  python3 - "$WORK/lines_whole.gpkg" "$WORK/lines_tile.gpkg" <<'PY' && pass tile_lines_coordinates || fail tile_lines_coordinates "see above"
import sqlite3, struct, sys
def segments(path):
    db = sqlite3.connect(path)
    out = {}
    for (name,) in db.execute("SELECT table_name FROM gpkg_contents WHERE data_type = 'features'"):
        rows = []
        for (blob,) in db.execute(f'SELECT geom FROM "{name}"'):
            flags = blob[3]
            envelope = {0: 0, 1: 32, 2: 48, 3: 48, 4: 64}[(flags >> 1) & 7]
            wkb = blob[8 + envelope:]
            order = "<" if wkb[0] == 1 else ">"
            n = struct.unpack(order + "I", wkb[5:9])[0]
            rows.append(struct.unpack(order + "%dd" % (2 * n), wkb[9:9 + 16 * n]))
        out[name] = rows
    return out
whole, tile = segments(sys.argv[1]), segments(sys.argv[2])
assert tile and set(tile) <= set(whole), (sorted(tile), sorted(whole))
for name, rows in tile.items():
    assert rows, name
    same = sum(any(max(abs(a - b) for a, b in zip(r, w)) < 0.01 for w in whole[name]) for r in rows)
    print(name, len(rows), "segments,", same, "as in the whole image")
    # 71-86 % here; without the shift into the whole image, next to none.
    assert same >= 0.5 * len(rows), name
PY
  expect_fail tile_match_truth "$WORK/t.gpkg" "-aoi and -truth" -- match "$SIM" -aoi "$small" \
    -truth "$SIM/groundtruth_edges.json" -o "$WORK/t.gpkg"
  # A tile the images do not see, and a malformed one.
  expect_fail tile_unseen "$WORK/far.gml" "no image sees the tile" -- run "$SIM" \
    -aoi "$(tile_box "$(python3 -c "print($split + 1e5)")" "$(python3 -c "print($split + 1e5 + 10)")")" \
    -o "$WORK/far.gml"
  expect_fail tile_bad_aoi "$WORK/bad.gml" "aoi" -- run "$SIM" -aoi 5,5,1,1 -o "$WORK/bad.gml"
}

test_run_refuses_bad_input() {
  small_block || return
  touch "$WORK/exists.gml"
  expect_fail run_exists "" "exists.*-overwrite" -- run "$SIM" -o "$WORK/exists.gml"
  expect_fail run_bad_min_edge_support "$WORK/z.gml" "min_edge_support" -- run "$SIM" -o "$WORK/z.gml" \
    -min_edge_support 1.5
  expect_fail run_bad_min_edge_support_unlined "$WORK/z.gml" "min_edge_support_unlined" -- run "$SIM" \
    -o "$WORK/z.gml" -min_edge_support_unlined -0.1
  expect_fail run_no_block "$WORK/x.gml" "nope" -- run "$WORK/nope" -o "$WORK/x.gml"
  expect_fail run_bad_format "$WORK/x.abc" "format|extension" -- run "$SIM" -o "$WORK/x.abc"
  # Images that would not fit in memory are refused before they are read,
  # pointing at tiles (the limit lowered to below what this block needs).
  expect_fail run_memory "$WORK/m.gml" "megapixels, which need about .* GB; ROOFSWEEP_MAX_MEMORY allows 0.1 GB.*-aoi" \
    -- run "$SIM" -o "$WORK/m.gml" --config ROOFSWEEP_MAX_MEMORY 0.1
  expect_ok run_memory_enough run "$SIM" -o "$WORK/m.gml" -q --config ROOFSWEEP_MAX_MEMORY 1
  # match reads the same images and gives the same advice.
  expect_fail match_memory "$WORK/match_memory.gpkg" "megapixels, which need about .* GB; ROOFSWEEP_MAX_MEMORY allows 0.1 GB.*-aoi" \
    -- match "$SIM" -o "$WORK/match_memory.gpkg" --config ROOFSWEEP_MAX_MEMORY 0.1
}

run_tests
