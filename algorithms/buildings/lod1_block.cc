#include "algorithms/buildings/lod1_block.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "algorithms/buildings/polygon2.h"
#include "algorithms/buildings/solid_check.h"
#include "algorithms/core/format.h"

namespace roofsweep {

Lod1Height Lod1HeightFromLines(const Ring2& outline, double ground_z, double max_height_m,
                               const std::vector<Segment3>& lines, const Lod1Options& o) {
  Lod1Height h;
  if (outline.size() < 3 || !std::isfinite(ground_z)) return h;
  auto over = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector2d q = x.head<2>();
    return InsideRing(outline, q) || DistanceToRing(outline, q) <= o.line_margin_m;
  };
  const double z_lo = ground_z + o.min_height_m, z_hi = ground_z + max_height_m;
  const double max_rise = std::tan(o.max_slope_deg * M_PI / 180.0);
  Eigen::Vector4d box = RingBounds(outline);
  box += Eigen::Vector4d(-o.line_margin_m, -o.line_margin_m, o.line_margin_m, o.line_margin_m);
  // Heights along each line at a fixed step, each sample weighted by the
  // length it stands for, where the line lies over the footprint: an eave
  // running on along a terrace counts for each house by its stretch, and a
  // sloped verge spreads its weight between eave and ridge as the roof's
  // area does.
  constexpr double kStep = 0.25;
  struct Stretch {
    std::vector<double> z;  // sorted
    double weight = 0;      // per sample (m)
  };
  std::vector<Stretch> stretches;
  for (const Segment3& l : lines) {
    const double za = l.a.z(), zb = l.b.z();
    if (!(za >= z_lo && zb >= z_lo && za <= z_hi && zb <= z_hi)) continue;
    if (!BoundsMeet(box, Eigen::Vector4d(std::min(l.a.x(), l.b.x()), std::min(l.a.y(), l.b.y()),
                                         std::max(l.a.x(), l.b.x()), std::max(l.a.y(), l.b.y()))))
      continue;
    const double run = (l.b - l.a).head<2>().norm();
    if (std::abs(zb - za) > max_rise * run) continue;
    const double len = l.Length();
    const int n = std::max(1, static_cast<int>(std::ceil(len / kStep)));
    Stretch st;
    st.weight = len / n;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d x = l.At((k + 0.5) / n);
      if (over(x)) st.z.push_back(x.z());
    }
    if (st.weight * static_cast<double>(st.z.size()) < o.min_line_length_m) continue;
    std::sort(st.z.begin(), st.z.end());
    stretches.push_back(std::move(st));
  }
  // The weighted quantile q of the stretches' heights (NaN for none).
  auto quantile = [&](double q) {
    std::vector<std::pair<double, double>> samples;  // z, weight
    double total = 0;
    for (const Stretch& st : stretches)
      for (double z : st.z) samples.emplace_back(z, st.weight), total += st.weight;
    if (samples.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(samples.begin(), samples.end());
    double acc = 0;
    for (const auto& [z, w] : samples)
      if ((acc += w) >= q * total) return z;
    return samples.back().first;  // rounding at q = 1
  };
  // A few short lines matched at a wrong height can outweigh the roof's
  // own (on `hard`, 1.6 m of line 41 m above a house 11 m high made its
  // block 42 m high): stretches that lie wholly farther than max_spread_m
  // from the median height go.
  const double median = quantile(0.5);
  stretches.erase(std::remove_if(stretches.begin(), stretches.end(),
                                 [&](const Stretch& st) {
                                   return st.z.front() > median + o.max_spread_m ||
                                          st.z.back() < median - o.max_spread_m;
                                 }),
                  stretches.end());
  for (const Stretch& st : stretches) {
    ++h.lines;
    h.length_m += st.weight * static_cast<double>(st.z.size());
  }
  if (h.lines < o.min_lines || h.length_m < o.min_length_m) return h;
  h.z = quantile(o.quantile);
  return h;
}

