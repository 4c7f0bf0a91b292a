#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace roofsweep {

// The LoD2 city model every stage hands on: reconstruction produces it, the
// simulator's ground truth is one, the writers (CityGML, CityJSON, GPKG)
// serialise it and the evaluator compares two of them.

enum class SurfaceType { kRoof, kWall, kGround, kClosure };
const char* SurfaceTypeName(SurfaceType t);  // "RoofSurface", "WallSurface", ...

// A planar polygon. Rings do not repeat their first vertex. The exterior
// ring is counter-clockwise seen from outside the solid (right-hand rule
// gives the outward normal), holes clockwise.
struct Polygon3 {
  std::vector<Eigen::Vector3d> exterior;
  std::vector<std::vector<Eigen::Vector3d>> holes;

  // Newell normal of the exterior ring (unit; zero for a degenerate ring).
  Eigen::Vector3d Normal() const;
  // Area of the polygon (exterior minus holes), m².
  double Area() const;
  // Whether the plan point lies inside the polygon seen from above
  // (exterior minus holes; even-odd rule, so either ring orientation).
  bool ContainsXY(const Eigen::Vector2d& p) const;
};

struct Surface {
  SurfaceType type = SurfaceType::kRoof;
  std::string id;  // optional, kept through round trips
  std::vector<Polygon3> polygons;
};

// SIG3D/AdV roof type codes used by CityGML bldg:roofType.
namespace roof_type {
constexpr int kUnknown = 0;
constexpr int kFlat = 1000;
constexpr int kMonopitch = 1010;  // shed
constexpr int kDualPent = 1020;
constexpr int kGabled = 1030;
constexpr int kHipped = 1040;
constexpr int kHalfHipped = 1050;
constexpr int kMansard = 1060;
constexpr int kPavilion = 1070;  // pyramid
constexpr int kCone = 1080;
constexpr int kCupola = 1090;
constexpr int kSawtooth = 1100;
constexpr int kArch = 1110;
constexpr int kPyramidalBroach = 1120;
constexpr int kCombination = 1130;
}  // namespace roof_type
const char* RoofTypeName(int code);  // "gabled", ...; "unknown" for 0 or unlisted

struct Building {
  std::string id;  // a valid xs:ID (starts with a letter)
  std::vector<Surface> surfaces;
  int roof_type = roof_type::kUnknown;
  double measured_height = 0;  // m, ground to highest roof point; 0 unknown
  // Level of detail of the surfaces: 2 (the roof's own shape) or 1, a block
  // model (the footprint extruded to one roof height, flat top), which the
  // run writes over a footprint whose roof it could not reconstruct, as
  // 3DBAG's LoD1.2. Written as lod1Solid (CityGML), "lod": "1" (CityJSON)
  // and field `lod`; the evaluation leaves LoD1 buildings out of the LoD2
  // figures. Parts share their building's.
  int lod = 2;
  // Generic attributes (quality figures, source ids): written as gen:* in
  // CityGML, attributes in CityJSON and fields in GeoPackage.
  std::map<std::string, double> double_attributes;
  std::map<std::string, std::string> string_attributes;
  // Building parts (CityGML bldg:consistsOfBuildingPart, CityJSON
  // BuildingPart children), each a solid with its own roof type and height:
  // one cadastral building whose wings or terraced units stand at different
  // heights. A building with parts carries the attributes that hold for the
  // whole (its footprint's id) and, in roofsweep's output, no surfaces of
  // its own; a model read from elsewhere may have both.
  std::vector<Building> parts;

  // Lowest ground z and highest roof z, over the parts too (NaN when there
  // are none).
  double GroundZ() const;
  double RoofTopZ() const;
  // Plan (x, y) centroid of the ground surfaces, over the parts too, area
  // weighted; empty when there is no ground surface of positive area. The
  // point that decides which tile of a tiled run a building belongs to.
  std::optional<Eigen::Vector2d> PlanCentroid() const;
  // The objects that carry geometry: this building when it has surfaces,
  // then its parts (depth first). What solid checks and counts go over.
  std::vector<const Building*> Solids() const;
  std::vector<Building*> Solids();
};

// A set of buildings in one coordinate system: the block CRS when written
// or read, the local frame inside the pipeline.
struct CityModel {
  std::string crs;  // as given ("EPSG:25833"); empty: local/unknown
  std::vector<Building> buildings;

  // Axis-aligned bounds of all vertices: (min x, min y, min z, max x, max y, max z).
  Eigen::Matrix<double, 6, 1> Bounds() const;

  // Replaces every vertex v by f(v) (a change of frame or CRS, a shift).
  template <typename F>
  void TransformVertices(F f) {
    // A lambda returning an Eigen expression (`return v + shift;`) would
    // hand back references to its own temporaries: demand a plain vector.
    static_assert(std::is_same_v<std::invoke_result_t<F&, const Eigen::Vector3d&>, Eigen::Vector3d>,
                  "TransformVertices: f must return Eigen::Vector3d (declare -> Eigen::Vector3d)");
    for (Building& b : buildings)
      for (Building* solid : b.Solids())
        for (Surface& s : solid->surfaces)
          for (Polygon3& p : s.polygons) {
            for (auto& v : p.exterior) v = f(v);
            for (auto& h : p.holes)
              for (auto& v : h) v = f(v);
          }
  }
};

// Moves every part's surfaces into its building and drops the parts: one
// object per building, as the evaluation compares them (a reference
// building modelled as parts is one building to find, and so is ours).
void MergeBuildingParts(CityModel* model);

}  // namespace roofsweep
