#include "io/citymodel/citygml_reader.h"

#include <citygml/citygml.h>
#include <citygml/citygmllogger.h>
#include <citygml/citymodel.h>
#include <citygml/envelope.h>
#include <citygml/geometry.h>
#include <citygml/linearring.h>
#include <citygml/polygon.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <mutex>

#include "algorithms/core/error.h"
#include "io/citymodel/crs_name.h"
#include "io/citymodel/output_file.h"

namespace roofsweep {

namespace {

using COT = citygml::CityObject::CityObjectsType;

// Keeps libcitygml's first error (xerces parse errors carry the line) instead
// of letting the library print to stderr.
class CapturingLogger : public citygml::CityGMLLogger {
 public:
  CapturingLogger() : CityGMLLogger(LOGLEVEL::LL_ERROR) {}
  void log(LOGLEVEL level, const std::string& message, const char*, int) const override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (level >= LOGLEVEL::LL_ERROR && first_error_.empty()) first_error_ = message;
  }
  std::string first_error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return first_error_;
  }

 private:
  mutable std::mutex mutex_;
  mutable std::string first_error_;
};

std::string OneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

std::vector<Eigen::Vector3d> ToRing(const citygml::LinearRing& ring) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& v : ring.getVertices()) out.emplace_back(v.x, v.y, v.z);
  if (out.size() > 1 && (out.front() - out.back()).norm() < 1e-9) out.pop_back();
  return out;
}

Polygon3 ToPolygon(const citygml::Polygon& p) {
  Polygon3 out;
  if (p.exteriorRing()) out.exterior = ToRing(*p.exteriorRing());
  for (const auto& r : p.interiorRings())
    if (r) out.holes.push_back(ToRing(*r));
  return out;
}

// All polygons of level of detail `lod` in a geometry tree (a Solid's
// polygons sit in nested geometries after xlink resolution); LoD2 also
// takes geometries without a level (0).
void CollectPolygons(const citygml::Geometry& g, std::vector<Polygon3>* out, unsigned lod = 2) {
  if (g.getLOD() == lod || (lod == 2 && g.getLOD() == 0))
    for (unsigned i = 0; i < g.getPolygonsCount(); ++i) {
      Polygon3 p = ToPolygon(*g.getPolygon(i));
      if (p.exterior.size() >= 3) out->push_back(std::move(p));
    }
  for (unsigned i = 0; i < g.getGeometriesCount(); ++i) CollectPolygons(g.getGeometry(i), out, lod);
}

bool SurfaceTypeOf(COT t, SurfaceType* out) {
  switch (t) {
    case COT::COT_RoofSurface:
    case COT::COT_OuterCeilingSurface:
      *out = SurfaceType::kRoof;
      return true;
    case COT::COT_WallSurface:
      *out = SurfaceType::kWall;
      return true;
    case COT::COT_GroundSurface:
    case COT::COT_OuterFloorSurface:
      *out = SurfaceType::kGround;
      return true;
    case COT::COT_ClosureSurface:
      *out = SurfaceType::kClosure;
      return true;
    default:
      return false;
  }
}

// Thematic surfaces of `obj` (not of its BuildingParts), appended to `b`.
// Returns the number of surfaces found.
int AddThematicSurfaces(const citygml::CityObject& obj, Building* b) {
  int n = 0;
  for (unsigned i = 0; i < obj.getChildCityObjectsCount(); ++i) {
    const citygml::CityObject& child = obj.getChildCityObject(i);
    SurfaceType type;
    if (SurfaceTypeOf(child.getType(), &type)) {
      Surface s;
      s.type = type;
      s.id = child.getId();
      for (unsigned g = 0; g < child.getGeometriesCount(); ++g)
        CollectPolygons(child.getGeometry(g), &s.polygons);
      if (!s.polygons.empty()) b->surfaces.push_back(std::move(s)), ++n;
    }
  }
  return n;
}

// A building modelled only as lod2Solid/lod2MultiSurface (or, `lod` 1, as
// an LoD1 block) has no semantics; the normal decides (cos 0.1 ~ 84 degrees
// keeps steep roofs roofs).
void AddUnclassifiedSurfaces(const citygml::CityObject& obj, Building* b, unsigned lod = 2) {
  std::vector<Polygon3> polys;
  for (unsigned g = 0; g < obj.getGeometriesCount(); ++g)
    CollectPolygons(obj.getGeometry(g), &polys, lod);
  for (auto& p : polys) {
    const double nz = p.Normal().z();
    Surface s;
    s.type = nz > 0.1 ? SurfaceType::kRoof : nz < -0.1 ? SurfaceType::kGround : SurfaceType::kWall;
    s.polygons.push_back(std::move(p));
    b->surfaces.push_back(std::move(s));
  }
}

