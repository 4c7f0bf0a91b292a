#include "algorithms/simulate/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>

#include "algorithms/core/error.h"
#include "algorithms/simulate/bvh.h"
#include "algorithms/simulate/ground_index.h"
#include "algorithms/simulate/noise.h"
#include "algorithms/simulate/random.h"
#include "algorithms/simulate/triangulate.h"

namespace roofsweep {
namespace sim {
namespace {

using V3 = Eigen::Vector3d;
using V3f = Eigen::Vector3f;
constexpr double kInf = std::numeric_limits<double>::infinity();

// 32 points spread evenly over the unit disc (Vogel's sunflower spiral),
// for sampling the sun disc without trigonometry per sample.
const std::vector<Eigen::Vector2d> kSunDisc = [] {
  std::vector<Eigen::Vector2d> p;
  const int n = 32;
  for (int i = 0; i < n; ++i) {
    const double r = std::sqrt((i + 0.5) / n), a = i * 2.399963229728653;
    p.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return p;
}();

struct CrownShape {
  V3 centre;
  V3 radii;
};

// Pixel to normalised camera coordinates; with distortion through a grid of
// exact undistortions every kStep pixels, interpolated bilinearly (the
// error is < 1e-3 px for real lenses and saves a Newton solve per sample).
class RayMap {
 public:
  RayMap(const Camera& cam) : cam_(cam) {
    if (!cam.HasDistortion()) return;
    gw_ = cam.width / kStep + 2;
    gh_ = cam.height / kStep + 2;
    grid_.resize(static_cast<size_t>(gw_) * gh_);
    tbb::parallel_for(0, gh_, [&](int j) {
      for (int i = 0; i < gw_; ++i)
        grid_[static_cast<size_t>(j) * gw_ + i] =
            cam.PixelToNormalized(Eigen::Vector2d(i * kStep, j * kStep));
    });
  }
  Eigen::Vector2d operator()(double x, double y) const {
    if (grid_.empty()) {
      const double yn = (y - cam_.cy) / cam_.fy;
      return {(x - cam_.cx - cam_.skew * yn) / cam_.fx, yn};
    }
    const double gx = std::clamp(x / kStep, 0.0, gw_ - 1.000001),
                 gy = std::clamp(y / kStep, 0.0, gh_ - 1.000001);
    const int i = static_cast<int>(gx), j = static_cast<int>(gy);
    const double fx = gx - i, fy = gy - j;
    const auto& g = grid_;
    const size_t k = static_cast<size_t>(j) * gw_ + i;
    return (1 - fy) * ((1 - fx) * g[k] + fx * g[k + 1]) +
           fy * ((1 - fx) * g[k + gw_] + fx * g[k + gw_ + 1]);
  }

 private:
  static constexpr int kStep = 4;
  const Camera& cam_;
  int gw_ = 0, gh_ = 0;
  std::vector<Eigen::Vector2d> grid_;
};

struct Hit {
  int face = -1;
  double t = kInf;
  V3 p;
};

}  // namespace

struct Renderer::Impl {
  Scene scene;
  RenderOptions opt;
  Bvh bvh;
  std::vector<FaceInfo> faces;
  std::vector<CrownShape> crowns;
  GroundIndex ground;
  V3 sun, sun_u, sun_v;   // direction to the sun and two axes across it
  double sun_radius = 0;  // rad
  double top_z = 0;       // highest vertex of the scene
  // Sums of the hills' positive and negative amplitudes: the terrain lies
  // within [plane - hill_down, plane + hill_up].
  double hill_up = 0, hill_down = 0;
  uint32_t ground_seed = 0;

