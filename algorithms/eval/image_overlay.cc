#include "algorithms/eval/image_overlay.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>

#include "algorithms/edges/gradient.h"
#include "algorithms/edges/thresholds.h"
#include "algorithms/simulate/triangulate.h"

namespace roofsweep {
namespace {

using Key = std::array<long long, 6>;

// Endpoints on a 1 mm grid, in a fixed order, so that the two faces that
// share an edge name it alike whichever way their rings run.
Key EdgeKey(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  auto q = [](const Eigen::Vector3d& p) {
    return std::array<long long, 3>{std::llround(p.x() * 1000), std::llround(p.y() * 1000),
                                    std::llround(p.z() * 1000)};
  };
  std::array<long long, 3> qa = q(a), qb = q(b);
  if (qb < qa) std::swap(qa, qb);
  return {qa[0], qa[1], qa[2], qb[0], qb[1], qb[2]};
}

template <typename F>
void ForEachRing(const Polygon3& p, F f) {
  f(p.exterior);
  for (const auto& h : p.holes) f(h);
}

// The fused colour gradient as vectors (the edge extraction's fusion),
// with the automatic low hysteresis threshold of that image.
struct ImageGradient {
  cv::Mat magnitude, gx, gy;  // CV_32F; zero on the outermost rows and columns
  float low = 0;
};

ImageGradient ComputeImageGradient(const cv::Mat& image, double sigma) {
  EdgeOptions eo;
  eo.sigma = sigma;
  GradientField field = ComputeGradient(GradientPlanes(image, eo.method), eo.method, eo.sigma);
  ImageGradient g;
  g.low = ChooseThresholds(field.magnitude, eo).low;
  g.gx = cv::Mat::zeros(image.rows, image.cols, CV_32F);
  g.gy = cv::Mat::zeros(image.rows, image.cols, CV_32F);
  for (int y = 1; y < image.rows - 1; ++y)
    GradientRow(field, y, nullptr, g.gx.ptr<float>(y), g.gy.ptr<float>(y));
  g.magnitude = std::move(field.magnitude);
  return g;
}

bool Supported(const ImageGradient& g, const Eigen::Vector2d& at, const Eigen::Vector2d& normal,
               const ImageEdgeOptions& o) {
  const double cos_max = std::cos(o.max_angle_deg * M_PI / 180.0);
  const int steps = static_cast<int>(std::floor(o.search_px / 0.5 + 1e-9));
  for (int k = -steps; k <= steps; ++k) {
    const Eigen::Vector2d q = at + 0.5 * k * normal;
    // Pixel (i, j) covers [i, i + 1) x [j, j + 1) (README, conventions).
    const int x = static_cast<int>(std::floor(q.x())), y = static_cast<int>(std::floor(q.y()));
    if (x < 1 || y < 1 || x >= g.magnitude.cols - 1 || y >= g.magnitude.rows - 1) continue;
    const float m = g.magnitude.at<float>(y, x);
    if (m < g.low || m <= 0) continue;
    const double gx = g.gx.at<float>(y, x), gy = g.gy.at<float>(y, x);
    const double n = std::hypot(gx, gy);
    // Either polarity: which side of a roof edge is brighter depends on the sun.
    if (n > 0 && std::abs(gx * normal.x() + gy * normal.y()) >= cos_max * n) return true;
  }
  return false;
}

cv::Mat ToRgb8(const cv::Mat& image) {
  cv::Mat rgb;
  if (image.channels() == 1) {
    cv::cvtColor(image, rgb, cv::COLOR_GRAY2RGB);
  } else {
    rgb = image;
  }
  cv::Mat out;
  rgb.convertTo(out, CV_8UC3, image.depth() == CV_8U ? 1.0 : 255.0);
  return out;
}

}  // namespace

double EdgeSupport::Fraction() const {
  return visible_px > 0 ? supported_px / visible_px : std::numeric_limits<double>::quiet_NaN();
}

EdgeSupport& EdgeSupport::operator+=(const EdgeSupport& o) {
  visible_px += o.visible_px;
  supported_px += o.supported_px;
  hidden_px += o.hidden_px;
  return *this;
}

std::vector<ModelEdge> ModelEdges(const CityModel& model) {
  std::vector<ModelEdge> edges;
  std::map<Key, size_t> seen;
  for (size_t bi = 0; bi < model.buildings.size(); ++bi) {
    for (const Building* solid : model.buildings[bi].Solids()) {
      for (const Surface& s : solid->surfaces) {
        const ModelEdgeKind kind =
            s.type == SurfaceType::kRoof ? ModelEdgeKind::kRoof : ModelEdgeKind::kWall;
        for (const Polygon3& p : s.polygons) {
          ForEachRing(p, [&](const std::vector<Eigen::Vector3d>& ring) {
            for (size_t i = 0; i < ring.size(); ++i) {
              const Eigen::Vector3d& a = ring[i];
              const Eigen::Vector3d& b = ring[(i + 1) % ring.size()];
              if ((b - a).norm() < 0.01) continue;
              const auto [it, added] = seen.emplace(EdgeKey(a, b), edges.size());
              if (added) {
                edges.push_back({Segment3{a, b}, kind, static_cast<int>(bi)});
              } else if (kind == ModelEdgeKind::kRoof) {
                edges[it->second].kind = ModelEdgeKind::kRoof;
              }
            }
          });
        }
      }
    }
  }
  return edges;
}

ModelOccluder::ModelOccluder(const CityModel& model) {
  std::vector<sim::Bvh::Triangle> tris;
  for (const Building& b : model.buildings)
    for (const Building* solid : b.Solids())
      for (const Surface& s : solid->surfaces)
        for (const Polygon3& p : s.polygons) {
          // Holes are not cut out (TriangulatePolygon has none): LoD2 roof
          // and wall polygons seldom have them, and a hole would only hide
          // a little more than it should.
          if (p.exterior.size() < 3) continue;
          for (const auto& t : sim::TriangulatePolygon(p.exterior))
            tris.push_back({p.exterior[t[0]].cast<float>(), p.exterior[t[1]].cast<float>(),
                            p.exterior[t[2]].cast<float>(), 0});
        }
  bvh_.Build(std::move(tris));
}

bool ModelOccluder::Visible(const Eigen::Vector3d& centre, const Eigen::Vector3d& point,
                            double tolerance_m) const {
  if (bvh_.size() == 0) return true;
  const Eigen::Vector3d d = point - centre;
  const double dist = d.norm();
  if (dist <= tolerance_m) return true;
  return !bvh_.Occluded(centre.cast<float>(), (d / dist).cast<float>(), 1e-3f,
                        static_cast<float>(dist - tolerance_m));
}

ImageOverlay OverlayModel(const cv::Mat& image, const Camera& camera, const Pose& pose,
                          const std::vector<ModelEdge>& edges, int buildings,
                          const ModelOccluder& occluder, const ImageEdgeOptions& o, bool draw) {
  ImageOverlay out;
  out.per_building.assign(static_cast<size_t>(std::max(buildings, 0)), EdgeSupport{});
  const ImageGradient g = ComputeImageGradient(image, o.sigma);
  if (draw) out.drawing = ToRgb8(image);
  const double w = image.cols, h = image.rows;
  const int thickness = std::max(1, static_cast<int>(std::lround(std::max(w, h) / 1000.0)));
  constexpr int kShift = 4;  // sub-pixel drawing, 1/16 px
  auto pt = [](const Eigen::Vector2d& p) {
    // OpenCV draws with integer coordinates at pixel centres.
    return cv::Point(static_cast<int>(std::lround((p.x() - 0.5) * (1 << kShift))),
                     static_cast<int>(std::lround((p.y() - 0.5) * (1 << kShift))));
  };
  const cv::Scalar kGood(0, 200, 0), kBad(255, 0, 0), kWall(0, 255, 255);

  // Walls first, so that the roof outline is drawn over them. Walls are
  // only drawn, never scored: without a drawing they cost nothing.
  for (const ModelEdgeKind pass : {ModelEdgeKind::kWall, ModelEdgeKind::kRoof}) {
    if (pass == ModelEdgeKind::kWall && !draw) continue;
    for (const ModelEdge& e : edges) {
      if (e.kind != pass) continue;
      const auto pa = Project(camera, pose, e.segment.a), pb = Project(camera, pose, e.segment.b);
      // Enough samples for step_px; an end behind the camera gives no
      // length to go by, so take many.
      const double length_px = pa && pb ? (*pb - *pa).norm() : 200.0 * o.step_px;
      const int n = std::max(1, static_cast<int>(std::ceil(length_px / o.step_px)));
      std::vector<std::optional<Eigen::Vector2d>> q(n + 1);
      for (int k = 0; k <= n; ++k) q[k] = Project(camera, pose, e.segment.At(k / double(n)));
      for (int k = 0; k < n; ++k) {
        if (!q[k] || !q[k + 1]) continue;
        const Eigen::Vector3d X = e.segment.At((k + 0.5) / n);
        const auto m = Project(camera, pose, X);
        if (!m) continue;
        if (m->x() < o.border_px || m->y() < o.border_px || m->x() >= w - o.border_px ||
            m->y() >= h - o.border_px)
          continue;
        const Eigen::Vector2d along = *q[k + 1] - *q[k];
        const double len = along.norm();
        if (len <= 0) continue;
        const bool visible = occluder.Visible(pose.C, X);
        if (pass == ModelEdgeKind::kWall) {
          if (visible)
            cv::line(out.drawing, pt(*q[k]), pt(*q[k + 1]), kWall, thickness, cv::LINE_AA, kShift);
          continue;
        }
        EdgeSupport s;
        if (!visible) {
          s.hidden_px = len;
        } else {
          s.visible_px = len;
          const Eigen::Vector2d normal(-along.y() / len, along.x() / len);
          if (Supported(g, *m, normal, o)) s.supported_px = len;
          if (draw)
            cv::line(out.drawing, pt(*q[k]), pt(*q[k + 1]), s.supported_px > 0 ? kGood : kBad,
                     thickness, cv::LINE_AA, kShift);
        }
        out.roof += s;
        if (e.building >= 0 && e.building < static_cast<int>(out.per_building.size()))
          out.per_building[e.building] += s;
      }
    }
  }
  return out;
}

std::vector<EdgeSupport> BuildingEdgeSupport(const CityModel& model, const Block& block,
                                             const std::vector<cv::Mat>& images,
                                             const ImageEdgeOptions& options) {
  const int nb = static_cast<int>(model.buildings.size());
  std::vector<EdgeSupport> total(static_cast<size_t>(nb));
  if (nb == 0) return total;
  const std::vector<ModelEdge> edges = ModelEdges(model);
  const ModelOccluder occluder(model);
  const size_t n = std::min(images.size(), block.views.size());
  std::vector<std::vector<EdgeSupport>> per_view(n);
  tbb::parallel_for(size_t{0}, n, [&](size_t v) {
    const View& view = block.views[v];
    per_view[v] = OverlayModel(images[v], block.CameraOf(view), view.pose, edges, nb, occluder,
                               options, /*draw=*/false)
                      .per_building;
  });
  for (const auto& pv : per_view)
    for (int b = 0; b < nb; ++b) total[b] += pv[b];
  return total;
}

}  // namespace roofsweep
