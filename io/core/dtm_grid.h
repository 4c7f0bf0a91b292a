#pragma once

// A DTM raster seen from the block: heights sampled at block-CRS positions
// and resampled onto a grid in the local frame (internal to io/core).

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/geometry/block.h"
#include "io/core/local_frame.h"

namespace roofsweep {

struct DtmGridOptions {
  // Largest grid side in cells; a coarser spacing is used beyond it, which
  // bounds memory at 8192² floats (256 MB).
  int max_cells_per_side = 8192;
  // Fixed-point steps that put a DTM height under a local (x, y): the
  // vertical of the local frame leans against the CRS's by up to the
  // angle subtended at the earth's centre (0.05° at 5 km); two steps bring
  // the horizontal error below 1 mm for any real block.
  int height_iterations = 2;
  // Spacing in metres of the lattice on which the local -> CRS mapping is
  // computed exactly through PROJ; cells in between interpolate it.
  double lattice_spacing_m = 100.0;
};

class DtmRaster {
 public:
  // block_crs: the block's CRS (empty: the DTM's coordinates are the
  // block's own). A DTM with its own horizontal CRS is transformed; its
  // heights are taken in the block's height system.
  DtmRaster(const std::string& path, const std::string& block_crs);
  ~DtmRaster();
  DtmRaster(const DtmRaster&) = delete;
  DtmRaster& operator=(const DtmRaster&) = delete;

  const std::string& path() const { return path_; }
  double min_height() const { return min_height_; }
  double max_height() const { return max_height_; }
  // DTM cell size in block units (metres for metric CRSs).
  double cell_size() const { return cell_size_; }

  // Block-CRS (x, y) to DTM pixel coordinates (corner origin) and back.
  Eigen::Vector2d CrsToPixel(const Eigen::Vector2d& xy) const;
  Eigen::Vector2d PixelToCrs(const Eigen::Vector2d& pixel) const;
  // Points along the raster's outline in block-CRS coordinates.
  std::vector<Eigen::Vector2d> OutlineCrs(int per_side = 16) const;

  // Reads the pixels overlapping [px0, px1) x [py0, py1) (clipped) into
  // memory; Sample* read only from the loaded window.
  void Load(double px0, double py0, double px1, double py1);
  // Bilinear height at pixel coordinates, NaN outside the raster or the
  // loaded window and next to nodata.
  double SamplePixel(const Eigen::Vector2d& pixel) const;
  // Loads a small window around (x, y) and samples it.
  double SampleCrsPoint(const Eigen::Vector2d& xy);

 private:
  std::string path_;
  GDALDataset* ds_ = nullptr;
  int width_ = 0, height_ = 0;
  double gt_[6] = {0, 1, 0, 0, 0, 1};
  double inv_gt_[6] = {0, 1, 0, 0, 0, 1};
  bool has_nodata_ = false;
  double nodata_ = 0;
  double min_height_ = 0, max_height_ = 0;
  double cell_size_ = 1;
  std::unique_ptr<OGRCoordinateTransformation> to_dtm_, to_block_;
  // Loaded window.
  int wx0_ = 0, wy0_ = 0, ww_ = 0, wh_ = 0;
  std::vector<float> window_;
};

// The DTM resampled onto a north-up grid in the local frame covering
// local_bbox (min x, min y, max x, max y), at the DTM's cell size. Cells
// with no DTM data are NaN.
GroundModel::Grid ResampleDtm(DtmRaster& dtm, const LocalFrame& frame,
                              const Eigen::Vector4d& local_bbox,
                              const DtmGridOptions& options = DtmGridOptions());

}  // namespace roofsweep
