#include "algorithms/matching/match_lines.h"

#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <map>
#include <numeric>
#include <random>
#include <sstream>

#include "algorithms/core/error.h"
#include "algorithms/edges/extract_segments.h"
#include "algorithms/matching/assignment.h"
#include "algorithms/matching/colour_balance.h"
#include "algorithms/matching/correlation.h"
#include "algorithms/matching/end_check.h"
#include "algorithms/matching/epipolar.h"
#include "algorithms/matching/junction_completion.h"
#include "algorithms/matching/junction_support.h"
#include "algorithms/matching/line_triangulation.h"
#include "algorithms/matching/residual_test.h"
#include "algorithms/matching/view_features.h"
#include "algorithms/matching/view_support.h"

namespace roofsweep {
namespace {

constexpr double kDeg = M_PI / 180.0;

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Ids of the true edges each segment lies on (both endpoints within 1.5 px
// of the projected edge line, directions within 3 degrees, overlapping it).
std::vector<std::vector<int>> TruthLabels(const ViewFeatures& v, const std::vector<Segment3>& edges,
                                          double min_length) {
  std::vector<std::vector<int>> labels(v.ideal.size());
  const double tol = 1.5, cos_max = std::cos(3 * kDeg);
  for (size_t e = 0; e < edges.size(); ++e) {
    const auto a = ProjectIdeal(v, edges[e].a), b = ProjectIdeal(v, edges[e].b);
    if (!a || !b || (*b - *a).norm() < 2) continue;
    Segment2D pe;
    pe.p0 = *a;
    pe.p1 = *b;
    const Eigen::Vector2d d = pe.Direction(), n(-d.y(), d.x());
    const double len = pe.Length();
    for (int id : v.index->Near(pe, tol)) {
      const Segment2D& s = v.ideal[id];
      if (s.Length() < min_length) continue;
      if (std::abs(s.Direction().dot(d)) < cos_max) continue;
      if (std::abs((s.p0 - pe.p0).dot(n)) > tol || std::abs((s.p1 - pe.p0).dot(n)) > tol) continue;
      const double u = (s.Midpoint() - pe.p0).dot(d);
      if (u < 0 || u > len) continue;
      labels[id].push_back(static_cast<int>(e));
    }
  }
  return labels;
}

bool Shares(const std::vector<int>& a, const std::vector<int>& b) {
  for (int x : a)
    for (int y : b)
      if (x == y) return true;
  return false;
}

// Marks the edges both label lists hold.
void MarkShared(const std::vector<int>& a, const std::vector<int>& b, std::vector<char>* marked) {
  for (int x : a)
    for (int y : b)
      if (x == y) (*marked)[x] = 1;
}

double MarkedLength(const std::vector<char>& marked, const std::vector<Segment3>& edges) {
  double sum = 0;
  for (size_t e = 0; e < edges.size(); ++e)
    if (marked[e]) sum += (edges[e].b - edges[e].a).norm();
  return sum;
}

struct Verified {
  PairHypothesis h;
  std::vector<std::pair<int, int>> support;  // (feature index, segment)
};

}  // namespace

std::vector<Segments2D> ExtractViewSegments(const std::vector<cv::Mat>& images,
                                            const MatchOptions& o,
                                            const EdgeOptions& edge_options) {
  std::vector<Segments2D> out(images.size());
  tbb::parallel_for(size_t{0}, images.size(), [&](size_t v) {
    out[v] = ExtractSegments(images[v], edge_options);
    if (!o.match_texture) {
      Segments2D& s = out[v];
      s.erase(std::remove_if(s.begin(), s.end(), [](const Segment2D& g) { return g.texture; }),
              s.end());
    }
  });
  return out;
}

MatchResult MatchLines(const Block& block, const std::vector<cv::Mat>& images,
                       const MatchOptions& o, const EdgeOptions& edge_options, Progress& progress,
                       const std::vector<Segment3>* truth) {
  MatchResult res;
  const int nv = static_cast<int>(block.views.size());
  if (static_cast<int>(images.size()) != nv)
    throw Error("match: " + std::to_string(images.size()) + " images for " + std::to_string(nv) +
                " views");
  if (nv < 2) {
    res.messages.push_back("match: the block has " + std::to_string(nv) +
                           " view(s); matching needs at least two: no 3D lines");
    return res;
  }
  auto t0 = std::chrono::steady_clock::now();
  ReportOrCancel(progress, 0.0, "edges");
  res.segments = ExtractViewSegments(images, o, edge_options);
  res.timings.edges_s = Seconds(t0);
  for (const auto& s : res.segments) res.funnel.segments += static_cast<long long>(s.size());

  t0 = std::chrono::steady_clock::now();
  ReportOrCancel(progress, 0.2, "flanking regions");
  std::vector<ColourCorrection> balance(nv);
  if (o.colour_balance) balance = EstimateColourBalance(block, images);
  std::vector<ViewFeatures> views(nv);
  tbb::parallel_for(0, nv, [&](int v) {
    views[v] = PrepareView(block, v, images[v], res.segments[v], o, balance[v]);
  });
  res.timings.features_s = Seconds(t0);

  std::vector<std::vector<std::vector<int>>> labels;
  if (truth) {
    labels.resize(nv);
    tbb::parallel_for(0, nv,
                      [&](int v) { labels[v] = TruthLabels(views[v], *truth, o.min_length); });
    res.truth_edges.assign(truth->size(), TruthEdgeReach{});
    for (int v = 0; v < nv; ++v) {
      std::vector<char> seen(truth->size(), 0);
      for (const std::vector<int>& ls : labels[v])
        for (int e : ls) seen[e] = 1;
      for (size_t e = 0; e < truth->size(); ++e) res.truth_edges[e].views += seen[e];
    }
    res.funnel.true_all = res.funnel.true_geometric = res.funnel.true_chromatic =
        res.funnel.true_correlation = res.funnel.true_verified = res.funnel.true_unambiguous =
            res.funnel.true_assigned = 0;
  }

  std::vector<char> edges_all, edges_geometric, edges_chromatic, edges_correlation, edges_verified,
      edges_unambiguous, edges_assigned;
  if (truth) {
    for (auto* m : {&edges_all, &edges_geometric, &edges_chromatic, &edges_correlation,
                    &edges_verified, &edges_unambiguous, &edges_assigned})
      m->assign(truth->size(), 0);
  }
  auto mark = [&](const PairHypothesis& h, std::vector<char>* m) {
    MarkShared(labels[h.vi][h.si], labels[h.vj][h.sj], m);
  };
  // With truth: the first two observations of a line carry one simulated edge.
  auto OnATrueEdge = [&](const Line3D& l) {
    const auto& [v0, s0] = l.observations[0];
    const auto& [v1, s1] = l.observations[1];
    return Shares(labels[v0][s0], labels[v1][s1]);
  };
  const auto z_range = SceneHeightRange(block, o.height_margin_m);
  t0 = std::chrono::steady_clock::now();
  std::vector<Verified> hyps;
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < nv; ++i)
    for (int j = i + 1; j < nv; ++j) pairs.emplace_back(i, j);
  int pair_no = 0;
  int identical = 0;
  for (const auto& [i, j] : pairs) {
    ReportOrCancel(progress, 0.25 + 0.5 * pair_no++ / pairs.size(), "candidates");
    const PairGeometry g = MakePairGeometry(views[i], views[j]);
    if (!g.valid) {
      ++identical;
      continue;
    }
    const int ns = static_cast<int>(views[i].ideal.size());
    std::vector<std::vector<PairHypothesis>> cand(ns);
    std::vector<char> skipped(ns, 0);
    tbb::parallel_for(0, ns, [&](int s) {
      if (views[i].ideal[s].Length() < o.min_length) return;
      if (EpipolarAngle(g.e_i, views[i].ideal[s]) < o.min_epipolar_angle) {
        skipped[s] = 1;
        return;
      }
      cand[s] = GeometricCandidates(views[i], views[j], i, j, g, s, z_range, o);
    });
    long long geometric = 0;
    for (int s = 0; s < ns; ++s) {
      geometric += static_cast<long long>(cand[s].size());
      res.funnel.skipped_epipolar += skipped[s];
    }
    if (geometric == 0) continue;
    ++res.funnel.view_pairs;
    res.funnel.geometric += geometric;

    // Side pairs: left of si goes with left of sj unless sj is reversed.
    auto side_j = [](const PairHypothesis& h, int side) { return h.reversed ? 1 - side : side; };
    ChromaticThresholds thr;
    if (o.mean_threshold > 0 && o.cov_threshold > 0) {
      thr.mean = o.mean_threshold;
      thr.cov = o.cov_threshold;
    } else {
      std::vector<int> with;
      for (int s = 0; s < ns; ++s)
        if (!cand[s].empty()) with.push_back(s);
      std::mt19937 rng(o.seed + static_cast<unsigned>(i * 1000 + j));
      std::shuffle(with.begin(), with.end(), rng);
      with.resize(std::min<size_t>(with.size(), static_cast<size_t>(o.init_segments)));
      // Per random segment, the candidate side that correlates best in a*b*
      // (§3.4's measure, which is blind to the statistics being calibrated):
      // most such pairs are correct, so the median of their statistics
      // describes correct pairs. (Taking the candidate with the smallest
      // statistics instead picks the minimum over many candidates and gave
      // thresholds that rejected 60 % of the correct pairs.)
      // In parallel over the sampled segments (serial, this was a quarter of
      // the candidate stage); collected in sampling order, as before.
      std::vector<std::pair<double, double>> sampled(with.size(), {-1.0, -1.0});
      tbb::parallel_for(0, static_cast<int>(with.size()), [&](int w) {
        const int s = with[w];
        double best_h = o.init_min_correlation, bm = -1, bc = -1;
        for (PairHypothesis h : cand[s])
          for (int side = 0; side < 2; ++side) {
            const SideColour& a = views[i].sides[s][side];
            const SideColour& b = views[j].sides[h.sj][side_j(h, side)];
            if (!a.valid || !b.valid) continue;
            if (!o.init_from_best_correlation) {
              // The most similar candidate side (the minimum statistics).
              const double m = MeanStatistic(a, b, o.max_test_pixels);
              const double c = CovStatistic(a, b, o.max_test_pixels);
              bm = bm < 0 ? m : std::min(bm, m);
              bc = bc < 0 ? c : std::min(bc, c);
              continue;
            }
            const double hc = SideCorrelation(views[i], views[j], g, h, side, o);
            if (hc > best_h) {
              best_h = hc;
              bm = MeanStatistic(a, b, o.max_test_pixels);
              bc = CovStatistic(a, b, o.max_test_pixels);
            }
          }
        sampled[w] = {bm, bc};
      });
      std::vector<std::pair<double, double>> stats;
      for (const auto& mc : sampled)
        if (mc.first >= 0) stats.push_back(mc);
      thr = InitThresholds(stats, o.threshold_factor);
    }

    std::vector<std::array<long long, 3>> counts(ns, {0, 0, 0});
    std::vector<std::array<long long, 3>> tcounts(ns, {0, 0, 0});
    // With truth, each true pair's partner and the last stage it passed
    // (0 geometric, 1 chromatic, 2 correlation), marked on the edges after
    // the parallel loop.
    std::vector<std::vector<std::pair<int, int>>> reached(ns);
    tbb::parallel_for(0, ns, [&](int s) {
      std::vector<PairHypothesis> kept;
      for (PairHypothesis& h : cand[s]) {
        const bool is_true = truth && Shares(labels[i][s], labels[j][h.sj]);
        h.true_pair = truth ? (is_true ? 1 : 0) : -1;
        if (is_true) {
          ++tcounts[s][0];
          reached[s].emplace_back(h.sj, 0);
        }
        for (int side = 0; side < 2; ++side)
          if (SidesCompatible(views[i].sides[s][side], views[j].sides[h.sj][side_j(h, side)], thr,
                              o.max_test_pixels))
            h.sides |= 1 << side;
        if (h.sides == 0) continue;
        ++counts[s][1];
        if (is_true) {
          ++tcounts[s][1];
          reached[s].back().second = 1;
        }
        double best = -9;
        for (int side = 0; side < 2; ++side) {
          if (!(h.sides & (1 << side))) continue;
          h.corr[side] = SideCorrelation(views[i], views[j], g, h, side, o);
          best = std::max(best, h.corr[side]);
        }
        if (!(best > o.min_correlation)) continue;
        h.score = best;
        ++counts[s][2];
        if (is_true) {
          ++tcounts[s][2];
          reached[s].back().second = 2;
        }
        kept.push_back(h);
      }
      cand[s] = std::move(kept);
    });
    for (int s = 0; s < ns; ++s) {
      res.funnel.chromatic += counts[s][1];
      res.funnel.correlation += counts[s][2];
      if (truth) {
        res.funnel.true_geometric += tcounts[s][0];
        res.funnel.true_chromatic += tcounts[s][1];
        res.funnel.true_correlation += tcounts[s][2];
        for (const auto& [sj, stage] : reached[s]) {
          MarkShared(labels[i][s], labels[j][sj], &edges_geometric);
          if (stage >= 1) MarkShared(labels[i][s], labels[j][sj], &edges_chromatic);
          if (stage >= 2) MarkShared(labels[i][s], labels[j][sj], &edges_correlation);
        }
      }
      for (PairHypothesis& h : cand[s]) hyps.push_back({h, {}});
    }
    if (truth) {
      // Which edges both views hold, and whether a segment of view i on
      // one meets the epipolar lines steeply enough to be tried.
      std::vector<char> in_j(truth->size(), 0), in_both(truth->size(), 0), tried(truth->size(), 0);
      for (const std::vector<int>& ls : labels[j])
        for (int e : ls) in_j[e] = 1;
      for (int s = 0; s < ns; ++s)
        for (int e : labels[i][s])
          if (in_j[e]) {
            in_both[e] = 1;
            tried[e] = tried[e] || !skipped[s];
          }
      for (size_t e = 0; e < truth->size(); ++e)
        if (in_both[e]) {
          ++res.truth_edges[e].view_pairs;
          res.truth_edges[e].along_epipolar += !tried[e];
        }
      MatchOptions loose = o;
      loose.max_angle_deviation = 90;
      for (int s = 0; s < ns; ++s) {
        if (labels[i][s].empty()) continue;
        if (skipped[s] || views[i].ideal[s].Length() < o.min_length) continue;
        // Eligible: on the same true edge and overlapping along it by the
        // minimum common length (fragments of one edge that do not overlap
        // are no correspondence), whatever the angle and height limits.
        for (const PairHypothesis& h :
             GeometricCandidates(views[i], views[j], i, j, g, s, std::nullopt, loose))
          if (Shares(labels[i][s], labels[j][h.sj])) {
            ++res.funnel.true_all;
            MarkShared(labels[i][s], labels[j][h.sj], &edges_all);
          }
      }
    }
  }
  res.timings.candidates_s = Seconds(t0);
  if (identical > 0)
    res.messages.push_back("match: " + std::to_string(identical) +
                           " view pair(s) share a projection centre (no stereo): skipped");
  if (res.funnel.view_pairs == 0) {
    res.messages.push_back(
        "match: no pair of views with distinct centres and overlapping epipolar strips: no 3D "
        "lines");
    return res;
  }

