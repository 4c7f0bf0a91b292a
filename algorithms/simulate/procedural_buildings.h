#pragma once

#include <Eigen/Core>
#include <string>

#include "algorithms/buildings/city_model.h"

namespace roofsweep {
namespace sim {

// Roof shapes the generator builds. Composites are gabled wings joined with
// valleys (their CityGML roofType is 1130, combination).
enum class RoofShape { kFlat, kShed, kGable, kHip, kHalfHip, kPyramid, kMansard, kLShape, kTShape };
constexpr int kRoofShapeCount = 9;
const char* RoofShapeName(RoofShape s);
int RoofShapeCode(RoofShape s);  // SIG3D roof type code

// One building in its own frame: footprint rectangle length x width centred
// at `center`, long axis rotated by `yaw_deg` counter-clockwise from +x.
struct BuildingSpec {
  std::string id = "BLDG_0001";
  RoofShape shape = RoofShape::kGable;
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double yaw_deg = 0;
  double length = 12;  // along the local x axis (ridge direction), m
  double width = 9;    // across, m
  double ground_z = 0;
  double eave_height = 6;    // above ground, m
  double ridge_height = 10;  // above ground, m (ignored for kFlat)
  // Half-hip: height of the hip's foot as a fraction of eave..ridge.
  double half_hip_fraction = 0.65;
  // Mansard: horizontal inset of the break line (m) and its height above
  // ground; the upper part is a low hip roof up to ridge_height.
  double mansard_inset = 1.2;
  double mansard_break_height = 9;
  // L/T wings: width and extension beyond the main eave (m); the wing roof
  // has the main roof's pitch so that its ridge is lower when it is narrower.
  double wing_width = 7;
  double wing_length = 7;
  double wing_offset = 0;  // T only: wing centre along the main axis, m
};

// Builds a closed LoD2 solid: every surface is one planar polygon, exterior
// rings counter-clockwise seen from outside, no T-junctions, so every edge is
// used exactly twice in opposite directions. Roof faces meet exactly at
// ridges, hips and valleys. Throws roofsweep::Error for impossible specs.
Building MakeBuilding(const BuildingSpec& spec);

}  // namespace sim
}  // namespace roofsweep
