#include "io/citymodel/ogr_citymodel.h"

#include <cpl_error.h>
#include <cpl_minixml.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "algorithms/core/error.h"
#include "io/citymodel/crs_name.h"

namespace roofsweep {

namespace fs = std::filesystem;

namespace {

// GDAL reports through CPLError; roofsweep reports through exceptions. The
// handler keeps GDAL quiet while we work and the last message goes into the
// roofsweep::Error.
class QuietGdal {
 public:
  QuietGdal() {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
  }
  ~QuietGdal() { CPLPopErrorHandler(); }
  static std::string Last() {
    const char* m = CPLGetLastErrorMsg();
    return m && *m ? std::string(": ") + m : std::string();
  }
};

const char* kReserved[] = {"id",
                           "roof_type",
                           "roof_type_name",
                           "measured_height",
                           "building_id",
                           "surface_id",
                           "surface_type",
                           "surface_index",
                           "building_index",
                           "fid",
                           "geom",
                           "building_part_id",
                           "lod"};

bool IsReserved(const std::string& name) {
  for (const char* r : kReserved)
    if (name == r) return true;
  return false;
}

const char* SurfaceLayerName(SurfaceType t) {
  switch (t) {
    case SurfaceType::kRoof:
      return "roof_surfaces";
    case SurfaceType::kWall:
      return "wall_surfaces";
    case SurfaceType::kGround:
      return "ground_surfaces";
    case SurfaceType::kClosure:
      return "closure_surfaces";
  }
  return "surfaces";
}

bool SurfaceTypeFromName(const std::string& n, SurfaceType* t) {
  for (SurfaceType s :
       {SurfaceType::kRoof, SurfaceType::kWall, SurfaceType::kGround, SurfaceType::kClosure})
    if (n == SurfaceTypeName(s) || n == SurfaceLayerName(s)) return *t = s, true;
  return false;
}

OGRLinearRing* MakeRing(const std::vector<Eigen::Vector3d>& ring) {
  auto* r = new OGRLinearRing();
  r->setNumPoints(static_cast<int>(ring.size()) + 1);
  for (size_t i = 0; i <= ring.size(); ++i) {
    const Eigen::Vector3d& v = ring[i % ring.size()];
    r->setPoint(static_cast<int>(i), v.x(), v.y(), v.z());
  }
  return r;
}

OGRMultiPolygon* MakeMultiPolygon(const std::vector<const Polygon3*>& polys) {
  auto* mp = new OGRMultiPolygon();
  for (const Polygon3* p : polys) {
    if (p->exterior.size() < 3) continue;
    auto* poly = new OGRPolygon();
    poly->addRingDirectly(MakeRing(p->exterior));
    for (const auto& h : p->holes)
      if (h.size() >= 3) poly->addRingDirectly(MakeRing(h));
    mp->addGeometryDirectly(poly);
  }
  mp->set3D(TRUE);
  return mp;
}

std::vector<Eigen::Vector3d> ReadRing(const OGRLinearRing* r) {
  std::vector<Eigen::Vector3d> out;
  if (!r) return out;
  for (int i = 0; i < r->getNumPoints(); ++i) out.emplace_back(r->getX(i), r->getY(i), r->getZ(i));
  if (out.size() > 1 && (out.front() - out.back()).norm() < 1e-12) out.pop_back();
  return out;
}

std::vector<Polygon3> ReadPolygons(const OGRGeometry* g) {
  std::vector<Polygon3> out;
  if (!g) return out;
  auto add = [&](const OGRPolygon* p) {
    Polygon3 q;
    q.exterior = ReadRing(p->getExteriorRing());
    for (int i = 0; i < p->getNumInteriorRings(); ++i)
      q.holes.push_back(ReadRing(p->getInteriorRing(i)));
    if (q.exterior.size() >= 3) out.push_back(std::move(q));
  };
  const auto flat = wkbFlatten(g->getGeometryType());
  if (flat == wkbPolygon) add(g->toPolygon());
  if (flat == wkbMultiPolygon)
    for (const OGRPolygon* p : *g->toMultiPolygon()) add(p);
  return out;
}

std::unique_ptr<OGRSpatialReference> Make3dSrs(const std::string& crs, const std::string& path,
                                               bool promote = true) {
  if (crs.empty()) return nullptr;
  auto srs = std::make_unique<OGRSpatialReference>();
  if (srs->SetFromUserInput(NormalizeCrsName(crs).c_str()) != OGRERR_NONE)
    throw Error(AtLine(path, 0, "unknown CRS '" + crs + "'"));
  srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  if (promote && srs->GetAxesCount() < 3 && srs->PromoteTo3D(nullptr) != OGRERR_NONE)
    throw Error(AtLine(path, 0, "cannot promote CRS '" + crs + "' to 3D"));
  return srs;
}

// Short name for a CRS read from a layer. A promoted 3D CRS has lost its EPSG
// code, so the 2D CRS it came from is identified instead.
std::string CrsName(const OGRSpatialReference* srs) {
  if (!srs) return "";
  auto named = [](const OGRSpatialReference& s) -> std::string {
    const char* auth = s.GetAuthorityName(nullptr);
    const char* code = s.GetAuthorityCode(nullptr);
    if (auth && code && EQUAL(auth, "EPSG")) return std::string("EPSG:") + code;
    return "";
  };
  std::string n = named(*srs);
  if (!n.empty()) return n;
  OGRSpatialReference two_d(*srs);
  if (two_d.DemoteTo2D(nullptr) == OGRERR_NONE) {
    n = named(two_d);
    if (!n.empty()) return n;
    int count = 0;
    int* confidence = nullptr;
    OGRSpatialReferenceH* matches = two_d.FindMatches(nullptr, &count, &confidence);
    if (matches && count > 0 && confidence[0] >= 90)
      n = named(*OGRSpatialReference::FromHandle(matches[0]));
    OSRFreeSRSArray(matches);
    CPLFree(confidence);
    if (!n.empty()) return n;
  }
  char* wkt = nullptr;
  const char* opts[] = {"FORMAT=WKT2_2019", nullptr};
  srs->exportToWkt(&wkt, opts);
  std::string s = wkt ? wkt : "";
  CPLFree(wkt);
  return s;
}

GDALDriver* WriteDriver(const std::string& name, const std::string& path) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName(name.c_str());
  if (!drv || !drv->GetMetadataItem(GDAL_DCAP_VECTOR))
    throw Error(AtLine(path, 0, "unknown vector format '" + name + "'"));
  if (!drv->GetMetadataItem(GDAL_DCAP_CREATE))
    throw Error(AtLine(path, 0, "format '" + name + "' cannot create files"));
  return drv;
}

std::string Upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

// Why not GDALValidateCreationOptions: it warns instead of failing, and its
// layer-option sibling GDALValidateOptions is not exported by libgdal. This
// checks names and the value types GDAL's option lists declare.
void CheckOptionsAgainstList(const std::string& path, const std::string& driver,
                             const char* list_xml, const std::vector<std::string>& options,
                             const std::string& kind) {
  if (options.empty()) return;
  CPLXMLNode* root = list_xml ? CPLParseXMLString(list_xml) : nullptr;
  struct Free {
    CPLXMLNode* n;
    ~Free() {
      if (n) CPLDestroyXMLNode(n);
    }
  } free_root{root};
  const CPLXMLNode* list = root;
  while (list && list->eType != CXT_Element) list = list->psNext;
  for (const std::string& o : options) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(AtLine(path, 0, kind + " '" + o + "' is not NAME=VALUE"));
    const std::string name = o.substr(0, eq), value = o.substr(eq + 1);
    const CPLXMLNode* found = nullptr;
    std::string known;
    for (const CPLXMLNode* c = list ? list->psChild : nullptr; c && !found; c = c->psNext) {
      if (c->eType != CXT_Element || !EQUAL(c->pszValue, "Option")) continue;
      const char* n = CPLGetXMLValue(c, "name", "");
      const char* alias = CPLGetXMLValue(c, "alias", "");
      if (EQUAL(n, name.c_str()) || (*alias && EQUAL(alias, name.c_str()))) found = c;
      known += (known.empty() ? "" : ", ") + std::string(n);
    }
    if (!found)
      throw Error(AtLine(
          path, 0,
          "format " + driver + " has no " + kind + " '" + name + "'" +
              (known.empty() ? std::string(" (it takes none)") : " (known: " + known + ")")));
    const std::string type = Upper(CPLGetXMLValue(found, "type", ""));
    const std::string v = Upper(value);
    bool ok = true;
    std::string expected;
    if (type == "BOOLEAN") {
      ok = v == "YES" || v == "NO" || v == "ON" || v == "OFF" || v == "TRUE" || v == "FALSE" ||
           v == "1" || v == "0";
      expected = "YES or NO";
    } else if (type == "INT" || type == "INTEGER") {
      char* end = nullptr;
      std::strtol(value.c_str(), &end, 10);
      ok = !value.empty() && *end == '\0';
      expected = "a whole number";
    } else if (type == "FLOAT") {
      char* end = nullptr;
      std::strtod(value.c_str(), &end);
      ok = !value.empty() && *end == '\0';
      expected = "a number";
    } else if (type == "STRING-SELECT") {
      ok = false;
      for (const CPLXMLNode* c = found->psChild; c; c = c->psNext) {
        if (c->eType != CXT_Element || !EQUAL(c->pszValue, "Value")) continue;
        const char* text = CPLGetXMLValue(c, nullptr, "");
        const char* alias = CPLGetXMLValue(c, "alias", "");
        if (EQUAL(text, value.c_str()) || (*alias && EQUAL(alias, value.c_str()))) ok = true;
        expected += (expected.empty() ? "" : ", ") + std::string(text);
      }
      expected = "one of " + expected;
    }
    if (!ok)
      throw Error(AtLine(path, 0,
                         "format " + driver + ": " + kind + " " + name + " expects " + expected +
                             ", got '" + value + "'"));
  }
}