  void AddPolygonFace(FaceInfo f, const Polygon3& poly, std::vector<Bvh::Triangle>& tris) {
    const auto& r = poly.exterior;
    f.normal = poly.Normal();
    if (f.normal.isZero()) return;
    double zmin = kInf;
    for (const V3& p : r)
      if (p.z() < zmin) zmin = p.z(), f.origin = p;
    f.d = -f.normal.dot(f.origin);
    const V3 up = V3::UnitZ();
    if (std::abs(f.normal.z()) < 0.999) {
      f.u_axis = f.normal.cross(up).normalized();
      f.v_axis = f.u_axis.cross(f.normal);  // down the slope
      if (f.v_axis.z() > 0) f.v_axis = -f.v_axis;
    } else {
      f.u_axis = (r[1] - r[0]).normalized();
      f.v_axis = f.normal.cross(f.u_axis);
    }
    const int id = static_cast<int>(faces.size());
    faces.push_back(f);
    for (const auto& t : TriangulatePolygon(r))
      tris.push_back({r[t[0]].cast<float>(), r[t[1]].cast<float>(), r[t[2]].cast<float>(), id});
  }

  void AddTree(int ti, std::vector<Bvh::Triangle>& tris) {
    const Tree& tree = scene.trees[ti];
    CrownShape cs;
    cs.centre = tree.base + V3(0, 0, tree.trunk_height + tree.crown_height / 2);
    cs.radii = V3(tree.crown_radius, tree.crown_radius, tree.crown_height / 2);
    crowns.push_back(cs);
    FaceInfo crown;
    crown.kind = FaceKind::kTreeCrown;
    crown.tree = ti;
    crown.material = tree.material;
    crown.seed = tree.seed;
    const int crown_id = static_cast<int>(faces.size());
    faces.push_back(crown);
    // Icosphere, subdivided twice (320 triangles; the shading normal is the
    // smooth ellipsoid's), with lumpy radii: an irregular crown.
    const double g = (1 + std::sqrt(5.0)) / 2;
    std::vector<V3> v = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    std::vector<std::array<int, 3>> f = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (V3& p : v) p.normalize();
    for (int level = 0; level < 2; ++level) {
      std::vector<std::array<int, 3>> nf;
      std::map<std::pair<int, int>, int> mid;
      auto midpoint = [&](int a, int b) {
        auto key = std::minmax(a, b);
        auto it = mid.find(key);
        if (it != mid.end()) return it->second;
        v.push_back((v[a] + v[b]).normalized());
        return mid[key] = static_cast<int>(v.size()) - 1;
      };
      for (const auto& t : f) {
        const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
        nf.push_back({t[0], ab, ca});
        nf.push_back({t[1], bc, ab});
        nf.push_back({t[2], ca, bc});
        nf.push_back({ab, bc, ca});
      }
      f = nf;
    }
    std::vector<V3> w(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
      const double lump =
          1 + 0.18 * GradientNoise(static_cast<float>(2 * v[i].x() + 3 * v[i].z()),
                                   static_cast<float>(2 * v[i].y() - v[i].z()), tree.seed);
      w[i] = cs.centre + lump * v[i].cwiseProduct(cs.radii);
    }
    for (const auto& t : f)
      tris.push_back(
          {w[t[0]].cast<float>(), w[t[1]].cast<float>(), w[t[2]].cast<float>(), crown_id});
    // Trunk: hexagonal prism up into the crown.
    FaceInfo trunk;
    trunk.kind = FaceKind::kTreeTrunk;
    trunk.tree = ti;
    trunk.material = 6;  // bark slot of the scene generators
    for (size_t m = 0; m < scene.materials.size(); ++m)
      if (scene.materials[m].pattern == Pattern::kBark) {
        trunk.material = static_cast<int>(m);
        break;
      }
    trunk.seed = tree.seed + 1;
    const int trunk_id = static_cast<int>(faces.size());
    faces.push_back(trunk);
    const double rt = 0.06 * tree.crown_radius + 0.1;
    const double top = tree.trunk_height + 0.3 * tree.crown_height;
    for (int k = 0; k < 6; ++k) {
      const double a0 = k * M_PI / 3, a1 = (k + 1) * M_PI / 3;
      const V3 p0 = tree.base + V3(rt * std::cos(a0), rt * std::sin(a0), 0);
      const V3 p1 = tree.base + V3(rt * std::cos(a1), rt * std::sin(a1), 0);
      const V3 h(0, 0, top);
      tris.push_back({p0.cast<float>(), p1.cast<float>(), (p1 + h).cast<float>(), trunk_id});
      tris.push_back({p0.cast<float>(), (p1 + h).cast<float>(), (p0 + h).cast<float>(), trunk_id});
    }
  }

