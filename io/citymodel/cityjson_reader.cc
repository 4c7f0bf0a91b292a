#include "io/citymodel/cityjson_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "algorithms/core/error.h"
#include "io/citymodel/crs_name.h"
#include "io/citymodel/output_file.h"

namespace roofsweep {

namespace {

using json = nlohmann::ordered_json;

// Carries the file name and line so that every error is one precise line.
struct Context {
  std::string path;
  int line = 0;
  [[noreturn]] void Fail(const std::string& pointer, const std::string& msg) const {
    throw Error(AtLine(path, line, (pointer.empty() ? "" : pointer + ": ") + msg));
  }
};

struct Transform {
  std::array<double, 3> scale{1, 1, 1};
  std::array<double, 3> translate{0, 0, 0};
};

Transform ReadTransform(const json& doc, const Context& ctx) {
  Transform t;
  if (!doc.contains("transform")) return t;  // CityJSON 1.0 allowed real coordinates
  const json& tr = doc["transform"];
  for (const char* key : {"scale", "translate"}) {
    if (!tr.contains(key) || !tr[key].is_array() || tr[key].size() != 3)
      ctx.Fail(std::string("/transform/") + key, "expected an array of 3 numbers");
    for (int k = 0; k < 3; ++k) {
      if (!tr[key][k].is_number()) ctx.Fail(std::string("/transform/") + key, "not a number");
      (std::string(key) == "scale" ? t.scale : t.translate)[k] = tr[key][k].get<double>();
    }
  }
  return t;
}

std::vector<Eigen::Vector3d> ReadVertices(const json& doc, const Transform& t, const Context& ctx) {
  std::vector<Eigen::Vector3d> out;
  if (!doc.contains("vertices")) return out;
  const json& vs = doc["vertices"];
  if (!vs.is_array()) ctx.Fail("/vertices", "expected an array");
  out.reserve(vs.size());
  for (size_t i = 0; i < vs.size(); ++i) {
    const json& v = vs[i];
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number())
      ctx.Fail("/vertices/" + std::to_string(i), "expected [x, y, z]");
    out.emplace_back(v[0].get<double>() * t.scale[0] + t.translate[0],
                     v[1].get<double>() * t.scale[1] + t.translate[1],
                     v[2].get<double>() * t.scale[2] + t.translate[2]);
  }
  return out;
}

bool SurfaceTypeFromName(const std::string& name, SurfaceType* t) {
  if (name == "RoofSurface" || name == "OuterCeilingSurface") return *t = SurfaceType::kRoof, true;
  if (name == "WallSurface") return *t = SurfaceType::kWall, true;
  if (name == "GroundSurface" || name == "OuterFloorSurface")
    return *t = SurfaceType::kGround, true;
  if (name == "ClosureSurface") return *t = SurfaceType::kClosure, true;
  return false;
}

class BuildingReader {
 public:
  BuildingReader(const std::vector<Eigen::Vector3d>& vertices, const Context& ctx)
      : vertices_(vertices), ctx_(ctx) {}

  void ReadAttributes(const json& obj, const std::string& ptr, Building* b) const {
    if (!obj.contains("attributes")) return;
    const json& attrs = obj["attributes"];
    if (!attrs.is_object()) ctx_.Fail(ptr + "/attributes", "expected an object");
    for (const auto& [k, v] : attrs.items()) {
      if (k == "measuredHeight" && v.is_number()) {
        b->measured_height = v.get<double>();
      } else if (k == "roofType" && (v.is_string() || v.is_number())) {
        b->roof_type = v.is_number() ? v.get<int>() : std::atoi(v.get<std::string>().c_str());
      } else if (v.is_number()) {
        b->double_attributes[k] = v.get<double>();
      } else if (v.is_string()) {
        b->string_attributes[k] = v.get<std::string>();
      } else if (!v.is_null()) {
        b->string_attributes[k] = v.dump();
      }
    }
  }

