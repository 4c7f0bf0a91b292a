#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/overlay_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Overlay(const std::vector<std::string>& args, Context& ctx) {
  OverlayRequest r;
  ArgParser p("overlay",
              "Draws a LoD2 model over every image of its block (roof edges green where an image "
              "edge runs along them, red where none does; walls cyan; what the model hides "
              "itself is not drawn) and prints the share of the visible roof-edge length that "
              "lies on an image edge, per view and for the least supported buildings: a check of "
              "a reconstruction on real images, where there is no ground truth.");
  p.Positional("BLOCK", &r.block, "block manifest, folder holding block.json, or FORMAT:SOURCE")
      .Positional("MODEL", &r.model, "LoD2 model (CityGML, CityJSON, GPKG), in any CRS")
      .Option("-o", &r.output_dir, "DIR", "output folder, one <view>.png per image (required)")
      .Repeated("-view", &r.views, "NAME", "only this view (default: every view)")
      .Option("-report", &r.report, "FILE",
              "also write the figures per view and per building as JSON")
      .Option("-search_px", &r.options.search_px, "PX",
              "an image edge this far across a roof edge supports it (1.5)")
      .Option("-max_angle", &r.options.max_angle_deg, "DEG",
              "the image gradient's direction within this of the edge's normal (20)")
      .Flag("-overwrite|--overwrite", &r.overwrite, "replace existing PNGs and report")
      .Example("roofsweep overlay out/block out/buildings.gml -o out/overlay")
      .Example(
          "roofsweep overlay block.json buildings.gpkg -o check -view 0042 -report check.json");
  if (!p.Parse(args)) return 0;
  if (r.output_dir.empty()) throw UsageError("Missing option -o DIR", p.Synopsis());
  RequireNewOutput(p, r.report, r.overwrite);
  if (!(r.options.search_px >= 0))
    throw UsageError("Option -search_px expects a distance of 0 px or more", p.Synopsis());
  if (!(r.options.max_angle_deg > 0 && r.options.max_angle_deg <= 90))
    throw UsageError("Option -max_angle expects an angle in (0, 90]", p.Synopsis());
  const OverlaySummary s = RunOverlay(r, *ctx.progress);
  if (!ctx.quiet)
    std::cout << FormatOverlaySummary(s) << "Wrote " << s.views.size() << " overlays into "
              << r.output_dir << "\n";
  return 0;
}

const CommandRegistration kRegistration{
    {"overlay", "draw a LoD2 model over the block's images and measure its edges' image support",
     Overlay, true}};

}  // namespace
}  // namespace roofsweep::cli