bool IsMultiLayer(const std::string& driver) {
  return EQUAL(driver.c_str(), "GPKG") || EQUAL(driver.c_str(), "SQLite");
}

// Opens the temporary copy for update, or creates a new dataset there.
GDALDataset* OpenOutput(GDALDriver* drv, const OutputFile& file, bool update,
                        const std::vector<std::string>& dataset_options) {
  QuietGdal quiet;
  std::error_code ec;
  if (update && fs::exists(file.path(), ec)) {
    fs::copy_file(file.path(), file.temp_path(), fs::copy_options::overwrite_existing, ec);
    if (ec) throw Error(AtLine(file.path(), 0, "cannot copy for update: " + ec.message()));
    const char* drivers[] = {drv->GetDescription(), nullptr};
    auto* ds = GDALDataset::Open(file.temp_path().c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE, drivers,
                                 nullptr, nullptr);
    if (!ds)
      throw Error(AtLine(
          file.path(), 0,
          std::string("cannot open for update as ") + drv->GetDescription() + QuietGdal::Last()));
    return ds;
  }
  char** dsco = nullptr;
  for (const std::string& o : dataset_options) dsco = CSLAddString(dsco, o.c_str());
  GDALDataset* ds = drv->Create(file.temp_path().c_str(), 0, 0, 0, GDT_Unknown, dsco);
  CSLDestroy(dsco);
  if (!ds) throw Error(AtLine(file.path(), 0, "cannot create" + QuietGdal::Last()));
  return ds;
}

