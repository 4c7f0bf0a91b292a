#include "algorithms/simulate/scene.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "algorithms/core/error.h"
#include "algorithms/simulate/ground_index.h"
#include "algorithms/simulate/procedural_buildings.h"
#include "algorithms/simulate/prop_edges.h"
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
enum Slot {
  kGrass,
  kAsphalt,
  kPaving,
  kPaint,
  kFoliage0,
  kFoliage1,
  kBark,
  kSoil,
  kHedge,
  kGlass,
  kSolar,
  kIron,
  kRoofMetal,
  kChimney0,
  kChimney1,
  kCar0,
  kSlotCount = kCar0 + 8
};

void AddBaseMaterials(Scene& s, uint64_t seed) {
  s.materials.resize(kSlotCount);
  s.materials[kGrass] = GrassMaterial(static_cast<uint32_t>(Hash(seed, 1)));
  s.materials[kAsphalt] = AsphaltMaterial(static_cast<uint32_t>(Hash(seed, 2)));
  s.materials[kPaving] = PavingMaterial(static_cast<uint32_t>(Hash(seed, 3)));
  s.materials[kPaint] = PaintMaterial(static_cast<uint32_t>(Hash(seed, 4)));
  s.materials[kFoliage0] = FoliageMaterial(0, static_cast<uint32_t>(Hash(seed, 5)));
  s.materials[kFoliage1] = FoliageMaterial(1, static_cast<uint32_t>(Hash(seed, 6)));
  s.materials[kBark] = BarkMaterial(static_cast<uint32_t>(Hash(seed, 7)));
  s.materials[kSoil] = SoilMaterial(static_cast<uint32_t>(Hash(seed, 8)));
  s.materials[kHedge] = HedgeMaterial(static_cast<uint32_t>(Hash(seed, 9)));
  s.materials[kGlass] = GlassMaterial(static_cast<uint32_t>(Hash(seed, 10)));
  s.materials[kSolar] = SolarPanelMaterial(static_cast<uint32_t>(Hash(seed, 11)));
  s.materials[kIron] = MetalMaterial(1, static_cast<uint32_t>(Hash(seed, 12)));
  s.materials[kRoofMetal] = MetalMaterial(0, static_cast<uint32_t>(Hash(seed, 13)));
  s.materials[kChimney0] = ChimneyMaterial(0, static_cast<uint32_t>(Hash(seed, 14)));
  s.materials[kChimney1] = ChimneyMaterial(1, static_cast<uint32_t>(Hash(seed, 15)));
  for (int k = 0; k < 8; ++k)
    s.materials[kCar0 + k] = CarMaterial(k, static_cast<uint32_t>(Hash(seed, 16 + k)));
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
    t.base = V3(p.x(), p.y(), scene.ground.HeightAt(p));
    t.material = rng.Chance(0.7) ? kFoliage0 : kFoliage1;
    t.seed = static_cast<uint32_t>(rng.Next());
    scene.trees.push_back(t);
  }
}

}  // namespace

