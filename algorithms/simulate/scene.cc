#include "algorithms/simulate/scene.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "algorithms/core/error.h"
#include "algorithms/simulate/procedural_buildings.h"
#include "algorithms/simulate/random.h"

namespace roofsweep {
namespace sim {

int GroundLayout::MaterialAt(const Eigen::Vector2d& p) const {
  for (auto it = regions.rbegin(); it != regions.rend(); ++it)
    if (it->Contains(p)) return it->material;
  return base_material;
}

namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

// Fixed material slots shared by the whole scene.
enum Slot { kGrass, kAsphalt, kPaving, kPaint, kFoliage0, kFoliage1, kBark, kSlotCount };

void AddBaseMaterials(Scene& s, uint64_t seed) {
  s.materials.resize(kSlotCount);
  s.materials[kGrass] = GrassMaterial(static_cast<uint32_t>(Hash(seed, 1)));
  s.materials[kAsphalt] = AsphaltMaterial(static_cast<uint32_t>(Hash(seed, 2)));
  s.materials[kPaving] = PavingMaterial(static_cast<uint32_t>(Hash(seed, 3)));
  s.materials[kPaint] = PaintMaterial(static_cast<uint32_t>(Hash(seed, 4)));
  s.materials[kFoliage0] = FoliageMaterial(0, static_cast<uint32_t>(Hash(seed, 5)));
  s.materials[kFoliage1] = FoliageMaterial(1, static_cast<uint32_t>(Hash(seed, 6)));
  s.materials[kBark] = BarkMaterial(static_cast<uint32_t>(Hash(seed, 7)));
  s.ground.base_material = kGrass;
}

// Oriented rectangle for overlap tests.
struct Rect {
  V2 c, axis, half;
  std::array<V2, 4> Corners() const {
    const V2 n(-axis.y(), axis.x());
    return {c - half.x() * axis - half.y() * n, c + half.x() * axis - half.y() * n,
            c + half.x() * axis + half.y() * n, c - half.x() * axis + half.y() * n};
  }
};

bool Overlap(const Rect& a, const Rect& b, double margin) {
  // Separating axis theorem on the four face normals.
  const auto ca = a.Corners(), cb = b.Corners();
  for (const V2& ax : {a.axis, V2(-a.axis.y(), a.axis.x()), b.axis, V2(-b.axis.y(), b.axis.x())}) {
    double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
    for (const V2& p : ca) amin = std::min(amin, p.dot(ax)), amax = std::max(amax, p.dot(ax));
    for (const V2& p : cb) bmin = std::min(bmin, p.dot(ax)), bmax = std::max(bmax, p.dot(ax));
    if (amax + margin < bmin || bmax + margin < amin) return false;
  }
  return true;
}

struct Box {
  double x0, y0, x1, y1;
  bool Contains(const V2& p) const {
    return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
  }
};

std::vector<Rect> FootprintRects(const BuildingSpec& b) {
  const double c = std::cos(b.yaw_deg * M_PI / 180), s = std::sin(b.yaw_deg * M_PI / 180);
  const V2 ax(c, s), n(-s, c);
  std::vector<Rect> r = {{b.center, ax, V2(b.length / 2, b.width / 2)}};
  if (b.shape == RoofShape::kLShape || b.shape == RoofShape::kTShape) {
    const double xc =
        b.shape == RoofShape::kLShape ? b.length / 2 - b.wing_width / 2 : b.wing_offset;
    r.push_back({b.center + xc * ax + (b.width / 2 + b.wing_length / 2) * n, ax,
                 V2(b.wing_width / 2, b.wing_length / 2)});
  }
  return r;
}

RoofShape PickShape(const std::array<double, 9>& w, Rng& rng) {
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  double x = rng.Uniform() * total;
  for (int i = 0; i < kRoofShapeCount; ++i) {
    if (x < w[i]) return static_cast<RoofShape>(i);
    x -= w[i];
  }
  return RoofShape::kGable;
}

double Tan(double deg) { return std::tan(deg * M_PI / 180); }

// Random dimensions for one detached building of the given shape.
BuildingSpec RandomSpec(RoofShape shape, const SceneOptions& o, Rng& rng) {
  BuildingSpec b;
  b.shape = shape;
  const double u = rng.Uniform();
  double L = o.min_length + (o.max_length - o.min_length) * u * u;
  double W = rng.Uniform(6, std::max(6.0, std::min(L, 13.0)));
  const double pitch = rng.Uniform(25, 50);
  b.eave_height = rng.Uniform(3, 9);
  switch (shape) {
    case RoofShape::kFlat:
      W = std::clamp(L * rng.Uniform(0.4, 0.9), std::min(6.0, L), 22.0);
      b.eave_height = rng.Uniform(3, 6) + 0.35 * L;
      break;
    case RoofShape::kShed:
      L = std::min(L, 25.0);
      W = std::min(W, L);
      break;
    case RoofShape::kPyramid:
      L = std::clamp(L, o.min_length, 14.0);
      W = L * rng.Uniform(0.85, 1.0);
      break;
    case RoofShape::kMansard:
      L = std::clamp(L, 10.0, 25.0);
      W = rng.Uniform(9, std::min(L, 14.0));
      break;
    case RoofShape::kLShape:
    case RoofShape::kTShape:
      L = std::clamp(L, 11.0, 22.0);
      W = rng.Uniform(7, 11);
      b.wing_width = W * rng.Uniform(0.55, 0.85);
      b.wing_length = W * rng.Uniform(0.5, 1.2);
      b.wing_offset = (L / 2 - b.wing_width / 2 - 1.0) * rng.Uniform(-0.8, 0.8);
      break;
    default:
      L = std::min(L, 28.0);
      W = std::min(W, L);
      break;
  }
  b.length = L;
  b.width = W;
  b.ridge_height = b.eave_height + Tan(pitch) * W / 2;
  if (shape == RoofShape::kShed) b.ridge_height = b.eave_height + Tan(rng.Uniform(8, 22)) * W;
  if (shape == RoofShape::kMansard) {
    b.mansard_inset = rng.Uniform(0.9, 1.6);
    b.mansard_break_height = b.eave_height + Tan(rng.Uniform(60, 72)) * b.mansard_inset;
    b.ridge_height =
        b.mansard_break_height + Tan(rng.Uniform(12, 22)) * (W - 2 * b.mansard_inset) / 2;
  }
  b.half_hip_fraction = rng.Uniform(0.5, 0.75);
  return b;
}

// Roof material of one building: a palette entry, sometimes matched in
// luminance to the lawn, optionally pulled towards the ground colour.
Material PickRoofMaterial(bool flat, const SceneOptions& o, const Scene& scene, Rng& rng,
                          uint32_t seed) {
  Material m = RoofMaterial(rng.Int(0, RoofMaterialCount(flat) - 1), flat, seed);
  const Eigen::Vector3f grass = scene.materials[kGrass].albedo;
  if (!flat && rng.Chance(o.isoluminant_fraction)) {
    m = RoofMaterial(0, false, seed);
    m.name = "isoluminant_red_tiles";
    m.albedo *= Luminance(grass) / Luminance(m.albedo);
  }
  m.albedo = grass + static_cast<float>(o.roof_contrast) * (m.albedo - grass);
  m.albedo = m.albedo.cwiseMax(0.005f);
  return m;
}

void AddBuilding(Scene& scene, const BuildingSpec& spec, int roof_mat, int wall_mat,
                 const SceneOptions& o, Rng& rng) {
  Building b = MakeBuilding(spec);
  std::vector<int> mats(b.surfaces.size(), wall_mat);
  const bool same = rng.Chance(o.same_roof_material);
  for (size_t i = 0; i < b.surfaces.size(); ++i) {
    if (b.surfaces[i].type != SurfaceType::kRoof) continue;
    mats[i] = roof_mat;
    if (!same && rng.Chance(0.5)) {
      // A re-roofed or differently weathered face of the same material.
      Material m = scene.materials[roof_mat];
      m.albedo *= static_cast<float>(rng.Uniform(0.8, 1.2));
      m.seed = static_cast<uint32_t>(rng.Next());
      scene.materials.push_back(m);
      mats[i] = static_cast<int>(scene.materials.size()) - 1;
    }
  }
  scene.city.buildings.push_back(std::move(b));
  scene.surface_materials.push_back(std::move(mats));
}

int PushMaterial(Scene& s, Material m) {
  s.materials.push_back(std::move(m));
  return static_cast<int>(s.materials.size()) - 1;
}

void AddTrees(Scene& scene, const SceneOptions& o, const std::vector<Rect>& blocked, Rng& rng) {
  const Box area{scene.area[0], scene.area[1], scene.area[2], scene.area[3]};
  for (int attempt = 0;
       attempt < 200 * o.tree_count && static_cast<int>(scene.trees.size()) < o.tree_count;
       ++attempt) {
    Tree t;
    t.crown_radius = rng.Uniform(1.8, 5.0);
    t.trunk_height = rng.Uniform(1.5, 4.0);
    t.crown_height = t.crown_radius * rng.Uniform(1.3, 2.2);
    const V2 p(rng.Uniform(area.x0, area.x1), rng.Uniform(area.y0, area.y1));
    const int ground_mat = scene.ground.MaterialAt(p);
    if (ground_mat == kAsphalt || ground_mat == kPaint) continue;
    const Rect me{p, V2::UnitX(), V2::Constant(0.6 * t.crown_radius)};
    bool ok = true;
    for (const Rect& r : blocked) ok = ok && !Overlap(me, r, 0.5);
    for (const Tree& other : scene.trees)
      ok = ok && (other.base.head<2>() - p).norm() > 0.8 * (other.crown_radius + t.crown_radius);
    if (!ok) continue;
    t.base = V3(p.x(), p.y(), scene.ground.z);
    t.material = rng.Chance(0.7) ? kFoliage0 : kFoliage1;
    t.seed = static_cast<uint32_t>(rng.Next());
    scene.trees.push_back(t);
  }
}

}  // namespace

Scene GenerateScene(const SceneOptions& o, uint64_t seed) {
  if (!(o.extent_x > 10 && o.extent_y > 10)) throw Error("simulate: scene extent must be > 10 m");
  if (o.min_length < 3 || o.max_length < o.min_length)
    throw Error("simulate: building length range must satisfy 3 <= min <= max");
  Scene scene;
  AddBaseMaterials(scene, seed);
  scene.ground.z = o.ground_z;
  const double ex = o.extent_x / 2, ey = o.extent_y / 2;
  scene.area << -ex, -ey, ex, ey;
  Rng rng(Hash(seed, 0x5ce7e));

  // Street grid: axes at random phase; streets run past the area so that
  // every image sees them continue.
  const double half_street = o.street_width / 2, half_total = half_street + o.sidewalk_width;
  const double reach = std::max(ex, ey) + 400;
  std::vector<double> xs, ys;  // street axes: x = const (north-south), y = const (east-west)
  for (double x = -ex + o.street_spacing * rng.Uniform(0.35, 0.65); x < ex; x += o.street_spacing)
    xs.push_back(x);
  for (double y = -ey + o.street_spacing * rng.Uniform(0.35, 0.65); y < ey; y += o.street_spacing)
    ys.push_back(y);
  auto near_cross = [&](double t, const std::vector<double>& cross, double pad) {
    for (double c : cross)
      if (std::abs(t - c) < half_total + pad) return true;
    return false;
  };
  // Yards first (lowest priority), filled in while placing buildings.
  std::vector<GroundRegion> yards;
  std::vector<GroundRegion> streets;
  auto street = [&](bool along_x, double pos) {
    const V2 ax = along_x ? V2::UnitX() : V2::UnitY();
    const V2 n = along_x ? V2::UnitY() : V2::UnitX();
    for (int side : {-1, 1})
      streets.push_back({pos * n + side * (half_street + o.sidewalk_width / 2) * n, ax,
                         V2(reach, o.sidewalk_width / 2), kPaving});
    return std::make_pair(ax, n);
  };
  for (double y : ys) street(true, y);
  for (double x : xs) street(false, x);
  for (double y : ys) streets.push_back({V2(0, y), V2::UnitX(), V2(reach, half_street), kAsphalt});
  for (double x : xs) streets.push_back({V2(x, 0), V2::UnitY(), V2(reach, half_street), kAsphalt});
  std::vector<GroundRegion> paint;
  auto markings = [&](bool along_x, double pos, const std::vector<double>& cross) {
    const V2 ax = along_x ? V2::UnitX() : V2::UnitY();
    const V2 n = along_x ? V2::UnitY() : V2::UnitX();
    for (double t = -reach + 1.5; t < reach; t += 9.0)  // centre line: 3 m dashes, 6 m gaps
      if (!near_cross(t, cross, 2.0))
        paint.push_back({t * ax + pos * n, ax, V2(1.5, 0.075), kPaint});
    // Edge lines, broken at crossings.
    for (int side : {-1, 1}) {
      double start = -reach;
      std::vector<double> cuts = cross;
      cuts.push_back(reach + half_total);
      std::sort(cuts.begin(), cuts.end());
      for (double c : cuts) {
        const double end = c - half_total - 1.0;
        if (end - start > 2)
          paint.push_back({0.5 * (start + end) * ax + (pos + side * (half_street - 0.4)) * n, ax,
                           V2(0.5 * (end - start), 0.06), kPaint});
        start = c + half_total + 1.0;
      }
    }
    // A zebra crossing before the first crossing street.
    if (!cross.empty()) {
      const double t0 = cross[0] - half_total - 3.0;
      for (int k = -3; k <= 3; ++k)
        paint.push_back({t0 * ax + (pos + k * 1.0) * n, ax, V2(1.5, 0.25), kPaint});
    }
  };
  for (double y : ys) markings(true, y, xs);
  for (double x : xs) markings(false, x, ys);

  // Blocks between streets, clipped to the area.
  std::vector<double> bx = {-ex}, by = {-ey};
  for (double x : xs) bx.push_back(x - half_total), bx.push_back(x + half_total);
  for (double y : ys) by.push_back(y - half_total), by.push_back(y + half_total);
  bx.push_back(ex);
  by.push_back(ey);
  std::vector<Box> blocks;
  const double setback = 1.5;
  for (size_t i = 0; i + 1 < bx.size(); i += 2)
    for (size_t j = 0; j + 1 < by.size(); j += 2)
      if (bx[i + 1] - bx[i] > 10 && by[j + 1] - by[j] > 10)
        blocks.push_back(
            {bx[i] + setback, by[j] + setback, bx[i + 1] - setback, by[j + 1] - setback});
  if (blocks.empty()) throw Error("simulate: no room for buildings between the streets");
  std::vector<double> block_area;
  for (const Box& b : blocks) block_area.push_back((b.x1 - b.x0) * (b.y1 - b.y0));
  const double total_area = std::accumulate(block_area.begin(), block_area.end(), 0.0);

  std::vector<Rect> placed;
  auto fits = [&](const std::vector<Rect>& rects, const Box& block, double margin) {
    for (const Rect& r : rects) {
      for (const V2& c : r.Corners())
        if (!block.Contains(c)) return false;
      for (const Rect& p : placed)
        if (Overlap(r, p, margin)) return false;
    }
    return true;
  };
  int n = 0;
  auto next_id = [&]() {
    char buf[32];
    std::snprintf(buf, sizeof buf, "BLDG_%04d", ++n);
    return std::string(buf);
  };

  for (int attempt = 0;
       attempt < 4000 && static_cast<int>(scene.city.buildings.size()) < o.building_count;
       ++attempt) {
    double pick = rng.Uniform() * total_area;
    size_t bi = 0;
    while (bi + 1 < blocks.size() && pick >= block_area[bi]) pick -= block_area[bi++];
    const Box& block = blocks[bi];
    const V2 c(rng.Uniform(block.x0, block.x1), rng.Uniform(block.y0, block.y1));
    const double base_yaw = rng.Chance(0.5) ? 0.0 : 90.0;
    if (rng.Chance(o.terrace_fraction)) {
      // Terraced row along the street direction: gable walls are party walls.
      const int units =
          std::min(rng.Int(2, 4), o.building_count - static_cast<int>(scene.city.buildings.size()));
      if (units < 2) continue;
      std::vector<double> widths;
      for (int k = 0; k < units; ++k) widths.push_back(rng.Uniform(6, 9));
      const double total = std::accumulate(widths.begin(), widths.end(), 0.0);
      const double depth = rng.Uniform(8.5, 12);
      const V2 ax(std::cos(base_yaw * M_PI / 180), std::sin(base_yaw * M_PI / 180));
      const Rect row{c, ax, V2(total / 2, depth / 2)};
      if (!fits({row}, block, 3.0)) continue;
      placed.push_back(row);
      const double eave = rng.Uniform(5, 9), pitch = rng.Uniform(30, 48);
      const bool same_mat = rng.Chance(0.4);
      const int shared_roof = PushMaterial(
          scene, PickRoofMaterial(false, o, scene, rng, static_cast<uint32_t>(rng.Next())));
      double x = -total / 2;
      for (int k = 0; k < units; ++k) {
        BuildingSpec b;
        b.id = next_id();
        const double r = rng.Uniform();
        b.shape = r < 0.7 ? RoofShape::kGable : (r < 0.85 ? RoofShape::kFlat : RoofShape::kShed);
        b.center = c + (x + widths[k] / 2) * ax;
        b.yaw_deg = base_yaw;
        b.length = widths[k];
        b.width = depth;
        b.ground_z = o.ground_z;
        b.eave_height = eave + (rng.Chance(0.5) ? rng.Uniform(-1.5, 1.5) : 0.0);
        b.ridge_height = b.eave_height + Tan(pitch + rng.Uniform(-5, 5)) * depth / 2;
        if (b.shape == RoofShape::kShed) b.ridge_height = b.eave_height + Tan(15) * depth;
        const bool flat = b.shape == RoofShape::kFlat;
        const int roof =
            (same_mat && !flat)
                ? shared_roof
                : PushMaterial(scene, PickRoofMaterial(flat, o, scene, rng,
                                                       static_cast<uint32_t>(rng.Next())));
        const int wall = PushMaterial(scene, WallMaterial(rng.Int(0, WallMaterialCount() - 1),
                                                          static_cast<uint32_t>(rng.Next())));
        AddBuilding(scene, b, roof, wall, o, rng);
        x += widths[k];
      }
      continue;
    }
    BuildingSpec b = RandomSpec(PickShape(o.shape_weights, rng), o, rng);
    b.id = "tmp";
    b.center = c;
    b.ground_z = o.ground_z;
    b.yaw_deg = rng.Chance(o.aligned_fraction)
                    ? base_yaw + rng.Uniform(-3, 3) + (rng.Chance(0.5) ? 180 : 0)
                    : rng.Uniform(0, 360);
    const auto rects = FootprintRects(b);
    if (!fits(rects, block, 2.5)) continue;
    b.id = next_id();
    placed.insert(placed.end(), rects.begin(), rects.end());
    if (rng.Chance(0.5)) {
      const Rect& r = rects[0];
      yards.push_back({r.c, r.axis, r.half + V2::Constant(rng.Uniform(1.2, 2.5)), kPaving});
    }
    const bool flat = b.shape == RoofShape::kFlat;
    const int roof = PushMaterial(
        scene, PickRoofMaterial(flat, o, scene, rng, static_cast<uint32_t>(rng.Next())));
    const int wall = PushMaterial(scene, WallMaterial(rng.Int(0, WallMaterialCount() - 1),
                                                      static_cast<uint32_t>(rng.Next())));
    AddBuilding(scene, b, roof, wall, o, rng);
  }
  scene.ground.regions = yards;
  scene.ground.regions.insert(scene.ground.regions.end(), streets.begin(), streets.end());
  scene.ground.regions.insert(scene.ground.regions.end(), paint.begin(), paint.end());
  AddTrees(scene, o, placed, rng);
  return scene;
}

Scene SceneFromCityModel(const CityModel& city, const SceneOptions& o, uint64_t seed) {
  if (city.buildings.empty()) throw Error("simulate: the city model has no buildings");
  Scene scene;
  AddBaseMaterials(scene, seed);
  scene.city = city;
  const auto bounds = city.Bounds();
  double ground = bounds[2];
  for (const Building& b : city.buildings)
    if (std::isfinite(b.GroundZ())) ground = std::min(ground, b.GroundZ());
  // Lower the terrain by a millimetre so ground surfaces never fight with it.
  scene.ground.z = ground - 1e-3;
  scene.area << bounds[0] - 10, bounds[1] - 10, bounds[3] + 10, bounds[4] + 10;
  Rng rng(Hash(seed, 0xc17));
  std::vector<Rect> blocked;
  for (const Building& b : city.buildings) {
    CityModel one;
    one.buildings.push_back(b);
    const auto bb = one.Bounds();
    blocked.push_back({V2(0.5 * (bb[0] + bb[3]), 0.5 * (bb[1] + bb[4])), V2::UnitX(),
                       V2(0.5 * (bb[3] - bb[0]), 0.5 * (bb[4] - bb[1]))});
    bool flat = true;
    for (const Surface& s : b.surfaces)
      if (s.type == SurfaceType::kRoof)
        for (const Polygon3& p : s.polygons) flat = flat && p.Normal().z() > 0.995;
    const int roof = PushMaterial(
        scene, PickRoofMaterial(flat, o, scene, rng, static_cast<uint32_t>(rng.Next())));
    const int wall = PushMaterial(scene, WallMaterial(rng.Int(0, WallMaterialCount() - 1),
                                                      static_cast<uint32_t>(rng.Next())));
    std::vector<int> mats;
    for (const Surface& s : b.surfaces) mats.push_back(s.type == SurfaceType::kRoof ? roof : wall);
    scene.surface_materials.push_back(mats);
  }
  AddTrees(scene, o, blocked, rng);
  return scene;
}

SceneTruth TruthOf(const Scene& scene) {
  SceneTruth t;
  t.city = scene.city;
  t.edges = ExtractBuildingEdges(scene.city);
  t.roof_planes = ExtractRoofPlanes(scene.city);
  // Ground markings: region borders where the material really changes,
  // found by walking each border in 5 cm steps and comparing both sides.
  const double margin = 80, step = 0.05, probe = 0.02;
  const Box keep{scene.area[0] - margin, scene.area[1] - margin, scene.area[2] + margin,
                 scene.area[3] + margin};
  for (const GroundRegion& r : scene.ground.regions) {
    const V2 n(-r.axis.y(), r.axis.x());
    const auto corners = Rect{r.center, r.axis, r.half_size}.Corners();
    for (int k = 0; k < 4; ++k) {
      V2 a = corners[k], b = corners[(k + 1) % 4];
      const V2 d = (b - a).normalized();
      const V2 out(d.y(), -d.x());  // corners run counter-clockwise
      const double len = (b - a).norm();
      double run_start = -1;
      auto flush = [&](double s0, double s1) {
        if (s1 - s0 < 0.1) return;
        const V2 p0 = a + s0 * d, p1 = a + s1 * d;
        TrueEdge e;
        e.a = V3(p0.x(), p0.y(), scene.ground.z);
        e.b = V3(p1.x(), p1.y(), scene.ground.z);
        e.kind = EdgeKind::kGroundMarking;
        t.edges.push_back(e);
      };
      const int steps = static_cast<int>(std::ceil(len / step));
      for (int i = 0; i <= steps; ++i) {
        const double s = std::min(len, i * step);
        const V2 p = a + s * d;
        bool differs = false;
        if (keep.Contains(p)) {
          const int in = scene.ground.MaterialAt(p - probe * out);
          const int ou = scene.ground.MaterialAt(p + probe * out);
          differs = in != ou && scene.materials[in].name != scene.materials[ou].name;
        }
        if (differs && run_start < 0) run_start = s;
        if (!differs && run_start >= 0) {
          flush(run_start, s - step);
          run_start = -1;
        }
      }
      if (run_start >= 0) flush(run_start, len);
    }
  }
  return t;
}

}  // namespace sim
}  // namespace roofsweep
