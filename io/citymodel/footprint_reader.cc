#include "io/citymodel/footprint_reader.h"

#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

#include "algorithms/buildings/polygon2.h"
#include "algorithms/core/error.h"
#include "io/core/crs_identity.h"
#include "io/core/crs_transform.h"
#include "io/core/gdal_util.h"

namespace roofsweep {
namespace {

namespace fs = std::filesystem;

struct DatasetCloser {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

// Vertices closer than this (metres, local frame) are one vertex.
constexpr double kSameVertex = 1e-6;
// Rings of less area (m²) are degenerate (collinear vertices).
constexpr double kMinArea = 1e-6;

bool IsPolygonal(OGRwkbGeometryType t) {
  const OGRwkbGeometryType flat = wkbFlatten(t);
  return flat == wkbPolygon || flat == wkbMultiPolygon || flat == wkbCurvePolygon ||
         flat == wkbMultiSurface;
}

std::string LayerNames(GDALDataset& ds) {
  std::string names;
  for (int i = 0; i < ds.GetLayerCount(); ++i)
    names += (names.empty() ? "" : ", ") + std::string(ds.GetLayer(i)->GetName());
  return names.empty() ? "no layers" : "layers: " + names;
}

// A layer of unknown geometry type (GeoJSON with mixed types, GML, ...)
// counts as a polygon layer when one of its features holds a polygon.
bool HoldsPolygons(OGRLayer& layer) {
  layer.ResetReading();
  bool found = false;
  for (auto& f : layer) {
    const OGRGeometry* g = f->GetGeometryRef();
    if (g && IsPolygonal(g->getGeometryType())) {
      found = true;
      break;
    }
  }
  layer.ResetReading();
  return found;
}

OGRLayer* SelectLayer(GDALDataset& ds, const std::string& path, const std::string& wanted) {
  if (!wanted.empty()) {
    OGRLayer* l = ds.GetLayerByName(wanted.c_str());
    if (!l) throw Error(AtLine(path, 0, "no layer '" + wanted + "' (" + LayerNames(ds) + ")"));
    const OGRwkbGeometryType t = l->GetGeomType();
    if (t == wkbNone || (wkbFlatten(t) != wkbUnknown && !IsPolygonal(t))) {
      throw Error(
          AtLine(path, 0,
                 "layer '" + wanted + "' holds " +
                     (t == wkbNone ? std::string("no geometries")
                                   : std::string(OGRGeometryTypeToName(t)) + " geometries") +
                     ", not polygons"));
    }
    return l;
  }
  for (int i = 0; i < ds.GetLayerCount(); ++i) {
    OGRLayer* l = ds.GetLayer(i);
    if (IsPolygonal(l->GetGeomType())) return l;
    if (wkbFlatten(l->GetGeomType()) == wkbUnknown && HoldsPolygons(*l)) return l;
  }
  throw Error(AtLine(path, 0, "no layer with polygon geometries (" + LayerNames(ds) + ")"));
}

// The horizontal part of a CRS (a compound CRS without its vertical CRS, a
// 3D CRS demoted to 2D, as roofsweep's own GPKG layers are 3D): footprints
// are plan-view outlines, their heights are not used.
// The GeoPackage's placeholders for "no CRS" (srs_id 0 and -1, which GDAL
// reports as CRSs on an unknown datum): no CRS.
bool IsUndefined(const OGRSpatialReference& srs) {
  const char* name = srs.GetName();
  return srs.GetAuthorityCode(nullptr) == nullptr && name &&
         (EQUAL(name, "Undefined geographic SRS") || EQUAL(name, "Undefined Cartesian SRS"));
}

// A definition of `srs` for CrsTransform: "AUTH:CODE" when the CRS carries
// one, else single-line WKT2.
std::string Definition(const OGRSpatialReference& srs) {
  const char* auth = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (auth && code && *auth && *code) return std::string(auth) + ":" + code;
  char* wkt = nullptr;
  const char* options[] = {"FORMAT=WKT2_2019", "MULTILINE=NO", nullptr};
  std::string out;
  if (srs.exportToWkt(&wkt, options) == OGRERR_NONE && wkt) out = wkt;
  CPLFree(wkt);
  return out;
}

// A short name for messages: "EPSG:4326", else the CRS's own name.
std::string ShortName(const OGRSpatialReference& srs) {
  const char* auth = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (auth && code && *auth && *code) return std::string(auth) + ":" + code;
  const char* name = srs.GetName();
  return name && *name ? name : "unnamed CRS";
}

// CrsTransform's messages begin "CRS '<definition>' -> '<target>': " or
// "CRS '<definition>': "; a WKT definition is too long to repeat, so the
// prefix is replaced by the CRS's short name.
std::string WithoutPrefix(const std::string& what, const std::string& source,
                          const std::string& target) {
  for (const std::string& p :
       {"CRS '" + source + "' -> '" + target + "': ", "CRS '" + source + "': "}) {
    if (what.compare(0, p.size(), p) == 0) return what.substr(p.size());
  }
  return what;
}

// Where the x (east/longitude) and y (north/latitude) of the project's
// convention are found in a geometry's coordinates: the layer's data axis
// mapping says which CRS axis each stored coordinate is, the traditional GIS
// order says which CRS axis is east (or longitude). Drivers reading a
// latitude-first file (GML with EPSG:4326 URNs, ...) either swap on reading
// or say so in the mapping; both cases end up east-first here.
struct AxisOrder {
  int from[2] = {0, 1};
  double sign[2] = {1, 1};