  // Six planar faces of an oriented box.
  void AddProp(int pi, std::vector<Bvh::Triangle>& tris) {
    const Prop& p = scene.props[pi];
    if (p.material < 0 || p.material >= static_cast<int>(scene.materials.size()))
      throw Error("simulate: prop material index out of range");
    for (int axis = 0; axis < 3; ++axis)
      for (int sign : {-1, 1}) {
        const V3 n = sign * p.axes.col(axis);
        const V3 a = p.axes.col((axis + 1) % 3) * p.half[(axis + 1) % 3];
        const V3 b = p.axes.col((axis + 2) % 3) * p.half[(axis + 2) % 3];
        const V3 c = p.center + p.half[axis] * n;
        Polygon3 poly;
        // Counter-clockwise seen from outside (a x b points along +axis).
        if (sign > 0)
          poly.exterior = {c - a - b, c + a - b, c + a + b, c - a + b};
        else
          poly.exterior = {c - a - b, c - a + b, c + a + b, c + a - b};
        FaceInfo f;
        f.kind = FaceKind::kProp;
        f.prop = pi;
        f.material = p.material;
        f.seed = p.seed + static_cast<uint32_t>(axis * 2 + (sign > 0));
        AddPolygonFace(f, poly, tris);
        if (!faces.empty() && faces.back().prop == pi && axis == 2 &&
            p.kind == PropKind::kSolarPanel) {
          // Texture frame of the panel face along the panel's own axes.
          faces.back().u_axis = p.axes.col(0);
          faces.back().v_axis = p.axes.col(1);
          faces.back().origin = p.center - p.half[0] * p.axes.col(0) - p.half[1] * p.axes.col(1);
        }
      }
  }