  // Appends the surfaces of the first LoD2 geometry of `obj` to `b`; with
  // none, those of the first LoD1 geometry (a block model), and b->lod = 1.
  void ReadGeometry(const json& obj, const std::string& ptr, Building* b) const {
    if (!obj.contains("geometry")) return;
    const json& geoms = obj["geometry"];
    if (!geoms.is_array()) ctx_.Fail(ptr + "/geometry", "expected an array");
    for (const char wanted : {'2', '1'})
      for (size_t gi = 0; gi < geoms.size(); ++gi) {
        const json& g = geoms[gi];
        const std::string gp = ptr + "/geometry/" + std::to_string(gi);
        if (!g.is_object() || !g.contains("type") || !g["type"].is_string())
          ctx_.Fail(gp, "geometry without a type");
        std::string lod;
        if (g.contains("lod"))
          lod = g["lod"].is_string() ? g["lod"].get<std::string>() : g["lod"].dump();
        if (lod.empty() || lod[0] != wanted) continue;
        ReadOneGeometry(g, gp, b);
        b->lod = wanted - '0';
        return;
      }
  }

 private:
  std::vector<Eigen::Vector3d> Ring(const json& ring, const std::string& ptr) const {
    if (!ring.is_array()) ctx_.Fail(ptr, "ring is not an array of vertex indices");
    std::vector<Eigen::Vector3d> out;
    for (size_t i = 0; i < ring.size(); ++i) {
      if (!ring[i].is_number_integer()) ctx_.Fail(ptr + "/" + std::to_string(i), "not an index");
      const long long idx = ring[i].get<long long>();
      if (idx < 0 || idx >= static_cast<long long>(vertices_.size()))
        ctx_.Fail(ptr + "/" + std::to_string(i),
                  "vertex index " + std::to_string(idx) + " out of range (" +
                      std::to_string(vertices_.size()) + " vertices)");
      out.push_back(vertices_[static_cast<size_t>(idx)]);
    }
    return out;
  }

  // `surfaces`: array of polygons (each an array of rings); `values`: the
  // matching semantic indices (or null).
  void ReadSurfaceList(const json& surfaces, const json* values, const json& semantics,
                       const std::string& ptr, Building* b) const {
    if (!surfaces.is_array()) ctx_.Fail(ptr, "expected an array of surfaces");
    std::map<long long, size_t> surface_of_semantic;
    for (size_t i = 0; i < surfaces.size(); ++i) {
      const json& poly = surfaces[i];
      const std::string pp = ptr + "/" + std::to_string(i);
      if (!poly.is_array() || poly.empty()) ctx_.Fail(pp, "polygon without rings");
      Polygon3 p;
      p.exterior = Ring(poly[0], pp + "/0");
      for (size_t r = 1; r < poly.size(); ++r)
        p.holes.push_back(Ring(poly[r], pp + "/" + std::to_string(r)));
      long long sem = -1;
      if (values && values->is_array() && i < values->size() && (*values)[i].is_number_integer())
        sem = (*values)[i].get<long long>();
      SurfaceType type;
      bool typed = false;
      std::string id;
      if (sem >= 0) {
        if (!semantics.is_array() || sem >= static_cast<long long>(semantics.size()))
          ctx_.Fail(pp, "semantic value " + std::to_string(sem) + " out of range");
        const json& so = semantics[static_cast<size_t>(sem)];
        if (so.contains("type") && so["type"].is_string())
          typed = SurfaceTypeFromName(so["type"].get<std::string>(), &type);
        if (so.contains("id") && so["id"].is_string()) id = so["id"].get<std::string>();
      }
      if (!typed) {  // no (usable) semantics: decide by the normal, as for CityGML
        const double nz = p.Normal().z();
        type = nz > 0.1    ? SurfaceType::kRoof
               : nz < -0.1 ? SurfaceType::kGround
                           : SurfaceType::kWall;
        sem = -1;
      }
      if (sem >= 0) {
        auto it = surface_of_semantic.find(sem);
        if (it != surface_of_semantic.end()) {
          b->surfaces[it->second].polygons.push_back(std::move(p));
          continue;
        }
        surface_of_semantic[sem] = b->surfaces.size();
      }
      Surface s;
      s.type = type;
      s.id = id;
      s.polygons.push_back(std::move(p));
      b->surfaces.push_back(std::move(s));
    }
  }