OGRLayer* CreateLayer(GDALDataset* ds, const std::string& name, OGRwkbGeometryType type,
                      OGRSpatialReference* srs, const std::string& path,
                      const std::vector<std::string>& layer_options) {
  QuietGdal quiet;
  for (int i = 0; i < ds->GetLayerCount(); ++i)
    if (EQUAL(ds->GetLayer(i)->GetName(), name.c_str())) {
      if (ds->DeleteLayer(i) != OGRERR_NONE)
        throw Error(AtLine(path, 0, "cannot replace layer '" + name + "'" + QuietGdal::Last()));
      break;
    }
  char** lco = nullptr;
  if (EQUAL(ds->GetDriver()->GetDescription(), "GPKG")) {
    lco = CSLSetNameValue(lco, "SPATIAL_INDEX", "YES");
    lco = CSLSetNameValue(lco, "GEOMETRY_NAME", "geom");
  }
  for (const std::string& o : layer_options) {
    const auto eq = o.find('=');
    lco = CSLSetNameValue(lco, o.substr(0, eq).c_str(), o.substr(eq + 1).c_str());
  }
  OGRLayer* layer = ds->CreateLayer(name.c_str(), srs, type, lco);
  CSLDestroy(lco);
  if (!layer)
    throw Error(AtLine(path, 0, "cannot create layer '" + name + "'" + QuietGdal::Last()));
  return layer;
}

void AddField(OGRLayer* layer, const std::string& name, OGRFieldType type,
              const std::string& path) {
  OGRFieldDefn def(name.c_str(), type);
  if (layer->CreateField(&def) != OGRERR_NONE)
    throw Error(AtLine(
        path, 0,
        "cannot add field '" + name + "' to layer '" + layer->GetName() + "'" + QuietGdal::Last()));
}

}  // namespace

struct OgrCityModelWriter::Layer {
  OGRLayer* layer = nullptr;
  std::set<std::string> fields;
};

std::string OgrDriverForPath(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".gpkg") return "GPKG";
  if (ext == ".fgb") return "FlatGeobuf";
  if (ext == ".geojson") return "GeoJSON";
  if (ext == ".sqlite") return "SQLite";
  return "";
}

bool IsOgrVectorWriteDriver(const std::string& name) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName(name.c_str());
  return drv && drv->GetMetadataItem(GDAL_DCAP_VECTOR) && drv->GetMetadataItem(GDAL_DCAP_CREATE);
}

void CheckOgrCreationOptions(const std::string& path, const std::string& driver,
                             const std::vector<std::string>& options, bool layer) {
  GDALDriver* drv = WriteDriver(driver, path);
  CheckOptionsAgainstList(
      path, drv->GetDescription(),
      drv->GetMetadataItem(layer ? GDAL_DS_LAYER_CREATIONOPTIONLIST : GDAL_DMD_CREATIONOPTIONLIST),
      options, layer ? "layer creation option" : "dataset creation option");
}

