#include "algorithms/eval/eval_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace roofsweep {
namespace {

nlohmann::json Num(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return nullptr;
  return *v;
}

std::string Fmt(const std::optional<double>& v, const char* format) {
  if (!v || !std::isfinite(*v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, *v);
  return buf;
}

std::string Pct(const std::optional<double>& v) { return v ? Fmt(*v * 100.0, "%.1f %%") : "n/a"; }

class Table {
 public:
  void Section(const std::string& title) { os_ << "\n" << title << "\n"; }
  void Row(const std::string& name, const std::string& value, const std::string& note = "") {
    char buf[256];
    std::snprintf(buf, sizeof buf, "  %-28s %14s  %s", name.c_str(), value.c_str(), note.c_str());
    std::string line = buf;
    while (!line.empty() && line.back() == ' ') line.pop_back();
    os_ << line << "\n";
  }
  std::string str() const { return os_.str(); }

 private:
  std::ostringstream os_;
};

std::string Of(int a, int b) { return std::to_string(a) + " of " + std::to_string(b); }

// The commonest roof type mistakes, most frequent first (a few lines).
std::vector<std::pair<std::pair<int, int>, int>> RoofTypeMistakes(const BuildingScores& b) {
  std::vector<std::pair<std::pair<int, int>, int>> out;
  for (const auto& [codes, n] : b.roof_type_pairs)
    if (codes.first != codes.second) out.emplace_back(codes, n);
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& x, const auto& y) { return x.second > y.second; });
  if (out.size() > 5) out.resize(5);
  return out;
}

// {"on_outline": {"count": n, "sum_squares_m2": s}, "inside": ..., ...}
nlohmann::json VertexPlacesJson(const GeometryScores& g) {
  static const char* const kKeys[kVertexPlaces] = {"on_outline", "inside", "over_another_roof",
                                                   "over_no_roof"};
  nlohmann::json j = nlohmann::json::object();
  for (int k = 0; k < kVertexPlaces; ++k)
    j[kKeys[k]] = {{"count", g.vertex_place_count[k]}, {"sum_squares_m2", g.vertex_place_sum2[k]}};
  return j;
}

// {"uncovered": {"count": n, "area_m2": a}, "other_slope": ..., ...} (UnmatchedKindKey)
nlohmann::json UnmatchedJson(const UnmatchedPlanes& u) {
  nlohmann::json j = nlohmann::json::object();
  for (int k = 0; k < kUnmatchedKinds; ++k)
    j[UnmatchedKindKey(static_cast<UnmatchedKind>(k))] = {{"count", u.count[k]},
                                                          {"area_m2", u.area_m2[k]}};
  return j;
}

nlohmann::json InputJson(const InputCounts& c) {
  return {{"roof_polygons", c.roof_polygons},
          {"vertical_roof_polygons", c.vertical},
          {"degenerate_roof_polygons", c.degenerate},
          {"invalid_roof_polygons", c.invalid},
          {"downward_roof_polygons", c.downward}};
}

}  // namespace