  // Verification in the other views.
  t0 = std::chrono::steady_clock::now();
  ReportOrCancel(progress, 0.8, "verification");
  std::vector<char> accepted(hyps.size(), 0);
  tbb::parallel_for(size_t{0}, hyps.size(), [&](size_t n) {
    Verified& vh = hyps[n];
    const PairHypothesis& h = vh.h;
    const ViewSupport vs = SupportInViews(views, h.line, {h.vi, h.vj}, o);
    vh.support = vs.segments;
    accepted[n] = vs.Accepted(o);
    vh.h.score += static_cast<double>(vh.support.size());
  });
  std::vector<Verified> kept;
  for (size_t n = 0; n < hyps.size(); ++n)
    if (accepted[n]) kept.push_back(std::move(hyps[n]));
  hyps = std::move(kept);
  res.funnel.verified = static_cast<long long>(hyps.size());
  if (truth)
    for (const Verified& v : hyps) {
      res.funnel.true_verified += v.h.true_pair == 1;
      if (v.h.true_pair == 1) mark(v.h, &edges_verified);
    }
  res.timings.verify_s = Seconds(t0);

  // One-to-one assignment.
  t0 = std::chrono::steady_clock::now();
  std::vector<AssignmentItem> items(hyps.size());
  for (size_t n = 0; n < hyps.size(); ++n) {
    items[n].score = hyps[n].h.score;
    items[n].keys = {{hyps[n].h.vi, hyps[n].h.si}, {hyps[n].h.vj, hyps[n].h.sj}};
    for (const auto& s : hyps[n].support) items[n].keys.push_back(s);
  }
  if (o.junction_ranking) {
    std::vector<Segment3> segs(hyps.size());
    std::vector<std::vector<std::pair<int, int>>> keys(hyps.size());
    for (size_t n = 0; n < hyps.size(); ++n) {
      segs[n] = hyps[n].h.line;
      keys[n] = items[n].keys;
    }
    JunctionSupportOptions jo;
    jo.distance_m = o.junction_rank_distance_m;
    const std::vector<int> ends = JunctionSupport(segs, keys, jo);
    for (size_t n = 0; n < hyps.size(); ++n) {
      const double support = static_cast<double>(hyps[n].support.size());
      const double correlation = hyps[n].h.score - support;
      items[n].score = support + (ends[n] + correlation) / 3.0;
    }
  }
  if (o.unique_matches) {
    const std::vector<char> unique = UnambiguousItems(items);
    for (size_t n = 0; n < items.size(); ++n)
      if (!unique[n]) items[n].keys.clear();
  }
  for (size_t n = 0; n < items.size(); ++n)
    if (!items[n].keys.empty()) {
      ++res.funnel.unambiguous;
      if (truth && hyps[n].h.true_pair == 1) {
        ++res.funnel.true_unambiguous;
        mark(hyps[n].h, &edges_unambiguous);
      }
    }
  const auto assigned = AssignOneToOne(items);
  res.timings.assign_s = Seconds(t0);