OgrCityModelWriter::OgrCityModelWriter(const std::string& path, const std::string& driver,
                                       const CityModelWriteOptions& options)
    : driver_name_(driver), options_(options), file_(path, options.overwrite || options.update) {
  WriteDriver(driver, path);  // fail early for an unknown format
  multi_layer_ = IsMultiLayer(driver);
  if (options.update && !multi_layer_)
    throw Error(AtLine(path, 0, "update is only supported for GPKG/SQLite, not " + driver));
  if (options.update && !options.dataset_options.empty())
    throw Error(AtLine(path, 0, "dataset creation options do not apply when updating a file"));
  CheckOgrCreationOptions(path, driver, options.dataset_options, false);
  CheckOgrCreationOptions(path, driver, options.layer_options, true);
}

OgrCityModelWriter::~OgrCityModelWriter() {
  if (ds_) GDALClose(ds_);  // the OutputFile then removes the temporary file
}

void OgrCityModelWriter::DeclareAttributes(const std::map<std::string, bool>& attributes) {
  for (const auto& [k, v] : attributes) declared_[k] = v;
}

void OgrCityModelWriter::EnsureField(Layer& l, const std::string& name, bool is_double) {
  if (l.fields.count(name)) return;
  if (IsReserved(name))
    throw Error(AtLine(file_.path(), 0,
                       "generic attribute '" + name + "' collides with a roofsweep field name"));
  QuietGdal quiet;
  AddField(l.layer, name, is_double ? OFTReal : OFTString, file_.path());
  l.fields.insert(name);
}

OgrCityModelWriter::Layer& OgrCityModelWriter::MakeLayer(const std::string& name,
                                                         bool building_fields, bool surface_fields,
                                                         bool part_fields) {
  auto l = std::make_unique<Layer>();
  l->layer =
      CreateLayer(ds_, name, wkbMultiPolygon25D, srs_.get(), file_.path(), options_.layer_options);
  auto field = [&](const char* n, OGRFieldType t) {
    AddField(l->layer, n, t, file_.path());
    l->fields.insert(n);
  };
  if (surface_fields) {
    field("building_id", OFTString);
    field("building_part_id", OFTString);
    field("surface_id", OFTString);
    field("surface_type", OFTString);
    field("surface_index", OFTInteger);
    // FlatGeobuf sorts features spatially; this restores building order.
    if (!multi_layer_) field("building_index", OFTInteger);
  } else {
    field("id", OFTString);
    if (part_fields) field("building_id", OFTString);
  }
  if (building_fields) {
    field("roof_type", OFTInteger);
    field("roof_type_name", OFTString);
    field("measured_height", OFTReal);
    field("lod", OFTInteger);
    if (options_.check_geometry) field(kValidityAttribute, OFTString);
    for (const auto& [k, is_double] : declared_) EnsureField(*l, k, is_double);
  }
  Layer& out = *l;
  layers_[name] = std::move(l);
  return out;
}

void OgrCityModelWriter::Begin(const std::string& crs, const Envelope3&) {
  GDALDriver* drv = WriteDriver(driver_name_, file_.path());
  // GeoJSON can only name a CRS by its code, which a promoted 3D CRS lacks.
  srs_ = Make3dSrs(crs, file_.path(), !EQUAL(driver_name_.c_str(), "GeoJSON"));
  ds_ = OpenOutput(drv, file_, options_.update, options_.dataset_options);
  QuietGdal quiet;
  if (multi_layer_) {
    MakeLayer("buildings", true, false);
    for (SurfaceType t : {SurfaceType::kRoof, SurfaceType::kWall, SurfaceType::kGround})
      MakeLayer(SurfaceLayerName(t), false, true);
  } else {
    MakeLayer("surfaces", true, true);
  }
  in_transaction_ = ds_->StartTransaction() == OGRERR_NONE;
}

void OgrCityModelWriter::MaybeCommitBatch() {
  // Commit in batches: one transaction per feature makes GPKG ~100x slower,
  // one for everything keeps a growing journal.
  if (++pending_ < 1000 || !in_transaction_) return;
  if (ds_->CommitTransaction() != OGRERR_NONE)
    throw Error(AtLine(file_.path(), 0, "commit failed" + QuietGdal::Last()));
  pending_ = 0;
  in_transaction_ = ds_->StartTransaction() == OGRERR_NONE;
}