namespace {

// Lot contents, accepted or dropped as a whole (terraced rows share walls).
struct LotPlan {
  V2 centre = V2::Zero();
  struct Item {
    BuildingSpec spec;
    int roof = -1, wall = -1;
  };
  std::vector<Item> buildings;
  std::vector<Prop> props;
  std::vector<GroundRegion> regions;
  std::vector<Tree> trees;
};

// A row of lots along one street: s runs along the street, t from the
// street (sidewalk edge) into the block; inward = along rotated by +90 deg,
// so a building with yaw along `along` has its local +y (wings) at the back.
struct Row {
  V2 origin, along, inward;
  double length = 0, depth = 0;
  V2 At(double s, double t) const { return origin + s * along + t * inward; }
  GroundRegion Region(double s0, double s1, double t0, double t1, int mat) const {
    return {At(0.5 * (s0 + s1), 0.5 * (t0 + t1)), along, V2(0.5 * (s1 - s0), 0.5 * (t1 - t0)), mat};
  }
};

double YawOf(const V2& d) { return std::atan2(d.y(), d.x()) * 180 / M_PI; }

bool Valid(const BuildingSpec& b) {
  try {
    MakeBuilding(b);
    return true;
  } catch (const Error&) {
    return false;
  }
}

// A box standing on the ground (or at height z0) with its long side along `dir`.
Prop BoxProp(PropKind kind, const V2& c, const V2& dir, double len, double wid, double z0,
             double height, int mat, uint32_t seed) {
  Prop p;
  p.kind = kind;
  p.center = V3(c.x(), c.y(), z0 + height / 2);
  p.axes.col(0) = V3(dir.x(), dir.y(), 0);
  p.axes.col(1) = V3(-dir.y(), dir.x(), 0);
  p.axes.col(2) = V3::UnitZ();
  p.half = V3(len / 2, wid / 2, height / 2);
  p.material = mat;
  p.seed = seed;
  return p;
}

// Where a box or a building over `r` stands: on its lowest corner, so that
// on a slope it never floats.
double LowestGround(const GroundLayout& g, const Rect& r) {
  double low = std::numeric_limits<double>::infinity();
  for (const V2& p : r.Corners()) low = std::min(low, g.HeightAt(p));
  return low;
}

// The same for a box of plan size len x wid, long side along `dir`.
double LowestGround(const GroundLayout& g, const V2& c, const V2& dir, double len, double wid) {
  return LowestGround(g, Rect{c, dir, V2(len / 2, wid / 2)});
}

// A car: body plus glass cabin, 4.0-4.8 m long.
void AddCar(std::vector<Prop>& props, const V2& c, const V2& dir, const GroundLayout& g, Rng& rng) {
  const double len = rng.Uniform(3.9, 4.8), wid = rng.Uniform(1.7, 1.85);
  const double z = LowestGround(g, c, dir, len, wid);
  const int colour = kCar0 + rng.Int(0, CarMaterialCount() - 1);
  const uint32_t seed = static_cast<uint32_t>(rng.Next());
  props.push_back(BoxProp(PropKind::kCar, c, dir, len, wid, z + 0.2, 0.75, colour, seed));
  props.push_back(BoxProp(PropKind::kCar, c - 0.05 * len * dir, dir, 0.5 * len, wid - 0.2, z + 0.95,
                          0.5, kGlass, seed + 1));
}

void AddHedge(LotPlan& lot, const Row& r, double s0, double s1, double t0, double t1,
              const GroundLayout& g, Rng& rng) {
  const double h = rng.Uniform(0.9, 1.8);
  const bool along = std::abs(s1 - s0) >= std::abs(t1 - t0);
  const V2 dir = along ? r.along : r.inward;
  const double len = along ? std::abs(s1 - s0) : std::abs(t1 - t0);
  const double wid = along ? std::abs(t1 - t0) : std::abs(s1 - s0);
  if (len < 1) return;
  const V2 c = r.At(0.5 * (s0 + s1), 0.5 * (t0 + t1));
  lot.props.push_back(BoxProp(PropKind::kHedge, c, dir, len, wid, LowestGround(g, c, dir, len, wid),
                              h, kHedge, static_cast<uint32_t>(rng.Next())));
}

Tree RandomTree(const V2& p, const GroundLayout& g, double rmin, double rmax, Rng& rng) {
  Tree t;
  t.crown_radius = rng.Uniform(rmin, rmax);
  t.trunk_height = rng.Uniform(1.5, 4.0);
  t.crown_height = t.crown_radius * rng.Uniform(1.3, 2.2);
  t.base = V3(p.x(), p.y(), g.HeightAt(p));
  t.material = rng.Chance(0.7) ? kFoliage0 : kFoliage1;
  t.seed = static_cast<uint32_t>(rng.Next());
  return t;
}

// Detached house with pitch, wings etc. fitted into at most `lmax` along its
// ridge and `wmax` across.
BuildingSpec HouseSpec(RoofShape shape, double lmax, double wmax, const SceneOptions& o, Rng& rng) {
  SceneOptions so = o;
  so.min_length = std::max(so.min_length, std::min(9.0, lmax));  // family houses, not sheds
  so.max_length = std::max(so.min_length, std::min(so.max_length, lmax));
  BuildingSpec b = RandomSpec(shape, so, rng);
  if (b.length > lmax || b.width > wmax) {
    const double L = std::min(b.length, lmax), W = std::min({b.width, wmax, L});
    const double pitch = std::atan((b.ridge_height - b.eave_height) / (b.width / 2));
    b.length = L;
    b.width = W;
    b.ridge_height = b.eave_height + std::tan(pitch) * W / 2;
    b.wing_width = std::min(b.wing_width, 0.8 * W);
    b.wing_offset = std::clamp(b.wing_offset, -(L / 2 - b.wing_width / 2 - 1.0),
                               L / 2 - b.wing_width / 2 - 1.0);
    b.mansard_inset = std::min(b.mansard_inset, W / 2 - 1.0);
    b.mansard_break_height = std::min(b.mansard_break_height, b.ridge_height - 0.5);
  }
  return b;
}

// Footprint of a spec placed in a row: every rectangle inside the lot.
bool InsideLot(const BuildingSpec& b, const Row& r, double s0, double s1, double t0, double t1) {
  for (const Rect& rect : FootprintRects(b))
    for (const V2& c : rect.Corners()) {
      const V2 d = c - r.origin;
      const double s = d.dot(r.along), t = d.dot(r.inward);
      if (s < s0 - 1e-6 || s > s1 + 1e-6 || t < t0 - 1e-6 || t > t1 + 1e-6) return false;
    }
  return true;
}

class TownBuilder {
 public:
  TownBuilder(Scene& scene, const SceneOptions& o, Rng& rng) : scene_(scene), o_(o), rng_(rng) {}

  int Roof(bool flat) {
    return PushMaterial(
        scene_, PickRoofMaterial(flat, o_, scene_, rng_, static_cast<uint32_t>(rng_.Next())));
  }
  int Wall() {
    return PushMaterial(scene_, WallMaterial(rng_.Int(0, WallMaterialCount() - 1),
                                             static_cast<uint32_t>(rng_.Next())));
  }
  void Push(LotPlan& lot, BuildingSpec b, int roof = -1, int wall = -1) {
    // On a slope the building stands on the lowest ground under it, as a
    // house with its downhill basement wall showing.
    b.ground_z = std::numeric_limits<double>::infinity();
    for (const Rect& rect : FootprintRects(b))
      b.ground_z = std::min(b.ground_z, LowestGround(scene_.ground, rect));
    const bool flat = b.shape == RoofShape::kFlat;
    lot.buildings.push_back({b, roof >= 0 ? roof : Roof(flat), wall >= 0 ? wall : Wall()});
  }
  // Small outbuilding (garage, shed) at (s, t) of the row.
  void Outbuilding(LotPlan& lot, const Row& r, double s, double t, double len, double dep,
                   bool garage) {
    BuildingSpec b;
    const double u = rng_.Uniform();
    b.shape = u < 0.55 ? RoofShape::kFlat : (u < 0.8 ? RoofShape::kGable : RoofShape::kShed);
    b.center = r.At(s, t);
    b.yaw_deg = YawOf(garage ? r.inward : r.along);
    b.length = garage ? dep : len;
    b.width = garage ? len : dep;
    b.eave_height = garage ? rng_.Uniform(2.4, 2.9) : rng_.Uniform(2.0, 2.4);
    b.ridge_height = b.eave_height +
                     (b.shape == RoofShape::kShed ? 0.12 * b.width : std::tan(0.6) * b.width / 2);
    Push(lot, b);
  }

