#pragma once

#include <ogr_spatialref.h>

#include <memory>
#include <string>

namespace roofsweep {

// The horizontal part of a CRS, in the project's axis order (x east, y
// north): a compound CRS loses its vertical part, a 3D one is demoted to 2D.
// Files of one block may give its CRS either way, and heights are always
// block heights, so CRSs are compared on this part.
std::unique_ptr<OGRSpatialReference> HorizontalCrs(const OGRSpatialReference& srs);

// "EPSG:25832" for a CRS that is, or whose horizontal part is, identified by
// an authority code, also when the definition itself carries none: GDAL
// stores the CRS of a GeoPackage layer of 3D features promoted to 3D, and the
// promoted WKT has no top-level ID, so "EPSG:25832" written would not read
// back as itself. Empty when no code is found.
std::string IdentifyCrs(const OGRSpatialReference& srs);

// Whether two CRS names ("EPSG:25832", "EPSG:25832+7837", WKT, PROJ strings)
// denote the same horizontal CRS. Names GDAL cannot read are compared as
// text.
bool SameHorizontalCrs(const std::string& a, const std::string& b);

}  // namespace roofsweep