void ReadAttributes(const citygml::CityObject& obj, Building* b) {
  for (const auto& [key, value] : obj.getAttributes()) {
    if (key == "bldg:measuredheight") {
      b->measured_height = value.asDouble(0.0);
    } else if (key == "bldg:rooftype") {
      b->roof_type = std::atoi(value.asString().c_str());
    } else if (key.find(':') == std::string::npos) {  // generic attributes keep plain names
      if (value.getType() == citygml::AttributeType::Double ||
          value.getType() == citygml::AttributeType::Integer)
        b->double_attributes[key] = value.asDouble();
      else
        b->string_attributes[key] = value.asString();
    }
  }
}

// A Building or BuildingPart with its parts (nested as in the file).
Building ReadBuildingObject(const citygml::CityObject& obj) {
  Building b;
  b.id = obj.getId();
  ReadAttributes(obj, &b);
  if (AddThematicSurfaces(obj, &b) == 0) AddUnclassifiedSurfaces(obj, &b);
  for (unsigned i = 0; i < obj.getChildCityObjectsCount(); ++i)
    if (obj.getChildCityObject(i).getType() == COT::COT_BuildingPart)
      b.parts.push_back(ReadBuildingObject(obj.getChildCityObject(i)));
  // LoD2 wins where a building has both; an LoD1 block is read only when
  // neither it nor a part has LoD2 geometry (roofsweep's fallback blocks,
  // LoD1 city models).
  if (b.Solids().empty()) {
    AddUnclassifiedSurfaces(obj, &b, 1);
    if (!b.surfaces.empty()) b.lod = 1;
  }
  return b;
}

// Cheap pre-check so that "not CityGML" gets a clear message instead of an
// empty model: the root element must be a CityModel in a CityGML namespace.
void CheckLooksLikeCityGml(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(8192, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  if (head.find("CityModel") == std::string::npos)
    throw Error(AtLine(path, 0, "not CityGML: no CityModel root element"));
  if (head.find("http://www.opengis.net/citygml/") == std::string::npos)
    throw Error(
        AtLine(path, 0,
               "not CityGML: the CityGML namespace http://www.opengis.net/citygml/{1.0,2.0} "
               "is not declared"));
}

}  // namespace

CityModel ReadCityGml(const std::string& path) {
  CheckInputFile(path);
  CheckLooksLikeCityGml(path);
  citygml::ParserParams params;
  params.tesselate = false;  // keep the rings (tesselation discards them)
  params.keepVertices = true;
  params.minLOD = 0;
  params.maxLOD = 4;
  auto logger = std::make_shared<CapturingLogger>();
  std::shared_ptr<const citygml::CityModel> m;
  try {
    m = citygml::load(path, params, logger);
  } catch (const std::exception& e) {
    throw Error(AtLine(path, 0, std::string("CityGML parse error: ") + OneLine(e.what())));
  } catch (...) {  // xerces throws its own types
    const std::string first = logger->first_error();
    throw Error(
        AtLine(path, 0, "CityGML parse error" + (first.empty() ? "" : ": " + OneLine(first))));
  }
  // libcitygml also logs errors it recovers from (e.g. an unexpected element
  // inside core:externalReference in the Berlin tiles), so a logged error is
  // fatal only when no model came back.
  if (!m) {
    const std::string first = logger->first_error();
    throw Error(
        AtLine(path, 0, "CityGML parse error" + (first.empty() ? "" : ": " + OneLine(first))));
  }

  CityModel out;
  std::string srs = m->getEnvelope().srsName();
  if (srs.empty()) srs = m->getSRSName();
  for (const citygml::CityObject* obj : m->getRootCityObjects()) {
    if (!obj || obj->getType() != COT::COT_Building) continue;
    if (srs.empty()) srs = obj->getEnvelope().srsName();
    for (unsigned g = 0; srs.empty() && g < obj->getGeometriesCount(); ++g)
      srs = obj->getGeometry(g).getSRSName();
    out.buildings.push_back(ReadBuildingObject(*obj));
  }
  out.crs = NormalizeCrsName(srs);
  return out;
}

}  // namespace roofsweep
