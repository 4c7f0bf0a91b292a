#pragma once

#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"

namespace roofsweep {

// Geometry checks on one LoD2 building in the spirit of val3dity (ISO 19107
// rules as profiled by Ledoux 2018). Written here because val3dity is not in
// Debian; the checks are the small, exact subset roofsweep's writers need to
// report honestly what they write. Codes are val3dity's so users can look
// them up.
enum class SolidError {
  kTooFewPoints = 101,           // ring with fewer than 3 distinct vertices
  kConsecutivePointsSame = 102,  // two consecutive vertices closer than the weld tolerance
  kRingSelfIntersection = 104,   // ring edges cross (in the polygon's plane)
  kNonPlanar = 203,              // vertex farther than planarity_tolerance from the best-fit plane
  kShellNotClosed = 302,         // an edge used by only one polygon
  kNonManifoldEdge = 303,        // an edge used by more than two polygons
  kPolygonWrongOrientation = 307,     // an edge used twice in the same direction
  kAllPolygonsWronglyOriented = 308,  // closed shell with negative signed volume
  kEmpty = 901,                       // building without polygons
};
const char* SolidErrorName(SolidError e);  // "NON_PLANAR_POLYGON_DISTANCE_PLANE", ...

struct SolidCheckOptions {
  // Maximum distance (m) of any vertex to the least-squares plane of its
  // polygon (val3dity's default is 1 cm).
  double planarity_tolerance = 0.01;
  // Vertices closer than this (m) are one vertex for the topology checks
  // (val3dity's snap_tolerance default is 1 mm).
  double weld_tolerance = 0.001;
};

struct SolidViolation {
  SolidError code;
  int surface = -1;    // index into Building::surfaces; -1 for the whole shell
  int polygon = -1;    // index into Surface::polygons
  std::string detail;  // e.g. "distance 0.034 m" or the edge's coordinates
};

struct SolidCheckResult {
  std::vector<SolidViolation> violations;
  double signed_volume = 0;  // m³ by the divergence theorem; > 0 for outward rings

  bool Valid() const { return violations.empty(); }
  // "valid", or the distinct codes with counts: "203 NON_PLANAR_POLYGON_DISTANCE_PLANE x2; 302
  // ...".
  std::string Summary() const;
};

// Checks every polygon of `building` and treats all its polygons together as
// one shell (the lod2Solid the writers emit).
SolidCheckResult CheckBuildingSolid(const Building& building,
                                    const SolidCheckOptions& options = {});

}  // namespace roofsweep