  LotPlan Detached(const Row& r, double s0, double s1) {
    LotPlan lot;
    const double w = s1 - s0, D = r.depth;
    const GroundLayout& ground = scene_.ground;
    lot.centre = r.At(0.5 * (s0 + s1), 0.5 * D);
    const double front = rng_.Uniform(2.5, 5.5), side = rng_.Uniform(1.0, 2.2);
    const bool garage = o_.clutter && rng_.Chance(0.55) && w > 14.5;
    const double garage_w = garage ? 3.6 : 0.0;
    RoofShape shape = PickShape(o_.shape_weights, rng_);
    if (shape == RoofShape::kFlat && rng_.Chance(0.5)) shape = RoofShape::kGable;
    const bool parallel = rng_.Chance(0.6);
    const double avail_s = w - 2 * side - (garage ? garage_w + 0.8 : 0.0);
    const double avail_t = D - front - 6.0;
    BuildingSpec b = parallel ? HouseSpec(shape, avail_s, std::min(avail_t, 13.0), o_, rng_)
                              : HouseSpec(shape, avail_t, std::min(avail_s, 13.0), o_, rng_);
    if (b.length < 5 || b.width < 5) return lot;
    const double along_len = parallel ? b.length : b.width;
    const double in_len = parallel ? b.width : b.length;
    const double sc =
        s0 + side + along_len / 2 + rng_.Uniform(0, std::max(0.0, avail_s - along_len));
    const double tc = front + in_len / 2;
    b.center = r.At(sc, tc);
    b.yaw_deg = YawOf(parallel ? r.along : r.inward);
    if (rng_.Chance(1 - o_.aligned_fraction)) b.yaw_deg += rng_.Uniform(-12, 12);
    if (!Valid(b) || !InsideLot(b, r, s0 + 0.8, s1 - 0.8, 1.0, D - 3.0)) {
      b.shape = RoofShape::kGable;
      b.yaw_deg = YawOf(parallel ? r.along : r.inward);
      if (!Valid(b) || !InsideLot(b, r, s0 + 0.8, s1 - 0.8, 1.0, D - 3.0)) return lot;
    }
    Push(lot, b);
    if (!o_.clutter) return lot;
    // Path to the front door, garden bed along the facade, patio behind.
    lot.regions.push_back(r.Region(sc - 0.6, sc + 0.6, 0, front, kPaving));
    if (rng_.Chance(0.5))
      lot.regions.push_back(
          r.Region(sc - along_len / 2, sc - 1.2, front - 1.1, front - 0.1, kSoil));
    if (rng_.Chance(0.6))
      lot.regions.push_back(r.Region(sc - along_len / 3, sc + along_len / 3, front + in_len,
                                     front + in_len + 3, kPaving));
    if (rng_.Chance(0.5)) {
      const double bs = rng_.Uniform(s0 + 1, s1 - 4), bt = rng_.Uniform(front + in_len + 4, D - 3);
      lot.regions.push_back(
          r.Region(bs, bs + rng_.Uniform(2, 4), bt, bt + rng_.Uniform(1, 2.5), kSoil));
    }
    if (garage) {
      const double gs = s1 - side - garage_w / 2, dep = rng_.Uniform(5.5, 6.5);
      Outbuilding(lot, r, gs, front + 1 + dep / 2, garage_w, dep, true);
      lot.regions.push_back(r.Region(gs - 1.6, gs + 1.6, 0, front + 1, kPaving));
      if (rng_.Chance(0.6)) AddCar(lot.props, r.At(gs, 0.5 + 0.5 * front), r.inward, ground, rng_);
    } else if (rng_.Chance(0.5)) {
      const double len = rng_.Uniform(2.2, 3.2), dep = rng_.Uniform(2.2, 3.2);
      const double ss = s0 + 1.0 + len / 2 + rng_.Uniform(0, w - 2.0 - len);
      const double ts = D - 1.0 - dep / 2;
      if (ts - dep / 2 > front + in_len + 1.0) Outbuilding(lot, r, ss, ts, len, dep, false);
    } else if (rng_.Chance(0.5) && w - along_len - 2 * side > 3) {
      // Car on a gravel/paved drive beside the house.
      const double ds = sc + along_len / 2 + 2.0;
      if (ds + 1.5 < s1) {
        lot.regions.push_back(r.Region(ds - 1.5, ds + 1.5, 0, front + 4, kPaving));
        if (rng_.Chance(0.7)) AddCar(lot.props, r.At(ds, front), r.inward, ground, rng_);
      }
    }
    if (rng_.Chance(0.5)) {  // front hedge with a gap for the path
      AddHedge(lot, r, s0 + 0.3, sc - 1.0, 0.2, 0.9, ground, rng_);
      if (!garage) AddHedge(lot, r, sc + 1.0, s1 - 0.3, 0.2, 0.9, ground, rng_);
    }
    if (rng_.Chance(0.4)) AddHedge(lot, r, s1 - 0.7, s1, front + in_len, D - 0.3, ground, rng_);
    // Garden fences on the side and back boundaries.
    if (rng_.Chance(0.6)) {
      const V2 c = r.At(s0 + 0.05, 0.5 * (front + D));
      lot.props.push_back(BoxProp(PropKind::kHedge, c, r.inward, D - front, 0.08,
                                  LowestGround(ground, c, r.inward, D - front, 0.08),
                                  rng_.Uniform(1.0, 1.8), kBark,
                                  static_cast<uint32_t>(rng_.Next())));
    }
    if (rng_.Chance(0.6)) {
      const V2 c = r.At(0.5 * (s0 + s1), D - 0.05);
      lot.props.push_back(BoxProp(PropKind::kHedge, c, r.along, w, 0.08,
                                  LowestGround(ground, c, r.along, w, 0.08), rng_.Uniform(1.0, 1.8),
                                  kBark, static_cast<uint32_t>(rng_.Next())));
    }
    for (int k = 0; k < 2; ++k)
      if (rng_.Chance(k == 0 ? 0.7 : 0.35))
        lot.trees.push_back(RandomTree(
            r.At(rng_.Uniform(s0 + 2, s1 - 2), rng_.Uniform(front + in_len + 1.5, D - 1.0)), ground,
            1.6, 4.8, rng_));
    // Front-garden shrub or small tree close to the facade (overhangs eaves).
    if (rng_.Chance(0.25))
      lot.trees.push_back(
          RandomTree(r.At(rng_.Uniform(s0 + 1.5, s1 - 1.5), front - 0.5), ground, 1.2, 2.5, rng_));
    return lot;
  }