  // 3D estimation.
  t0 = std::chrono::steady_clock::now();
  ReportOrCancel(progress, 0.9, "triangulation");
  auto observe = [&](int v, int s) {
    return LineObservation{views[v].P, views[v].ideal[s].p0, views[v].ideal[s].p1};
  };
  std::vector<int> track_of;
  for (size_t n = 0; n < hyps.size(); ++n)
    if (!assigned[n].empty()) track_of.push_back(static_cast<int>(n));
  res.funnel.assigned = static_cast<long long>(track_of.size());
  if (truth)
    for (int n : track_of) {
      res.funnel.true_assigned += hyps[n].h.true_pair == 1;
      if (hyps[n].h.true_pair == 1) mark(hyps[n].h, &edges_assigned);
    }
  if (truth) {
    res.funnel.true_edges_all_m = MarkedLength(edges_all, *truth);
    const std::vector<char>* stages[] = {&edges_all,         &edges_geometric, &edges_chromatic,
                                         &edges_correlation, &edges_verified,  &edges_unambiguous,
                                         &edges_assigned};
    for (size_t e = 0; e < truth->size(); ++e)
      for (size_t k = 0; k < std::size(stages); ++k)
        if ((*stages[k])[e]) res.truth_edges[e].stage = static_cast<int>(k) + 1;
    res.funnel.true_edges_geometric_m = MarkedLength(edges_geometric, *truth);
    res.funnel.true_edges_chromatic_m = MarkedLength(edges_chromatic, *truth);
    res.funnel.true_edges_correlation_m = MarkedLength(edges_correlation, *truth);
    res.funnel.true_edges_verified_m = MarkedLength(edges_verified, *truth);
    res.funnel.true_edges_unambiguous_m = MarkedLength(edges_unambiguous, *truth);
    res.funnel.true_edges_assigned_m = MarkedLength(edges_assigned, *truth);
  }
  std::vector<Line3D> lines(track_of.size());
  std::vector<char> ok(track_of.size(), 0);
  auto estimate = [&](const std::vector<std::pair<int, int>>& obs_keys, const Segment3& init,
                      Line3D* line) {
    std::vector<LineObservation> obs;
    for (const auto& [v, s] : obs_keys) obs.push_back(observe(v, s));
    const LineEstimate est = TriangulateLine(obs, init);
    if (!est.valid || est.rms_px > o.max_residual) return false;
    line->segment = est.segment;
    if (z_range && !z_range->Clip(&line->segment)) return false;
    line->rms_px = est.rms_px;
    line->observations = obs_keys;
    // Orient like the first observation.
    const auto& [v0, s0] = obs_keys.front();
    const auto pa = ProjectIdeal(views[v0], line->segment.a),
               pb = ProjectIdeal(views[v0], line->segment.b);
    if (pa && pb && (*pb - *pa).dot(views[v0].ideal[s0].p1 - views[v0].ideal[s0].p0) < 0)
      std::swap(line->segment.a, line->segment.b);
    line->colour_left = res.segments[v0][s0].colour_left;
    line->colour_right = res.segments[v0][s0].colour_right;
    return true;
  };
  tbb::parallel_for(size_t{0}, track_of.size(), [&](size_t k) {
    const Verified& vh = hyps[track_of[k]];
    ok[k] =
        estimate(assigned[track_of[k]], vh.h.line, &lines[k]) && lines[k].Views() >= o.min_views;
  });
  std::vector<Line3D> good;
  for (size_t k = 0; k < lines.size(); ++k)
    if (ok[k]) good.push_back(std::move(lines[k]));
  res.funnel.lines_before_merge = static_cast<int>(good.size());