void OgrCityModelWriter::Write(const Building& b) {
  if (!ds_) throw Error(AtLine(file_.path(), 0, "OgrCityModelWriter::Write before Begin"));
  QuietGdal quiet;
  // Fields must exist before a feature is made from the layer definition.
  auto ensure_building_fields = [&](Layer& l, const Building& o,
                                    const std::map<std::string, std::string>& strings) {
    for (const auto& kv : o.double_attributes) EnsureField(l, kv.first, true);
    for (const auto& kv : strings)
      if (!l.fields.count(kv.first)) EnsureField(l, kv.first, false);
  };
  auto set_building_fields = [&](OGRFeature& f, const Building& o,
                                 const std::map<std::string, std::string>& strings) {
    if (o.roof_type != roof_type::kUnknown) {
      f.SetField("roof_type", o.roof_type);
      f.SetField("roof_type_name", RoofTypeName(o.roof_type));
    }
    if (o.measured_height > 0) f.SetField("measured_height", o.measured_height);
    f.SetField("lod", o.lod);
    for (const auto& [k, v] : o.double_attributes) f.SetField(k.c_str(), v);
    for (const auto& [k, v] : strings) f.SetField(k.c_str(), v.c_str());
  };
  auto write = [&](Layer& l, OGRFeature* f) {
    if (l.layer->CreateFeature(f) != OGRERR_NONE)
      throw Error(AtLine(file_.path(), 0,
                         "cannot write building '" + b.id + "' to layer '" + l.layer->GetName() +
                             "'" + QuietGdal::Last()));
    MaybeCommitBatch();
  };
  auto ground_of = [](const Building& o) {
    std::vector<const Polygon3*> ground;
    for (const auto& s : o.surfaces)
      if (s.type == SurfaceType::kGround)
        for (const auto& p : s.polygons) ground.push_back(&p);
    return ground;
  };
  const std::vector<const Building*> solids = b.Solids();

  if (multi_layer_) {
    Layer& bl = *layers_["buildings"];
    const auto strings = StringAttributesToWrite(b, options_);
    ensure_building_fields(bl, b, strings);
    std::vector<const Polygon3*> ground;  // the footprint of all its parts
    for (const Building* o : solids) {
      const auto g = ground_of(*o);
      ground.insert(ground.end(), g.begin(), g.end());
    }
    OGRFeature f(bl.layer->GetLayerDefn());
    set_building_fields(f, b, strings);
    f.SetField("id", b.id.c_str());
    if (!ground.empty()) f.SetGeometryDirectly(MakeMultiPolygon(ground));
    write(bl, &f);
    for (const Building* part : solids) {
      if (part == &b) continue;
      // Only files with parts get the layer.
      if (!layers_.count("building_parts")) MakeLayer("building_parts", true, false, true);
      Layer& pl = *layers_["building_parts"];
      const auto part_strings = StringAttributesToWrite(*part, options_);
      ensure_building_fields(pl, *part, part_strings);
      OGRFeature pf(pl.layer->GetLayerDefn());
      set_building_fields(pf, *part, part_strings);
      pf.SetField("id", part->id.c_str());
      pf.SetField("building_id", b.id.c_str());
      const auto g = ground_of(*part);
      if (!g.empty()) pf.SetGeometryDirectly(MakeMultiPolygon(g));
      write(pl, &pf);
    }
  }
  // One running surface_index over the building's parts keeps their order.
  int surface_index = 0;
  for (const Building* o : solids) {
    // The flat layout repeats the attributes of the solid the surface bounds.
    const auto strings =
        multi_layer_ ? std::map<std::string, std::string>{} : StringAttributesToWrite(*o, options_);
    if (!multi_layer_) ensure_building_fields(*layers_["surfaces"], *o, strings);
    for (const Surface& s : o->surfaces) {
      // Closure surfaces: a layer only when present.
      if (multi_layer_ && !layers_.count(SurfaceLayerName(s.type)))
        MakeLayer(SurfaceLayerName(s.type), false, true);
      Layer& sl = *layers_[multi_layer_ ? SurfaceLayerName(s.type) : "surfaces"];
      OGRFeature f(sl.layer->GetLayerDefn());
      if (!multi_layer_) set_building_fields(f, *o, strings);
      f.SetField("building_id", b.id.c_str());
      if (o != &b) f.SetField("building_part_id", o->id.c_str());
      if (!s.id.empty()) f.SetField("surface_id", s.id.c_str());
      f.SetField("surface_type", SurfaceTypeName(s.type));
      f.SetField("surface_index", surface_index++);
      if (!multi_layer_) f.SetField("building_index", static_cast<int>(written_));
      std::vector<const Polygon3*> polys;
      for (const auto& p : s.polygons) polys.push_back(&p);
      f.SetGeometryDirectly(MakeMultiPolygon(polys));
      write(sl, &f);
    }
  }
  ++written_;
}

