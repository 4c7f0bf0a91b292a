#include "algorithms/edges/segment_index.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>

#include "algorithms/core/error.h"
#include "algorithms/edges/segment_geometry.h"

namespace roofsweep {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BBox = bg::model::box<BPoint>;
using Value = std::pair<BBox, int>;

struct SegmentIndex::Impl {
  Segments2D segments;
  bgi::rtree<Value, bgi::rstar<16>> tree;

  std::vector<int> Query(const BBox& box) const {
    std::vector<Value> found;
    tree.query(bgi::intersects(box), std::back_inserter(found));
    std::vector<int> ids;
    ids.reserve(found.size());
    for (const Value& v : found) ids.push_back(v.second);
    std::sort(ids.begin(), ids.end());
    return ids;
  }
};

namespace {

BBox Box(const Segment2D& s, double pad) {
  return BBox(BPoint(std::min(s.p0.x(), s.p1.x()) - pad, std::min(s.p0.y(), s.p1.y()) - pad),
              BPoint(std::max(s.p0.x(), s.p1.x()) + pad, std::max(s.p0.y(), s.p1.y()) + pad));
}

}  // namespace

SegmentIndex::SegmentIndex(const Segments2D& segments) : impl_(std::make_unique<Impl>()) {
  impl_->segments = segments;
  std::vector<Value> values;
  values.reserve(segments.size());
  for (size_t i = 0; i < segments.size(); ++i) {
    if (!segments[i].p0.allFinite() || !segments[i].p1.allFinite()) {
      throw Error("SegmentIndex: segment " + std::to_string(i) + " has a non-finite endpoint");
    }
    values.emplace_back(Box(segments[i], 0), static_cast<int>(i));
  }
  // The range constructor bulk-loads (packing), which gives a better tree
  // than repeated inserts and the same tree for the same input.
  impl_->tree = bgi::rtree<Value, bgi::rstar<16>>(values.begin(), values.end());
}

SegmentIndex::~SegmentIndex() = default;
SegmentIndex::SegmentIndex(SegmentIndex&&) noexcept = default;
SegmentIndex& SegmentIndex::operator=(SegmentIndex&&) noexcept = default;

int SegmentIndex::size() const { return static_cast<int>(impl_->segments.size()); }

std::vector<int> SegmentIndex::Near(const Segment2D& query, double radius) const {
  std::vector<int> ids = impl_->Query(Box(query, radius));
  ids.erase(
      std::remove_if(ids.begin(), ids.end(),
                     [&](int id) { return SegmentDistance(query, impl_->segments[id]) > radius; }),
      ids.end());
  return ids;
}

std::vector<int> SegmentIndex::Neighbours(int id, double radius) const {
  if (id < 0 || id >= size()) {
    throw Error("SegmentIndex::Neighbours: id " + std::to_string(id) + " out of range");
  }
  std::vector<int> ids = Near(impl_->segments[id], radius);
  ids.erase(std::remove(ids.begin(), ids.end(), id), ids.end());
  return ids;
}

std::vector<int> SegmentIndex::NearPoint(const Eigen::Vector2d& point, double radius) const {
  Segment2D dot;
  dot.p0 = dot.p1 = point;
  return Near(dot, radius);
}

std::vector<int> SegmentIndex::InBox(const Eigen::Vector2d& min, const Eigen::Vector2d& max) const {
  return impl_->Query(BBox(BPoint(min.x(), min.y()), BPoint(max.x(), max.y())));
}

cv::Mat RasterizeSegments(const Segments2D& segments, cv::Size size) {
  if (size.width < 0 || size.height < 0) throw Error("RasterizeSegments: negative size");
  cv::Mat labels(size, CV_32S, cv::Scalar(-1));
  // Drawing the shorter ones first lets the longer ones overwrite them.
  std::vector<int> order(segments.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const double la = segments[a].Length();
    const double lb = segments[b].Length();
    return la != lb ? la < lb : a > b;
  });
  for (int id : order) {
    const Segment2D& s = segments[id];
    if (!s.p0.allFinite() || !s.p1.allFinite()) continue;
    const double length = s.Length();
    const int steps = static_cast<int>(std::ceil(length / 0.25));
    for (int k = 0; k <= steps; ++k) {
      const Eigen::Vector2d p =
          steps == 0 ? s.p0 : Eigen::Vector2d(s.p0 + (s.p1 - s.p0) * k / steps);
      const double fx = std::floor(p.x());
      const double fy = std::floor(p.y());
      if (fx < 0 || fy < 0 || fx >= size.width || fy >= size.height) continue;
      labels.at<int>(static_cast<int>(fy), static_cast<int>(fx)) = id;
    }
  }
  return labels;
}

}  // namespace roofsweep
