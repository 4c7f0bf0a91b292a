#include <cmath>
#include <cstdio>
#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/simulate_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Simulate(const std::vector<std::string>& args, Context& ctx) {
  SimulateRequest r;
  int seed = 1;
  std::string origin, aoi, overlap;
  std::string presets;
  for (const auto& p : sim::SimulationPresetNames()) presets += (presets.empty() ? "" : ", ") + p;
  ArgParser p(
      "simulate",
      "Renders an oriented aerial block of LoD2 buildings with exactly known cameras and "
      "writes images, orientation, a block manifest and the ground truth: the LoD2 model "
      "(groundtruth.gml), its 3D edges (groundtruth_edges.json), what each view sees of each "
      "roof polygon (groundtruth_visibility.json, for eval's completeness over the roofs "
      "the images show) and the building footprints (footprints.gpkg).");
  p.Option("-preset|--preset", &r.preset, "NAME", "one of " + presets + " (default realistic)")
      .Option("-seed|--seed", &seed, "N", "random seed; the same seed gives the same block (1)")
      .Option("-citygml|--citygml", &r.citygml, "FILE",
              "render this LoD2 model (CityGML, CityJSON, GPKG) instead of a generated scene")
      .Option("-aoi", &aoi, "MINX,MINY,MAXX,MAXY",
              "with -citygml: only buildings whose plan centre lies in this window (model CRS)")
      .Option("-o", &r.output_dir, "DIR", "output folder (required)")
      .Option("-a_srs", &r.crs, "SRS", "CRS to place a generated scene in (EPSG:25832)")
      .Option("-origin", &origin, "E,N,H",
              "where the scene centre lies in that CRS (691000,5335000,520)")
      .Option("-if", &r.image_format, "jpg|tif|png", "image format (png for easy, else jpg)")
      .Option("-jpeg_quality", &r.jpeg_quality, "Q", "JPEG quality (92)")
      .Option("-strips", &r.strips, "N", "number of flight strips (preset)")
      .Option("-views|--views", &r.images_per_strip, "N", "images per strip (preset)")
      .Option("-size", &r.image_size, "PX",
              "square image size in pixels (preset); the lens stays, so fewer pixels at one -gsd "
              "cover less ground from the same height, with shorter baselines (a smaller "
              "base-to-height ratio)")
      .Option("-gsd", &r.gsd, "M",
              "ground sample distance in metres (preset); the flying height follows it (GSD x "
              "focal length in pixels)")
      .Option("-buildings", &r.buildings, "N", "number of generated buildings (preset)")
      .Flag("-obliques", &r.obliques, "add oblique views (forward, backward, left, right)")
      .Option(
          "-overlap", &overlap, "FORWARD,SIDE",
          "forward and side overlap of the nadir images in percent (preset: 80,60, hard 60,25); "
          "60,30 is the classic mapping flight")
      .Option("-terrain_slope", &r.terrain_slope_percent, "PERCENT",
              "the ground falls by this much per 100 m (0: flat); each building stands on the "
              "lowest ground under it, and the block gets a DTM (dtm.tif) instead of one ground "
              "height")
      .Option("-terrain_aspect", &r.terrain_aspect_deg, "DEG",
              "direction the ground falls towards, clockwise from north (0)")
      .Option("-terrain_relief", &r.terrain_relief_m, "M",
              "smooth hills and hollows 35-90 m wide on the ground, their heights spanning up "
              "to this (0: none); the block gets a DTM (dtm.tif)")
      .Flag("-overwrite", &r.overwrite, "replace an existing output folder")
      .Example("roofsweep simulate -preset realistic -seed 7 -o out/block")
      .Example(
          "roofsweep simulate -preset realistic -terrain_slope 8 -terrain_aspect 120 -o out/hill")
      .Example("roofsweep simulate -preset realistic -terrain_relief 12 -o out/hills")
      .Example("roofsweep simulate -citygml 3910_5819.gml -o out/berlin");
  if (!p.Parse(args)) return 0;
  if (r.output_dir.empty()) throw UsageError("Missing option -o DIR", p.Synopsis());
  RequireNewOutput(p, r.output_dir, r.overwrite);
  if (seed < 0) throw UsageError("Option -seed expects a non-negative number", p.Synopsis());
  r.seed = static_cast<uint64_t>(seed);
  if (!origin.empty()) {
    double e, n, h;
    char tail;
    if (std::sscanf(origin.c_str(), "%lf,%lf,%lf%c", &e, &n, &h, &tail) != 3) {
      throw UsageError("Option -origin expects E,N,H, got '" + origin + "'", p.Synopsis());
    }
    r.origin = Eigen::Vector3d(e, n, h);
  }
  if (!aoi.empty()) r.aoi = ParseAoi(p, aoi);
  if (!overlap.empty()) {
    double f, s;
    char tail;
    if (std::sscanf(overlap.c_str(), "%lf,%lf%c", &f, &s, &tail) != 2 || !std::isfinite(f) ||
        !std::isfinite(s) || f < 0 || s < 0) {
      throw UsageError("Option -overlap expects FORWARD,SIDE in percent, got '" + overlap + "'",
                       p.Synopsis());
    }
    r.forward_overlap = f / 100;
    r.side_overlap = s / 100;
  }
  const SimulateSummary s = RunSimulate(r, *ctx.progress);
  if (!ctx.quiet) {
    std::printf(
        "Wrote %s: %d views, %d buildings, %d roof planes, %d edges, GSD %.3f m "
        "(rendered in %.1f s)\n",
        r.output_dir.c_str(), s.views, s.buildings, s.roof_planes, s.edges, s.gsd_m,
        s.seconds_render);
  }
  return 0;
}

const CommandRegistration kRegistration{
    {"simulate", "render an oriented aerial block of LoD2 buildings with ground truth", Simulate,
     true}};

}  // namespace
}  // namespace roofsweep::cli