  void Build() {
    if (opt.supersampling < 1 || opt.supersampling > 8)
      throw Error("simulate: supersampling must be in 1..8");
    if (scene.surface_materials.size() != scene.city.buildings.size())
      throw Error("simulate: scene has no materials for some buildings");
    const double az = opt.sun_azimuth_deg * M_PI / 180, el = opt.sun_elevation_deg * M_PI / 180;
    sun = V3(std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el));
    sun_u = sun.cross(V3::UnitZ()).normalized();
    sun_v = sun.cross(sun_u);
    sun_radius = std::max(0.0, opt.sun_radius_deg) * M_PI / 180;
    FaceInfo terrain;
    terrain.kind = FaceKind::kTerrain;
    terrain.normal = V3::UnitZ();
    terrain.d = -scene.ground.z;
    if (!scene.ground.slope.isZero()) {
      terrain.normal = V3(-scene.ground.slope.x(), -scene.ground.slope.y(), 1).normalized();
      terrain.d = -terrain.normal.z() * scene.ground.z;
    }
    for (const Hill& k : scene.ground.hills)
      (k.amplitude > 0 ? hill_up : hill_down) += std::abs(k.amplitude);
    terrain.material = scene.ground.base_material;
    faces.push_back(terrain);
    ground_seed = static_cast<uint32_t>(scene.materials.empty() ? 1 : scene.materials[0].seed);
    std::vector<Bvh::Triangle> tris;
    for (size_t bi = 0; bi < scene.city.buildings.size(); ++bi) {
      const Building& b = scene.city.buildings[bi];
      if (scene.surface_materials[bi].size() != b.surfaces.size())
        throw Error("simulate: building " + b.id + ": material count differs from surface count");
      for (size_t si = 0; si < b.surfaces.size(); ++si) {
        const Surface& s = b.surfaces[si];
        // Ground surfaces lie on the terrain and are never seen.
        if (s.type == SurfaceType::kGround) continue;
        for (size_t pi = 0; pi < s.polygons.size(); ++pi) {
          FaceInfo f;
          f.kind = s.type == SurfaceType::kRoof
                       ? FaceKind::kRoof
                       : (s.type == SurfaceType::kWall ? FaceKind::kWall : FaceKind::kClosure);
          f.building = static_cast<int>(bi);
          f.surface = static_cast<int>(si);
          f.polygon = static_cast<int>(pi);
          f.material = scene.surface_materials[bi][si];
          if (f.material < 0 || f.material >= static_cast<int>(scene.materials.size()))
            throw Error("simulate: building " + b.id + ": material index out of range");
          f.seed = static_cast<uint32_t>(Hash(scene.materials[f.material].seed, bi));
          AddPolygonFace(f, s.polygons[pi], tris);
        }
      }
    }
    for (size_t ti = 0; ti < scene.trees.size(); ++ti) AddTree(static_cast<int>(ti), tris);
    for (size_t pi = 0; pi < scene.props.size(); ++pi) AddProp(static_cast<int>(pi), tris);
    top_z = scene.ground.z;
    for (const Bvh::Triangle& t : tris)
      top_z = std::max({top_z, double(t.a.z()), double(t.b.z()), double(t.c.z())});
    bvh.Build(std::move(tris));
    ground.Build(scene.ground, scene.area);
  }

  // Where a ray meets the terrain (kInf: it does not). On a plane exactly;
  // over hills by Newton's method on the ray's height above the ground,
  // started where it meets the plane under the hills and safeguarded by a
  // march in steps of 0.25 m of height. Rays going up never meet it: the
  // sun's rays from the ground cast no shadows of hills (nor do they on the
  // renderer's plane).
  double TerrainHit(const V3& o, const V3& d) const {
    const FaceInfo& terrain = faces[0];
    const double den = terrain.normal.dot(d);
    if (!(den < 0)) return kInf;
    const double t_plane = -(terrain.normal.dot(o) + terrain.d) / den;
    const GroundLayout& g = scene.ground;
    if (g.Planar()) return t_plane;
    auto above = [&](double t) {
      const V3 p = o + t * d;
      return p.z() - g.HeightAt(p.head<2>());
    };
    // The plane raised and lowered by the hills' extremes brackets the hit.
    const double k = terrain.normal.z() / -den;  // ray length per metre of plane height
    const double t_hi = std::max(0.0, t_plane - k * hill_up);
    const double t_lo = t_plane + k * hill_down;
    double t = t_plane;
    for (int i = 0; i < 12; ++i) {
      const V3 p = o + t * d;
      const double f = p.z() - g.HeightAt(p.head<2>());
      if (std::abs(f) < 1e-5) {
        if (t >= t_hi && t <= t_lo) return t;
        break;
      }
      const double df = d.z() - g.GradientAt(p.head<2>()).dot(d.head<2>());
      if (!(df < 0)) break;
      t -= f / df;
    }
    // Grazing rays: the first sign change from the top of the bracket.
    const double dt = 0.25 / std::max(1e-3, -d.z());
    double t0 = t_hi;
    if (above(t0) <= 0) return t0;
    for (double t1 = t_hi + dt;; t1 += dt) {
      t1 = std::min(t1, t_lo);
      const double f1 = above(t1);
      if (f1 <= 0) {
        for (int i = 0; i < 40; ++i) {
          const double tm = 0.5 * (t0 + t1);
          (above(tm) > 0 ? t0 : t1) = tm;
        }
        return 0.5 * (t0 + t1);
      }
      if (t1 >= t_lo) return kInf;
      t0 = t1;
    }
  }

