#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"

namespace roofsweep {
namespace sim {

// What a scene edge is, so an evaluator can judge detector findings and
// 3D lines against the true scene per kind.
enum class EdgeKind {
  kRidge,          // convex, horizontal, faces fall away on both sides
  kHip,            // convex, inclined
  kValley,         // concave roof-roof
  kBreak,          // convex horizontal between faces sloping the same way (mansard knee)
  kEave,           // horizontal roof edge over a wall, the roof descending to it
  kVerge,          // inclined roof edge over a (gable) wall
  kWallTop,        // horizontal roof edge over a wall, roof flat or rising to it
  kStep,           // roof edge against a higher wall (own or a neighbour's)
  kParty,          // roof edge on a wall shared flush with a neighbour
  kRoofOther,      // roof edge without a second face (open model)
  kWallCorner,     // wall-wall
  kFootprint,      // wall-ground
  kGroundMarking,  // painted line border or pavement edge on the terrain
  kProp,           // edge of a car, hedge, chimney, solar panel, ... in the open air (not LoD2)
  // kProp stays last: EdgeKindFromName walks the kinds up to it.
};
const char* EdgeKindName(EdgeKind k);
// The kind of an EdgeKindName (as groundtruth_edges.json holds it); nullopt
// for any other name.
std::optional<EdgeKind> EdgeKindFromName(const std::string& name);
// Edges on the roof outline or inside a roof (everything up to kRoofOther).
bool IsRoofEdge(EdgeKind k);

struct TrueEdge {
  Eigen::Vector3d a, b;
  EdgeKind kind = EdgeKind::kRoofOther;
  int building = -1;  // index into CityModel::buildings; -1 for ground markings and props
};

// A roof face: plane n·X + d = 0 with unit n pointing up/out.
struct RoofPlane {
  int building = -1;
  int surface = -1;  // index into Building::surfaces
  Eigen::Vector4d plane = Eigen::Vector4d::Zero();
  Polygon3 polygon;
};

// Edges between the faces of every building, classified. Edges whose faces
// are coplanar are not edges and are left out. `tolerance` (m) merges
// vertices; real models with T-junctions yield kRoofOther/kWallCorner pieces.
std::vector<TrueEdge> ExtractBuildingEdges(const CityModel& city, double tolerance = 1e-4);

std::vector<RoofPlane> ExtractRoofPlanes(const CityModel& city);

// Ground truth of a simulated scene, in the local ENU frame.
struct SceneTruth {
  CityModel city;
  std::vector<TrueEdge> edges;  // building edges, then ground markings, then props
  std::vector<RoofPlane> roof_planes;
};

}  // namespace sim
}  // namespace roofsweep
