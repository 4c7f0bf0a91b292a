#include "io/citymodel/procedural_buildings.h"

#include <cmath>

namespace roofsweep::testing {

namespace {
using V = Eigen::Vector3d;

Surface Make(SurfaceType t, std::vector<V> ring) {
  Surface s;
  s.type = t;
  s.polygons.push_back(Polygon3{std::move(ring), {}});
  return s;
}

// Ground (clockwise from above) and four walls following the footprint
// A B C D (counter-clockwise from above); `top(i)` gives the wall-top height
// at corner i and `extra(i)` an optional apex between corners i and i+1.
void AddGroundAndWalls(Building* b, const std::vector<V>& foot, double top,
                       const std::vector<std::vector<V>>& gable_apex) {
  b->surfaces.push_back(Make(SurfaceType::kGround, {foot[0], foot[3], foot[2], foot[1]}));
  for (int i = 0; i < 4; ++i) {
    const V& p = foot[i];
    const V& q = foot[(i + 1) % 4];
    std::vector<V> ring{p, q, V(q.x(), q.y(), top)};
    for (const V& a : gable_apex[i]) ring.push_back(a);
    ring.push_back(V(p.x(), p.y(), top));
    b->surfaces.push_back(Make(SurfaceType::kWall, ring));
  }
}

std::vector<V> Footprint(double x0, double y0, double z0, double w, double d) {
  return {V(x0, y0, z0), V(x0 + w, y0, z0), V(x0 + w, y0 + d, z0), V(x0, y0 + d, z0)};
}
}  // namespace

Building MakeBox(const std::string& id, double x0, double y0, double z0, double w, double d,
                 double h) {
  Building b;
  b.id = id;
  const auto f = Footprint(x0, y0, z0, w, d);
  AddGroundAndWalls(&b, f, z0 + h, {{}, {}, {}, {}});
  std::vector<V> roof;
  for (const V& p : f) roof.push_back(V(p.x(), p.y(), z0 + h));
  b.surfaces.push_back(Make(SurfaceType::kRoof, roof));
  b.roof_type = roof_type::kFlat;
  b.measured_height = h;
  return b;
}

Building MakeGable(const std::string& id, double x0, double y0, double z0, double w, double d,
                   double eave, double ridge) {
  Building b;
  b.id = id;
  const auto f = Footprint(x0, y0, z0, w, d);
  const double ze = z0 + eave, zr = z0 + ridge, ym = y0 + d / 2;
  const V rw(x0, ym, zr), re(x0 + w, ym, zr);
  AddGroundAndWalls(&b, f, ze, {{}, {re}, {}, {rw}});
  const V ae(x0, y0, ze), be(x0 + w, y0, ze), ce(x0 + w, y0 + d, ze), de(x0, y0 + d, ze);
  b.surfaces.push_back(Make(SurfaceType::kRoof, {ae, be, re, rw}));
  b.surfaces.push_back(Make(SurfaceType::kRoof, {ce, de, rw, re}));
  b.roof_type = roof_type::kGabled;
  b.measured_height = ridge;
  return b;
}

Building MakeHip(const std::string& id, double x0, double y0, double z0, double w, double d,
                 double eave, double ridge, double inset) {
  Building b;
  b.id = id;
  const auto f = Footprint(x0, y0, z0, w, d);
  const double ze = z0 + eave, zr = z0 + ridge, ym = y0 + d / 2;
  const V rw(x0 + inset, ym, zr), re(x0 + w - inset, ym, zr);
  AddGroundAndWalls(&b, f, ze, {{}, {}, {}, {}});
  const V ae(x0, y0, ze), be(x0 + w, y0, ze), ce(x0 + w, y0 + d, ze), de(x0, y0 + d, ze);
  b.surfaces.push_back(Make(SurfaceType::kRoof, {ae, be, re, rw}));
  b.surfaces.push_back(Make(SurfaceType::kRoof, {be, ce, re}));
  b.surfaces.push_back(Make(SurfaceType::kRoof, {ce, de, rw, re}));
  b.surfaces.push_back(Make(SurfaceType::kRoof, {de, ae, rw}));
  b.roof_type = roof_type::kHipped;
  b.measured_height = ridge;
  return b;
}

Building MakeCityBuilding(int i, int cols, double x0, double y0, double z0) {
  // Non-round coordinates (x.xxx7) catch precision loss in writers.
  const double x = x0 + 20.0 * (i % cols) + 0.1237;
  const double y = y0 + 20.0 * (i / cols) + 0.4561;
  const double z = z0 + 0.25 * (i % 7) + 0.0003;
  char id[32];
  std::snprintf(id, sizeof id, "BLDG_%06d", i + 1);
  Building b = i % 3 == 0   ? MakeBox(id, x, y, z, 10.5, 8.25, 6.5)
               : i % 3 == 1 ? MakeGable(id, x, y, z, 12.0, 8.0, 5.5, 9.25)
                            : MakeHip(id, x, y, z, 14.0, 9.0, 6.0, 10.5, 3.0);
  b.double_attributes["roofsweep_rmse"] = 0.05 + 0.001 * (i % 13);
  b.string_attributes["source"] = "procedural";
  for (size_t s = 0; s < b.surfaces.size(); ++s)
    b.surfaces[s].id = std::string(id) + "_s" + std::to_string(s);
  return b;
}

int CityColumns(int n) {
  return std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n)))));
}

CityModel MakeCity(int n, double x0, double y0, double z0, const std::string& crs) {
  CityModel m;
  m.crs = crs;
  const int cols = CityColumns(n);
  for (int i = 0; i < n; ++i) m.buildings.push_back(MakeCityBuilding(i, cols, x0, y0, z0));
  return m;
}

}  // namespace roofsweep::testing
