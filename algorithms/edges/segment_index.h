#pragma once

#include <Eigen/Core>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "algorithms/edges/segment2d.h"

namespace roofsweep {

// An R-tree (Boost.Geometry, bulk-loaded) over the bounding boxes of a set
// of segments, for "neighbouring lines" queries (Scholze et al. 2000, §2.3).
// Ids are indices into the vector it was built from; results are sorted.
// The segments are copied, so the index stays valid on its own. Boost's
// headers stay in the .cc (compile cost for everyone who includes this).
class SegmentIndex {
 public:
  explicit SegmentIndex(const Segments2D& segments);
  ~SegmentIndex();
  SegmentIndex(SegmentIndex&&) noexcept;
  SegmentIndex& operator=(SegmentIndex&&) noexcept;

  int size() const;

  // Segments whose distance to `query` (segment to segment) is <= radius.
  std::vector<int> Near(const Segment2D& query, double radius) const;
  // Segments within `radius` of segment `id`, excluding `id` itself.
  std::vector<int> Neighbours(int id, double radius) const;
  // Segments within `radius` of a point.
  std::vector<int> NearPoint(const Eigen::Vector2d& point, double radius) const;
  // Segments whose bounding box meets the box [min, max].
  std::vector<int> InBox(const Eigen::Vector2d& min, const Eigen::Vector2d& max) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The raster form of the segments (§2.3): a CV_32S image of `size` where a
// pixel holds the id of the segment passing through it, -1 where none.
// Each segment marks the pixels its centre line crosses (sampled every
// 0.25 px). Where segments share a pixel the longer one wins (ties: the
// lower id), so the map does not depend on drawing order.
cv::Mat RasterizeSegments(const Segments2D& segments, cv::Size size);

}  // namespace roofsweep
