#pragma once

#include <string>

#include "algorithms/buildings/city_model.h"

namespace roofsweep {

// Reads CityGML 1.0 or 2.0 LoD2 buildings with libcitygml (the independent
// reader; roofsweep does not parse CityGML itself). Thematic surfaces
// (Roof/Wall/Ground/ClosureSurface, with OuterCeiling/OuterFloor mapped to
// Roof/Ground) become Surfaces; a building that only has a lod2Solid or
// lod2MultiSurface gets its polygons classified by their normal (up: roof,
// down: ground, else wall). BuildingParts become the Building's parts,
// nested as in the file. The closing duplicate vertex of each ring is dropped. The CRS is
// the envelope's srsName (model, else first building, else first geometry),
// normalised to "EPSG:NNNN".
//
// Throws roofsweep::Error (one line, naming the file) for a missing file,
// malformed XML (with libcitygml's message, which names the line), or a
// document that is not CityGML. A CityGML file without buildings gives an
// empty model.
CityModel ReadCityGml(const std::string& path);

}  // namespace roofsweep