void OgrCityModelWriter::End() {
  if (!ds_) throw Error(AtLine(file_.path(), 0, "OgrCityModelWriter::End before Begin"));
  QuietGdal quiet;
  if (in_transaction_ && ds_->CommitTransaction() != OGRERR_NONE)
    throw Error(AtLine(file_.path(), 0, "commit failed" + QuietGdal::Last()));
  in_transaction_ = false;
  // GDALClose flushes (FlatGeobuf writes its index here), so its errors count.
  CPLErrorReset();
  GDALClose(ds_);
  ds_ = nullptr;
  if (CPLGetLastErrorType() >= CE_Failure)
    throw Error(AtLine(file_.path(), 0, "writing failed on close" + QuietGdal::Last()));
  file_.Commit();
}

CityModel ReadOgrCityModel(const std::string& path) {
  CheckInputFile(path);
  GDALAllRegister();
  QuietGdal quiet;
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY,
                                                    nullptr, nullptr, nullptr));
  if (!ds) throw Error(AtLine(path, 0, "cannot open as a vector dataset" + QuietGdal::Last()));

  CityModel model;
  std::map<std::string, size_t> index;
  auto building = [&](const std::string& id) -> Building& {
    auto it = index.find(id);
    if (it != index.end()) return model.buildings[it->second];
    index[id] = model.buildings.size();
    model.buildings.emplace_back();
    model.buildings.back().id = id;
    return model.buildings.back();
  };
  auto part = [](Building& b, const std::string& id) -> Building& {
    for (Building& p : b.parts)
      if (p.id == id) return p;
    b.parts.emplace_back();
    b.parts.back().id = id;
    return b.parts.back();
  };
  auto read_attributes = [](OGRFeature& f, Building& b) {
    OGRFeatureDefn* defn = f.GetDefnRef();
    for (int i = 0; i < defn->GetFieldCount(); ++i) {
      const std::string name = defn->GetFieldDefn(i)->GetNameRef();
      if (!f.IsFieldSetAndNotNull(i)) continue;
      if (name == "roof_type") {
        b.roof_type = f.GetFieldAsInteger(i);
      } else if (name == "measured_height") {
        b.measured_height = f.GetFieldAsDouble(i);
      } else if (name == "lod") {
        b.lod = f.GetFieldAsInteger(i) == 1 ? 1 : 2;
      } else if (IsReserved(name)) {
        continue;
      } else if (defn->GetFieldDefn(i)->GetType() == OFTReal ||
                 defn->GetFieldDefn(i)->GetType() == OFTInteger ||
                 defn->GetFieldDefn(i)->GetType() == OFTInteger64) {
        b.double_attributes[name] = f.GetFieldAsDouble(i);
      } else {
        b.string_attributes[name] = f.GetFieldAsString(i);
      }
    }
  };

  bool found = false;
  std::string names;
  if (OGRLayer* bl = ds->GetLayerByName("buildings")) {
    found = true;
    model.crs = CrsName(bl->GetSpatialRef());
    bl->ResetReading();
    for (auto& f : *bl) read_attributes(*f, building(f->GetFieldAsString("id")));
  }
  if (OGRLayer* pl = ds->GetLayerByName("building_parts")) {
    pl->ResetReading();
    for (auto& f : *pl)
      read_attributes(
          *f, part(building(f->GetFieldAsString("building_id")), f->GetFieldAsString("id")));
  }
  struct Pending {
    size_t building;
    std::string part;  // empty: the building's own surface
    int index;
    Surface surface;
  };
  std::vector<Pending> surfaces;
  std::map<std::string, int> order;  // building_index of the flat layout
  for (int li = 0; li < ds->GetLayerCount(); ++li) {
    OGRLayer* l = ds->GetLayer(li);
    const std::string lname = l->GetName();
    names += (names.empty() ? "" : ", ") + lname;
    SurfaceType layer_type;
    const bool flat = lname == "surfaces";
    if (!flat && !SurfaceTypeFromName(lname, &layer_type)) continue;
    found = true;
    if (model.crs.empty()) model.crs = CrsName(l->GetSpatialRef());
    OGRFeatureDefn* defn = l->GetLayerDefn();
    const int i_bid = defn->GetFieldIndex("building_id");
    if (i_bid < 0) throw Error(AtLine(path, 0, "layer '" + lname + "' has no building_id field"));
    const int i_sid = defn->GetFieldIndex("surface_id");
    const int i_type = defn->GetFieldIndex("surface_type");
    const int i_idx = defn->GetFieldIndex("surface_index");
    const int i_bidx = defn->GetFieldIndex("building_index");
    const int i_part = defn->GetFieldIndex("building_part_id");
    l->ResetReading();
    for (auto& f : *l) {
      Pending p;
      Building& b = building(f->GetFieldAsString(i_bid));
      p.building = index[b.id];
      if (i_part >= 0 && f->IsFieldSetAndNotNull(i_part)) p.part = f->GetFieldAsString(i_part);
      if (i_bidx >= 0 && f->IsFieldSetAndNotNull(i_bidx))
        order[b.id] = f->GetFieldAsInteger(i_bidx);
      if (flat) read_attributes(*f, p.part.empty() ? b : part(b, p.part));
      p.index = i_idx >= 0 ? f->GetFieldAsInteger(i_idx) : static_cast<int>(surfaces.size());
      p.surface.type = layer_type;
      if (i_type >= 0 && f->IsFieldSetAndNotNull(i_type) &&
          !SurfaceTypeFromName(f->GetFieldAsString(i_type), &p.surface.type) && flat)
        throw Error(AtLine(path, 0,
                           "layer '" + lname + "' feature " + std::to_string(f->GetFID()) +
                               ": unknown surface_type '" + f->GetFieldAsString(i_type) + "'"));
      if (i_sid >= 0 && f->IsFieldSetAndNotNull(i_sid)) p.surface.id = f->GetFieldAsString(i_sid);
      p.surface.polygons = ReadPolygons(f->GetGeometryRef());
      surfaces.push_back(std::move(p));
    }
  }
  if (!found)
    throw Error(AtLine(path, 0,
                       "no roofsweep city model layers (buildings, roof_surfaces, ...; "
                       "found: " +
                           (names.empty() ? std::string("none") : names) + ")"));
  // Surfaces come layer by layer; surface_index restores the original order.
  std::stable_sort(surfaces.begin(), surfaces.end(), [](const Pending& a, const Pending& b) {
    return a.building != b.building ? a.building < b.building : a.index < b.index;
  });
  // FlatGeobuf reads features in spatial order: parts, too, are put back in
  // the order of their first surface.
  std::map<std::pair<size_t, std::string>, int> first_surface;
  for (auto& p : surfaces) {
    Building& b = model.buildings[p.building];
    first_surface.emplace(std::make_pair(p.building, p.part), p.index);
    (p.part.empty() ? b : part(b, p.part)).surfaces.push_back(std::move(p.surface));
  }
  for (size_t i = 0; i < model.buildings.size(); ++i) {
    auto first = [&](const Building& p) {
      auto it = first_surface.find({i, p.id});
      return it == first_surface.end() ? INT_MAX : it->second;
    };
    std::stable_sort(model.buildings[i].parts.begin(), model.buildings[i].parts.end(),
                     [&](const Building& a, const Building& b) { return first(a) < first(b); });
  }
  if (!order.empty())
    std::stable_sort(model.buildings.begin(), model.buildings.end(),
                     [&](const Building& a, const Building& b) {
                       auto ia = order.find(a.id), ib = order.find(b.id);
                       return (ia == order.end() ? INT_MAX : ia->second) <
                              (ib == order.end() ? INT_MAX : ib->second);
                     });
  return model;
}

