#include <iostream>

#include "io/core/block_manifest.h"
#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/info_lib.h"

namespace roofsweep::cli {
namespace {

int Info(const std::vector<std::string>& args, Context&) {
  std::string block;
  bool json = false;
  double tiles = 0;
  ArgParser p("info",
              "Describes a block: images, cameras, CRS, GSD per image, overlap graph, warnings.");
  p.Positional("BLOCK", &block, "block manifest, folder holding block.json, or FORMAT:SOURCE")
      .Flag("--json|-json", &json, "print one JSON object instead of the table")
      .Option("-tiles", &tiles, "SIZE",
              "print instead the tiles of a SIZE grid (block CRS units, aligned to multiples of "
              "SIZE) that at least two images see, one MINX,MINY,MAXX,MAXY per line: the -aoi of "
              "each `run` a batch engine starts (with --json: an array)")
      .Example("roofsweep info out/block")
      .Example("roofsweep info vgg:merton1 --json")
      .Example(
          "roofsweep info city/block.json -tiles 250 | xargs -P 8 -I{} roofsweep run "
          "city/block.json -aoi {} -o tiles/{}.gml");
  if (!p.Parse(args)) return 0;
  if (p.Given("-tiles") && !(tiles > 0))
    throw UsageError("Option -tiles expects a positive tile size", p.Synopsis());
  const BlockInfo info = RunInfo(block);
  if (tiles > 0) {
    std::cout << FormatTiles(info, tiles, json);
    return 0;
  }
  if (json) {
    std::cout << InfoToJson(info).dump(2) << "\n";
  } else {
    std::cout << FormatInfoText(info);
  }
  return 0;
}

const CommandRegistration kRegistration{
    {"info", "describe a block: images, cameras, CRS, GSD, overlaps, warnings", Info}};

}  // namespace
}  // namespace roofsweep::cli
