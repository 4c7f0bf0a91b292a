#pragma once

// Tiled runs: a batch engine runs one `roofsweep run` per tile of a city
// block (the manifest's aoi or -aoi). Each run reads only what can see its
// tile and writes only the buildings it owns, so that the tiles' outputs
// together hold every building once.

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"
#include "algorithms/geometry/block_overview.h"
#include "algorithms/geometry/block_window.h"
#include "io/core/local_frame.h"

namespace roofsweep {

struct TileCut {
  // Local x, y box processed: the tile grown by the buffer on every side.
  Eigen::Vector4d region = Eigen::Vector4d::Zero();
  // Per view of the cut block, the window of its image to read; empty when
  // the block was not cut (no ground model to bound the heights).
  std::vector<PixelWindow> windows;
  // Pixels the cut block's views read (windows, or whole images when not cut).
  long long pixels_read = 0;
  std::string message;  // what was cut, for the log
  // The images are read in windows: the segment ids of the lines then index
  // a window's segments, which name no segment of the whole image.
  bool Windowed() const { return !windows.empty(); }
};

// Cuts `block` (which has an aoi) down to the views that see its tile and
// the buffer around it, between the ground and max_building_height above
// it, each with the window of its image that does. Buildings that straddle
// the tile's border are reconstructed whole when they reach no further than
// `buffer_m` beyond it. Throws when no view sees the tile.
TileCut CutBlockToTile(Block* block, double buffer_m, const std::string& source);

// Keeps the buildings whose plan centroid (of the ground surfaces) lies in
// the tile `aoi` (block CRS: min x <= E < max x, min y <= N < max y; one
// tile of a grid owns each point) and prefixes their ids (and their parts')
// with the tile's tag, so that the tiles' outputs can be merged. The others
// are left to the neighbouring tiles: one line each in the return value,
// and their planes' plane_building cleared with that reason.
//
// With footprints, a building labelled with a footprint (footprint_id) is
// owned by the tile that holds the footprint's own centroid (local frame,
// area weighted over the pieces that share the id), which does not depend
// on the reconstruction: neighbouring tiles agree on it exactly.
std::vector<std::string> KeepTileBuildings(const Eigen::Vector4d& aoi, const LocalFrame& frame,
                                           const std::vector<Footprint>& footprints,
                                           AssemblyResult* assembled);

// Refuses, before any image is read, a run whose images would not fit in
// this machine's memory: about kRunBytesPerPixel for every pixel read (the
// images as float RGB and what the stages derive from them; measured on the
// simulated blocks) against the physical memory, or against the GDAL
// configuration option ROOFSWEEP_MAX_MEMORY (GB) when set. The error names
// -aoi: a tiled run reads only what sees its tile.
void RequireMemoryForImages(long long pixels, int views, const std::string& source);

// The images of `block`'s views, in parallel: with `tile` (its cut, or
// null) only the window of each image that sees the tile, and refused
// before any is read when they would not fit in memory.
std::vector<cv::Mat> ReadBlockImages(const Block& block, const TileCut* tile,
                                     const std::string& source);

// The tiles of a grid of `size` (block CRS units, aligned to multiples of
// it, so that the grids of neighbouring blocks meet) that at least two
// views' ground footprints cover in part (a stereo pair; footprints from
// BlockOverview, local frame), as min x, min y, max x, max y, row by row
// from the south-west.
std::vector<Eigen::Vector4d> TileGrid(const std::vector<ViewFootprint>& footprints,
                                      const LocalFrame& frame, double size);

// "t<min x>_<min y>" of the tile, usable in an xs:ID.
std::string TileTag(const Eigen::Vector4d& aoi);

}  // namespace roofsweep