  // Terraced rows of 3-7 houses sharing party walls.
  std::vector<LotPlan> Terraces(const Row& r) {
    std::vector<LotPlan> lots;
    double s = rng_.Uniform(1, 4);
    while (s < r.length - 18) {
      LotPlan lot;
      const int units = rng_.Int(3, 7);
      const double depth = rng_.Uniform(9.5, 12.5), front = rng_.Uniform(2, 5);
      const double eave = rng_.Uniform(5, 8), pitch = rng_.Uniform(30, 48);
      const bool same_mat = rng_.Chance(0.5);
      const int shared_roof = Roof(false);
      const int shared_wall = Wall();
      double x = s;
      for (int k = 0; k < units; ++k) {
        const double uw = rng_.Uniform(5.5, 8);
        if (x + uw > r.length - 1) break;
        BuildingSpec b;
        const double u = rng_.Uniform();
        b.shape = u < 0.75 ? RoofShape::kGable : (u < 0.9 ? RoofShape::kFlat : RoofShape::kShed);
        b.center = r.At(x + uw / 2, front + depth / 2);
        b.yaw_deg = YawOf(r.along);
        b.length = uw;
        b.width = depth;
        b.eave_height = eave + (rng_.Chance(0.3) ? rng_.Uniform(-1.2, 1.2) : 0.0);
        b.ridge_height = b.eave_height + Tan(pitch) * depth / 2;
        if (b.shape == RoofShape::kShed) b.ridge_height = b.eave_height + Tan(15) * depth;
        const bool flat = b.shape == RoofShape::kFlat;
        Push(lot, b, (same_mat && !flat) ? shared_roof : -1, same_mat ? shared_wall : -1);
        if (o_.clutter) {
          lot.regions.push_back(r.Region(x + uw / 2 - 0.5, x + uw / 2 + 0.5, 0, front, kPaving));
          if (rng_.Chance(0.4))
            lot.regions.push_back(r.Region(x + 0.3, x + uw / 2 - 0.8, 0.4, front - 0.3, kSoil));
          if (rng_.Chance(0.6))
            AddHedge(lot, r, x + uw - 0.2, x + uw + 0.2, front + depth + 0.5, r.depth - 0.5,
                     scene_.ground, rng_);
          if (rng_.Chance(0.5))
            lot.regions.push_back(
                r.Region(x + 0.5, x + uw - 0.5, front + depth, front + depth + 2.5, kPaving));
          if (rng_.Chance(0.3) && r.depth - front - depth > 9)
            Outbuilding(lot, r, x + uw / 2, r.depth - 2.0, std::min(uw - 1.5, 2.6), 2.4, false);
          if (rng_.Chance(0.25))
            lot.trees.push_back(
                RandomTree(r.At(x + uw / 2, rng_.Uniform(front + depth + 3, r.depth - 1)),
                           scene_.ground, 1.5, 3.5, rng_));
        }
        x += uw;
      }
      if (!lot.buildings.empty()) {
        lot.centre = r.At(0.5 * (s + x), 0.5 * r.depth);
        lots.push_back(std::move(lot));
      }
      s = x + rng_.Uniform(3, 6);
    }
    return lots;
  }

  // Apartment bars (3-5 storeys) with parking behind.
  std::vector<LotPlan> Apartments(const Row& r) {
    std::vector<LotPlan> lots;
    double s = rng_.Uniform(2, 5);
    while (s < r.length - 22) {
      LotPlan lot;
      BuildingSpec b;
      const double len = std::min(rng_.Uniform(22, 45), r.length - s - 2);
      const double dep = std::min(rng_.Uniform(10.5, 13.5), r.depth - 10);
      const double front = rng_.Uniform(3, 6);
      const double u = rng_.Uniform();
      b.shape = u < 0.5 ? RoofShape::kFlat : (u < 0.8 ? RoofShape::kGable : RoofShape::kHip);
      b.center = r.At(s + len / 2, front + dep / 2);
      b.yaw_deg = YawOf(r.along);
      b.length = len;
      b.width = dep;
      b.eave_height = rng_.Uniform(9, 15.5);
      b.ridge_height = b.eave_height + Tan(rng_.Uniform(25, 40)) * dep / 2;
      Push(lot, b);
      lot.centre = r.At(s + len / 2, 0.5 * r.depth);
      if (o_.clutter) {
        lot.regions.push_back(r.Region(s + len / 2 - 1, s + len / 2 + 1, 0, front, kPaving));
        // Parking behind the bar: asphalt, painted bays, cars.
        const double p0 = front + dep + 2, p1 = std::min(r.depth - 1.0, p0 + 12.0);
        if (p1 - p0 > 10) {
          lot.regions.push_back(r.Region(s, s + len, p0, p1, kAsphalt));
          for (double bs = s + 0.5; bs + 2.5 < s + len; bs += 2.5) {
            lot.regions.push_back(r.Region(bs - 0.06, bs + 0.06, p1 - 5, p1, kPaint));
            if (rng_.Chance(0.65))
              AddCar(lot.props, r.At(bs + 1.25, p1 - 2.5), r.inward, scene_.ground, rng_);
          }
        }
      }
      lots.push_back(std::move(lot));
      s += len + rng_.Uniform(8, 14);
    }
    return lots;
  }

  // Tall attached town houses on the building line (urban perimeter row).
  std::vector<LotPlan> UrbanRow(const Row& r) {
    std::vector<LotPlan> lots;
    LotPlan lot;
    double x = 0.5;
    const double dep = std::min(rng_.Uniform(11, 14), r.depth - 6);
    while (x < r.length - 9) {
      BuildingSpec b;
      const double uw = std::min(rng_.Uniform(9, 17), r.length - 0.5 - x);
      if (uw < 7) break;
      const double u = rng_.Uniform();
      b.shape = u < 0.45 ? RoofShape::kGable : (u < 0.75 ? RoofShape::kFlat : RoofShape::kMansard);
      if (b.shape == RoofShape::kMansard && uw < dep) b.shape = RoofShape::kGable;
      b.center = r.At(x + uw / 2, 0.3 + dep / 2);
      b.yaw_deg = YawOf(r.along);
      b.length = uw;
      b.width = dep;
      b.eave_height = rng_.Uniform(10, 16);
      b.ridge_height = b.eave_height + Tan(rng_.Uniform(30, 45)) * dep / 2;
      b.mansard_inset = rng_.Uniform(1.0, 1.6);
      b.mansard_break_height = b.eave_height + Tan(rng_.Uniform(60, 72)) * b.mansard_inset;
      b.ridge_height = b.shape == RoofShape::kMansard
                           ? b.mansard_break_height + Tan(15) * (dep - 2 * b.mansard_inset) / 2
                           : b.ridge_height;
      if (!Valid(b)) b.shape = RoofShape::kGable;
      Push(lot, b);
      x += uw;
    }
    if (lot.buildings.empty()) return lots;
    lot.centre = r.At(0.5 * x, 0.5 * r.depth);
    if (o_.clutter) {
      lot.regions.push_back(r.Region(0.5, x, 0.3 + dep, r.depth - 0.5, kPaving));
      // A row of garages at the back of the courtyard.
      for (double g = 2; g + 3 < x && rng_.Chance(0.85); g += 3.1)
        if (r.depth - dep > 14) Outbuilding(lot, r, g + 1.5, r.depth - 3.5, 3.0, 6.0, true);
      if (rng_.Chance(0.7))
        lot.trees.push_back(
            RandomTree(r.At(rng_.Uniform(3, x - 3), dep + 4), scene_.ground, 2.5, 5.0, rng_));
    }
    lots.push_back(std::move(lot));
    return lots;
  }