std::string FormatTable(const EvalResult& r) {
  Table t;
  const auto& p = r.roof_planes;
  const auto& g = r.geometry;
  const auto& b = r.buildings;
  t.Section("Roof planes (overlap >= " + Fmt(r.options.plane_overlap_fraction * 100, "%.0f") +
            " %, normals within " + Fmt(r.options.max_normal_angle_deg, "%.1f") + " deg)");
  t.Row("completeness", Pct(p.completeness), Of(p.tp_reference, p.n_reference) + " reference");
  t.Row("correctness", Pct(p.correctness), Of(p.tp_result, p.n_result) + " result");
  t.Row("quality", Pct(p.quality));
  const std::string large = " >= " + Fmt(r.options.large_plane_m2, "%.0f m2");
  t.Row("completeness" + large, Pct(p.completeness_large),
        Of(p.tp_reference_large, p.n_reference_large) + " reference");
  t.Row("correctness" + large, Pct(p.correctness_large),
        Of(p.tp_result_large, p.n_result_large) + " result");
  t.Row("over-segmented (1:M)", std::to_string(p.n_1_to_m), "reference planes");
  t.Row("under-segmented (N:1)", std::to_string(p.n_n_to_1), "result planes");
  t.Row("N:M clusters", std::to_string(p.n_n_to_m));
  // Why planes went unmatched (UnmatchedKind): where to look first.
  for (const bool result_side : {true, false}) {
    const UnmatchedPlanes& u = result_side ? p.false_result : p.missed_reference;
    t.Row(result_side ? "false result planes" : "missed reference planes",
          std::to_string(result_side ? p.n_result - p.tp_result : p.n_reference - p.tp_reference));
    for (int k = 0; k < kUnmatchedKinds; ++k)
      t.Row(std::string("  ") + UnmatchedKindName(static_cast<UnmatchedKind>(k), result_side),
            std::to_string(u.count[k]), Fmt(u.area_m2[k], "%.0f m2"));
  }
  t.Section("Geometry of matched planes");
  t.Row("matched pairs", std::to_string(g.matched_pairs));
  t.Row("normal angle median", Fmt(g.angle_median_deg, "%.2f deg"));
  t.Row("normal angle RMS", Fmt(g.angle_rms_deg, "%.2f deg"));
  t.Row("vertex RMS XY", Fmt(g.vertex_rms_m, "%.3f m"),
        std::to_string(g.vertices) + " vertices, " + std::to_string(g.vertex_outliers) +
            " beyond " + Fmt(r.options.vertex_max_distance_m, "%.1f m"));
  if (r.options.gsd_m > 0) t.Row("vertex RMS XY", Fmt(g.vertex_rms_gsd, "%.2f GSD"));
  t.Row("vertex distance median", Fmt(g.vertex_median_m, "%.3f m"), "all vertices");
  if (r.options.gsd_m > 0) t.Row("vertices within 2 GSD", Pct(g.vertex_within_2gsd));
  // Where the rest lie: the share of the vertices and of the RMS's sum of
  // squares, by place (VertexPlace).
  {
    int n = 0;
    double sum2 = 0;
    for (int k = 0; k < kVertexPlaces; ++k)
      n += g.vertex_place_count[k], sum2 += g.vertex_place_sum2[k];
    for (int k = 0; k < kVertexPlaces && n > 0; ++k)
      t.Row(std::string("  ") + VertexPlaceName(static_cast<VertexPlace>(k)),
            Fmt(100.0 * g.vertex_place_count[k] / n, "%.1f %%"),
            std::to_string(g.vertex_place_count[k]) + " vertices" +
                (sum2 > 0 ? ", " + Fmt(100.0 * g.vertex_place_sum2[k] / sum2, "%.1f %%") +
                                " of the squares"
                          : ""));
  }
  t.Row("RMSZ", Fmt(g.rmsz_m, "%.3f m"),
        std::to_string(g.rmsz_cells) + " cells of " + Fmt(r.options.rmsz_grid_m, "%.2f m"));
  t.Row("mean dZ (result - ref)", Fmt(g.dz_mean_m, "%+.3f m"));
  t.Section("Buildings (footprint overlap >= " +
            Fmt(r.options.building_overlap_fraction * 100, "%.0f") + " %)");
  t.Row("completeness", Pct(b.completeness), Of(b.tp_reference, b.n_reference) + " reference");
  t.Row("correctness", Pct(b.correctness), Of(b.tp_result, b.n_result) + " result");
  t.Row("quality", Pct(b.quality));
  t.Row(
      "roof top within " + Fmt(r.options.building_top_tolerance_m, "%.1f m"),
      Pct(b.top_compared > 0 ? std::optional<double>(
                                   static_cast<double>(b.top_compared - b.top_off) / b.top_compared)
                             : std::nullopt),
      Of(b.top_compared - b.top_off, b.top_compared) + " found, " +
          (b.top_rms_m ? "RMS " + Fmt(*b.top_rms_m, "%.2f m") : std::string("RMS n/a")));
  t.Row("roof type agreement", Pct(b.roof_type_agreement),
        Of(b.roof_type_same, b.roof_type_compared) + " with known type");
  for (const auto& [codes, n] : RoofTypeMistakes(b))
    t.Row("  " + std::string(RoofTypeName(codes.first)) + " as " + RoofTypeName(codes.second),
          std::to_string(n), "buildings");
  if (r.lines3d.evaluated) {
    const auto& l = r.lines3d;
    t.Section("3D lines (within " + Fmt(r.options.lines.distance_m * 100, "%.0f") + " cm, " +
              Fmt(r.options.lines.angle_deg, "%.0f") + " deg)");
    t.Row("precision", Pct(l.precision),
          Fmt(l.raw.result_on_reference_m, "%.1f") + " of " + Fmt(l.raw.result_length_m, "%.1f m") +
              ", " + std::to_string(l.raw.segments) + " segments");
    if (l.on_clutter)
      t.Row("  of it on clutter", Pct(l.on_clutter), "cars, chimneys, solar panels");
    t.Row("on a surface, no edge", Pct(l.on_surface),
          r.options.lines.ground.Known() ? "texture, shadows (roofs, walls, terrain)"
                                         : "texture, shadows (roofs, walls)");
    t.Row("off every surface", Pct(l.off_surface), "mismatches, trees");
    t.Row(
        "completeness", Pct(l.completeness),
        Fmt(l.raw.reference_covered_m, "%.1f") + " of " + Fmt(l.raw.reference_length_m, "%.1f m"));
    t.Row(
        "roof edge completeness", Pct(l.roof_edge_completeness),
        Fmt(l.raw.roof_edge_covered_m, "%.1f") + " of " + Fmt(l.raw.roof_edge_length_m, "%.1f m"));
  }
  const auto skipped = [](const InputCounts& c) {
    return std::to_string(c.vertical) + " vertical, " + std::to_string(c.degenerate) +
           " degenerate, " + std::to_string(c.invalid) + " invalid";
  };
  t.Section("Roof polygons left out");
  t.Row("result", std::to_string(r.result_input.roof_polygons) + " total", skipped(r.result_input));
  t.Row("reference", std::to_string(r.reference_input.roof_polygons) + " total",
        skipped(r.reference_input));
  return t.str();
}

