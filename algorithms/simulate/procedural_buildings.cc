#include "algorithms/simulate/procedural_buildings.h"

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "algorithms/core/error.h"

namespace roofsweep {
namespace sim {

const char* RoofShapeName(RoofShape s) {
  switch (s) {
    case RoofShape::kFlat:
      return "flat";
    case RoofShape::kShed:
      return "shed";
    case RoofShape::kGable:
      return "gable";
    case RoofShape::kHip:
      return "hip";
    case RoofShape::kHalfHip:
      return "half-hip";
    case RoofShape::kPyramid:
      return "pyramid";
    case RoofShape::kMansard:
      return "mansard";
    case RoofShape::kLShape:
      return "L-shape";
    case RoofShape::kTShape:
      return "T-shape";
  }
  return "?";
}

int RoofShapeCode(RoofShape s) {
  switch (s) {
    case RoofShape::kFlat:
      return roof_type::kFlat;
    case RoofShape::kShed:
      return roof_type::kMonopitch;
    case RoofShape::kGable:
      return roof_type::kGabled;
    case RoofShape::kHip:
      return roof_type::kHipped;
    case RoofShape::kHalfHip:
      return roof_type::kHalfHipped;
    case RoofShape::kPyramid:
      return roof_type::kPavilion;
    case RoofShape::kMansard:
      return roof_type::kMansard;
    case RoofShape::kLShape:
    case RoofShape::kTShape:
      return roof_type::kCombination;
  }
  return roof_type::kUnknown;
}

namespace {

using V3 = Eigen::Vector3d;
using V2 = Eigen::Vector2d;

// Collects polygons in the building frame (x along the ridge, z up from the
// ground), then places them in the world.
class SolidBuilder {
 public:
  void Add(SurfaceType type, std::vector<V3> ring) { faces_.push_back({type, std::move(ring)}); }

  // Wall over the footprint edge a -> b (footprint counter-clockwise from
  // above); `tops` runs from above b back to above a.
  void Wall(const V2& a, const V2& b, const std::vector<V3>& tops) {
    std::vector<V3> ring = {V3(a.x(), a.y(), 0), V3(b.x(), b.y(), 0)};
    ring.insert(ring.end(), tops.begin(), tops.end());
    Add(SurfaceType::kWall, ring);
  }
  void FlatWall(const V2& a, const V2& b, double h) {
    Wall(a, b, {V3(b.x(), b.y(), h), V3(a.x(), a.y(), h)});
  }
  void Walls(const std::vector<V2>& footprint, double h) {
    for (size_t i = 0; i < footprint.size(); ++i)
      FlatWall(footprint[i], footprint[(i + 1) % footprint.size()], h);
  }
  void Ground(const std::vector<V2>& footprint) {
    std::vector<V3> ring;
    for (auto it = footprint.rbegin(); it != footprint.rend(); ++it)
      ring.emplace_back(it->x(), it->y(), 0);
    Add(SurfaceType::kGround, ring);
  }

  Building Finish(const BuildingSpec& spec) const {
    Building b;
    b.id = spec.id;
    b.roof_type = RoofShapeCode(spec.shape);
    const double c = std::cos(spec.yaw_deg * M_PI / 180), s = std::sin(spec.yaw_deg * M_PI / 180);
    double top = 0;
    int n = 0;
    for (const auto& f : faces_) {
      Polygon3 poly;
      for (const V3& p : f.ring) {
        const V3 w(spec.center.x() + c * p.x() - s * p.y(), spec.center.y() + s * p.x() + c * p.y(),
                   spec.ground_z + p.z());
        // Composites can produce zero-length edges where a wing is flush
        // with the main body; drop the repeated vertex.
        if (!poly.exterior.empty() && (poly.exterior.back() - w).norm() < 1e-9) continue;
        poly.exterior.push_back(w);
      }
      while (poly.exterior.size() > 1 &&
             (poly.exterior.front() - poly.exterior.back()).norm() < 1e-9)
        poly.exterior.pop_back();
      if (f.type == SurfaceType::kRoof)
        for (const V3& p : f.ring) top = std::max(top, p.z());
      Surface surf;
      surf.type = f.type;
      surf.id = spec.id + "_surf_" + std::to_string(n++);
      surf.polygons.push_back(std::move(poly));
      b.surfaces.push_back(std::move(surf));
    }
    b.measured_height = top;
    return b;
  }