namespace {

void WriteOneLayer(GDALDataset* ds, const std::string& path, const FeatureLayerData& data,
                   const std::string& description, OGRSpatialReference* srs,
                   const std::vector<std::string>& layer_options) {
  const std::string& layer_name = data.name;
  const LayerGeometry geometry = data.geometry;
  const OGRwkbGeometryType type = geometry == LayerGeometry::kLineStringZ  ? wkbLineString25D
                                  : geometry == LayerGeometry::kLineString ? wkbLineString
                                  : geometry == LayerGeometry::kMultiLineStringZ
                                      ? wkbMultiLineString25D
                                  : geometry == LayerGeometry::kMultiPolygonZ ? wkbMultiPolygon25D
                                  : geometry == LayerGeometry::kPointZ        ? wkbPoint25D
                                                                              : wkbNone;
  // GPKG stores "no CRS" as srs_id 0, the undefined GEOGRAPHIC system,
  // which tools show as lat/lon; 2D layers without a CRS are image or other
  // Cartesian coordinates, which GDAL maps to srs_id -1 from this name.
  OGRSpatialReference cartesian;
  if (!srs && type == wkbLineString && EQUAL(ds->GetDriver()->GetDescription(), "GPKG") &&
      cartesian.SetFromUserInput("LOCAL_CS[\"Undefined cartesian SRS\"]") == OGRERR_NONE)
    srs = &cartesian;
  OGRLayer* layer = CreateLayer(ds, layer_name, type, srs, path, layer_options);
  if (!description.empty()) layer->SetMetadataItem("DESCRIPTION", description.c_str());
  std::map<std::string, OGRFieldType> fields;
  for (const auto& f : data.features) {
    for (const auto& kv : f.integers) fields.emplace(kv.first, OFTInteger64);
    for (const auto& kv : f.reals) fields.emplace(kv.first, OFTReal);
    for (const auto& kv : f.strings) fields.emplace(kv.first, OFTString);
  }
  for (const auto& [name, t] : fields) AddField(layer, name, t, path);
  const bool tx = ds->StartTransaction() == OGRERR_NONE;
  for (size_t i = 0; i < data.features.size(); ++i) {
    const LayerFeature& lf = data.features[i];
    OGRFeature f(layer->GetLayerDefn());
    for (const auto& [k, v] : lf.integers) f.SetField(k.c_str(), static_cast<GIntBig>(v));
    for (const auto& [k, v] : lf.reals) f.SetField(k.c_str(), v);
    for (const auto& [k, v] : lf.strings) f.SetField(k.c_str(), v.c_str());
    auto line = [](const std::vector<Eigen::Vector3d>& pts, bool z) {
      auto* ls = new OGRLineString();
      for (const auto& p : pts) {
        if (z)
          ls->addPoint(p.x(), p.y(), p.z());
        else
          ls->addPoint(p.x(), p.y());
      }
      return ls;
    };
    if ((type == wkbLineString25D || type == wkbLineString) && !lf.lines.empty()) {
      f.SetGeometryDirectly(line(lf.lines[0], type == wkbLineString25D));
    } else if (type == wkbMultiLineString25D) {
      auto* ml = new OGRMultiLineString();
      for (const auto& l : lf.lines) ml->addGeometryDirectly(line(l, true));
      f.SetGeometryDirectly(ml);
    } else if (type == wkbPoint25D) {
      f.SetGeometryDirectly(new OGRPoint(lf.point.x(), lf.point.y(), lf.point.z()));
    } else if (type == wkbMultiPolygon25D) {
      std::vector<const Polygon3*> polys;
      for (const auto& p : lf.polygons) polys.push_back(&p);
      f.SetGeometryDirectly(MakeMultiPolygon(polys));
    }
    if (layer->CreateFeature(&f) != OGRERR_NONE)
      throw Error(AtLine(path, 0,
                         "cannot write feature " + std::to_string(i) + " to layer '" + layer_name +
                             "'" + QuietGdal::Last()));
  }
  if (tx && ds->CommitTransaction() != OGRERR_NONE)
    throw Error(AtLine(path, 0, "commit failed" + QuietGdal::Last()));
}

}  // namespace