nlohmann::json ToJson(const EvalResult& r) {
  const auto& p = r.roof_planes;
  const auto& g = r.geometry;
  const auto& b = r.buildings;
  const auto& l = r.lines3d;
  const auto& o = r.options;
  nlohmann::json j;
  j["roof_planes"] = {{"completeness", Num(p.completeness)},
                      {"correctness", Num(p.correctness)},
                      {"quality", Num(p.quality)},
                      {"n_reference", p.n_reference},
                      {"n_result", p.n_result},
                      {"tp_reference", p.tp_reference},
                      {"tp_result", p.tp_result},
                      {"n_1_to_m", p.n_1_to_m},
                      {"n_n_to_1", p.n_n_to_1},
                      {"n_n_to_m", p.n_n_to_m},
                      {"completeness_large", Num(p.completeness_large)},
                      {"correctness_large", Num(p.correctness_large)},
                      {"n_reference_large", p.n_reference_large},
                      {"n_result_large", p.n_result_large},
                      {"tp_reference_large", p.tp_reference_large},
                      {"tp_result_large", p.tp_result_large},
                      {"false_result", UnmatchedJson(p.false_result)},
                      {"missed_reference", UnmatchedJson(p.missed_reference)}};
  j["geometry"] = {{"matched_pairs", g.matched_pairs},
                   {"angle_median_deg", Num(g.angle_median_deg)},
                   {"angle_rms_deg", Num(g.angle_rms_deg)},
                   {"angle_max_deg", Num(g.angle_max_deg)},
                   {"vertex_rms_m", Num(g.vertex_rms_m)},
                   {"vertex_rms_gsd", Num(g.vertex_rms_gsd)},
                   {"vertex_median_m", Num(g.vertex_median_m)},
                   {"vertex_within_2gsd", Num(g.vertex_within_2gsd)},
                   {"vertices", g.vertices},
                   {"vertex_places", VertexPlacesJson(g)},
                   {"vertex_outliers", g.vertex_outliers},
                   {"rmsz_m", Num(g.rmsz_m)},
                   {"dz_mean_m", Num(g.dz_mean_m)},
                   {"rmsz_cells", g.rmsz_cells},
                   {"rmsz_cells_result_only", g.rmsz_cells_result_only},
                   {"rmsz_cells_reference_only", g.rmsz_cells_reference_only}};
  j["buildings"] = {{"completeness", Num(b.completeness)},
                    {"correctness", Num(b.correctness)},
                    {"quality", Num(b.quality)},
                    {"n_reference", b.n_reference},
                    {"n_result", b.n_result},
                    {"tp_reference", b.tp_reference},
                    {"tp_result", b.tp_result},
                    {"top_compared", b.top_compared},
                    {"top_off", b.top_off},
                    {"top_rms_m", Num(b.top_rms_m)},
                    {"roof_type_agreement", Num(b.roof_type_agreement)},
                    {"roof_type_compared", b.roof_type_compared},
                    {"roof_type_same", b.roof_type_same},
                    {"roof_type_pairs", nlohmann::json::array()}};
  for (const auto& [codes, n] : b.roof_type_pairs)
    j["buildings"]["roof_type_pairs"].push_back({{"reference", RoofTypeName(codes.first)},
                                                 {"result", RoofTypeName(codes.second)},
                                                 {"count", n}});
  j["lines3d"] = {{"evaluated", l.evaluated},
                  {"precision", Num(l.precision)},
                  {"completeness", Num(l.completeness)},
                  {"roof_edge_completeness", Num(l.roof_edge_completeness)},
                  {"on_clutter", Num(l.on_clutter)},
                  {"on_surface", Num(l.on_surface)},
                  {"off_surface", Num(l.off_surface)},
                  {"segments", l.raw.segments},
                  {"result_length_m", l.raw.result_length_m},
                  {"reference_length_m", l.raw.reference_length_m},
                  {"roof_edge_length_m", l.raw.roof_edge_length_m}};
  j["input"] = {{"result", InputJson(r.result_input)}, {"reference", InputJson(r.reference_input)}};
  j["options"] = {{"plane_overlap_fraction", o.plane_overlap_fraction},
                  {"max_normal_angle_deg", o.max_normal_angle_deg},
                  {"segmentation_overlap_fraction", o.segmentation_overlap_fraction},
                  {"coplanar_angle_deg", o.planes.coplanar_angle_deg},
                  {"coplanar_distance_m", o.planes.coplanar_distance_m},
                  {"group_gap_m", o.planes.group_gap_m},
                  {"vertical_roof_deg", o.planes.vertical_roof_deg},
                  {"vertex_max_distance_m", o.vertex_max_distance_m},
                  {"gsd_m", o.gsd_m},
                  {"rmsz_grid_m", o.rmsz_grid_m},
                  {"building_overlap_fraction", o.building_overlap_fraction},
                  {"large_plane_m2", o.large_plane_m2},
                  {"line_distance_m", o.lines.distance_m},
                  {"line_angle_deg", o.lines.angle_deg}};
  return j;
}