  static AxisOrder Of(const OGRSpatialReference& layer_srs) {
    AxisOrder a;
    OGRSpatialReference traditional(layer_srs);
    traditional.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const std::vector<int> data = layer_srs.GetDataAxisToSRSAxisMapping();
    const std::vector<int> want = traditional.GetDataAxisToSRSAxisMapping();
    if (data.size() < 2 || want.size() < 2) return a;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        if (std::abs(data[i]) == std::abs(want[j])) {
          a.from[j] = i;
          a.sign[j] = (data[i] > 0) == (want[j] > 0) ? 1.0 : -1.0;
        }
    return a;
  }
  Eigen::Vector2d Apply(double x, double y) const {
    const double v[2] = {x, y};
    return {sign[0] * v[from[0]], sign[1] * v[from[1]]};
  }
};

// Why the ring is not simple, or empty when it is: two non-adjacent edges
// meet (cross, touch or overlap), which also finds spikes.
//
// Not OGRGeometry::IsValid: it needs GEOS, which GDAL may be built without
// (OGRGeometryFactory::haveGEOS()), its verdict depends on the GEOS version,
// and it also judges the holes, which are not used. This test gives the
// same answer everywhere.
std::string Crossing(const Ring2& r) {
  std::pair<size_t, size_t> edges;
  if (!RingSelfIntersects(r, &edges)) return "";
  return "exterior ring crosses itself (edges " + std::to_string(edges.first) + " and " +
         std::to_string(edges.second) + ")";
}

class Reader {
 public:
  Reader(const std::string& path, OGRLayer& layer, const LocalFrame& frame,
         const FootprintReadOptions& options, std::vector<std::string>* messages)
      : path_(path), layer_(layer), frame_(frame), options_(options), messages_(messages) {
    name_ = layer.GetName();
    SetUpCrs();
    SetUpId();
  }

  std::vector<Footprint> Read() {
    std::vector<Footprint> out;
    layer_.ResetReading();
    long long index = 0;
    for (auto& f : layer_) {
      const GIntBig fid = f->GetFID() == OGRNullFID ? index : f->GetFID();
      ++index;
      const std::string fid_text = std::to_string(fid);
      std::string id;
      if (id_field_ >= 0 && f->IsFieldSetAndNotNull(id_field_)) id = f->GetFieldAsString(id_field_);
      if (id.empty()) id = fid_text;

      const OGRGeometry* g = f->GetGeometryRef();
      if (!g || g->IsEmpty()) {
        Note(fid_text, "no geometry");
        continue;
      }
      std::unique_ptr<OGRGeometry> linear;
      if (g->hasCurveGeometry()) {
        linear.reset(g->getLinearGeometry());
        if (!linear) {
          Note(fid_text, "cannot approximate its curves by straight lines");
          continue;
        }
        g = linear.get();
      }
      const OGRwkbGeometryType flat = wkbFlatten(g->getGeometryType());
      std::vector<const OGRPolygon*> parts;
      if (flat == wkbPolygon) {
        parts.push_back(g->toPolygon());
      } else if (flat == wkbMultiPolygon) {
        for (const OGRPolygon* p : *g->toMultiPolygon()) parts.push_back(p);
      } else {
        Note(fid_text,
             std::string(OGRGeometryTypeToName(g->getGeometryType())) + " is not a polygon");
        continue;
      }
      for (size_t k = 0; k < parts.size(); ++k) {
        const std::string who =
            parts.size() > 1 ? fid_text + " part " + std::to_string(k + 1) : fid_text;
        std::string why;
        Footprint fp;
        fp.id = id;
        fp.holes = parts[k]->getNumInteriorRings();
        fp.outline = Outline(*parts[k], fid_text, &why);
        if (!why.empty()) {
          Note(who, why);
          continue;
        }
        if (options_.extent && !BoundsMeet(RingBounds(fp.outline), *options_.extent)) continue;
        out.push_back(std::move(fp));
      }
    }
    return out;
  }

