#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/match_flags.h"
#include "plugin/cli/match_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Match(const std::vector<std::string>& args, Context& ctx) {
  MatchRequest r;
  MatchFlags flags;
  std::string aoi;
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
      .Option("-aoi", &aoi, "MINX,MINY,MAXX,MAXY",
              "match one tile, in the block CRS (default: the block's aoi, if any): read only the "
              "views and image windows that see it and its buffer, as `run -aoi` does; the "
              "observations then name no segment (-1)")
      .Option("-tile_buffer", &r.tile_buffer_m, "M", "match this far around the tile (default 30)")
      .Option("-truth", &r.truth, "FILE",
              "groundtruth_edges.json of `roofsweep simulate` (true-pair counts and line scores), "
              "or an Oxford VGG set folder (match precision/recall against nview-lines)")
      .Option("-truth_edges", &r.truth_edges_output, "FILE",
              "with a simulator's -truth: write every true edge (layer truth_edges) with how far "
              "matching got on it: views and view pairs holding a segment on it, the pairs along "
              "its epipolar lines, the furthest stage a true pair reached, the reach category of "
              "the summary, and the length the 3D lines cover (10 cm, 10 deg)");
  flags.Add(p, &r.match, &r.edges);
  p.Example("roofsweep match out/block -o lines3d.gpkg")
      .Example("roofsweep match sim/block.json -o l.gpkg -truth sim/groundtruth_edges.json")
      .Example("roofsweep match city/block.json -aoi 391800,5819000,392000,5819200 -o t.gpkg");
  if (!p.Parse(args)) return 0;
  flags.Apply(p);
  r.aoi = ParseTileOptions(p, aoi, r.tile_buffer_m);
  if (r.aoi && !r.truth.empty())
    throw UsageError("Options -aoi and -truth exclude each other: the truth scores a whole block",
                     p.Synopsis());
  if (!r.assign_crs.empty() && !r.target_crs.empty())
    throw UsageError("Options -a_srs and -t_srs exclude each other", p.Synopsis());
  if (r.output.empty()) throw UsageError("Missing option -o FILE", p.Synopsis());
  RequireVectorFormat(p, r.output, r.format);
  RequireNewOutput(p, r.output, r.overwrite);
  if (!r.truth_edges_output.empty()) {
    if (r.truth.empty())
      throw UsageError("Option -truth_edges needs -truth (groundtruth_edges.json)", p.Synopsis());
    RequireVectorFormat(p, r.truth_edges_output, "");
    RequireNewOutput(p, r.truth_edges_output, r.overwrite);
  }
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
    {"match", "match edge segments across views and write 3D lines", Match, true}};

}  // namespace
}  // namespace roofsweep::cli
