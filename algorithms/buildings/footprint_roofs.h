#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "algorithms/buildings/assemble_buildings.h"
#include "algorithms/buildings/footprint.h"

namespace roofsweep {

// Options of RoofModelsOver. Slopes in degrees.
struct RoofModelOptions {
  // Shed roofs falling towards each side of the footprint's rectangle:
  // garages and carports (5-10°), lean-tos and modern sheds.
  std::vector<double> shed_slopes_deg = {5, 7.5, 10, 15, 20, 30};
  // Gable roofs with the ridge along either axis of the rectangle.
  std::vector<double> gable_slopes_deg = {25, 30, 35, 40, 45};
  // Hipped roofs: all four sides of the rectangle fall at one slope, the
  // ridge along its long axis (a pyramid over a square). A third of the
  // reference roofs of the `realistic` blocks are hipped or pavilion roofs;
  // without this model a gable took their place over a bare footprint, its
  // gable ends 2.5-3 m past the hips (`hard-1` s1 BLDG_0037, BLDG_0049).
  std::vector<double> hip_slopes_deg = {25, 30, 35, 40, 45};
  // A face smaller than this (plan, m²) is no face: the model is left out.
  double min_face_m2 = 1.0;
};

// One face of a roof model: its patch and its plane when the model's eaves
// stand at height 0 (the plane moves up with the eaves).
struct RoofModelFace {
  Ring2 patch;  // convex, counter-clockwise
  Eigen::Vector4d plane = Eigen::Vector4d(0, 0, 1, 0);
};

struct RoofModel {
  std::string name;  // "flat", "shed 10° falling north-east", "gable 35° along 120°"
  std::vector<RoofModelFace> faces;
};

// Parametric roofs over a footprint, the way LoD2 production fits them
// over cadastral outlines: flat, shed (falling to each side of the
// footprint's rectangle, at each of shed_slopes_deg), gable (ridge
// along each axis, at each of gable_slopes_deg) and hipped (every side
// falling at each of hip_slopes_deg), eaves at height 0. The
// rectangle is the one of least area whose side lies along an edge of the
// footprint's hull; faces are the hull cut at the ridge. Only hypotheses:
// the caller finds their heights and verifies each face against the images.
std::vector<RoofModel> RoofModelsOver(const Footprint& footprint,
                                      const RoofModelOptions& options = {});

// The face as a roof plane hypothesis with its eaves at height h over the
// footprint, marked derived so that it yields to every plane found
// directly. It has no supporting 3D line: the footprint's outline stands
// for them (longest_line_m is its longest edge), as the cadastre says a
// building stands there.
RoofPlaneHypothesis RoofModelFaceAt(const Footprint& footprint, const RoofModel& model, size_t face,
                                    double h);

}  // namespace roofsweep
