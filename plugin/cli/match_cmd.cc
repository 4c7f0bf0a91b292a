#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/match_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Match(const std::vector<std::string>& args, Context& ctx) {
  MatchRequest r;
  bool init_best = false, no_junctions = false, no_junction_ranking = false;
  int seed = static_cast<int>(r.match.seed);
  ArgParser p("match",
              "Matches straight colour edge segments across the views of a block and writes 3D "
              "lines (Scholze et al. 2000): geometric, chromatic and correlation tests, "
              "verification in the other views, one-to-one assignment, least-squares lines.");
  p.Positional("BLOCK", &r.block, "block manifest, folder holding block.json, or FORMAT:SOURCE")
      .Option("-o", &r.output, "FILE", "output with a LineStringZ layer lines3d (.gpkg, .fgb, ...)")
      .Option("-of|-f", &r.format, "FORMAT", "GDAL vector driver, when the extension does not tell")
      .KeyValues("-dsco", &r.dataset_options,
                 "GDAL dataset creation option (e.g. GPKG VERSION=1.2)")
      .KeyValues("-lco", &r.layer_options,
                 "GDAL layer creation option (e.g. GPKG SPATIAL_INDEX=NO, FID=fid)")
      .Flag("-overwrite", &r.overwrite, "replace an existing output file")
      .Option("-a_srs", &r.assign_crs, "SRS", "CRS to assign to the lines (no reprojection)")
      .Option("-t_srs", &r.target_crs, "SRS",
              "reproject the lines from the block CRS through PROJ (ballpark height steps "
              "refused)")
      .Option("-truth", &r.truth, "FILE",
              "groundtruth_edges.json of `roofsweep simulate` (true-pair counts and line scores), "
              "or an Oxford VGG set folder (match precision/recall against nview-lines)")
      .Flag("-chromatic_init_best", &init_best,
            "chromatic thresholds from the best-correlating candidates (keeps more true pairs, ~2x "
            "slower)")
      .Option("-chromatic_factor", &r.match.threshold_factor, "F",
              "chromatic thresholds = F x median statistic of the best candidates (default 8)")
      .Option("-min_epipolar_angle", &r.match.min_epipolar_angle, "DEG",
              "a segment meeting a pair's epipolar lines at less than DEG is matched in other "
              "pairs only (default 20; the paper: 40)")
      .Option("-min_length", &r.match.min_length, "PX", "shortest segment matched (default 15)")
      .Option("-seed", &seed, "N",
              "seed of matching's random draws: the segments that calibrate the chromatic "
              "thresholds, the subsets of the robust colour estimates (default 1; another seed "
              "shows how much the result depends on them)")
      .Flag("-no_junctions", &no_junctions,
            "do not complete lines along the epipolar lines from the 3D lines at their ends")
      .Flag("-no_junction_ranking", &no_junction_ranking,
            "rank rival matches of equal support by correlation alone, not first by how many of "
            "their ends meet other 3D lines")
      .Example("roofsweep match out/block -o lines3d.gpkg")
      .Example("roofsweep match sim/block.json -o l.gpkg -truth sim/groundtruth_edges.json");
  if (!p.Parse(args)) return 0;
  r.match.init_from_best_correlation = init_best;
  r.match.junction_completion = !no_junctions;
  r.match.junction_ranking = !no_junction_ranking;
  if (seed < 0) throw UsageError("-seed must be 0 or more", p.Synopsis());
  r.match.seed = static_cast<unsigned>(seed);
  if (!r.assign_crs.empty() && !r.target_crs.empty())
    throw UsageError("Options -a_srs and -t_srs exclude each other", p.Synopsis());
  if (r.output.empty()) throw UsageError("Missing option -o FILE", p.Synopsis());
  RequireVectorFormat(p, r.output, r.format);
  RequireNewOutput(p, r.output, r.overwrite);
  const MatchSummary s = RunMatch(r, *ctx.progress);
  if (!ctx.quiet) {
    std::cout << FormatMatchSummary(s);
    std::cout << "Wrote " << r.output << ": " << s.result.lines.size() << " 3D lines\n";
  } else {
    for (const std::string& m : s.result.messages) std::cerr << m << "\n";
  }
  return 0;
}

const CommandRegistration kRegistration{
    {"match", "match edge segments across views and write 3D lines", Match}};

}  // namespace
}  // namespace roofsweep::cli