std::string FormatLod1Table(const Lod1Scores& s) {
  Table t;
  t.Section("LoD1 blocks (footprints without an LoD2 roof; left out of the figures above)");
  t.Row("blocks", std::to_string(s.blocks),
        Of(s.over_reference, s.blocks) + " over a reference building");
  t.Row("found at LoD2 or as a block", Pct(s.found_fraction),
        Of(s.found, s.n_reference) + " reference, " + std::to_string(s.found_by_block_only) +
            " as a block only");
  t.Row("block top RMSZ", Fmt(s.rmsz_m, "%.3f m"),
        s.cells > 0 ? std::to_string(s.cells) + " cells, mean " + Fmt(s.dz_mean_m, "%+.2f m")
                    : std::string());
  t.Row("at the roofs' mean heights", Fmt(s.rmsz_at_mean_m, "%.3f m"),
        "the least a flat block can reach");
  return t.str();
}

nlohmann::json Lod1ToJson(const Lod1Scores& s) {
  return {{"blocks", s.blocks},
          {"over_reference", s.over_reference},
          {"n_reference", s.n_reference},
          {"found", s.found},
          {"found_by_block_only", s.found_by_block_only},
          {"found_fraction", Num(s.found_fraction)},
          {"cells", s.cells},
          {"rmsz_m", Num(s.rmsz_m)},
          {"dz_mean_m", Num(s.dz_mean_m)},
          {"rmsz_at_mean_m", Num(s.rmsz_at_mean_m)}};
}

}  // namespace roofsweep
