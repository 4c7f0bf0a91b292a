#pragma once

#include <Eigen/Core>
#include <vector>

namespace roofsweep {
namespace sim {

// Bounding volume hierarchy over triangles for ray casting. Own code rather
// than Embree (not a dependency, and its results may vary with the CPU's
// SIMD width) or CGAL's AABB tree (exact predicates, far too slow for 10^8
// rays): the scenes have a few thousand triangles, single-ray traversal in
// float is plenty and bit-identical for every thread count.
class Bvh {
 public:
  struct Triangle {
    Eigen::Vector3f a, b, c;
    int id = -1;  // caller's face id
  };
  struct Hit {
    float t = 0;
    int id = -1;
  };

  void Build(std::vector<Triangle> triangles);
  // Closest hit with t in (t_min, t_max); false when none.
  bool Intersect(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir, float t_min,
                 float t_max, Hit* hit) const;
  // Any hit with t in (t_min, t_max).
  bool Occluded(const Eigen::Vector3f& origin, const Eigen::Vector3f& dir, float t_min,
                float t_max) const;
  size_t size() const { return tris_.size(); }

 private:
  struct Node {
    Eigen::Vector3f lo, hi;
    int first = 0;  // leaf: first triangle; inner: right child (left is this + 1)
    int count = 0;  // leaf: number of triangles, inner: 0
    int axis = 0;
  };
  struct Tri {
    Eigen::Vector3f v0, e1, e2;
    int id;
  };
  int BuildNode(std::vector<int>& idx, int begin, int end, const std::vector<Triangle>& in,
                const std::vector<Eigen::Vector3f>& centroids);
  template <bool kAnyHit>
  bool Traverse(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max,
                Hit* hit) const;

  std::vector<Node> nodes_;
  std::vector<Tri> tris_;
};

}  // namespace sim
}  // namespace roofsweep
