#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/buildings/footprint.h"
#include "io/core/local_frame.h"

namespace roofsweep {

struct FootprintReadOptions {
  std::string layer;     // empty: the first layer with polygon geometry
  std::string id_field;  // empty: "id", "identificatie", "gml_id" or "fid" if present, else the FID
  std::string block_crs;  // the block's CRS; footprints in another CRS are transformed
  // Only footprints whose bounding box meets this box (local frame: min x,
  // min y, max x, max y) are returned; empty: all.
  std::optional<Eigen::Vector4d> extent;
};

// Building footprints from any OGR polygon layer (GeoPackage, Shapefile,
// GeoJSON, FlatGeobuf, a PostGIS connection string), in the block's local
// frame: one Footprint per polygon (a MultiPolygon's parts share the id),
// exterior ring counter-clockwise, closing vertex dropped, z ignored.
// A layer without a CRS is read as block coordinates (`messages` says so).
// Throws roofsweep::Error with a one-line message naming the file (and the
// feature) for: a missing or unreadable dataset, no such layer, no polygon
// layer, an unknown or untransformable CRS, NaN/infinite coordinates.
// Polygons with fewer than three distinct vertices or a self-crossing
// exterior ring are skipped and named in `messages`.
std::vector<Footprint> ReadFootprints(const std::string& path, const LocalFrame& frame,
                                      const FootprintReadOptions& options,
                                      std::vector<std::string>* messages);

}  // namespace roofsweep