Building Lod1Block(const Ring2& outline, double ground_z, double roof_z) {
  Building b;
  b.lod = 1;
  Polygon3 floor, roof;
  for (auto it = outline.rbegin(); it != outline.rend(); ++it)
    floor.exterior.emplace_back(it->x(), it->y(), ground_z);
  for (const auto& p : outline) roof.exterior.emplace_back(p.x(), p.y(), roof_z);
  b.surfaces.push_back({SurfaceType::kGround, "", {floor}});
  b.surfaces.push_back({SurfaceType::kRoof, "", {roof}});
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector2d& p = outline[i];
    const Eigen::Vector2d& q = outline[(i + 1) % outline.size()];
    Polygon3 wall;
    wall.exterior = {{p.x(), p.y(), ground_z},
                     {q.x(), q.y(), ground_z},
                     {q.x(), q.y(), roof_z},
                     {p.x(), p.y(), roof_z}};
    b.surfaces.push_back({SurfaceType::kWall, "", {wall}});
  }
  b.measured_height = roof_z - ground_z;
  return b;
}

Lod1Counts AddLod1Blocks(const std::vector<Footprint>& footprints, const GroundModel& ground,
                         double max_building_height_m, const std::vector<Segment3>& lines,
                         const Lod1Options& o, AssemblyResult* assembled) {
  CityModel* model = &assembled->model;
  Lod1Counts counts;
  std::set<std::string> built;
  for (const Building& b : model->buildings) {
    const auto it = b.string_attributes.find("footprint_id");
    if (it != b.string_attributes.end()) built.insert(it->second);
  }
  // Pieces of one id (a multipolygon footprint) in footprint order.
  std::vector<std::string> order;
  std::map<std::string, std::vector<size_t>> pieces;
  for (size_t f = 0; f < footprints.size(); ++f) {
    if (built.count(footprints[f].id)) continue;
    auto& list = pieces[footprints[f].id];
    if (list.empty()) order.push_back(footprints[f].id);
    list.push_back(f);
  }
  counts.footprints_without = static_cast<int>(order.size());
  for (const std::string& id : order) {
    const auto reason = assembled->footprint_rejection.find(id);
    const bool has_reason = reason != assembled->footprint_rejection.end();
    Building whole;
    int n_lines = 0, courtyards = 0;
    double length = 0, area = 0;
    for (size_t fi : pieces[id]) {
      const Footprint* f = &footprints[fi];
      double ground_z = std::numeric_limits<double>::infinity();
      for (const auto& p : f->outline) ground_z = std::min(ground_z, ground.HeightAt(p.x(), p.y()));
      const Lod1Height h =
          Lod1HeightFromLines(f->outline, ground_z, max_building_height_m, lines, o);
      if (!(h.z > ground_z)) continue;
      Building block = Lod1Block(f->outline, ground_z, h.z);
      if (!CheckBuildingSolid(block).Valid()) continue;  // a degenerate outline
      whole.parts.push_back(std::move(block));
      n_lines += h.lines;
      length += h.length_m;
      area += SignedArea(f->outline);
      courtyards += f->holes;
    }
    if (whole.parts.empty()) continue;
    Building b;
    if (whole.parts.size() == 1) {
      b = std::move(whole.parts[0]);
    } else {
      b = std::move(whole);
      b.lod = 1;
      for (size_t k = 0; k < b.parts.size(); ++k) {
        b.parts[k].id = StrFormat("rs_l%04d_p%zu", counts.blocks + 1, k + 1);
        b.measured_height = std::max(b.measured_height, b.parts[k].measured_height);
      }
    }
    ++counts.blocks;
    b.id = StrFormat("rs_l%04d", counts.blocks);
    const std::string why = has_reason ? reason->second.why : std::string("no LoD2 building kept");
    b.string_attributes["footprint_id"] = id;
    b.string_attributes["outline"] =
        courtyards > 0 ? StrFormat("footprint (%d courtyards not modelled)", courtyards)
                       : std::string("footprint");
    b.string_attributes["lod1_reason"] = why;
    b.double_attributes["supporting_lines"] = n_lines;
    b.double_attributes["lod1_line_length_m"] = length;
    b.double_attributes["footprint_m2"] = area;
    if (has_reason && reason->second.line < assembled->rejected.size())
      assembled->rejected[reason->second.line] += "; a flat block instead (LoD1)";
    model->buildings.push_back(std::move(b));
  }
  return counts;
}

}  // namespace roofsweep
