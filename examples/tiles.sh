#!/usr/bin/env bash
# A block cut into tiles that a batch engine runs: here `xargs -P` on one
# machine; a cluster's scheduler (Slurm, HTCondor, a CI matrix) runs the same
# command lines. Each tile's run reads only what sees the tile and writes the
# buildings whose ground centre lies in it; `convert -append` then gathers
# the tiles into one model that holds every building once. CI runs this
# script (tests/e2e), so every line here works.
#
#   examples/tiles.sh [path/to/roofsweep] [work folder] [tile size in m]
set -euo pipefail
RS=${1:-roofsweep}
W=${2:-tiles}
SIZE=${3:-60}
mkdir -p "$W/out"

# 1. A small simulated block; with real data, start from its block.json.
"$RS" simulate -preset easy -seed 2 -size 512 -gsd 0.15 -strips 2 -views 3 -buildings 8 \
  -o "$W/sim" -overwrite -q

# 2. The tiles of a grid that at least two images see, one
#    "MINX,MINY,MAXX,MAXY" line each (block CRS). Aligned to the tile size, so
#    that the grids of neighbouring blocks meet.
"$RS" info "$W/sim" -tiles "$SIZE" >"$W/tiles.txt"
echo "$(wc -l <"$W/tiles.txt") tiles of $SIZE m"

# 3. The batch: one run per tile, two at a time.
export RS W
xargs -P 2 -I{} sh -c '"$RS" run "$W/sim" -aoi {} -o "$W/out/$(echo {} | tr , _).gml" -overwrite -q' \
  <"$W/tiles.txt"

# 4. The tiles gathered into one model, and scored against the ground truth.
rm -f "$W/city.gml"
for t in "$W"/out/*.gml; do "$RS" convert "$t" "$W/city.gml" -append -allow_empty -q; done
"$RS" eval "$W/city.gml" "$W/sim"
