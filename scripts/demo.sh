#!/usr/bin/env bash
# make demo: simulate a small city block, reconstruct it as LoD2 buildings,
# write CityGML/CityJSON/GeoPackage into out/ and print the quality tables.
set -euo pipefail
BUILD=${1:-build}
RS="$BUILD/plugin/cli/roofsweep"
OUT=out
mkdir -p "$OUT"

echo "== 1. simulate the 'realistic' preset (oriented images + ground truth) -> $OUT/block"
"$RS" simulate -preset realistic -seed 1 -o "$OUT/block" -overwrite
"$RS" info "$OUT/block"

echo "== 2. colour edges and straight segments -> $OUT/lines.gpkg (overlays in $OUT/lines_png)"
mkdir -p "$OUT/lines_png"
"$RS" lines "$OUT/block" -o "$OUT/lines.gpkg" -png "$OUT/lines_png" -overwrite

echo "== 3. segment matching into 3D lines -> $OUT/lines3d.gpkg, scored against the true edges"
"$RS" match "$OUT/block" -o "$OUT/lines3d.gpkg" -truth "$OUT/block/groundtruth_edges.json" -overwrite

echo "== 4. LoD2 buildings (half-plane sweep, roof planes, closed solids) -> $OUT/buildings.{gpkg,gml,city.json}"
"$RS" run "$OUT/block" -lines "$OUT/lines3d.gpkg" -o "$OUT/buildings.gpkg" \
  -report "$OUT/run_report.json" -overwrite
"$RS" convert "$OUT/buildings.gpkg" "$OUT/buildings.gml" -overwrite
"$RS" convert "$OUT/buildings.gpkg" "$OUT/buildings.city.json" -overwrite

echo "== 5. quality against the ground truth (plan-view overlay: $OUT/eval.png)"
"$RS" eval "$OUT/buildings.gml" "$OUT/block" -lines "$OUT/lines3d.gpkg" -png "$OUT/eval.png" -overwrite

echo "== 6. the same with building footprints (as from a cadastre: the simulator's footprints.gpkg)"
echo "   -> $OUT/buildings_footprints.gpkg: walls on the footprints, buildings labelled footprint_id,"
echo "      an LoD1 block (lod = 1) over a footprint whose roof was not reconstructed"
"$RS" run "$OUT/block" -lines "$OUT/lines3d.gpkg" -footprints "$OUT/block/footprints.gpkg" \
  -o "$OUT/buildings_footprints.gpkg" -report "$OUT/run_report_footprints.json" -overwrite
"$RS" eval "$OUT/buildings_footprints.gpkg" "$OUT/block" -png "$OUT/eval_footprints.png" -overwrite

echo "== 7. the buildings drawn over every image, as on a real block without ground truth -> $OUT/overlay/"
echo "   (roof edges green on an image edge, red off it; the share per view and the least supported buildings)"
"$RS" overlay "$OUT/block" "$OUT/buildings.gpkg" -o "$OUT/overlay" -report "$OUT/overlay.json" -overwrite