 private:
  struct Face {
    SurfaceType type;
    std::vector<V3> ring;
  };
  std::vector<Face> faces_;
};

void Require(bool ok, const BuildingSpec& spec, const std::string& what) {
  if (!ok) throw Error("building " + spec.id + " (" + RoofShapeName(spec.shape) + "): " + what);
}

// Low hip roof (or pyramid when the ridge has zero length) over the
// rectangle [-l/2, l/2] x [-w/2, w/2] from height h0 to h1 (l >= w).
void HipRoof(SolidBuilder& sb, double l, double w, double h0, double h1, double inset) {
  const V3 p0(-l / 2, -w / 2, h0), p1(l / 2, -w / 2, h0), p2(l / 2, w / 2, h0),
      p3(-l / 2, w / 2, h0);
  const double rx = l / 2 - inset;
  if (rx > 1e-9) {
    const V3 r0(-rx, 0, h1), r1(rx, 0, h1);
    sb.Add(SurfaceType::kRoof, {p0, p1, r1, r0});
    sb.Add(SurfaceType::kRoof, {p1, p2, r1});
    sb.Add(SurfaceType::kRoof, {p2, p3, r0, r1});
    sb.Add(SurfaceType::kRoof, {p3, p0, r0});
  } else {
    const V3 apex(0, 0, h1);
    sb.Add(SurfaceType::kRoof, {p0, p1, apex});
    sb.Add(SurfaceType::kRoof, {p1, p2, apex});
    sb.Add(SurfaceType::kRoof, {p2, p3, apex});
    sb.Add(SurfaceType::kRoof, {p3, p0, apex});
  }
}

}  // namespace

Building MakeBuilding(const BuildingSpec& spec) {
  const double L = spec.length, W = spec.width, he = spec.eave_height, hr = spec.ridge_height;
  Require(L > 0.5 && W > 0.5 && std::isfinite(L) && std::isfinite(W), spec,
          "length and width must be > 0.5 m");
  Require(he > 0.5, spec, "eave height must be > 0.5 m");
  if (spec.shape != RoofShape::kFlat) Require(hr > he + 0.05, spec, "ridge must be above the eave");

  const V2 f0(-L / 2, -W / 2), f1(L / 2, -W / 2), f2(L / 2, W / 2), f3(-L / 2, W / 2);
  const std::vector<V2> rect = {f0, f1, f2, f3};
  auto at = [](const V2& p, double z) { return V3(p.x(), p.y(), z); };
  SolidBuilder sb;

  switch (spec.shape) {
    case RoofShape::kFlat:
      sb.Add(SurfaceType::kRoof, {at(f0, he), at(f1, he), at(f2, he), at(f3, he)});
      sb.Walls(rect, he);
      sb.Ground(rect);
      break;
    case RoofShape::kShed:  // rises towards +y
      sb.Add(SurfaceType::kRoof, {at(f0, he), at(f1, he), at(f2, hr), at(f3, hr)});
      sb.FlatWall(f0, f1, he);
      sb.Wall(f1, f2, {at(f2, hr), at(f1, he)});
      sb.FlatWall(f2, f3, hr);
      sb.Wall(f3, f0, {at(f0, he), at(f3, hr)});
      sb.Ground(rect);
      break;
    case RoofShape::kGable: {
      const V3 r0(-L / 2, 0, hr), r1(L / 2, 0, hr);
      sb.Add(SurfaceType::kRoof, {at(f0, he), at(f1, he), r1, r0});
      sb.Add(SurfaceType::kRoof, {at(f2, he), at(f3, he), r0, r1});
      sb.FlatWall(f0, f1, he);
      sb.Wall(f1, f2, {at(f2, he), r1, at(f1, he)});
      sb.FlatWall(f2, f3, he);
      sb.Wall(f3, f0, {at(f0, he), r0, at(f3, he)});
      sb.Ground(rect);
      break;
    }
    case RoofShape::kHip:
    case RoofShape::kPyramid: {
      Require(L >= W - 1e-9, spec, "hip and pyramid roofs need length >= width");
      // Equal pitch on all four sides puts the hip foot W/2 in from the gable
      // end; a pyramid has its apex in the middle.
      const double inset = spec.shape == RoofShape::kPyramid ? L / 2 : std::min(W / 2, 0.45 * L);
      HipRoof(sb, L, W, he, hr, inset);
      sb.Walls(rect, he);
      sb.Ground(rect);
      break;
    }
    case RoofShape::kHalfHip: {
      const double f = spec.half_hip_fraction;
      Require(f > 0.1 && f < 0.9, spec, "half_hip_fraction must be in (0.1, 0.9)");
      const double hm = he + f * (hr - he);
      const double ym = -W / 2 + f * W / 2;  // < 0: where the verge reaches hm
      const double d = std::min(-ym, 0.3 * L);
      const V3 A(L / 2, ym, hm), A2(L / 2, -ym, hm), B(-L / 2, ym, hm), B2(-L / 2, -ym, hm);
      const V3 R0(-L / 2 + d, 0, hr), R1(L / 2 - d, 0, hr);
      sb.Add(SurfaceType::kRoof, {at(f0, he), at(f1, he), A, R1, R0, B});
      sb.Add(SurfaceType::kRoof, {at(f2, he), at(f3, he), B2, R0, R1, A2});
      sb.Add(SurfaceType::kRoof, {A, A2, R1});
      sb.Add(SurfaceType::kRoof, {B2, B, R0});
      sb.FlatWall(f0, f1, he);
      sb.Wall(f1, f2, {at(f2, he), A2, A, at(f1, he)});
      sb.FlatWall(f2, f3, he);
      sb.Wall(f3, f0, {at(f0, he), B, B2, at(f3, he)});
      sb.Ground(rect);
      break;
    }
    case RoofShape::kMansard: {
      const double a = spec.mansard_inset, hb = spec.mansard_break_height;
      Require(L >= W - 1e-9, spec, "mansard roofs need length >= width");
      Require(a > 0.05 && a < W / 2 - 0.5, spec, "mansard inset must leave >= 1 m on top");
      Require(hb > he + 0.05 && hb < hr - 0.05, spec,
              "mansard break must lie between eave and ridge");
      const V2 q0(-L / 2 + a, -W / 2 + a), q1(L / 2 - a, -W / 2 + a), q2(L / 2 - a, W / 2 - a),
          q3(-L / 2 + a, W / 2 - a);
      sb.Add(SurfaceType::kRoof, {at(f0, he), at(f1, he), at(q1, hb), at(q0, hb)});
      sb.Add(SurfaceType::kRoof, {at(f1, he), at(f2, he), at(q2, hb), at(q1, hb)});
      sb.Add(SurfaceType::kRoof, {at(f2, he), at(f3, he), at(q3, hb), at(q2, hb)});
      sb.Add(SurfaceType::kRoof, {at(f3, he), at(f0, he), at(q0, hb), at(q3, hb)});
      const double l = L - 2 * a, w = W - 2 * a;
      HipRoof(sb, l, w, hb, hr, std::min(w / 2, 0.45 * l));
      sb.Walls(rect, he);
      sb.Ground(rect);
      break;
    }
    case RoofShape::kLShape:
    case RoofShape::kTShape: {
      const double w2 = spec.wing_width, E = spec.wing_length;
      Require(w2 > 1 && w2 <= 0.85 * W, spec, "wing width must be in (1 m, 0.85 width]");
      Require(E > 0.5, spec, "wing length must be > 0.5 m");
      double xc = L / 2 - w2 / 2;  // L: flush with the +x gable end
      if (spec.shape == RoofShape::kTShape) {
        xc = spec.wing_offset;
        Require(std::abs(xc) + w2 / 2 <= L / 2 - 1.0, spec,
                "T wing must stay >= 1 m inside the main gable ends");
      }
      // Same pitch as the main roof, so the valleys run at 45 degrees in plan
      // from the eave corners to where the wing ridge meets the main roof.
      const double slope = (hr - he) / (W / 2);
      const double h2 = he + slope * w2 / 2;
      const V3 r0(-L / 2, 0, hr), r1(L / 2, 0, hr);
      const V2 w0(xc + w2 / 2, W / 2), w1(xc + w2 / 2, W / 2 + E), w2p(xc - w2 / 2, W / 2 + E),
          w3(xc - w2 / 2, W / 2);
      const V3 V(xc, W / 2 - w2 / 2, h2), wr(xc, W / 2 + E, h2);
      sb.Add(SurfaceType::kRoof, {at(f0, he), at(f1, he), r1, r0});
      sb.Add(SurfaceType::kRoof, {at(f2, he), at(w0, he), V, at(w3, he), at(f3, he), r0, r1});
      sb.Add(SurfaceType::kRoof, {at(w0, he), at(w1, he), wr, V});
      sb.Add(SurfaceType::kRoof, {at(w2p, he), at(w3, he), V, wr});
      sb.FlatWall(f0, f1, he);
      sb.Wall(f1, f2, {at(f2, he), r1, at(f1, he)});
      if ((f2 - w0).norm() > 1e-9) sb.FlatWall(f2, w0, he);
      sb.FlatWall(w0, w1, he);
      sb.Wall(w1, w2p, {at(w2p, he), wr, at(w1, he)});
      sb.FlatWall(w2p, w3, he);
      sb.FlatWall(w3, f3, he);
      sb.Wall(f3, f0, {at(f0, he), r0, at(f3, he)});
      std::vector<V2> fp = {f0, f1, f2};
      if ((f2 - w0).norm() > 1e-9) fp.push_back(w0);
      fp.insert(fp.end(), {w1, w2p, w3, f3});
      sb.Ground(fp);
      break;
    }
  }
  return sb.Finish(spec);
}

}  // namespace sim
}  // namespace roofsweep