  void ReadOneGeometry(const json& g, const std::string& gp, Building* b) const {
    const std::string type = g["type"].get<std::string>();
    if (!g.contains("boundaries")) ctx_.Fail(gp, "geometry without boundaries");
    const json& bnd = g["boundaries"];
    const json empty = json::array();
    const json* sem_surfaces = &empty;
    const json* values = nullptr;
    if (g.contains("semantics")) {
      const json& s = g["semantics"];
      if (s.contains("surfaces")) sem_surfaces = &s["surfaces"];
      if (s.contains("values")) values = &s["values"];
    }
    auto sub = [&](const json* v, size_t i) -> const json* {
      return v && v->is_array() && i < v->size() ? &(*v)[i] : nullptr;
    };
    if (type == "MultiSurface" || type == "CompositeSurface") {
      ReadSurfaceList(bnd, values, *sem_surfaces, gp + "/boundaries", b);
    } else if (type == "Solid") {
      if (!bnd.is_array() || bnd.empty()) ctx_.Fail(gp + "/boundaries", "solid without a shell");
      ReadSurfaceList(bnd[0], sub(values, 0), *sem_surfaces, gp + "/boundaries/0", b);
    } else if (type == "MultiSolid" || type == "CompositeSolid") {
      if (!bnd.is_array()) ctx_.Fail(gp + "/boundaries", "expected an array of solids");
      for (size_t i = 0; i < bnd.size(); ++i) {
        const std::string sp = gp + "/boundaries/" + std::to_string(i);
        if (!bnd[i].is_array() || bnd[i].empty()) ctx_.Fail(sp, "solid without a shell");
        ReadSurfaceList(bnd[i][0], sub(sub(values, i), 0), *sem_surfaces, sp + "/0", b);
      }
    } else {
      ctx_.Fail(gp + "/type", "unsupported geometry type '" + type + "' for a building");
    }
  }