  // Commercial or industrial hall with a parking lot in front.
  std::vector<LotPlan> Commercial(const Row& r) {
    std::vector<LotPlan> lots;
    double s = rng_.Uniform(2, 4);
    while (s < r.length - 25) {
      LotPlan lot;
      BuildingSpec b;
      const double len = std::min(rng_.Uniform(28, 42), r.length - s - 2);
      const double parking = rng_.Uniform(10, 13);
      const double dep = std::min(rng_.Uniform(16, 26), r.depth - parking - 1.5);
      if (dep < 10) break;
      const double u = rng_.Uniform();
      b.shape = u < 0.6 ? RoofShape::kFlat : (u < 0.8 ? RoofShape::kShed : RoofShape::kGable);
      b.center = r.At(s + len / 2, parking + dep / 2);
      b.yaw_deg = YawOf(r.along);
      b.length = len;
      b.width = dep;
      b.eave_height = rng_.Uniform(5.5, 10);
      b.ridge_height = b.eave_height + Tan(b.shape == RoofShape::kShed ? 6 : 12) *
                                           (b.shape == RoofShape::kShed ? dep : dep / 2);
      Push(lot, b);
      lot.centre = r.At(s + len / 2, 0.5 * r.depth);
      if (o_.clutter) {
        lot.regions.push_back(r.Region(s, s + len, 0, parking, kAsphalt));
        for (double bs = s + 0.5; bs + 2.5 < s + len; bs += 2.5) {
          lot.regions.push_back(r.Region(bs - 0.06, bs + 0.06, 0.5, 5.5, kPaint));
          if (rng_.Chance(0.55))
            AddCar(lot.props, r.At(bs + 1.25, 3.0), r.inward, scene_.ground, rng_);
        }
      }
      lots.push_back(std::move(lot));
      s += len + rng_.Uniform(5, 10);
    }
    return lots;
  }

  std::vector<LotPlan> FillRow(const Row& r, int type_in) {
    int type = type_in;
    if (r.length < 12 || r.depth < 14) return {};
    // Bars with parking and halls need deep lots; shallow rows get houses.
    if ((type == 2 || type == 4) && r.depth < 25) type = rng_.Chance(0.5) ? 0 : 1;
    switch (type) {
      case 1:
        return Terraces(r);
      case 2:
        return Apartments(r);
      case 3:
        return UrbanRow(r);
      case 4:
        return Commercial(r);
      default: {
        std::vector<LotPlan> lots;
        double s = 0.3;
        while (r.length - s >= 11) {
          double w = rng_.Uniform(11.5, 17);
          if (r.length - s - w < 11) w = r.length - s - 0.3;
          if (w > 24) w = 18;
          lots.push_back(Detached(r, s, s + w));
          s += w;
        }
        return lots;
      }
    }
  }

