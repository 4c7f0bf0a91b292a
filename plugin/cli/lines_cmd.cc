#include <cstdio>
#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/lines_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Lines(const std::vector<std::string>& args, Context& ctx) {
  LinesRequest r;
  std::string method = "max";
  double min_length = r.edges.min_length;
  std::string aoi;
  ArgParser p("lines",
              "Extracts straight colour edge segments (Scholze et al. 2000) from every image of a "
              "block (or those that see a tile: -aoi) and writes one LineString layer per image "
              "(lines_<image stem>) in image "
              "pixel coordinates: x right, y down, origin at the top-left corner of the "
              "top-left pixel; no CRS.");
  p.Positional("BLOCK", &r.block, "block manifest, folder holding block.json, or FORMAT:SOURCE")
      .Option("-o", &r.output, "FILE", "output vector file, one layer per image (required)")
      .Option("-of", &r.format, "FMT", "GDAL vector driver (from the extension; GPKG for .gpkg)")
      .Option("-method|--method", &method, "max|dizenzo|grey",
              "gradient fusion of the colour bands (max)")
      .Option("-min-length|--min-length", &min_length, "PX", "shortest segment kept (15)")
      .Flag("-coarse_edges|--coarse-edges", &r.edges.coarse_fusion,
            "also take the edges found at half resolution where no full-resolution segment "
            "lies (hips and valleys broken up by tile courses; attribute scale = 2)")
      .Option("-png|--png", &r.png_dir, "DIR", "also write <layer>.png overlays into DIR")
      .Option("-aoi", &aoi, "MINX,MINY,MAXX,MAXY",
              "one tile, in the block CRS (default: the block's aoi, if any): only the images "
              "that see it and its buffer, each in the window that does, as `run -aoi` reads "
              "them (needs the orientation); coordinates stay those of the whole image")
      .Option("-tile_buffer", &r.tile_buffer_m, "M", "read this far around the tile (default 30)")
      .KeyValues("-dsco", &r.dataset_options,
                 "GDAL dataset creation option (e.g. GPKG VERSION=1.2)")
      .KeyValues("-lco", &r.layer_options,
                 "GDAL layer creation option, every layer (e.g. GPKG SPATIAL_INDEX=NO)")
      .Flag("-overwrite|--overwrite", &r.overwrite, "replace an existing output file")
      .Example("roofsweep lines out/block -o lines.gpkg -png out/overlays")
      .Example("roofsweep lines vgg:merton1 -o merton_lines.gpkg --method dizenzo")
      .Example("roofsweep lines city/block.json -aoi 391800,5819000,392000,5819200 -o t.gpkg");
  if (!p.Parse(args)) return 0;
  if (r.output.empty()) throw UsageError("Missing option -o FILE", p.Synopsis());
  RequireVectorFormat(p, r.output, r.format);
  RequireNewOutput(p, r.output, r.overwrite);
  r.aoi = ParseTileOptions(p, aoi, r.tile_buffer_m);
  if (method == "max") {
    r.edges.method = GradientMethod::kMax;
  } else if (method == "dizenzo") {
    r.edges.method = GradientMethod::kDiZenzo;
  } else if (method == "grey") {
    r.edges.method = GradientMethod::kGrey;
  } else {
    throw UsageError("Option -method expects max, dizenzo or grey, got '" + method + "'",
                     p.Synopsis());
  }
  if (!(min_length >= 2))
    throw UsageError("Option -min-length expects a length of at least 2 px", p.Synopsis());
  r.edges.min_length = min_length;
  const LinesSummary s = RunLines(r, *ctx.progress);
  if (!ctx.quiet) std::cout << FormatLinesSummary(s) << "Wrote " << r.output << "\n";
  return 0;
}

const CommandRegistration kRegistration{
    {"lines", "extract straight colour edge segments of every image, one layer per image", Lines,
     true}};

}  // namespace
}  // namespace roofsweep::cli
