#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/camera.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/geometry/view.h"
#include "algorithms/simulate/bvh.h"

namespace roofsweep {

// A LoD2 model drawn over the images of its block, and how much of its roof
// outline those images show as edges. On a real block there is no reference
// model: superimposing the model on the images is how a photogrammetrist
// checks it, and the share of projected roof edges that lie on an image
// edge is the figure that goes with the picture (it needs no ground truth).

enum class ModelEdgeKind {
  kRoof,  // an edge of a roof polygon: eave, verge, ridge, hip, valley, step
  kWall,  // any other edge: wall corners, the foot of the walls
};

struct ModelEdge {
  Segment3 segment;
  ModelEdgeKind kind = ModelEdgeKind::kRoof;
  int building = -1;  // index into CityModel::buildings (a part counts as its building)
};

// Every polygon edge of the model once: an edge two faces share (a ridge,
// the eave between roof and wall) is one edge, of kind kRoof when either
// face is a roof. Edges shorter than 1 cm are left out.
std::vector<ModelEdge> ModelEdges(const CityModel& model);

// The model's own surfaces as occluders: a point of the model is hidden in a
// view when another of its faces lies between it and the projection centre
// (a roof seen behind a taller neighbour, the far eave of an oblique view).
class ModelOccluder {
 public:
  explicit ModelOccluder(const CityModel& model);
  // True when nothing of the model lies on the segment from `centre` to
  // `point` short of the last `tolerance_m` before the point (the faces
  // through the point itself do not hide it).
  bool Visible(const Eigen::Vector3d& centre, const Eigen::Vector3d& point,
               double tolerance_m = 0.2) const;

 private:
  sim::Bvh bvh_;
};

struct ImageEdgeOptions {
  // Gradient smoothing, px: the edge extraction's default (EdgeOptions).
  double sigma = 1.0;
  // A sample of a projected roof edge is supported when a pixel within
  // search_px across the edge has a colour gradient of at least the edge
  // extraction's automatic low hysteresis threshold, pointing across the
  // edge within max_angle_deg. 1.5 px is the tolerance of the 2D segment
  // evaluation (issue 4) and admits a model edge about one GSD off.
  double search_px = 1.5;
  double max_angle_deg = 20.0;
  double step_px = 1.0;  // sample spacing along the projected edge
  // Samples nearer than this to the image border are not scored (the
  // gradient is zero on the outermost rows and columns).
  double border_px = 3.0;
};

struct EdgeSupport {
  double visible_px = 0;    // projected roof-edge length inside the image, not hidden
  double supported_px = 0;  // ... of it with an image edge along it
  double hidden_px = 0;     // projected roof-edge length hidden by the model itself
  // supported / visible; NaN when nothing is visible.
  double Fraction() const;
  EdgeSupport& operator+=(const EdgeSupport& o);
};

struct ImageOverlay {
  EdgeSupport roof;                       // all roof edges in this image
  std::vector<EdgeSupport> per_building;  // indexed like CityModel::buildings
  // The image (8-bit RGB) with the visible roof edges drawn green where
  // supported and red where not, and the visible wall edges in cyan.
  cv::Mat drawing;
};

// `image`: as ReadImage returns it (CV_32FC3 R, G, B, or CV_32FC1, in
// [0, 1]); `buildings`: the model's building count, for per_building.
// Gradients are fused over the colour bands (the maximum of the per-band
// norms, Scholze et al. 2000), so a ridge seen only as a change of hue
// counts as seen. With draw false, `drawing` stays empty.
ImageOverlay OverlayModel(const cv::Mat& image, const Camera& camera, const Pose& pose,
                          const std::vector<ModelEdge>& edges, int buildings,
                          const ModelOccluder& occluder, const ImageEdgeOptions& options = {},
                          bool draw = true);

// The image support of each building's roof edges summed over every view
// of the block (`images` in block order, as ReadImage returns them),
// indexed like model.buildings; the model in the block's local frame.
// Views are processed in parallel and summed in block order.
std::vector<EdgeSupport> BuildingEdgeSupport(const CityModel& model, const Block& block,
                                             const std::vector<cv::Mat>& images,
                                             const ImageEdgeOptions& options = {});

}  // namespace roofsweep
