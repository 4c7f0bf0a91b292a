#include "algorithms/simulate/bvh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace roofsweep {
namespace sim {

void Bvh::Build(std::vector<Triangle> in) {
  nodes_.clear();
  tris_.clear();
  if (in.empty()) return;
  std::vector<Eigen::Vector3f> centroids;
  centroids.reserve(in.size());
  for (const auto& t : in) centroids.push_back((t.a + t.b + t.c) / 3.0f);
  std::vector<int> idx(in.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  nodes_.reserve(2 * in.size());
  BuildNode(idx, 0, static_cast<int>(idx.size()), in, centroids);
  tris_.reserve(in.size());
  for (int i : idx) tris_.push_back({in[i].a, in[i].b - in[i].a, in[i].c - in[i].a, in[i].id});
}

int Bvh::BuildNode(std::vector<int>& idx, int begin, int end, const std::vector<Triangle>& in,
                   const std::vector<Eigen::Vector3f>& centroids) {
  const int me = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo, clo = lo, chi = -lo;
  for (int i = begin; i < end; ++i) {
    const auto& t = in[idx[i]];
    lo = lo.cwiseMin(t.a).cwiseMin(t.b).cwiseMin(t.c);
    hi = hi.cwiseMax(t.a).cwiseMax(t.b).cwiseMax(t.c);
    clo = clo.cwiseMin(centroids[idx[i]]);
    chi = chi.cwiseMax(centroids[idx[i]]);
  }
  nodes_[me].lo = lo;
  nodes_[me].hi = hi;
  const int n = end - begin;
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  if (n <= 4 || chi[axis] - clo[axis] <= 0) {
    nodes_[me].first = begin;
    nodes_[me].count = n;
    return me;
  }
  // Binned surface area heuristic along the widest centroid axis.
  constexpr int kBins = 12;
  struct Bin {
    Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
    Eigen::Vector3f hi = Eigen::Vector3f::Constant(-std::numeric_limits<float>::max());
    int n = 0;
  } bins[kBins];
  const float scale = kBins / (chi[axis] - clo[axis]);
  auto bin_of = [&](int i) {
    return std::min(kBins - 1, static_cast<int>((centroids[i][axis] - clo[axis]) * scale));
  };
  for (int i = begin; i < end; ++i) {
    Bin& b = bins[bin_of(idx[i])];
    const auto& t = in[idx[i]];
    b.lo = b.lo.cwiseMin(t.a).cwiseMin(t.b).cwiseMin(t.c);
    b.hi = b.hi.cwiseMax(t.a).cwiseMax(t.b).cwiseMax(t.c);
    ++b.n;
  }
  auto area = [](const Eigen::Vector3f& l, const Eigen::Vector3f& h) {
    const Eigen::Vector3f e = (h - l).cwiseMax(0.0f);
    return e.x() * e.y() + e.y() * e.z() + e.z() * e.x();
  };
  float best = std::numeric_limits<float>::max();
  int best_split = kBins / 2;
  for (int s = 1; s < kBins; ++s) {
    Bin l, r;
    for (int k = 0; k < s; ++k)
      l.lo = l.lo.cwiseMin(bins[k].lo), l.hi = l.hi.cwiseMax(bins[k].hi), l.n += bins[k].n;
    for (int k = s; k < kBins; ++k)
      r.lo = r.lo.cwiseMin(bins[k].lo), r.hi = r.hi.cwiseMax(bins[k].hi), r.n += bins[k].n;
    if (l.n == 0 || r.n == 0) continue;
    const float cost = l.n * area(l.lo, l.hi) + r.n * area(r.lo, r.hi);
    if (cost < best) best = cost, best_split = s;
  }
  int mid = static_cast<int>(std::partition(idx.begin() + begin, idx.begin() + end,
                                            [&](int i) { return bin_of(i) < best_split; }) -
                             idx.begin());
  if (mid == begin || mid == end) {  // SAH found nothing: split by count
    mid = begin + n / 2;
    std::nth_element(idx.begin() + begin, idx.begin() + mid, idx.begin() + end,
                     [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
  }
  BuildNode(idx, begin, mid, in, centroids);
  const int right = BuildNode(idx, mid, end, in, centroids);
  nodes_[me].first = right;
  nodes_[me].count = 0;
  nodes_[me].axis = axis;
  return me;
}

template <bool kAnyHit>
bool Bvh::Traverse(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max,
                   Hit* hit) const {
  if (nodes_.empty()) return false;
  const Eigen::Vector3f inv(1.0f / d.x(), 1.0f / d.y(), 1.0f / d.z());
  const bool neg[3] = {d.x() < 0, d.y() < 0, d.z() < 0};
  int stack[64];
  int sp = 0;
  stack[sp++] = 0;
  bool found = false;
  float best = t_max;
  while (sp > 0) {
    const Node& node = nodes_[stack[--sp]];
    // Slab test.
    float t0 = t_min, t1 = best;
    for (int a = 0; a < 3; ++a) {
      float ta = (node.lo[a] - o[a]) * inv[a];
      float tb = (node.hi[a] - o[a]) * inv[a];
      if (neg[a]) std::swap(ta, tb);
      t0 = ta > t0 ? ta : t0;
      t1 = tb < t1 ? tb : t1;
    }
    if (t0 > t1) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        // Möller–Trumbore.
        const Tri& tr = tris_[i];
        const Eigen::Vector3f p = d.cross(tr.e2);
        const float det = tr.e1.dot(p);
        if (std::abs(det) < 1e-12f) continue;
        const float inv_det = 1.0f / det;
        const Eigen::Vector3f s = o - tr.v0;
        const float u = s.dot(p) * inv_det;
        if (u < 0.0f || u > 1.0f) continue;
        const Eigen::Vector3f q = s.cross(tr.e1);
        const float v = d.dot(q) * inv_det;
        if (v < 0.0f || u + v > 1.0f) continue;
        const float t = tr.e2.dot(q) * inv_det;
        if (t > t_min && t < best) {
          if (kAnyHit) return true;
          best = t;
          hit->t = t;
          hit->id = tr.id;
          found = true;
        }
      }
    } else {
      const int left = static_cast<int>(&node - nodes_.data()) + 1, right = node.first;
      // Visit the nearer child first.
      if (neg[node.axis]) {
        stack[sp++] = left;
        stack[sp++] = right;
      } else {
        stack[sp++] = right;
        stack[sp++] = left;
      }
    }
  }
  return found;
}

bool Bvh::Intersect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max,
                    Hit* hit) const {
  return Traverse<false>(o, d, t_min, t_max, hit);
}

bool Bvh::Occluded(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min,
                   float t_max) const {
  return Traverse<true>(o, d, t_min, t_max, nullptr);
}

}  // namespace sim
}  // namespace roofsweep