  Hit Trace(const V3& o, const V3& d) const {
    Hit h;
    const double t_ground = TerrainHit(o, d);
    Bvh::Hit bh;
    const float t_max = static_cast<float>(std::min(t_ground * 1.0001 + 0.01, 1e7));
    if (bvh.Intersect(o.cast<float>(), d.cast<float>(), 0.0f, t_max, &bh)) {
      const FaceInfo& f = faces[bh.id];
      double t = bh.t;
      if (f.kind != FaceKind::kTreeCrown && f.kind != FaceKind::kTreeTrunk) {
        const double den = f.normal.dot(d);
        if (std::abs(den) > 1e-9) t = -(f.normal.dot(o) + f.d) / den;  // exact plane hit
      }
      if (t < t_ground) {
        h.face = bh.id;
        h.t = t;
        h.p = o + t * d;
        return h;
      }
    }
    if (std::isfinite(t_ground)) {
      h.face = 0;
      h.t = t_ground;
      h.p = o + t_ground * d;
      h.p.z() = scene.ground.HeightAt(h.p.head<2>());
    }
    return h;
  }

  // Linear radiance seen along d from o; `pixel_angle` is the angular size
  // of one sample (rad), for texture filtering.
  V3f Shade(const V3& o, const V3& d, double pixel_angle, uint64_t rnd) const {
    const Hit h = Trace(o, d);
    if (h.face < 0) return opt.haze_rgb;  // sky (obliques near the horizon)
    const FaceInfo& f = faces[h.face];
    V3 n = f.normal;
    int material = f.material;
    float u = 0, v = 0;
    uint32_t seed = f.seed;
    switch (f.kind) {
      case FaceKind::kTerrain:
        if (!scene.ground.Planar()) {
          const Eigen::Vector2d gr = scene.ground.GradientAt(h.p.head<2>());
          n = V3(-gr.x(), -gr.y(), 1).normalized();
        }
        material = ground.MaterialAt(h.p.head<2>());
        u = static_cast<float>(h.p.x());
        v = static_cast<float>(h.p.y());
        seed = ground_seed;
        break;
      case FaceKind::kTreeCrown: {
        const CrownShape& c = crowns[f.tree];
        const V3 q = (h.p - c.centre).cwiseQuotient(c.radii);
        n = q.cwiseQuotient(c.radii).normalized();
        // Leaf clumps tilt the shading normal.
        const float px = static_cast<float>(h.p.x() * 1.3),
                    py = static_cast<float>(h.p.y() * 1.3 + h.p.z());
        n += 0.55 * V3(GradientNoise(px, py, seed), GradientNoise(px + 31.7f, py, seed),
                       0.5 * GradientNoise(px, py + 17.1f, seed));
        n.normalize();
        u = static_cast<float>(h.p.x() + 0.6 * h.p.z());
        v = static_cast<float>(h.p.y() - 0.4 * h.p.z());
        break;
      }
      case FaceKind::kTreeTrunk:
        u = static_cast<float>(h.p.x() + h.p.y());
        v = static_cast<float>(-h.p.z());
        n = V3(h.p.x() - scene.trees[f.tree].base.x(), h.p.y() - scene.trees[f.tree].base.y(), 0)
                .normalized();
        break;
      default: {
        const V3 r = h.p - f.origin;
        u = static_cast<float>(r.dot(f.u_axis));
        v = static_cast<float>(r.dot(f.v_axis));
        break;
      }
    }
    if (f.kind != FaceKind::kTreeCrown && n.dot(d) > 0) n = -n;  // seen from behind (open models)
    const double cos_view = std::max(0.25, std::abs(n.dot(d)));
    const float footprint = static_cast<float>(h.t * pixel_angle / cos_view);
    const V3f albedo = EvaluateAlbedo(scene.materials[material], u, v, footprint, seed);
    const double ns = n.dot(sun);
    V3f light = opt.sky_rgb * static_cast<float>(0.55 + 0.45 * n.z());
    if (ns > 0) {
      bool lit = true;
      if (opt.shadows) {
        // A random point of the sun disc (uniform in the disc).
        const Eigen::Vector2d& q = kSunDisc[Mix64(rnd ^ 0x5a5a) % kSunDisc.size()];
        const V3 to_sun =
            (sun + sun_radius * q.x() * sun_u + sun_radius * q.y() * sun_v).normalized();
        const V3 start = h.p + 0.01 * (f.kind == FaceKind::kTreeCrown ? sun : n);
        // Nothing stands above top_z: the ray can stop there.
        const float t_max =
            to_sun.z() > 1e-6 ? static_cast<float>((top_z - start.z()) / to_sun.z()) + 0.01f : 1e5f;
        lit = t_max <= 0 || !bvh.Occluded(start.cast<float>(), to_sun.cast<float>(), 0.0f, t_max);
      }
      if (lit) light += opt.sun_rgb * static_cast<float>(ns);
    }
    return albedo.cwiseProduct(light);
  }

