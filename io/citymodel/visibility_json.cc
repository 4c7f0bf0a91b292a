#include "io/citymodel/visibility_json.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "algorithms/core/error.h"
#include "io/citymodel/output_file.h"

namespace roofsweep {

using json = nlohmann::json;

void WriteRoofVisibilityJson(const RoofVisibilityFile& file, const std::string& path,
                             bool overwrite) {
  json j = {{"crs", file.crs}, {"views", file.views}, {"roof_polygons", json::array()}};
  for (const RoofVisibilityFile::Polygon& p : file.polygons) {
    json seen = json::array();
    for (float f : p.seen) seen.push_back(std::round(static_cast<double>(f) * 1000) / 1000);
    j["roof_polygons"].push_back({{"building", p.building},
                                  {"centroid", {p.centroid.x(), p.centroid.y(), p.centroid.z()}},
                                  {"seen", seen}});
  }
  WriteTextFile(path, j.dump(1) + "\n", overwrite);
}

RoofVisibilityFile ReadRoofVisibilityJson(const std::string& path) {
  CheckInputFile(path);
  std::ifstream f(path);
  const json j = json::parse(f, nullptr, false);
  if (!j.is_object() || !j.contains("roof_polygons") || !j["roof_polygons"].is_array())
    throw Error(path + ": not a roof visibility file of roofsweep simulate");
  RoofVisibilityFile out;
  if (j.contains("crs") && j["crs"].is_string()) out.crs = j["crs"].get<std::string>();
  if (j.contains("views") && j["views"].is_array())
    for (const json& v : j["views"])
      if (v.is_string()) out.views.push_back(v.get<std::string>());
  auto numbers = [](const json& a) {
    return a.is_array() &&
           std::all_of(a.begin(), a.end(), [](const json& v) { return v.is_number(); });
  };
  for (const json& p : j["roof_polygons"]) {
    if (!p.is_object() || !p.contains("centroid") || !numbers(p["centroid"]) ||
        p["centroid"].size() != 3 || !p.contains("seen") || !numbers(p["seen"]))
      throw Error(path + ": roof polygon " + std::to_string(out.polygons.size()) +
                  " has no centroid of three numbers or no list of numbers 'seen'");
    RoofVisibilityFile::Polygon q;
    if (p.contains("building") && p["building"].is_string())
      q.building = p["building"].get<std::string>();
    for (int k = 0; k < 3; ++k) q.centroid[k] = p["centroid"][k].get<double>();
    for (const json& v : p["seen"]) q.seen.push_back(v.get<float>());
    out.polygons.push_back(std::move(q));
  }
  return out;
}

}  // namespace roofsweep
