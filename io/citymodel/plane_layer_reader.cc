#include "io/citymodel/plane_layer_reader.h"

#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogrsf_frmts.h>

#include <memory>

#include "algorithms/core/error.h"
#include "io/citymodel/output_file.h"
#include "io/core/crs_identity.h"

namespace roofsweep {

PlaneHypothesisSet ReadPlaneHypotheses(const std::string& path) {
  CheckInputFile(path);
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY,
                                                    nullptr, nullptr, nullptr));
  if (!ds) throw Error(path + ": not a vector dataset GDAL can open");
  OGRLayer* layer = ds->GetLayerByName("roof_planes");
  if (!layer) throw Error(path + ": no layer 'roof_planes' (written by roofsweep run -planes)");
  const int status = layer->GetLayerDefn()->GetFieldIndex("status");
  const int reason = layer->GetLayerDefn()->GetFieldIndex("reason");
  if (status < 0) throw Error(path + ": layer 'roof_planes' has no field 'status'");
  PlaneHypothesisSet set;
  if (const OGRSpatialReference* srs = layer->GetSpatialRef()) set.crs = IdentifyCrs(*srs);
  layer->ResetReading();
  for (auto& feature : *layer) {
    const OGRGeometry* g = feature->GetGeometryRef();
    if (!g) continue;
    const OGRPolygon* poly = nullptr;
    const auto t = wkbFlatten(g->getGeometryType());
    if (t == wkbPolygon) {
      poly = g->toPolygon();
    } else if (t == wkbMultiPolygon && g->toMultiPolygon()->getNumGeometries() > 0) {
      poly = g->toMultiPolygon()->getGeometryRef(0);
    }
    if (!poly || !poly->getExteriorRing()) continue;
    PlaneHypothesisRecord r;
    const OGRLinearRing* ring = poly->getExteriorRing();
    for (int i = 0; i < ring->getNumPoints(); ++i)
      r.patch.emplace_back(ring->getX(i), ring->getY(i), ring->getZ(i));
    if (r.patch.size() > 1 && r.patch.front() == r.patch.back()) r.patch.pop_back();
    r.status = feature->GetFieldAsString(status);
    if (reason >= 0 && feature->IsFieldSetAndNotNull(reason))
      r.reason = feature->GetFieldAsString(reason);
    set.planes.push_back(std::move(r));
  }
  return set;
}

}  // namespace roofsweep