 private:
  Scene& scene_;
  const SceneOptions& o_;
  Rng& rng_;
};

// Chimneys, solar panels, roof windows and roof-top boxes on one building's
// roof planes. They stand on (or poke through) a plane without changing it.
void AddRoofObjects(Scene& scene, int bi, Rng& rng) {
  const Building& b = scene.city.buildings[bi];
  for (const Surface& s : b.surfaces) {
    if (s.type != SurfaceType::kRoof) continue;
    for (const Polygon3& poly : s.polygons) {
      const V3 n = poly.Normal();
      if (n.isZero() || n.z() < 0.3) continue;
      // Plane frame: u horizontal, v down the slope (flat: any).
      V3 ua = std::abs(n.z()) < 0.999 ? V3(n.cross(V3::UnitZ()).normalized()) : V3::UnitX();
      V3 va = n.cross(ua);
      if (va.z() > 0) va = -va;
      const V3 o = poly.exterior[0];
      std::vector<V2> ring;
      for (const V3& p : poly.exterior) ring.push_back(V2((p - o).dot(ua), (p - o).dot(va)));
      auto inside = [&](const V2& q, double margin) {
        bool in = false;
        for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
          const V2 &a = ring[i], &c = ring[j];
          if ((a.y() > q.y()) != (c.y() > q.y()) &&
              q.x() < (c.x() - a.x()) * (q.y() - a.y()) / (c.y() - a.y()) + a.x())
            in = !in;
          // Distance to the edge for the margin.
          const V2 e = c - a;
          const double t = std::clamp((q - a).dot(e) / std::max(1e-12, e.squaredNorm()), 0.0, 1.0);
          if ((a + t * e - q).norm() < margin) return false;
        }
        return in;
      };
      V2 lo = ring[0], hi = ring[0];
      for (const V2& q : ring) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
      auto place = [&](double hu, double hv, double margin, V2* c) {
        for (int k = 0; k < 12; ++k) {
          const V2 q(rng.Uniform(lo.x() + hu, hi.x() - hu), rng.Uniform(lo.y() + hv, hi.y() - hv));
          if (hi.x() - lo.x() < 2 * hu || hi.y() - lo.y() < 2 * hv) return false;
          bool ok = true;
          for (int cu : {-1, 1})
            for (int cv : {-1, 1}) ok = ok && inside(q + V2(cu * hu, cv * hv), margin);
          if (ok) {
            *c = q;
            return true;
          }
        }
        return false;
      };
      const bool flat = n.z() > 0.99;
      const uint32_t seed = static_cast<uint32_t>(rng.Next());
      V2 c;
      if (!flat && rng.Chance(0.22)) {  // photovoltaic array parallel to the plane
        const int cols = rng.Int(3, 8), rows = rng.Int(1, 3);
        const double hu = 0.5 * cols * 1.0, hv = 0.5 * rows * 1.7;
        if (place(hu, hv, 0.5, &c)) {
          Prop p;
          p.kind = PropKind::kSolarPanel;
          p.axes.col(0) = ua;
          p.axes.col(1) = va;
          p.axes.col(2) = n;
          p.half = V3(hu, hv, 0.03);
          p.center = o + c.x() * ua + c.y() * va + 0.14 * n;
          p.material = kSolar;
          p.seed = seed;
          scene.props.push_back(p);
          continue;
        }
      }
      if (!flat && rng.Chance(0.2) && place(0.4, 0.6, 0.4, &c)) {  // roof window
        Prop p;
        p.kind = PropKind::kSkylight;
        p.axes.col(0) = ua;
        p.axes.col(1) = va;
        p.axes.col(2) = n;
        p.half = V3(0.4, 0.6, 0.06);
        p.center = o + c.x() * ua + c.y() * va + 0.02 * n;
        p.material = kGlass;
        p.seed = seed;
        scene.props.push_back(p);
      }
      if (!flat && rng.Chance(0.25) && place(0.35, 0.35, 0.3, &c)) {  // chimney
        const V3 foot = o + c.x() * ua + c.y() * va;
        double top = foot.z();
        for (const V3& q : poly.exterior) top = std::max(top, q.z());
        top += rng.Uniform(0.4, 1.0);
        const double bottom = foot.z() - 1.0;
        const V2 dir(ua.x(), ua.y());
        Prop p = BoxProp(PropKind::kChimney, foot.head<2>(), dir.normalized(),
                         rng.Uniform(0.45, 0.8), rng.Uniform(0.45, 0.8), bottom, top - bottom,
                         rng.Chance(0.5) ? kChimney0 : kChimney1, seed);
        scene.props.push_back(p);
      }
      if (flat) {
        const int boxes = rng.Int(0, 3);
        for (int k = 0; k < boxes; ++k) {
          const double hu = rng.Uniform(0.5, 2.0), hv = rng.Uniform(0.5, 1.5);
          if (!place(hu, hv, 0.8, &c)) break;
          const V3 foot = o + c.x() * ua + c.y() * va;
          scene.props.push_back(
              BoxProp(PropKind::kRoofBox, foot.head<2>(), V2(ua.x(), ua.y()).normalized(), 2 * hu,
                      2 * hv, foot.z() - 0.2, rng.Uniform(0.6, 2.2), kRoofMetal, seed + k));
        }
        const int lights = rng.Chance(0.4) ? rng.Int(2, 6) : 0;
        for (int k = 0; k < lights; ++k) {
          if (!place(0.6, 0.6, 0.8, &c)) break;
          const V3 foot = o + c.x() * ua + c.y() * va;
          scene.props.push_back(BoxProp(PropKind::kSkylight, foot.head<2>(),
                                        V2(ua.x(), ua.y()).normalized(), 1.2, 1.2, foot.z() - 0.2,
                                        0.45, kGlass, seed + 10 + k));
        }
      }
    }
  }
}

}  // namespace

const char* PropKindName(PropKind k) {
  switch (k) {
    case PropKind::kCar:
      return "car";
    case PropKind::kHedge:
      return "hedge";
    case PropKind::kChimney:
      return "chimney";
    case PropKind::kSolarPanel:
      return "solar_panel";
    case PropKind::kSkylight:
      return "skylight";
    case PropKind::kRoofBox:
      return "roof_box";
  }
  return "?";
}

