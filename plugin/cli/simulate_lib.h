#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>

#include "algorithms/core/progress.h"
#include "algorithms/simulate/presets.h"

namespace roofsweep {

struct SimulateRequest {
  std::string preset = "realistic";
  uint64_t seed = 1;
  std::string citygml;  // optional: a real LoD2 model to render (any format ReadCityModel reads)
  // With citygml: keep only buildings whose plan centre lies in this window
  // (min x, min y, max x, max y in the model's CRS).
  std::optional<Eigen::Vector4d> aoi;
  // The block is placed in a real CRS so that every later stage works as on
  // real data: local ENU at `origin` (CRS coordinates, ellipsoidal height of
  // the ground). A model read from --citygml keeps its own CRS and place.
  std::string crs = "EPSG:25832";
  Eigen::Vector3d origin = Eigen::Vector3d(691000.0, 5335000.0, 520.0);
  std::string image_format;  // jpg, tif or png; empty: the preset's (png for easy, else jpg)
  int jpeg_quality = 92;
  std::string output_dir;
  bool overwrite = false;
  // Overrides of the preset (0 / negative: keep the preset's value).
  int strips = 0;
  int images_per_strip = 0;
  int image_size = 0;
  double gsd = 0;
  int buildings = -1;
  bool obliques = false;
  // Forward and side overlap of the nadir images, fractions (negative: the
  // preset's, 80 / 60 %). 60 / 30 % is the classic mapping flight: most
  // ground seen in two or three images of one strip.
  double forward_overlap = -1;
  double side_overlap = -1;
  // Terrain: a plane falling by terrain_slope_percent towards the azimuth
  // terrain_aspect_deg (clockwise from the local north, as a GIS aspect).
  // Not 0: the block gets a DTM (dtm.tif) instead of one ground height.
  double terrain_slope_percent = 0;
  double terrain_aspect_deg = 0;
  // Hills and hollows on that plane spanning up to this many metres
  // (sim::SceneOptions::terrain_relief_m); not 0: a DTM too.
  double terrain_relief_m = 0;
};

struct SimulateSummary {
  int views = 0;
  int buildings = 0;
  int roof_planes = 0;
  int edges = 0;
  double gsd_m = 0;
  double seconds_render = 0;
};

// `roofsweep simulate`: renders the block and writes, into output_dir:
//   images/<view>.<ext>            the rendered images
//   orientation/opk.txt            Pix4D-style external orientation (grid OPK)
//   orientation/camera.yaml        orthority-style interior orientation
//   block.json                     the manifest, made by importing the two
//                                  files above (so the readers are exercised)
//   dtm.tif                        with a terrain slope: the terrain heights
//                                  (1 m cells, block CRS), named by block.json
//   groundtruth.gml                LoD2 ground truth, CityGML 2.0, block CRS
//   groundtruth_edges.json         3D roof, wall and prop edges and ground
//                                  markings, with kinds
//   footprints.gpkg                the true building footprints (ground
//                                  surfaces, layer `footprints`, field id) for
//                                  `run`'s footprint input; not in block.json
//   simulation.json                what was simulated (preset, seed, options)
// The folder is written under a temporary name and renamed when complete.
SimulateSummary RunSimulate(const SimulateRequest& request, Progress& progress);

}  // namespace roofsweep
