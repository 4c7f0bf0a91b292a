#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/eval/plan_geometry.h"

// What the evaluator compares: roof planes and building footprints seen from
// above.

namespace roofsweep::eval {

struct RoofPlaneOptions {
  // Roof polygons of one building are one "roof plane" when their upward
  // normals differ by at most this angle...
  double coplanar_angle_deg = 2.0;
  // ... every vertex of each lies within this distance of the other's plane...
  double coplanar_distance_m = 0.10;
  // ... and they touch in plan view (gap at most this). Real LoD2 data (e.g.
  // Berlin) splits one roof face into several coplanar polygons, sometimes
  // across RoofSurfaces; two separate dormers at the same height stay two.
  double group_gap_m = 0.05;
  // Roof polygons steeper than this (normal within 90° - this of horizontal)
  // have next to no plan area; they are counted and left out.
  double vertical_roof_deg = 85.0;
};

struct RoofPlane {
  int building = -1;                                  // index into CityModel::buildings
  std::vector<std::pair<int, int>> polygons;          // (surface index, polygon index)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, z >= 0, area-weighted
  MultiPolygon2 plan;                                 // region: the xy projections of its polygons
  MultiPolygon2 outline;  // merged outline of `plan` (drawing, vertex distances)
  double plan_area = 0;   // m²
  Box2 box;
};

struct RoofPlaneSet {
  std::vector<RoofPlane> planes;  // ordered by building, then first polygon
  int roof_polygons = 0;          // all polygons of RoofSurfaces
  int vertical_polygons = 0;      // left out: steeper than vertical_roof_deg
  int degenerate_polygons = 0;    // left out: no normal or no plan area
  int invalid_polygons = 0;       // left out: self-intersecting in plan
  int downward_polygons = 0;      // normal pointed down (ring orientation); flipped, kept
};

RoofPlaneSet ExtractRoofPlanes(const CityModel& model, const RoofPlaneOptions& options);

// Plan-view footprint of a building: the union of its GroundSurfaces, or of
// its non-vertical roof polygons when it has no GroundSurface.
MultiPolygon2 BuildingFootprint(const Building& building, const RoofPlaneOptions& options);

// Upward unit normal (z >= 0) of a polygon; zero when degenerate.
Eigen::Vector3d UpwardNormal(const Polygon3& polygon);

// The polygon projected to xy (holes kept).
Polygon2 ProjectXY(const Polygon3& polygon);

}  // namespace roofsweep::eval
