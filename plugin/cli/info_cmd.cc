#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/info_lib.h"

namespace roofsweep::cli {
namespace {

int Info(const std::vector<std::string>& args, Context&) {
  std::string block;
  bool json = false;
  ArgParser p("info",
              "Describes a block: images, cameras, CRS, GSD per image, overlap graph, warnings.");
  p.Positional("BLOCK", &block, "block manifest, folder holding block.json, or FORMAT:SOURCE")
      .Flag("--json|-json", &json, "print one JSON object instead of the table")
      .Example("roofsweep info out/block")
      .Example("roofsweep info vgg:merton1 --json");
  if (!p.Parse(args)) return 0;
  const BlockInfo info = RunInfo(block);
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