  // Merge collinear fragments (union-find over close, parallel, overlapping
  // or nearly touching lines), then re-estimate from all observations.
  const int nl = static_cast<int>(good.size());
  std::vector<int> parent(nl);
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) {
    return parent[x] == x ? x : parent[x] = find(parent[x]);
  };
  const double cos_merge = std::cos(o.merge_angle * kDeg);
  std::vector<int> by_x(nl);
  std::iota(by_x.begin(), by_x.end(), 0);
  auto minx = [&](int k) { return std::min(good[k].segment.a.x(), good[k].segment.b.x()); };
  auto maxx = [&](int k) { return std::max(good[k].segment.a.x(), good[k].segment.b.x()); };
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return minx(a) < minx(b); });
  for (int ia = 0; ia < nl; ++ia) {
    const int a = by_x[ia];
    const Segment3& A = good[a].segment;
    for (int ib = ia + 1; ib < nl; ++ib) {
      const int b = by_x[ib];
      if (minx(b) > maxx(a) + o.merge_gap_m) break;
      const Segment3& B = good[b].segment;
      if (std::abs(A.Direction().dot(B.Direction())) < cos_merge) continue;
      const Eigen::Vector3d d = A.Direction();
      auto off = [&](const Eigen::Vector3d& p) {
        const Eigen::Vector3d w = p - A.a;
        return (w - w.dot(d) * d).norm();
      };
      if (off(B.a) > o.merge_distance_m || off(B.b) > o.merge_distance_m) continue;
      const double la = 0, lb = A.Length();
      const double u0 = (B.a - A.a).dot(d), u1 = (B.b - A.a).dot(d);
      const double gap = std::max(std::min(u0, u1) - lb, la - std::max(u0, u1));
      if (gap > o.merge_gap_m) continue;
      // Two fragments seen in the same view as different segments may still
      // be one line; the observations are merged as they are.
      parent[find(a)] = find(b);
    }
  }
  std::map<int, std::vector<int>> groups;
  for (int k = 0; k < nl; ++k) groups[find(k)].push_back(k);
  for (auto& [root, members] : groups) {
    if (members.size() == 1) {
      res.lines.push_back(good[members[0]]);
      continue;
    }
    std::vector<std::pair<int, int>> keys;
    int longest = members[0];
    for (int m : members) {
      if (good[m].segment.Length() > good[longest].segment.Length()) longest = m;
      for (const auto& k : good[m].observations)
        if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
    }
    Line3D merged;
    if (estimate(keys, good[longest].segment, &merged)) {
      res.lines.push_back(merged);
    } else {
      for (int m : members) res.lines.push_back(good[m]);
    }
  }
  if (o.residual_alpha > 0) {
    std::vector<LineFitResidual> fits;
    for (const Line3D& l : res.lines) fits.push_back({l.rms_px, l.Views()});
    const ResidualNoise noise = EstimateResidualNoise(fits);
    res.funnel.residual_sigma_px = noise.sigma_px;
    res.funnel.residual_lines = noise.lines;
    if (truth) res.funnel.residual_rejected_true = 0;
    auto consistent_fit = [&](const Line3D& l) {
      return ResidualConsistent({l.rms_px, l.Views()}, noise.sigma_px, o.residual_alpha);
    };
    // A line that fails loses its worst supporting observation (a view with
    // a larger orientation error, a neighbouring segment taken as support)
    // and is tested again, as a track is cleaned of outlying observations in
    // bundle adjustment; but only while the verification's minimum support
    // remains besides the matched pair (observations 0 and 1), so that a
    // wrong pair cannot shed the views that contradict it.
    const int min_observations = 2 + std::max(1, o.min_support_segments);
    tbb::parallel_for(size_t{0}, res.lines.size(), [&](size_t k) {
      Line3D& l = res.lines[k];
      while (!consistent_fit(l) && l.Views() > min_observations) {
        size_t worst = 2;
        double worst_r2 = -1;
        for (size_t m = 2; m < l.observations.size(); ++m) {
          const auto& [v, s] = l.observations[m];
          const double r2 = LineResidual(observe(v, s), l.segment.a, l.segment.b).squaredNorm();
          if (r2 > worst_r2) {
            worst_r2 = r2;
            worst = m;
          }
        }
        std::vector<std::pair<int, int>> keys = l.observations;
        keys.erase(keys.begin() + static_cast<long>(worst));
        Line3D pruned;
        if (!estimate(keys, l.segment, &pruned)) break;
        l = std::move(pruned);
      }
    });
    std::vector<Line3D> consistent;
    for (Line3D& l : res.lines) {
      if (consistent_fit(l)) {
        consistent.push_back(std::move(l));
        continue;
      }
      ++res.funnel.residual_rejected;
      if (truth) res.funnel.residual_rejected_true += OnATrueEdge(l);
    }
    res.lines = std::move(consistent);
  }
  if (o.check_ends) {
    std::vector<double> cut(res.lines.size(), 0);
    tbb::parallel_for(size_t{0}, res.lines.size(),
                      [&](size_t k) { cut[k] = CutUnconfirmedEnds(views, o, &res.lines[k]); });
    for (double c : cut)
      if (c > 0) {
        ++res.funnel.ends_cut;
        res.funnel.ends_cut_m += c;
      }
  }
  if (o.junction_completion) {
    JunctionCompletion jc = CompleteAtJunctions(views, res.lines, z_range, o);
    res.funnel.junction_candidates = jc.candidates;
    res.funnel.junction_verified = jc.verified;
    res.funnel.junction_lines = static_cast<int>(jc.lines.size());
    res.funnel.junction_horizontal = jc.horizontal;
    if (truth) {
      res.funnel.junction_true = 0;
      for (const Line3D& l : jc.lines) res.funnel.junction_true += OnATrueEdge(l);
    }
    for (Line3D& l : jc.lines) res.lines.push_back(std::move(l));
  }
  res.funnel.lines = static_cast<int>(res.lines.size());
  res.timings.triangulate_s = Seconds(t0);
  ReportOrCancel(progress, 1.0, "done");
  return res;
}

