#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/edges/edge_options.h"

namespace roofsweep {

struct LinesRequest {
  std::string block;   // anything OpenBlockManifest accepts
  std::string output;  // vector file holding one layer per image (.gpkg)
  std::string format;  // GDAL driver; empty: from the extension
  bool overwrite = false;
  std::vector<std::string> dataset_options, layer_options;  // -dsco, -lco NAME=VALUE
  std::string png_dir;  // optional: overlays of the segments on each image
  EdgeOptions edges;
  // One tile (block CRS: min x, min y, max x, max y), replacing the
  // manifest's aoi: only the views that see it and tile_buffer_m around it
  // are read, each in the window that does (as `run -aoi`; this needs the
  // block's orientation). The segments keep the whole image's coordinates.
  std::optional<Eigen::Vector4d> aoi;
  double tile_buffer_m = 30;
};

struct LinesImageSummary {
  std::string image;  // manifest image name
  std::string layer;
  int width = 0, height = 0, bands = 0;  // of what was read: the image or its window
  int segments = 0;
  double ms = 0;  // read + extraction
};

struct LinesSummary {
  std::vector<LinesImageSummary> images;  // in manifest order (a tile's views only)
  std::string tile;                       // what a tile cut, for the log; empty without one
  double seconds = 0;
};

// Layer name for an image file: "lines_" + the file stem with every
// character outside [A-Za-z0-9_] replaced by '_' ("001.jpg" -> "lines_001").
std::string LinesLayerName(const std::string& image_path);

// `roofsweep lines`: straight colour edge segments (Scholze et al. 2000, §2)
// of every image of a block. Writes one 2D LineString layer per image
// (LinesLayerName; names that collide, ignoring case, get "_2", "_3", ...),
// in image pixel coordinates: x right, y down, origin at the top-left
// CORNER of the top-left pixel, no CRS. Fields per segment: length_px,
// direction_deg (atan2(dy, dx) from p0 to p1, image axes, y down),
// contrast, band, method, rms_residual_px, support, texture, scale
// (Segment2D::scale), colour_left,
// colour_right (#rrggbb; the brighter side is on the left walking p0->p1).
// Images are processed in parallel; the output does not depend on the
// thread count. Any unreadable image refuses the whole block (nothing is
// written). With a tile (request.aoi or the manifest's aoi), only the
// layers of the views that see it, their segments found in the window read
// (ending at its border) but in the whole image's coordinates; the png_dir
// overlays then show the windows. With png_dir, writes <layer>.png:
// the image with the segments drawn over it.
LinesSummary RunLines(const LinesRequest& request, Progress& progress);

std::string FormatLinesSummary(const LinesSummary& summary);

}  // namespace roofsweep
