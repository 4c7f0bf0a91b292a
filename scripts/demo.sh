#!/usr/bin/env bash
# make demo: simulate a small city block, reconstruct it, write
# CityGML/CityJSON/GeoPackage into out/ and print the quality table.
set -euo pipefail
BUILD=${1:-build}
RS="$BUILD/plugin/cli/roofsweep"
OUT=out
mkdir -p "$OUT"
if ! "$RS" simulate --help >/dev/null 2>&1; then
  echo "demo: 'roofsweep simulate' is not built yet (issue: the yardstick)."; exit 0
fi
"$RS" simulate --preset realistic --seed 1 -o "$OUT/block" -overwrite
"$RS" info "$OUT/block"
if ! "$RS" run --help >/dev/null 2>&1; then
  echo "demo: reconstruction ('roofsweep run') is not built yet; the simulated block is in $OUT/block."; exit 0
fi
"$RS" run "$OUT/block" -o "$OUT/buildings.gpkg" -overwrite
"$RS" convert "$OUT/buildings.gpkg" "$OUT/buildings.gml" -overwrite
"$RS" convert "$OUT/buildings.gpkg" "$OUT/buildings.city.json" -overwrite
"$RS" eval "$OUT/buildings.gml" "$OUT/block/groundtruth.gml"