const char* DepthFrom(const Line3D& line) {
  if (!line.from_junctions) return "stereo";
  return line.horizontal_assumed ? "junction_horizontal" : "junctions";
}

std::string FormatFunnel(const MatchFunnel& f) {
  std::ostringstream out;
  char buf[200];
  out << "Reduction of match candidates (Scholze et al. 2000, sec. 4), " << f.view_pairs
      << " view pairs, " << f.segments << " segments:\n";
  const bool t = f.true_all >= 0;
  std::snprintf(buf, sizeof buf, "  %-28s %12s%s\n", "stage", "pairs",
                t ? "   true pairs  kept   true edges (m)  kept" : "");
  out << buf;
  auto row = [&](const char* name, long long n, long long tn, double edges_m = -1) {
    if (t) {
      std::snprintf(buf, sizeof buf, "  %-28s %12lld %12lld %5.1f%%", name, n, tn,
                    f.true_all > 0 ? 100.0 * tn / f.true_all : 0.0);
      out << buf;
      if (edges_m >= 0) {
        std::snprintf(buf, sizeof buf, " %16.1f %5.1f%%", edges_m,
                      f.true_edges_all_m > 0 ? 100.0 * edges_m / f.true_edges_all_m : 0.0);
        out << buf;
      }
      out << "\n";
    } else {
      std::snprintf(buf, sizeof buf, "  %-28s %12lld\n", name, n);
      out << buf;
    }
  };
  if (t) row("eligible true pairs", -1, f.true_all, f.true_edges_all_m);
  row("geometric", f.geometric, f.true_geometric, f.true_edges_geometric_m);
  row("chromatic (integrated)", f.chromatic, f.true_chromatic, f.true_edges_chromatic_m);
  row("chromatic correlation", f.correlation, f.true_correlation, f.true_edges_correlation_m);
  row("verified in other views", f.verified, f.true_verified, f.true_edges_verified_m);
  row("unambiguous", f.unambiguous, f.true_unambiguous, f.true_edges_unambiguous_m);
  row("one-to-one (final)", f.assigned, f.true_assigned, f.true_edges_assigned_m);
  std::snprintf(buf, sizeof buf, "  3D lines: %d (before merging collinear fragments: %d)\n",
                f.lines, f.lines_before_merge);
  out << buf;
  std::snprintf(buf, sizeof buf, "  segment/pair combinations skipped as nearly epipolar: %lld\n",
                f.skipped_epipolar);
  out << buf;
  if (f.residual_sigma_px > 0) {
    std::snprintf(buf, sizeof buf,
                  "  residual test: noise %.3f px (from %d lines in 3+ views), %d lines "
                  "rejected",
                  f.residual_sigma_px, f.residual_lines, f.residual_rejected);
    out << buf;
    if (f.residual_rejected_true >= 0) {
      std::snprintf(buf, sizeof buf, " (%d of them on a true edge)", f.residual_rejected_true);
      out << buf;
    }
    out << "\n";
  } else if (f.residual_lines >= 0) {
    std::snprintf(buf, sizeof buf, "  residual test: not run (%d lines in 3+ views)\n",
                  f.residual_lines);
    out << buf;
  }
  std::snprintf(buf, sizeof buf,
                "  ends no stereo pair holds, not confirmed at the line's depth: %d lines cut "
                "back by %.1f m\n",
                f.ends_cut, f.ends_cut_m);
  out << buf;
  std::snprintf(buf, sizeof buf,
                "  junction completion: %lld unused segments anchored at both ends (or at one), "
                "%lld verified, %d 3D lines added (%d of them horizontal from one junction)",
                f.junction_candidates, f.junction_verified, f.junction_lines,
                f.junction_horizontal);
  out << buf;
  if (f.junction_true >= 0) {
    std::snprintf(buf, sizeof buf, ", %d on a true edge", f.junction_true);
    out << buf;
  }
  out << "\n";
  return out.str();
}

}  // namespace roofsweep