void CheckFeatureLayerOutput(const std::string& path, const FeatureLayerOptions& options) {
  const std::string driver = options.driver.empty() ? OgrDriverForPath(path) : options.driver;
  if (driver.empty())
    throw Error(AtLine(path, 0, "cannot tell the vector format from the extension; name it"));
  WriteDriver(driver, path);
  if (options.update && !options.dataset_options.empty())
    throw Error(AtLine(path, 0, "dataset creation options do not apply when updating a file"));
  CheckOgrCreationOptions(path, driver, options.dataset_options, false);
  CheckOgrCreationOptions(path, driver, options.layer_options, true);
  CheckOutputPath(path, options.overwrite || options.update);
}

void WriteFeatureLayers(const std::string& path, const std::vector<FeatureLayerData>& layers,
                        const FeatureLayerOptions& options) {
  const std::string driver = options.driver.empty() ? OgrDriverForPath(path) : options.driver;
  if (driver.empty())
    throw Error(AtLine(path, 0, "cannot tell the vector format from the extension; name it"));
  GDALDriver* drv = WriteDriver(driver, path);
  if (layers.size() > 1 && !IsMultiLayer(driver))
    throw Error(AtLine(path, 0,
                       "format " + driver + " holds one layer; " + std::to_string(layers.size()) +
                           " needed (use .gpkg)"));
  if (options.update && !options.dataset_options.empty())
    throw Error(AtLine(path, 0, "dataset creation options do not apply when updating a file"));
  CheckOgrCreationOptions(path, driver, options.dataset_options, false);
  CheckOgrCreationOptions(path, driver, options.layer_options, true);
  OutputFile file(path, options.overwrite || options.update);
  auto srs = Make3dSrs(options.crs, path, !EQUAL(driver.c_str(), "GeoJSON"));
  GDALDataset* ds = OpenOutput(drv, file, options.update, options.dataset_options);
  struct Closer {
    GDALDataset*& ds;
    ~Closer() {
      if (ds) GDALClose(ds);
    }
  } closer{ds};
  QuietGdal quiet;
  for (const FeatureLayerData& l : layers)
    WriteOneLayer(ds, path, l, l.description.empty() ? options.description : l.description,
                  srs.get(), options.layer_options);
  CPLErrorReset();
  GDALClose(ds);
  ds = nullptr;
  if (CPLGetLastErrorType() >= CE_Failure)
    throw Error(AtLine(path, 0, "writing failed on close" + QuietGdal::Last()));
  file.Commit();
}

void WriteFeatureLayer(const std::string& path, const std::string& layer_name,
                       LayerGeometry geometry, const std::vector<LayerFeature>& features,
                       const FeatureLayerOptions& options) {
  FeatureLayerData data;
  data.name = layer_name;
  data.geometry = geometry;
  data.features = features;
  WriteFeatureLayers(path, {data}, options);
}

}  // namespace roofsweep
