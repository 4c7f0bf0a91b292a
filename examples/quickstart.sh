#!/usr/bin/env bash
# A first session with roofsweep, as a new user would type it. CI runs this
# script (tests/e2e), so every line here works.
#
#   examples/quickstart.sh [path/to/roofsweep] [work folder]
set -euo pipefail
RS=${1:-roofsweep}
W=${2:-quickstart}
mkdir -p "$W"

# 1. A small simulated aerial block with ground truth (images, OPK, camera, CityGML).
"$RS" simulate -preset easy -seed 2 -size 768 -gsd 0.1 -strips 1 -views 4 -o "$W/sim" -overwrite -q

# 2. Import its orientation the way real data comes: an OPK text file plus a
#    camera file, positions in ETRS89 / UTM 32N with ellipsoidal heights.
"$RS" import opk "$W/sim/orientation/opk.txt" -camera "$W/sim/orientation/camera.yaml" \
  -images "$W/sim/images" -a_srs EPSG:25832 -ground 520 -o "$W/block.json" -overwrite -q
"$RS" info "$W/block.json"

# 3. Colour edges (one layer per image) and 3D lines. GDAL options work as in
#    the GDAL utilities, e.g. --config to set a GDAL configuration option.
"$RS" lines "$W/block.json" -o "$W/lines.gpkg" -overwrite -q --config GDAL_NUM_THREADS 2
"$RS" match "$W/block.json" -o "$W/lines3d.gpkg" -overwrite -q

# 4. LoD2 buildings: half-plane sweep about the 3D lines, roof planes,
#    closed solids with walls to the ground. -lines reuses step 3's lines
#    (without it, run matches the segments itself); -report lists why each
#    rejected plane or building was not built.
"$RS" run "$W/block.json" -lines "$W/lines3d.gpkg" -o "$W/buildings.gpkg" -report "$W/run.json" \
  -overwrite -q

# 5. Convert between formats (-of names the format when the extension does not).
"$RS" convert "$W/buildings.gpkg" "$W/buildings.gml" -overwrite -q
"$RS" convert "$W/buildings.gpkg" "$W/buildings.city.json" -of CityJSON -overwrite -q
"$RS" convert "$W/sim/groundtruth.gml" "$W/truth.fgb" -of FlatGeobuf -overwrite -q

# 6. Score the buildings and the 3D lines against the ground truth, with a
#    plan-view overlay to look at.
"$RS" eval "$W/buildings.gml" "$W/sim" -lines "$W/lines3d.gpkg" -png "$W/overlay.png" -overwrite

# 7. On a real block there is no ground truth: draw the buildings over the
#    images and see how much of their roof outline lies on image edges
#    (green where it does, red where it does not; -report lists each building).
"$RS" overlay "$W/block.json" "$W/buildings.gpkg" -o "$W/check" -report "$W/check.json" -overwrite -q
