#pragma once

#include <string>

#include "algorithms/buildings/city_model.h"

namespace roofsweep {

// Reads Buildings from CityJSON 2.0 (1.1 too: same geometry encoding). The
// first geometry with lod "2" or "2.x" is used: Solid (outer shell),
// MultiSolid/CompositeSolid (outer shells) or Multi/CompositeSurface.
// Semantic objects become Surfaces (their "id" attribute is kept); polygons
// without semantics are classified by their normal. BuildingParts become the
// parts of their parent (nested as "parents" says). Order follows the file.
// Throws roofsweep::Error naming the file and the JSON pointer at fault.
CityModel ReadCityJson(const std::string& path);

// Reads CityJSON Text Sequences (.city.jsonl): header line, then one
// CityJSONFeature per line. Errors name the file and line.
CityModel ReadCityJsonSeq(const std::string& path);

}  // namespace roofsweep
