#include "algorithms/eval/test_models.h"

namespace roofsweep::eval_test {
namespace {

using V = Eigen::Vector3d;

Surface Make(SurfaceType t, std::vector<std::vector<V>> rings) {
  Surface s;
  s.type = t;
  for (auto& r : rings) s.polygons.push_back({std::move(r), {}});
  return s;
}

// Footprint corners counter-clockwise from above, with the roof height of
// each corner; walls are rectangles except where `extra_top` adds apex
// points (gable ends): extra_top[i] lies on the top of the wall from corner
// i to corner i+1, listed from i+1's end towards i.
Building Solid(const std::string& id, const std::vector<Eigen::Vector2d>& fp, double z0,
               const std::vector<double>& top, const std::vector<std::vector<V>>& extra_top,
               std::vector<Surface> roofs, int type) {
  Building b;
  b.id = id;
  b.roof_type = type;
  std::vector<V> ground;
  for (size_t i = fp.size(); i-- > 0;) ground.push_back(V(fp[i].x(), fp[i].y(), z0));
  b.surfaces.push_back(Make(SurfaceType::kGround, {ground}));
  for (size_t i = 0; i < fp.size(); ++i) {
    const size_t j = (i + 1) % fp.size();
    std::vector<V> wall = {V(fp[i].x(), fp[i].y(), z0), V(fp[j].x(), fp[j].y(), z0),
                           V(fp[j].x(), fp[j].y(), top[j])};
    if (i < extra_top.size())
      for (const V& p : extra_top[i]) wall.push_back(p);
    wall.push_back(V(fp[i].x(), fp[i].y(), top[i]));
    b.surfaces.push_back(Make(SurfaceType::kWall, {wall}));
  }
  for (auto& r : roofs) b.surfaces.push_back(std::move(r));
  double zmax = z0;
  for (const auto& s : b.surfaces)
    for (const auto& p : s.polygons)
      for (const auto& v : p.exterior) zmax = std::max(zmax, v.z());
  b.measured_height = zmax - z0;
  return b;
}

}  // namespace

Camera NadirTestCamera() {
  Camera c;
  c.width = 200;
  c.height = 200;
  c.fx = c.fy = 500;
  c.cx = c.cy = 100;
  return c;
}

Pose NadirTestPose(double x, double y) {
  Pose p;
  p.R << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  p.C = V(x, y, 100);
  return p;
}

Building Box(const std::string& id, double x0, double y0, double l, double w, double z0, double h) {
  const double x1 = x0 + l, y1 = y0 + w, z = z0 + h;
  return Solid(
      id, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, z0, {z, z, z, z}, {},
      {Make(SurfaceType::kRoof, {{V(x0, y0, z), V(x1, y0, z), V(x1, y1, z), V(x0, y1, z)}})},
      roof_type::kFlat);
}

Building Gable(const std::string& id, double x0, double y0, double l, double w, double z0, double h,
               double rise, double ridge_fraction) {
  const double x1 = x0 + l, y1 = y0 + w, ze = z0 + h, zr = ze + rise;
  const double ym = y0 + ridge_fraction * w;
  std::vector<Surface> roofs = {
      Make(SurfaceType::kRoof, {{V(x0, y0, ze), V(x1, y0, ze), V(x1, ym, zr), V(x0, ym, zr)}}),
      Make(SurfaceType::kRoof, {{V(x0, ym, zr), V(x1, ym, zr), V(x1, y1, ze), V(x0, y1, ze)}})};
  // East wall (corner 1 -> 2) and west wall (corner 3 -> 0) carry the apex.
  return Solid(id, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, z0, {ze, ze, ze, ze},
               {{}, {V(x1, ym, zr)}, {}, {V(x0, ym, zr)}}, std::move(roofs), roof_type::kGabled);
}

Building Hip(const std::string& id, double x0, double y0, double l, double w, double z0, double h,
             double rise) {
  const double x1 = x0 + l, y1 = y0 + w, ze = z0 + h, zr = ze + rise;
  const double ym = y0 + w / 2, xa = x0 + w / 2, xb = x1 - w / 2;
  std::vector<Surface> roofs = {
      Make(SurfaceType::kRoof, {{V(x0, y0, ze), V(x1, y0, ze), V(xb, ym, zr), V(xa, ym, zr)}}),
      Make(SurfaceType::kRoof, {{V(x1, y0, ze), V(x1, y1, ze), V(xb, ym, zr)}}),
      Make(SurfaceType::kRoof, {{V(x1, y1, ze), V(x0, y1, ze), V(xa, ym, zr), V(xb, ym, zr)}}),
      Make(SurfaceType::kRoof, {{V(x0, y1, ze), V(x0, y0, ze), V(xa, ym, zr)}})};
  return Solid(id, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, z0, {ze, ze, ze, ze}, {},
               std::move(roofs), roof_type::kHipped);
}

CityModel ThreeHouses() {
  CityModel m;
  m.crs = "EPSG:25833";
  m.buildings = {Box("B_box", 0, 0, 10, 8, 30, 6), Gable("B_gable", 40, 0, 12, 8, 30, 6, 3),
                 Hip("B_hip", 80, 0, 14, 10, 30, 6, 4)};
  return m;
}

CityModel Transformed(const CityModel& m,
                      const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& f) {
  CityModel out = m;
  for (auto& b : out.buildings)
    for (auto& s : b.surfaces)
      for (auto& p : s.polygons) {
        for (auto& v : p.exterior) v = f(v);
        for (auto& h : p.holes)
          for (auto& v : h) v = f(v);
      }
  return out;
}

std::vector<Segment3> UniqueRoofEdges(const CityModel& m) {
  std::vector<Segment3> out;
  for (const auto& b : m.buildings)
    for (const auto& s : b.surfaces) {
      if (s.type != SurfaceType::kRoof) continue;
      for (const auto& p : s.polygons)
        for (size_t i = 0; i < p.exterior.size(); ++i) {
          const Segment3 e{p.exterior[i], p.exterior[(i + 1) % p.exterior.size()]};
          bool seen = false;
          for (const auto& o : out)
            seen |= ((o.a - e.b).norm() < 1e-9 && (o.b - e.a).norm() < 1e-9) ||
                    ((o.a - e.a).norm() < 1e-9 && (o.b - e.b).norm() < 1e-9);
          if (!seen) out.push_back(e);
        }
    }
  return out;
}

}  // namespace roofsweep::eval_test
