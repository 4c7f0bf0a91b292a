#include "io/citymodel/segments_json.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "algorithms/core/error.h"
#include "io/citymodel/output_file.h"

namespace roofsweep {

using nlohmann::json;

void WriteSegmentsJson(const SegmentSet& set, const std::string& path, bool overwrite) {
  json j;
  j["type"] = "roofsweep_segments";
  j["crs"] = set.crs.empty() ? json(nullptr) : json(set.crs);
  json& segs = j["segments"] = json::array();
  for (const LabelledSegment& s : set.segments) {
    segs.push_back({{"a", {s.segment.a.x(), s.segment.a.y(), s.segment.a.z()}},
                    {"b", {s.segment.b.x(), s.segment.b.y(), s.segment.b.z()}},
                    {"kind", s.kind},
                    {"building", s.building}});
  }
  OutputFile out(path, overwrite);
  {
    std::ofstream f(out.temp_path());
    f << j.dump(1) << "\n";
    if (!f) throw Error(path + ": cannot write");
  }
  out.Commit();
}

SegmentSet ReadSegmentsJson(const std::string& path) {
  CheckInputFile(path);
  std::ifstream f(path);
  json j;
  try {
    j = json::parse(f);
  } catch (const json::parse_error& e) {
    throw Error(path + ": invalid JSON: " + e.what());
  }
  if (!j.is_object() || j.value("type", "") != "roofsweep_segments" || !j.contains("segments") ||
      !j["segments"].is_array()) {
    throw Error(path + ": not a roofsweep segments document (type \"roofsweep_segments\")");
  }
  SegmentSet set;
  if (j.contains("crs") && j["crs"].is_string()) set.crs = j["crs"].get<std::string>();
  const json& segs = j["segments"];
  for (size_t i = 0; i < segs.size(); ++i) {
    const std::string at = path + ": /segments/" + std::to_string(i);
    const json& s = segs[i];
    auto point = [&](const char* key) {
      if (!s.contains(key) || !s[key].is_array() || s[key].size() != 3) {
        throw Error(at + "/" + key + ": expected [x, y, z]");
      }
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) {
        if (!s[key][k].is_number()) throw Error(at + "/" + key + ": not a number");
        p(k) = s[key][k].get<double>();
      }
      if (!p.allFinite()) throw Error(at + "/" + key + ": not finite");
      return p;
    };
    LabelledSegment ls;
    ls.segment.a = point("a");
    ls.segment.b = point("b");
    ls.kind = s.value("kind", "");
    ls.building = s.value("building", -1);
    set.segments.push_back(ls);
  }
  return set;
}

}  // namespace roofsweep
