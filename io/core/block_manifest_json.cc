// Reading and writing the block manifest as JSON (schemas/block.schema.json).

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "io/core/block_manifest.h"
#include "io/core/block_schema.h"
#include "io/core/manifest_paths.h"

namespace fs = std::filesystem;
using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

namespace roofsweep {
namespace {

// Above this |phi| omega/phi/kappa lose digits (gimbal lock), so the matrix
// itself is written.
constexpr double kOpkMaxPhiDeg = 85.0;

const valijson::Schema& BlockSchema() {
  static valijson::Schema schema;
  static std::once_flag once;
  std::call_once(once, [] {
    const json doc = json::parse(kBlockSchemaJson);
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    valijson::adapters::NlohmannJsonAdapter adapter(doc);
    parser.populateSchema(adapter, schema);
  });
  return schema;
}

// valijson's context {"<root>", "[images]", "[3]", "[camera]"} as the JSON
// pointer "/images/3/camera".
std::string JsonPointer(const std::vector<std::string>& context) {
  std::string out;
  for (size_t i = 1; i < context.size(); ++i) {
    std::string token = context[i];
    if (token.size() >= 2 && token.front() == '[' && token.back() == ']') {
      token = token.substr(1, token.size() - 2);
    }
    std::string escaped;
    for (char c : token) {
      if (c == '~') {
        escaped += "~0";
      } else if (c == '/') {
        escaped += "~1";
      } else {
        escaped += c;
      }
    }
    out += "/" + escaped;
  }
  return out.empty() ? "/" : out;
}

std::string ShortDump(const json& value) {
  std::string s = value.dump();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

void ValidateAgainstSchema(const json& doc, const std::string& path) {
  valijson::Validator validator;
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter adapter(doc);
  if (validator.validate(BlockSchema(), adapter, &results)) return;
  // The first error is the innermost one; the rest are its enclosing
  // "failed to validate ..." summaries or independent later errors.
  valijson::ValidationResults::Error first;
  results.popError(first);
  const std::string pointer = JsonPointer(first.context);
  std::string message = path + ": " + pointer + ": " + first.description;
  // Say what was found: "Value type not permitted" alone rarely helps.
  if (pointer != "/") {
    try {
      const json::json_pointer ptr(pointer);
      if (doc.contains(ptr)) message += " (found " + ShortDump(doc.at(ptr)) + ")";
    } catch (const json::exception&) {
      // A key that is no valid pointer token; the pointer alone must do.
    }
  }
  throw Error(message);
}

[[noreturn]] void ThrowSyntaxError(const std::string& path, const std::string& text,
                                   const json::parse_error& e) {
  const size_t byte = std::min<size_t>(e.byte, text.size());
  int line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i + 1 < byte; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  const size_t column = byte >= line_start ? byte - line_start : 0;
  // Drop nlohmann's "[json.exception.parse_error.101] parse error at line
  // 3, column 5: " prefix; the position is in our own prefix.
  std::string what = e.what();
  const size_t colon = what.find(": ", what.find("parse error"));
  if (colon != std::string::npos) what = what.substr(colon + 2);
  throw Error(AtLine(path, line, "column " + std::to_string(column) + ": invalid JSON: " + what));
}

Eigen::Vector3d Vec3(const json& a) {
  return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()};
}

Camera CameraFromJson(const json& j) {
  Camera c;
  c.id = j.at("id").get<std::string>();
  c.width = j.at("width").get<int>();
  c.height = j.at("height").get<int>();
  c.fx = j.at("fx").get<double>();
  c.fy = j.at("fy").get<double>();
  c.cx = j.at("cx").get<double>();
  c.cy = j.at("cy").get<double>();
  c.skew = j.value("skew", 0.0);
  c.k1 = j.value("k1", 0.0);
  c.k2 = j.value("k2", 0.0);
  c.k3 = j.value("k3", 0.0);
  c.p1 = j.value("p1", 0.0);
  c.p2 = j.value("p2", 0.0);
  c.pixel_size_mm = j.value("pixel_size_mm", 0.0);
  return c;
}

ManifestImage ImageFromJson(const json& j) {
  ManifestImage im;
  im.path = j.at("path").get<std::string>();
  im.name =
      j.contains("name") ? j.at("name").get<std::string>() : fs::path(im.path).stem().string();
  im.camera = j.at("camera").get<std::string>();
  im.position = Vec3(j.at("position"));
  if (j.contains("opk")) {
    const Eigen::Vector3d opk = Vec3(j.at("opk"));
    im.rotation = OpkToRotation(opk.x(), opk.y(), opk.z());
  } else {
    const json& r = j.at("rotation");
    for (int k = 0; k < 9; ++k)
      im.rotation(k / 3, k % 3) = r.at(static_cast<size_t>(k)).get<double>();
  }
  return im;
}

BlockManifest ManifestFromJson(const json& doc) {
  BlockManifest m;
  if (doc.contains("crs") && !doc.at("crs").is_null()) m.crs = doc.at("crs").get<std::string>();
  m.height_type = doc.value("height_type", std::string("ellipsoidal"));
  m.geoid_undulation = doc.value("geoid_undulation", 0.0);
  for (const json& c : doc.at("cameras")) m.cameras.push_back(CameraFromJson(c));
  for (const json& i : doc.at("images")) m.images.push_back(ImageFromJson(i));
  if (doc.contains("ground")) {
    const json& g = doc.at("ground");
    if (g.contains("height")) m.ground_height = g.at("height").get<double>();
    if (g.contains("dtm")) m.dtm = g.at("dtm").get<std::string>();
    if (g.contains("dsm")) m.dsm = g.at("dsm").get<std::string>();
    m.terrain_window_m = g.value("terrain_window_m", 30.0);
  }
  m.max_building_height = doc.value("max_building_height", 60.0);
  if (doc.contains("footprints")) {
    m.footprints = doc.at("footprints").at("path").get<std::string>();
    m.footprints_layer = doc.at("footprints").value("layer", std::string());
  }
  if (doc.contains("aoi")) {
    const json& a = doc.at("aoi");
    m.aoi = Eigen::Vector4d(a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>(),
                            a.at(3).get<double>());
  }
  return m;
}

ordered_json Array(const Eigen::VectorXd& v) {
  ordered_json a = ordered_json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

ordered_json ManifestToOrderedJson(const BlockManifest& m, const fs::path& manifest_dir) {
  ordered_json doc;
  doc["roofsweep_block"] = "1.0";
  doc["crs"] = m.crs.empty() ? ordered_json(nullptr) : ordered_json(m.crs);
  doc["height_type"] = m.height_type;
  if (m.height_type == "orthometric") doc["geoid_undulation"] = m.geoid_undulation;
  ordered_json cameras = ordered_json::array();
  for (const Camera& c : m.cameras) {
    ordered_json j;
    j["id"] = c.id;
    j["width"] = c.width;
    j["height"] = c.height;
    j["fx"] = c.fx;
    j["fy"] = c.fy;
    j["cx"] = c.cx;
    j["cy"] = c.cy;
    if (c.skew != 0) j["skew"] = c.skew;
    j["k1"] = c.k1;
    j["k2"] = c.k2;
    j["k3"] = c.k3;
    j["p1"] = c.p1;
    j["p2"] = c.p2;
    if (c.pixel_size_mm != 0) j["pixel_size_mm"] = c.pixel_size_mm;
    cameras.push_back(j);
  }
  doc["cameras"] = cameras;
  ordered_json images = ordered_json::array();
  for (const ManifestImage& im : m.images) {
    ordered_json j;
    j["name"] = im.name;
    j["path"] = manifest_paths::ForManifest(im.path, m.base_dir, manifest_dir);
    j["camera"] = im.camera;
    j["position"] = Array(im.position);
    const Eigen::Vector3d opk = RotationToOpk(im.rotation);
    if (std::abs(opk.y()) <= kOpkMaxPhiDeg) {
      // 1e-10 degrees (2e-12 rad) is far below any orientation's accuracy
      // and turns 0.7000000000000002 back into 0.7, so that writing a
      // manifest that was read gives the same text.
      j["opk"] = Array(opk.unaryExpr([](double a) { return std::round(a * 1e10) / 1e10; }));
    } else {
      const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r = im.rotation;
      j["rotation"] = Array(Eigen::Map<const Eigen::VectorXd>(r.data(), 9));
    }
    images.push_back(j);
  }
  doc["images"] = images;
  if (m.ground_height || !m.dtm.empty() || !m.dsm.empty()) {
    ordered_json g;
    if (m.ground_height) g["height"] = *m.ground_height;
    if (!m.dtm.empty()) g["dtm"] = manifest_paths::ForManifest(m.dtm, m.base_dir, manifest_dir);
    if (!m.dsm.empty()) {
      g["dsm"] = manifest_paths::ForManifest(m.dsm, m.base_dir, manifest_dir);
      g["terrain_window_m"] = m.terrain_window_m;
    }
    doc["ground"] = g;
  }
  doc["max_building_height"] = m.max_building_height;
  if (!m.footprints.empty()) {
    ordered_json f;
    f["path"] = manifest_paths::ForManifest(m.footprints, m.base_dir, manifest_dir);
    if (!m.footprints_layer.empty()) f["layer"] = m.footprints_layer;
    doc["footprints"] = f;
  }
  if (m.aoi) doc["aoi"] = Array(*m.aoi);
  return doc;
}

// Pretty printing with short number arrays on one line, so a 1000-image
// manifest stays readable; nlohmann's dump() puts every number on its own
// line. Numbers use nlohmann's shortest round-trip form.
void Print(const ordered_json& j, int indent, std::ostringstream& out) {
  const std::string pad(static_cast<size_t>(indent), ' ');
  const std::string inner(static_cast<size_t>(indent + 2), ' ');
  if (j.is_object()) {
    if (j.empty()) {
      out << "{}";
      return;
    }
    out << "{\n";
    size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      out << inner << ordered_json(it.key()).dump() << ": ";
      Print(it.value(), indent + 2, out);
      out << (i + 1 < j.size() ? ",\n" : "\n");
    }
    out << pad << "}";
  } else if (j.is_array()) {
    bool flat = true;
    for (const auto& e : j) flat = flat && e.is_primitive();
    if (flat) {
      out << "[";
      for (size_t i = 0; i < j.size(); ++i) out << (i ? ", " : "") << j[i].dump();
      out << "]";
      return;
    }
    out << "[\n";
    for (size_t i = 0; i < j.size(); ++i) {
      out << inner;
      Print(j[i], indent + 2, out);
      out << (i + 1 < j.size() ? ",\n" : "\n");
    }
    out << pad << "]";
  } else {
    out << j.dump();
  }
}

std::string TemporaryName(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  return (path.parent_path() /
          ("." + path.filename().string() + ".tmp" + std::to_string(static_cast<long>(::getpid())) +
           "_" + std::to_string(counter++)))
      .string();
}

}  // namespace

BlockManifest ReadManifest(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path + ": no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw Error(path + ": read error");
  const std::string text = buffer.str();
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    ThrowSyntaxError(path, text, e);
  }
  ValidateAgainstSchema(doc, path);
  BlockManifest m = ManifestFromJson(doc);
  m.source = path;
  m.base_dir = fs::absolute(path).parent_path().lexically_normal().string();
  ValidateManifest(m, false);
  return m;
}

std::string ManifestToJson(const BlockManifest& manifest, const std::string& manifest_path) {
  ValidateManifest(manifest, false);
  const fs::path dir = fs::absolute(manifest_path).parent_path().lexically_normal();
  std::ostringstream out;
  Print(ManifestToOrderedJson(manifest, dir), 0, out);
  out << "\n";
  return out.str();
}

void WriteManifest(const BlockManifest& manifest, const std::string& path, bool overwrite) {
  std::error_code ec;
  if (!overwrite && fs::exists(path, ec)) {
    throw Error(path + ": already exists; refusing to overwrite it");
  }
  const std::string text = ManifestToJson(manifest, path);
  const std::string tmp = TemporaryName(fs::path(path));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot create " + tmp + " for writing");
    out << text;
    out.close();
    if (!out) {
      fs::remove(tmp, ec);
      throw Error(path + ": write error");
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error(path + ": cannot move the written file into place (" + ec.message() + ")");
  }
}

}  // namespace roofsweep
