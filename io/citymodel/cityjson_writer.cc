#include "io/citymodel/cityjson_writer.h"

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "algorithms/core/error.h"
#include "io/citymodel/crs_name.h"

namespace roofsweep {

using json = nlohmann::ordered_json;

struct CityJsonWriter::State {
  std::array<double, 3> scale{0.001, 0.001, 0.001};
  std::array<double, 3> translate{0, 0, 0};
  std::string crs;
  Envelope3 envelope;
  json city_objects = json::object();
  json vertices = json::array();
  std::map<std::array<long long, 3>, long long> vertex_index;

  void Setup(const std::string& crs_in, const Envelope3& env, bool geographic) {
    crs = crs_in;
    envelope = env;
    if (geographic) scale = {1e-8, 1e-8, 0.001};
    for (int k = 0; k < 3; ++k) translate[k] = std::isfinite(env[k]) ? std::floor(env[k]) : 0.0;
  }

  long long Index(const Eigen::Vector3d& v) {
    std::array<long long, 3> q;
    for (int k = 0; k < 3; ++k) q[k] = std::llround((v[k] - translate[k]) / scale[k]);
    auto [it, inserted] = vertex_index.emplace(q, static_cast<long long>(vertex_index.size()));
    if (inserted) vertices.push_back(q);
    return it->second;
  }

  void ResetVertices() {
    vertices = json::array();
    vertex_index.clear();
  }

  json Header() const {
    json j = {{"type", "CityJSON"},
              {"version", "2.0"},
              {"transform", {{"scale", scale}, {"translate", translate}}},
              {"CityObjects", json::object()},
              {"vertices", json::array()}};
    json meta = json::object();
    const std::string url = CrsToOgcUrl(crs);
    if (!url.empty()) meta["referenceSystem"] = url;
    if (envelope.allFinite())
      meta["geographicalExtent"] = {envelope[0], envelope[1], envelope[2],
                                    envelope[3], envelope[4], envelope[5]};
    if (!meta.empty()) j["metadata"] = meta;
    return j;
  }

  // One CityObject; `b_type` "Building" or "BuildingPart" (the caller links
  // parents and children).
  json CityObject(const Building& b, const CityModelWriteOptions& options, const char* b_type) {
    json attributes = json::object();
    if (b.measured_height > 0 && std::isfinite(b.measured_height))
      attributes["measuredHeight"] = b.measured_height;
    if (b.roof_type != roof_type::kUnknown) attributes["roofType"] = std::to_string(b.roof_type);
    for (const auto& [k, v] : b.double_attributes) attributes[k] = v;
    for (const auto& [k, v] : StringAttributesToWrite(b, options)) attributes[k] = v;

    json shell = json::array();
    json surfaces = json::array();
    json values = json::array();
    for (size_t si = 0; si < b.surfaces.size(); ++si) {
      const Surface& s = b.surfaces[si];
      json sem = {{"type", SurfaceTypeName(s.type)}};
      if (!s.id.empty()) sem["id"] = s.id;
      surfaces.push_back(sem);
      for (const Polygon3& p : s.polygons) {
        json poly = json::array();
        for (size_t r = 0; r <= p.holes.size(); ++r) {
          const auto& ring = r == 0 ? p.exterior : p.holes[r - 1];
          json idx = json::array();
          for (const auto& v : ring) idx.push_back(Index(v));
          poly.push_back(idx);
        }
        shell.push_back(poly);
        values.push_back(si);
      }
    }
    json obj = {{"type", b_type}, {"attributes", attributes}};
    if (shell.empty()) {
      obj["geometry"] = json::array();
    } else {
      obj["geometry"] = json::array(
          {{{"type", "Solid"},
            {"lod", b.lod == 1 ? "1" : "2"},
            {"boundaries", json::array({shell})},
            {"semantics", {{"surfaces", surfaces}, {"values", json::array({values})}}}}});
    }
    return obj;
  }
};

namespace {
// Adds the building (a BuildingPart when `parent` is given) and its parts
// to `objects`, linked by "children" and "parents" (CityJSON 2.0).
void AddCityObjects(CityJsonWriter::State* state, const Building& b, const std::string& key,
                    const std::string& parent, const CityModelWriteOptions& options,
                    const std::string& path, json* objects) {
  if (objects->contains(key)) throw Error(AtLine(path, 0, "duplicate building id '" + key + "'"));
  json obj = state->CityObject(b, options, parent.empty() ? "Building" : "BuildingPart");
  if (!parent.empty()) obj["parents"] = json::array({parent});
  std::vector<std::string> keys;
  for (size_t k = 0; k < b.parts.size(); ++k)
    keys.push_back(b.parts[k].id.empty() ? key + "_part_" + std::to_string(k + 1) : b.parts[k].id);
  if (!keys.empty()) obj["children"] = keys;
  (*objects)[key] = std::move(obj);
  for (size_t k = 0; k < b.parts.size(); ++k)
    AddCityObjects(state, b.parts[k], keys[k], key, options, path, objects);
}

void WriteAll(const std::string& path, std::FILE* f, const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), f) != text.size())
    throw Error(AtLine(path, 0, "write failed (disk full?)"));
}