  // Supersampled radiance of one view, rows in parallel.
  cv::Mat Radiance(const Camera& cam, const Pose& pose, int view_index, uint64_t seed,
                   Progress* progress) const {
    cam.Validate("simulate");
    const RayMap rays(cam);
    const int W = cam.width, H = cam.height, ss = opt.supersampling;
    cv::Mat out(H, W, CV_32FC3);
    const Eigen::Matrix3d Rt = pose.R.transpose();
    const double pixel_angle = 1.0 / (std::max(cam.fx, cam.fy) * ss);
    const uint64_t view_key = Hash(seed, 0x7a11, static_cast<uint64_t>(view_index));
    const int bands = 16;
    for (int band = 0; band < bands; ++band) {
      const int r0 = band * H / bands, r1 = (band + 1) * H / bands;
      tbb::parallel_for(tbb::blocked_range<int>(r0, r1, 2),
                        [&](const tbb::blocked_range<int>& rows) {
                          for (int y = rows.begin(); y < rows.end(); ++y) {
                            auto* row = out.ptr<cv::Vec3f>(y);
                            for (int x = 0; x < W; ++x) {
                              V3f sum = V3f::Zero();
                              const uint64_t pk = Hash(view_key, static_cast<uint64_t>(y) * W + x);
                              for (int sy = 0; sy < ss; ++sy)
                                for (int sx = 0; sx < ss; ++sx) {
                                  const uint64_t h = Hash(pk, sy * ss + sx);
                                  // Stratified jitter inside the sample's cell (one sample:
                                  // the pixel centre, so depth maps and images agree).
                                  const double jx = ss == 1 ? 0.5 : (sx + ToUnit(h)) / ss;
                                  const double jy = ss == 1 ? 0.5 : (sy + ToUnit(Mix64(h))) / ss;
                                  const Eigen::Vector2d nrm = rays(x + jx, y + jy);
                                  const V3 d = (Rt * V3(nrm.x(), nrm.y(), 1.0)).normalized();
                                  sum += Shade(pose.C, d, pixel_angle, h);
                                }
                              sum /= static_cast<float>(ss * ss);
                              row[x] = cv::Vec3f(sum.x(), sum.y(), sum.z());
                            }
                          }
                        });
      if (progress) ReportOrCancel(*progress, static_cast<double>(band + 1) / bands);
    }
    return out;
  }
};

Renderer::Renderer(const Scene& scene, const RenderOptions& options) : impl_(new Impl) {
  impl_->scene = scene;
  impl_->opt = options;
  impl_->Build();
}

Renderer::~Renderer() = default;

const std::vector<FaceInfo>& Renderer::faces() const { return impl_->faces; }
size_t Renderer::triangle_count() const { return impl_->bvh.size(); }

cv::Mat Renderer::RenderRadiance(const Camera& camera, const Pose& pose, int view_index,
                                 uint64_t seed) const {
  return impl_->Radiance(camera, pose, view_index, seed, nullptr);
}

cv::Mat Renderer::Render(const SimulatedView& view, int view_index, uint64_t seed,
                         Progress* progress) const {
  const RenderOptions& o = impl_->opt;
  cv::Mat rad = impl_->Radiance(view.camera, view.pose, view_index, seed, progress);
  if (o.psf_sigma_px > 0)
    cv::GaussianBlur(rad, rad, cv::Size(0, 0), o.psf_sigma_px, o.psf_sigma_px, cv::BORDER_REFLECT);
  const Camera& cam = view.camera;
  const int W = cam.width, H = cam.height;
  // Flight-line colour calibration differs slightly per strip.
  V3f gain;
  for (int c = 0; c < 3; ++c) {
    Rng g(Hash(seed, 0x5791, static_cast<uint64_t>(view.strip), static_cast<uint64_t>(c)));
    gain[c] = static_cast<float>(o.exposure * (1 + o.strip_gain_sigma * g.Normal()));
  }
  const double r2max = std::max({cam.cx * cam.cx + cam.cy * cam.cy,
                                 (W - cam.cx) * (W - cam.cx) + (H - cam.cy) * (H - cam.cy),
                                 (W - cam.cx) * (W - cam.cx) + cam.cy * cam.cy,
                                 cam.cx * cam.cx + (H - cam.cy) * (H - cam.cy)});
  const uint64_t noise_key = Hash(seed, 0x401e, static_cast<uint64_t>(view_index));
  cv::Mat out(H, W, CV_8UC3);
  tbb::parallel_for(tbb::blocked_range<int>(0, H, 8), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const auto* in = rad.ptr<cv::Vec3f>(y);
      auto* px = out.ptr<cv::Vec3b>(y);
      for (int x = 0; x < W; ++x) {
        const double dx = x + 0.5 - cam.cx, dy = y + 0.5 - cam.cy;
        const double vig = 1 - o.vignetting * (dx * dx + dy * dy) / r2max;
        Rng rng(Hash(noise_key, static_cast<uint64_t>(y) * W + x));
        for (int c = 0; c < 3; ++c) {
          double s = in[x][c] * gain[c] * vig;
          s = (1 - o.haze) * s + o.haze * o.haze_rgb[c];
          const double sigma =
              std::sqrt(o.read_noise * o.read_noise + o.shot_noise * std::max(0.0, s));
          if (sigma > 0) s += sigma * rng.Normal();
          px[x][c] = static_cast<uchar>(std::lround(255.0 * LinearToSrgb(static_cast<float>(s))));
        }
      }
    }
  });
  return out;
}

GeometryMaps Renderer::RenderGeometry(const Camera& cam, const Pose& pose) const {
  cam.Validate("simulate");
  const RayMap rays(cam);
  GeometryMaps m;
  m.depth.create(cam.height, cam.width, CV_32F);
  m.face.create(cam.height, cam.width, CV_32S);
  const Eigen::Matrix3d Rt = pose.R.transpose();
  const V3 axis = pose.ViewingDirection();
  tbb::parallel_for(
      tbb::blocked_range<int>(0, cam.height, 8), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
          for (int x = 0; x < cam.width; ++x) {
            const Eigen::Vector2d nrm = rays(x + 0.5, y + 0.5);
            const V3 d = (Rt * V3(nrm.x(), nrm.y(), 1.0)).normalized();
            const Hit h = impl_->Trace(pose.C, d);
            m.face.at<int>(y, x) = h.face;
            m.depth.at<float>(y, x) = h.face < 0 ? std::numeric_limits<float>::infinity()
                                                 : static_cast<float>(h.t * d.dot(axis));
          }
      });
  return m;
}

}  // namespace sim
}  // namespace roofsweep
