#include "io/citymodel/segments_json.h"

#include <ogrsf_frmts.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "algorithms/core/error.h"
#include "io/citymodel/output_file.h"
#include "io/core/crs_identity.h"

namespace roofsweep {

using nlohmann::json;

std::string FormatObservations(const std::vector<std::pair<std::string, int>>& observations) {
  std::string out;
  for (const auto& [name, id] : observations)
    out += (out.empty() ? "" : " ") + name + ":" + std::to_string(id);
  return out;
}

std::vector<std::pair<std::string, int>> ParseObservations(const std::string& text) {
  std::vector<std::pair<std::string, int>> out;
  std::istringstream in(text);
  std::string token;
  while (in >> token) {
    const size_t colon = token.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == token.size()) return {};
    char* end = nullptr;
    const long id = std::strtol(token.c_str() + colon + 1, &end, 10);
    if (*end != '\0' || id < -1) return {};
    out.emplace_back(token.substr(0, colon), static_cast<int>(id));
  }
  return out;
}

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
  WriteTextFile(path, j.dump(1) + "\n", overwrite);
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

namespace {

bool LooksLikeJson(const std::string& path) {
  std::ifstream f(path);
  char c = 0;
  while (f.get(c) && std::isspace(static_cast<unsigned char>(c))) {
  }
  return c == '{';
}

void AddLineString(const OGRLineString& ls, const std::string& kind, double rms_px,
                   const std::vector<std::pair<std::string, int>>& observations, SegmentSet* set) {
  for (int i = 0; i + 1 < ls.getNumPoints(); ++i) {
    LabelledSegment s;
    s.segment.a = {ls.getX(i), ls.getY(i), ls.getZ(i)};
    s.segment.b = {ls.getX(i + 1), ls.getY(i + 1), ls.getZ(i + 1)};
    s.kind = kind;
    s.rms_px = rms_px;
    s.observations = observations;
    set->segments.push_back(s);
  }
}

}  // namespace

SegmentSet ReadSegments(const std::string& path, const std::string& layer_name) {
  CheckInputFile(path);
  if (LooksLikeJson(path)) {
    // A GeoJSON file is JSON too; only roofsweep's own document says so.
    std::ifstream f(path);
    std::string text((std::istreambuf_iterator<char>(f)), {});
    if (text.find("roofsweep_segments") != std::string::npos) return ReadSegmentsJson(path);
  }
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY,
                                                    nullptr, nullptr, nullptr));
  if (!ds) throw Error(path + ": not a segments document nor a vector dataset GDAL can open");
  OGRLayer* layer = nullptr;
  if (!layer_name.empty()) {
    layer = ds->GetLayerByName(layer_name.c_str());
    if (!layer) throw Error(path + ": no layer '" + layer_name + "'");
  } else {
    layer = ds->GetLayerByName("lines3d");
    for (int i = 0; !layer && i < ds->GetLayerCount(); ++i) {
      const auto t = wkbFlatten(ds->GetLayer(i)->GetGeomType());
      if (t == wkbLineString || t == wkbMultiLineString) layer = ds->GetLayer(i);
    }
    if (!layer) throw Error(path + ": no layer with line geometry");
  }
  SegmentSet set;
  if (const OGRSpatialReference* srs = layer->GetSpatialRef()) set.crs = IdentifyCrs(*srs);
  const int kind_field = layer->GetLayerDefn()->GetFieldIndex("kind");
  const int rms_field = layer->GetLayerDefn()->GetFieldIndex("rms_px");
  const int depth_field = layer->GetLayerDefn()->GetFieldIndex("depth_from");
  const int views_field = layer->GetLayerDefn()->GetFieldIndex("views");
  const int observations_field = layer->GetLayerDefn()->GetFieldIndex("observations");
  layer->ResetReading();
  for (auto& feature : *layer) {
    const OGRGeometry* g = feature->GetGeometryRef();
    if (!g) continue;
    const std::string kind = kind_field >= 0 ? feature->GetFieldAsString(kind_field) : "";
    const bool stereo = (depth_field < 0 || !feature->IsFieldSetAndNotNull(depth_field) ||
                         std::string(feature->GetFieldAsString(depth_field)) == "stereo") &&
                        (views_field < 0 || !feature->IsFieldSetAndNotNull(views_field) ||
                         feature->GetFieldAsInteger(views_field) >= 3);
    const double rms_px = stereo && rms_field >= 0 && feature->IsFieldSetAndNotNull(rms_field)
                              ? feature->GetFieldAsDouble(rms_field)
                              : std::numeric_limits<double>::quiet_NaN();
    const auto observations =
        observations_field >= 0 && feature->IsFieldSetAndNotNull(observations_field)
            ? ParseObservations(feature->GetFieldAsString(observations_field))
            : std::vector<std::pair<std::string, int>>();
    const auto t = wkbFlatten(g->getGeometryType());
    if (t == wkbLineString) {
      AddLineString(*g->toLineString(), kind, rms_px, observations, &set);
    } else if (t == wkbMultiLineString) {
      for (const OGRLineString* part : *g->toMultiLineString())
        AddLineString(*part, kind, rms_px, observations, &set);
    }
  }
  return set;
}

}  // namespace roofsweep
