#pragma once

#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "algorithms/eval/image_overlay.h"

namespace roofsweep {

struct OverlayRequest {
  std::string block;               // anything OpenBlockManifest accepts
  std::string model;               // LoD2 model (CityGML, CityJSON, GPKG) in any CRS
  std::string output_dir;          // one <view>.png per image
  std::string report;              // optional JSON: the figures per view and per building
  std::vector<std::string> views;  // view names; empty: every view
  bool overwrite = false;
  ImageEdgeOptions options;
};

struct OverlayViewSummary {
  std::string view;
  std::string file;  // the PNG written
  EdgeSupport roof;
};

struct OverlayBuildingSummary {
  std::string id;
  EdgeSupport roof;  // over all views
  int views = 0;     // views in which some of its roof outline is visible
  // Mean of its roof vertices in the block's CRS (the model's coordinates
  // when the block has none), to find it in a GIS.
  double x = 0, y = 0;
};

struct OverlaySummary {
  std::vector<OverlayViewSummary> views;          // in block order
  std::vector<OverlayBuildingSummary> buildings;  // in model order
  EdgeSupport total;
  std::vector<std::string> messages;  // reprojection and the like
  double seconds = 0;
};

// `roofsweep overlay`: draws a LoD2 model over every image of its block
// (roof edges green where an image edge runs along them, red where none
// does; walls cyan; what the model itself hides is not drawn) and measures
// the share of the visible projected roof-edge length that lies on an image
// edge (ImageEdgeOptions), per view, per building and overall: a check of a
// reconstruction that needs no ground truth. The model is reprojected to
// the block's CRS when it is in another; a model without a CRS is taken to
// be in the block's. Every PNG is written under a temporary name and
// renamed; existing ones need overwrite. Views are processed in parallel;
// the output does not depend on the thread count.
OverlaySummary RunOverlay(const OverlayRequest& request, Progress& progress);

std::string FormatOverlaySummary(const OverlaySummary& summary);

}  // namespace roofsweep