Scene GenerateScene(const SceneOptions& o, uint64_t seed) {
  if (!(o.extent_x > 10 && o.extent_y > 10)) throw Error("simulate: scene extent must be > 10 m");
  if (o.min_length < 3 || o.max_length < o.min_length)
    throw Error("simulate: building length range must satisfy 3 <= min <= max");
  if (!(o.street_spacing > 20 && o.block_length > 20))
    throw Error("simulate: street_spacing and block_length must be > 20 m");
  if (!o.ground_slope.allFinite() || o.ground_slope.norm() > 0.5)
    throw Error("simulate: the ground slope must be at most 50 %");
  Scene scene;
  AddBaseMaterials(scene, seed);
  scene.ground.z = o.ground_z;
  scene.ground.slope = o.ground_slope;
  const double ex = o.extent_x / 2, ey = o.extent_y / 2;
  if (!std::isfinite(o.terrain_relief_m) || o.terrain_relief_m < 0 || o.terrain_relief_m > 50)
    throw Error("simulate: the terrain relief must be 0..50 m");
  if (o.terrain_relief_m > 0) {
    // A stream of its own, so that the town on flat ground stays the same
    // for a seed. About one hill per 100 x 100 m, over the area and a
    // margin that the images see past it; amplitudes of both signs.
    Rng hill_rng(Hash(seed, 0x4177));
    const double mx = ex + 100, my = ey + 100;
    const int n = std::max(3, static_cast<int>(std::lround(4 * mx * my / 1e4)));
    for (int i = 0; i < n; ++i) {
      Hill h;
      h.centre = V2(hill_rng.Uniform(-mx, mx), hill_rng.Uniform(-my, my));
      h.sigma = hill_rng.Uniform(35, 90);
      h.amplitude = hill_rng.Uniform(-0.5, 0.5) * o.terrain_relief_m;
      scene.ground.hills.push_back(h);
    }
  }
  scene.area << -ex, -ey, ex, ey;
  Rng rng(Hash(seed, 0x5ce7e));

  // Street grid over the area and beyond (every image sees streets continue;
  // blocks are filled a block beyond the area so that image borders are built up too).
  const double half_street = o.street_width / 2, half_total = half_street + o.sidewalk_width;
  const double reach = std::max(ex, ey) + 400;
  const double fill_x = ex + o.block_length, fill_y = ey + o.street_spacing;
  std::vector<double> xs, ys;  // street axes: x = const (north-south), y = const (east-west)
  for (double x = -fill_x + o.block_length * rng.Uniform(0.2, 0.8); x < fill_x; x += o.block_length)
    xs.push_back(x);
  for (double y = -fill_y + o.street_spacing * rng.Uniform(0.2, 0.8); y < fill_y;
       y += o.street_spacing * rng.Uniform(0.8, 1.2))
    ys.push_back(y);
  auto near_cross = [&](double t, const std::vector<double>& cross, double pad) {
    for (double c : cross)
      if (std::abs(t - c) < half_total + pad) return true;
    return false;
  };
  std::vector<GroundRegion> streets;
  auto street = [&](bool along_x, double pos) {
    const V2 ax = along_x ? V2::UnitX() : V2::UnitY();
    const V2 n = along_x ? V2::UnitY() : V2::UnitX();
    for (int side : {-1, 1})
      streets.push_back({pos * n + side * (half_street + o.sidewalk_width / 2) * n, ax,
                         V2(reach, o.sidewalk_width / 2), kPaving});
  };
  for (double y : ys) street(true, y);
  for (double x : xs) street(false, x);
  for (double y : ys) streets.push_back({V2(0, y), V2::UnitX(), V2(reach, half_street), kAsphalt});
  for (double x : xs) streets.push_back({V2(x, 0), V2::UnitY(), V2(reach, half_street), kAsphalt});
  std::vector<GroundRegion> paint;
  std::vector<Prop> street_props;
  std::vector<Tree> street_trees;
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
    if (!o.clutter) return;
    const double lim = along_x ? fill_x : fill_y;
    // Manhole covers on the centre line, drains at the kerb, parked cars,
    // trees in the sidewalk.
    for (double t = -lim + rng.Uniform(0, 30); t < lim; t += rng.Uniform(25, 45))
      if (!near_cross(t, cross, 1.5))
        paint.push_back({t * ax + (pos + rng.Uniform(-1.2, 1.2)) * n, ax, V2(0.33, 0.33), kIron});
    for (int side : {-1, 1}) {
      for (double t = -lim + rng.Uniform(0, 20); t < lim; t += rng.Uniform(18, 30))
        if (!near_cross(t, cross, 1.0))
          paint.push_back(
              {t * ax + (pos + side * (half_street - 0.25)) * n, ax, V2(0.25, 0.18), kIron});
      for (double t = -lim; t < lim; t += 6.0)
        if (!near_cross(t, cross, 6.0) && rng.Chance(0.22))
          AddCar(street_props, t * ax + (pos + side * (half_street - 1.25)) * n,
                 rng.Chance(0.5) ? V2(ax) : V2(-ax), scene.ground, rng);
      for (double t = -lim; t < lim; t += 11.0)
        if (!near_cross(t, cross, 4.0) && rng.Chance(0.18))
          street_trees.push_back(RandomTree(t * ax + (pos + side * (half_street + 1.0)) * n,
                                            scene.ground, 2.0, 4.5, rng));
    }
    // A few cars driving.
    for (double t = -lim; t < lim; t += 10.0)
      if (!near_cross(t, cross, 6.0) && rng.Chance(0.03))
        AddCar(street_props, t * ax + (pos + (rng.Chance(0.5) ? 1.7 : -1.7)) * n,
               rng.Chance(0.5) ? V2(ax) : V2(-ax), scene.ground, rng);
  };
  for (double y : ys) markings(true, y, xs);
  for (double x : xs) markings(false, x, ys);

  // Blocks between the streets; each has two rows of lots back to back,
  // facing the streets along x. Block type per block, sometimes mixed.
  std::vector<double> bx = {-fill_x}, by = {-fill_y};
  for (double x : xs) bx.push_back(x - half_total), bx.push_back(x + half_total);
  for (double y : ys) by.push_back(y - half_total), by.push_back(y + half_total);
  bx.push_back(fill_x);
  by.push_back(fill_y);
  TownBuilder town(scene, o, rng);
  std::vector<LotPlan> plans;
  const double total_w = std::accumulate(o.block_weights.begin(), o.block_weights.end(), 0.0);
  auto pick_type = [&]() {
    double x = rng.Uniform() * total_w;
    for (int i = 0; i < 5; ++i) {
      if (x < o.block_weights[i]) return i;
      x -= o.block_weights[i];
    }
    return 0;
  };
  for (size_t i = 0; i + 1 < bx.size(); i += 2)
    for (size_t j = 0; j + 1 < by.size(); j += 2) {
      const double x0 = bx[i], x1 = bx[i + 1], y0 = by[j], y1 = by[j + 1];
      if (x1 - x0 < 12 || y1 - y0 < 20) continue;
      const int type = pick_type();
      const double mid = 0.5 * (y0 + y1);
      const Row south{V2(x0, y0), V2::UnitX(), V2::UnitY(), x1 - x0, mid - y0};
      const Row north{V2(x1, y1), -V2::UnitX(), -V2::UnitY(), x1 - x0, y1 - mid};
      for (const Row& r : {south, north}) {
        auto lots = town.FillRow(r, rng.Chance(0.8) ? type : pick_type());
        for (auto& l : lots) plans.push_back(std::move(l));
      }
    }
  // Fill from the centre outwards up to the building bound.
  std::vector<size_t> order(plans.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return plans[a].centre.norm() < plans[b].centre.norm();
  });
  int n = 0;
  std::vector<Tree> tree_candidates;
  for (size_t k : order) {
    LotPlan& lot = plans[k];
    if (lot.buildings.empty()) continue;
    // Buildings only where the cameras see them (the area): those across
    // the border are dropped (a terrace loses its end houses), their lots
    // stay gardens.
    std::vector<LotPlan::Item> keep;
    for (const auto& item : lot.buildings) {
      bool inside = true;
      std::vector<V3> corners;
      const double top =
          item.spec.ground_z + std::max(item.spec.eave_height, item.spec.ridge_height);
      for (const Rect& rect : FootprintRects(item.spec))
        for (const V2& c : rect.Corners()) {
          inside = inside && std::abs(c.x()) <= ex && std::abs(c.y()) <= ey;
          corners.push_back(V3(c.x(), c.y(), item.spec.ground_z));
          corners.push_back(V3(c.x(), c.y(), top));
        }
      if (inside && !o.visibility_views.empty()) {
        int seen = 0;
        for (const auto& [cam, pose] : o.visibility_views) {
          bool all = true;
          for (const V3& X : corners) {
            const auto q = Project(cam, pose, X);
            all = all && q && q->x() >= 2 && q->y() >= 2 && q->x() <= cam.width - 2 &&
                  q->y() <= cam.height - 2;
          }
          seen += all;
        }
        inside = seen >= o.min_views;
      }
      if (inside) keep.push_back(item);
    }
    if (keep.empty() || n + static_cast<int>(keep.size()) > o.building_count) continue;
    for (auto& item : keep) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "BLDG_%04d", ++n);
      item.spec.id = buf;
      AddBuilding(scene, item.spec, item.roof, item.wall, o, rng);
      // Own generator per building: the town is the same with or without
      // roof objects.
      Rng roof_rng(Hash(seed, 0x200f, static_cast<uint64_t>(n)));
      if (o.roof_objects)
        AddRoofObjects(scene, static_cast<int>(scene.city.buildings.size()) - 1, roof_rng);
    }
    scene.ground.regions.insert(scene.ground.regions.end(), lot.regions.begin(), lot.regions.end());
    scene.props.insert(scene.props.end(), lot.props.begin(), lot.props.end());
    tree_candidates.insert(tree_candidates.end(), lot.trees.begin(), lot.trees.end());
  }
  // Ground regions: lots first (lowest priority), then streets and paint.
  scene.ground.regions.insert(scene.ground.regions.end(), streets.begin(), streets.end());
  scene.ground.regions.insert(scene.ground.regions.end(), paint.begin(), paint.end());
  if (!scene.city.buildings.empty())
    scene.props.insert(scene.props.end(), street_props.begin(), street_props.end());
  // Trees: garden and street trees in a seeded order up to tree_count;
  // garden trees may overhang roofs, which is wanted (occluders).
  if (!scene.city.buildings.empty())
    tree_candidates.insert(tree_candidates.end(), street_trees.begin(), street_trees.end());
  for (size_t i = tree_candidates.size(); i > 1; --i)
    std::swap(tree_candidates[i - 1], tree_candidates[rng.Int(0, static_cast<int>(i) - 1)]);
  for (const Tree& t : tree_candidates) {
    if (static_cast<int>(scene.trees.size()) >= o.tree_count) break;
    bool ok = true;
    for (const Tree& other : scene.trees)
      ok = ok && (other.base.head<2>() - t.base.head<2>()).norm() >
                     0.8 * (other.crown_radius + t.crown_radius);
    if (ok) scene.trees.push_back(t);
  }
  return scene;
}
Scene SceneFromCityModel(const CityModel& city, const SceneOptions& o, uint64_t seed) {
  if (city.buildings.empty()) throw Error("simulate: the city model has no buildings");
  if (!o.ground_slope.isZero() || o.terrain_relief_m > 0)
    throw Error("simulate: a ground slope or relief needs a generated town, not a city model");
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

namespace {

// A plan edge laid on the terrain: one piece on a plane, pieces of at most
// 2 m over hills (their sigma is 35 m or more, so a 2 m chord stays within
// a centimetre of the ground even at 50 m of relief, 3 mm at 12 m).
std::vector<TrueEdge> TerrainPieces(const GroundLayout& g, const TrueEdge& e) {
  const V2 a = e.a.head<2>(), b = e.b.head<2>();
  const int n = g.Planar() ? 1 : std::max(1, static_cast<int>(std::ceil((b - a).norm() / 2.0)));
  std::vector<TrueEdge> out;
  for (int i = 0; i < n; ++i) {
    TrueEdge piece = e;
    const V2 p0 = a + (b - a) * (double(i) / n), p1 = a + (b - a) * (double(i + 1) / n);
    piece.a = V3(p0.x(), p0.y(), g.HeightAt(p0));
    piece.b = V3(p1.x(), p1.y(), g.HeightAt(p1));
    out.push_back(piece);
  }
  return out;
}

}  // namespace

SceneTruth TruthOf(const Scene& scene) {
  SceneTruth t;
  t.city = scene.city;
  t.edges = ExtractBuildingEdges(scene.city);
  if (!scene.ground.slope.isZero() || !scene.ground.Planar()) {
    // What the images show of a wall's foot is where it enters the terrain,
    // above the building's base everywhere but at its lowest corner. On a
    // plane the cut of a straight edge is straight; over hills it bends, so
    // it is followed in pieces (TerrainPieces).
    std::vector<TrueEdge> cut;
    for (TrueEdge& e : t.edges) {
      if (e.kind == EdgeKind::kWallCorner) {
        for (V3* p : {&e.a, &e.b}) p->z() = std::max(p->z(), scene.ground.HeightAt(p->head<2>()));
      } else if (e.kind == EdgeKind::kFootprint) {
        for (TrueEdge& piece : TerrainPieces(scene.ground, e)) cut.push_back(piece);
        continue;
      }
      cut.push_back(e);
    }
    t.edges = std::move(cut);
  }
  t.roof_planes = ExtractRoofPlanes(scene.city);
  // Ground markings: region borders where the material really changes,
  // found by walking each border in 5 cm steps and comparing both sides.
  const double margin = 80, step = 0.05, probe = 0.02;
  const Box keep{scene.area[0] - margin, scene.area[1] - margin, scene.area[2] + margin,
                 scene.area[3] + margin};
  GroundIndex index;
  index.Build(scene.ground, scene.area);
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
        e.a = V3(p0.x(), p0.y(), 0);
        e.b = V3(p1.x(), p1.y(), 0);
        e.kind = EdgeKind::kGroundMarking;
        for (TrueEdge& piece : TerrainPieces(scene.ground, e)) t.edges.push_back(piece);
      };
      const int steps = static_cast<int>(std::ceil(len / step));
      for (int i = 0; i <= steps; ++i) {
        const double s = std::min(len, i * step);
        const V2 p = a + s * d;
        bool differs = false;
        if (keep.Contains(p)) {
          const int in = index.MaterialAt(p - probe * out);
          const int ou = index.MaterialAt(p + probe * out);
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
  for (TrueEdge& e : PropEdges(scene, t.roof_planes)) t.edges.push_back(e);
  return t;
}

}  // namespace sim
}  // namespace roofsweep