  const std::vector<Eigen::Vector3d>& vertices_;
  const Context& ctx_;
};

// Adds the Buildings of one CityObjects member, with their BuildingParts
// (nested as the "parents" links say), to `model`.
void ReadCityObjects(const json& doc, const std::vector<Eigen::Vector3d>& vertices,
                     const Context& ctx, CityModel* model) {
  if (!doc.contains("CityObjects") || !doc["CityObjects"].is_object())
    ctx.Fail("/CityObjects", "missing or not an object");
  BuildingReader reader(vertices, ctx);
  const json& objs = doc["CityObjects"];
  // Parts may be listed before their parent: collect every object first,
  // then hang each part under its parent, deepest parts first.
  std::map<std::string, Building> read;
  std::map<std::string, std::string> parent_of;
  std::map<std::string, int> seq;  // file order
  std::vector<std::string> roots;
  for (const auto& [id, obj] : objs.items()) {
    const std::string ptr = "/CityObjects/" + id;
    if (!obj.is_object() || !obj.contains("type") || !obj["type"].is_string())
      ctx.Fail(ptr, "city object without a type");
    const std::string type = obj["type"].get<std::string>();
    if (type != "Building" && type != "BuildingPart") continue;
    Building b;
    b.id = id;
    reader.ReadAttributes(obj, ptr, &b);
    reader.ReadGeometry(obj, ptr, &b);
    read[id] = std::move(b);
    seq[id] = static_cast<int>(seq.size());
    if (type == "Building") {
      roots.push_back(id);
      continue;
    }
    if (!obj.contains("parents") || !obj["parents"].is_array() || obj["parents"].empty() ||
        !obj["parents"][0].is_string())
      ctx.Fail(ptr + "/parents", "BuildingPart without a parent Building");
    parent_of[id] = obj["parents"][0].get<std::string>();
  }
  // Depth of each part below its building; a chain that does not end at a
  // Building (or loops) is an error.
  std::vector<std::tuple<int, int, std::string>> by_depth;
  for (const auto& [id, parent] : parent_of) {
    int depth = 1;
    std::string up = parent;
    while (parent_of.count(up) && depth <= static_cast<int>(parent_of.size())) {
      up = parent_of[up];
      ++depth;
    }
    if (!read.count(up) || parent_of.count(up))
      ctx.Fail("/CityObjects/" + id + "/parents", "BuildingPart without a parent Building");
    by_depth.emplace_back(depth, seq[id], id);
  }
  std::sort(by_depth.begin(), by_depth.end(), std::greater<>());
  // Deeper parts are complete before they are moved into theirs; pushed in
  // reverse file order, each list is reversed once complete.
  for (const auto& [depth, order, id] : by_depth) {
    Building& b = read[id];
    std::reverse(b.parts.begin(), b.parts.end());
    read[parent_of[id]].parts.push_back(std::move(b));
  }
  for (const std::string& id : roots) {
    Building& b = read[id];
    std::reverse(b.parts.begin(), b.parts.end());
    model->buildings.push_back(std::move(b));
  }
}

std::string ReadCrs(const json& doc) {
  if (doc.contains("metadata") && doc["metadata"].is_object() &&
      doc["metadata"].contains("referenceSystem") && doc["metadata"]["referenceSystem"].is_string())
    return NormalizeCrsName(doc["metadata"]["referenceSystem"].get<std::string>());
  return "";
}

json Parse(const std::string& text, const Context& ctx) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    std::string msg = e.what();
    // nlohmann's message starts with "[json.exception.parse_error.101] "
    const auto pos = msg.find("] ");
    ctx.Fail("", "JSON syntax error: " + (pos == std::string::npos ? msg : msg.substr(pos + 2)));
  }
}

void CheckType(const json& doc, const char* want, const Context& ctx) {
  if (!doc.is_object() || !doc.contains("type") || doc["type"] != want)
    ctx.Fail("/type", std::string("not ") + want + " (expected \"type\": \"" + want + "\")");
}

}  // namespace

CityModel ReadCityJson(const std::string& path) {
  CheckInputFile(path);
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Context ctx{path, 0};
  const json doc = Parse(text, ctx);
  CheckType(doc, "CityJSON", ctx);
  const Transform t = ReadTransform(doc, ctx);
  const auto vertices = ReadVertices(doc, t, ctx);
  CityModel model;
  model.crs = ReadCrs(doc);
  ReadCityObjects(doc, vertices, ctx, &model);
  return model;
}

CityModel ReadCityJsonSeq(const std::string& path) {
  CheckInputFile(path);
  std::ifstream in(path, std::ios::binary);
  Context ctx{path, 0};
  std::string line;
  CityModel model;
  Transform t;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++ctx.line;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const json doc = Parse(line, ctx);
    if (!have_header) {
      CheckType(doc, "CityJSON", ctx);
      t = ReadTransform(doc, ctx);
      model.crs = ReadCrs(doc);
      have_header = true;
      // The header may hold objects too (allowed, if unusual).
      ReadCityObjects(doc, ReadVertices(doc, t, ctx), ctx, &model);
      continue;
    }
    CheckType(doc, "CityJSONFeature", ctx);
    ReadCityObjects(doc, ReadVertices(doc, t, ctx), ctx, &model);
  }
  if (!have_header) throw Error(AtLine(path, 0, "empty file: no CityJSON header line"));
  return model;
}

}  // namespace roofsweep