 private:
  void Message(const std::string& text) {
    if (messages_) messages_->push_back(text);
  }
  void Note(const std::string& who, const std::string& why) {
    Message(path_ + ": feature " + who + " skipped: " + why);
  }

  void SetUpCrs() {
    const OGRSpatialReference* srs = layer_.GetSpatialRef();
    if (!srs || srs->IsEmpty() || IsUndefined(*srs)) {
      if (!options_.block_crs.empty()) {
        Message(path_ + ": layer '" + name_ + "' has no CRS; read as block coordinates");
      }
      return;
    }
    axes_ = AxisOrder::Of(*srs);
    if (options_.block_crs.empty()) {
      Message(path_ + ": layer '" + name_ + "' is in " + ShortName(*srs) +
              " but the block has no CRS; read as block coordinates");
      return;
    }
    gdal::ErrorCapture quiet;
    OGRSpatialReference block;
    if (block.SetFromUserInput(options_.block_crs.c_str()) != OGRERR_NONE) {
      throw Error(AtLine(path_, 0,
                         "cannot read the block CRS '" + options_.block_crs + "' (" +
                             quiet.Message("GDAL does not know it") + ")"));
    }
    const auto layer_h = HorizontalCrs(*srs);
    const auto block_h = HorizontalCrs(block);
    const char* same_options[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES", nullptr};
    if (layer_h->IsSame(block_h.get(), same_options)) return;

    const std::string source = Definition(*layer_h);
    const std::string target = Definition(*block_h);
    crs_name_ = ShortName(*layer_h) + "' -> '" + options_.block_crs;
    CrsTransformOptions to;
    to.ballpark_hint = "reproject the footprints to the block CRS first (ogr2ogr -t_srs)";
    to.area_of_interest = AreaOfInterest();
    try {
      to_block_.emplace(source, target, to);
    } catch (const Error& e) {
      throw Error(AtLine(path_, 0,
                         "layer '" + name_ + "': CRS '" + crs_name_ +
                             "': " + WithoutPrefix(e.what(), source, target)));
    }
    source_ = source;
    target_ = target;
  }

  // Longitude/latitude box around the block origin, so that PROJ picks the
  // transformation valid at the block (several exist for most datums).
  std::optional<Eigen::Vector4d> AreaOfInterest() const {
    if (!frame_.HasCrs()) return std::nullopt;
    try {
      const Eigen::Vector3d g =
          CrsTransform::ToOwnGeographic3D(options_.block_crs).Forward(frame_.OriginCrs());
      const double d = 0.1;  // degrees, some kilometres: a block and its margin
      return Eigen::Vector4d(g.x() - d, std::max(-90.0, g.y() - d), g.x() + d,
                             std::min(90.0, g.y() + d));
    } catch (const Error&) {
      return std::nullopt;  // PROJ's first choice then
    }
  }

  void SetUpId() {
    OGRFeatureDefn* defn = layer_.GetLayerDefn();
    if (!options_.id_field.empty()) {
      id_field_ = defn->GetFieldIndex(options_.id_field.c_str());
      if (id_field_ >= 0) return;
      // The FID column of GPKG/SQLite/PostGIS is no field but can be asked for.
      const char* fid_column = layer_.GetFIDColumn();
      if (fid_column && EQUAL(fid_column, options_.id_field.c_str())) return;
      std::string fields;
      for (int i = 0; i < defn->GetFieldCount(); ++i)
        fields += (fields.empty() ? "" : ", ") + std::string(defn->GetFieldDefn(i)->GetNameRef());
      throw Error(AtLine(path_, 0,
                         "layer '" + name_ + "' has no field '" + options_.id_field + "' (" +
                             (fields.empty() ? "no fields" : "fields: " + fields) + ")"));
    }
    // GetFieldIndex compares case-insensitively.
    for (const char* name : {"id", "identificatie", "gml_id", "fid"}) {
      id_field_ = defn->GetFieldIndex(name);
      if (id_field_ >= 0) return;
    }
  }

  // The exterior ring in the local frame, closing vertex and repeated
  // vertices dropped, counter-clockwise; empty with `why` set when it is
  // degenerate or not simple.
  Ring2 Outline(const OGRPolygon& polygon, const std::string& fid, std::string* why) const {
    Ring2 ring;
    const OGRLinearRing* r = polygon.getExteriorRing();
    if (!r) {
      *why = "no exterior ring";
      return ring;
    }
    // Heights are ignored: every vertex is placed at the block origin's
    // height, where the local plan view is taken (a footprint point's local
    // x, y move by height x distance / earth radius, ~1 cm per 100 m of
    // height at 600 m from the origin).
    const double z = frame_.OriginCrs().z();
    for (int i = 0; i < r->getNumPoints(); ++i) {
      const double x = r->getX(i), y = r->getY(i);
      if (!std::isfinite(x) || !std::isfinite(y)) {
        throw Error(AtLine(path_, 0, "feature " + fid + ": coordinate is not finite"));
      }
      const Eigen::Vector2d xy = axes_.Apply(x, y);
      Eigen::Vector3d crs(xy.x(), xy.y(), z);
      if (to_block_) {
        try {
          crs = to_block_->Forward(crs);
        } catch (const Error& e) {
          throw Error(AtLine(path_, 0,
                             "feature " + fid + ": CRS '" + crs_name_ +
                                 "': " + WithoutPrefix(e.what(), source_, target_)));
        }
        crs.z() = z;
      }
      const Eigen::Vector2d p = frame_.ToLocal(crs).head<2>();
      if (ring.empty() || (p - ring.back()).norm() > kSameVertex) ring.push_back(p);
    }
    while (ring.size() > 1 && (ring.front() - ring.back()).norm() <= kSameVertex) ring.pop_back();
    if (ring.size() < 3) {
      *why = "fewer than 3 distinct vertices";
      return {};
    }
    // Crossing before area: a symmetric bow-tie has zero signed area.
    *why = Crossing(ring);
    if (!why->empty()) return {};
    const double area = SignedArea(ring);
    if (std::abs(area) < kMinArea) {
      *why = "zero area";
      return {};
    }
    // Counter-clockwise with the same first vertex.
    if (area < 0) std::reverse(ring.begin() + 1, ring.end());
    return ring;
  }

  const std::string& path_;
  OGRLayer& layer_;
  const LocalFrame& frame_;
  const FootprintReadOptions& options_;
  std::vector<std::string>* messages_;
  std::string name_;
  AxisOrder axes_;
  std::optional<CrsTransform> to_block_;
  std::string source_, target_, crs_name_;
  int id_field_ = -1;
};

}  // namespace

std::vector<Footprint> ReadFootprints(const std::string& path, const LocalFrame& frame,
                                      const FootprintReadOptions& options,
                                      std::vector<std::string>* messages) {
  gdal::EnsureRegistered();
  gdal::ErrorCapture errors;
  DatasetPtr ds(GDALDataset::FromHandle(
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  if (!ds) {
    std::error_code ec;
    // Connection strings (PG:..., /vsicurl/...) are no files: only a plain
    // path that is not there is "no such file".
    if (path.find(':') == std::string::npos && path.rfind("/vsi", 0) != 0 &&
        !fs::exists(path, ec)) {
      throw Error(AtLine(path, 0, "no such file"));
    }
    throw Error(AtLine(path, 0,
                       "cannot open as a vector dataset (" +
                           errors.Message("GDAL does not recognise the format") + ")"));
  }
  OGRLayer* layer = SelectLayer(*ds, path, options.layer);
  Reader reader(path, *layer, frame, options, messages);
  return reader.Read();
}

}  // namespace roofsweep
