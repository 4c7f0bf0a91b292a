#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "algorithms/geometry/block.h"
#include "algorithms/geometry/block_overview.h"
#include "io/core/block_manifest.h"

namespace roofsweep {

struct BlockInfo {
  BlockManifest manifest;  // as read, CRS coordinates
  Block block;             // local frame
  BlockOverview overview;  // footprints, GSD, overlaps, warnings
};

// `roofsweep info`: reads BLOCK (anything OpenBlockManifest accepts) and
// analyses it. Image files are not opened.
BlockInfo RunInfo(const std::string& block);

std::string FormatInfoText(const BlockInfo& info);
nlohmann::json InfoToJson(const BlockInfo& info);

// `info -tiles SIZE`: the tiles of the aligned SIZE grid that at least two
// images see (TileGrid), one MINX,MINY,MAXX,MAXY per line, or with `json` a
// JSON array of [minx, miny, maxx, maxy].
std::string FormatTiles(const BlockInfo& info, double size, bool json);

}  // namespace roofsweep