std::string BuildingKey(const Building& b, size_t counter) {
  return b.id.empty() ? "BLDG_" + std::to_string(counter) : b.id;
}
}  // namespace

CityJsonWriter::CityJsonWriter(const std::string& path, const CityModelWriteOptions& options)
    : options_(options), file_(path, options.overwrite) {}
CityJsonWriter::~CityJsonWriter() = default;

void CityJsonWriter::Begin(const std::string& crs, const Envelope3& envelope) {
  state_ = std::make_unique<State>();
  state_->Setup(crs, envelope, CrsIsGeographic(crs));
}

void CityJsonWriter::Write(const Building& b) {
  if (!state_) throw Error(AtLine(file_.path(), 0, "CityJsonWriter::Write before Begin"));
  AddCityObjects(state_.get(), b, BuildingKey(b, ++count_), "", options_, file_.path(),
                 &state_->city_objects);
}

void CityJsonWriter::End() {
  if (!state_) throw Error(AtLine(file_.path(), 0, "CityJsonWriter::End before Begin"));
  json doc = state_->Header();
  doc["CityObjects"] = std::move(state_->city_objects);
  doc["vertices"] = std::move(state_->vertices);
  std::FILE* f = std::fopen(file_.temp_path().c_str(), "wb");
  if (!f) throw Error(AtLine(file_.path(), 0, "cannot create file"));
  try {
    WriteAll(file_.path(), f, doc.dump());
    WriteAll(file_.path(), f, "\n");
  } catch (...) {
    std::fclose(f);
    throw;
  }
  if (std::fclose(f) != 0) throw Error(AtLine(file_.path(), 0, "write failed on close"));
  state_.reset();
  file_.Commit();
}

CityJsonSeqWriter::CityJsonSeqWriter(const std::string& path, const CityModelWriteOptions& options)
    : options_(options), file_(path, options.overwrite) {}

CityJsonSeqWriter::~CityJsonSeqWriter() {
  if (out_) std::fclose(out_);
}

void CityJsonSeqWriter::Begin(const std::string& crs, const Envelope3& envelope) {
  state_ = std::make_unique<CityJsonWriter::State>();
  state_->Setup(crs, envelope, CrsIsGeographic(crs));
  out_ = std::fopen(file_.temp_path().c_str(), "wb");
  if (!out_) throw Error(AtLine(file_.path(), 0, "cannot create file"));
  WriteAll(file_.path(), out_, state_->Header().dump() + "\n");
}

void CityJsonSeqWriter::Write(const Building& b) {
  if (!out_) throw Error(AtLine(file_.path(), 0, "CityJsonSeqWriter::Write before Begin"));
  const std::string key = BuildingKey(b, ++count_);
  state_->ResetVertices();  // each feature carries its own vertices
  json objects = json::object();
  AddCityObjects(state_.get(), b, key, "", options_, file_.path(), &objects);
  json feature = {{"type", "CityJSONFeature"},
                  {"id", key},
                  {"CityObjects", std::move(objects)},
                  {"vertices", std::move(state_->vertices)}};
  WriteAll(file_.path(), out_, feature.dump() + "\n");
}

void CityJsonSeqWriter::End() {
  if (!out_) throw Error(AtLine(file_.path(), 0, "CityJsonSeqWriter::End before Begin"));
  const int rc = std::fclose(out_);
  out_ = nullptr;
  if (rc != 0) throw Error(AtLine(file_.path(), 0, "write failed on close"));
  file_.Commit();
}

}  // namespace roofsweep
