#pragma once

#include <functional>
#include <string>
#include <vector>

#include "algorithms/core/progress.h"

namespace roofsweep::cli {

// What every subcommand gets besides its own arguments.
struct Context {
  bool quiet = false;            // -q: no progress, no summary chatter
  Progress* progress = nullptr;  // GDAL term progress, or a null one with -q
};

// A subcommand: parses its arguments and calls a library function
// (plugin/cli/<name>_lib.h), so the QGIS provider and other hosts can call
// the same code. Returns the process exit code.
struct Command {
  std::string name;
  std::string purpose;  // one line, for `roofsweep --help`
  std::function<int(const std::vector<std::string>& args, Context& ctx)> run;
  // Reads or renders images, hundreds of MB of them: worth restarting the
  // process with a huge-page heap (ReexecWithHugePageHeap) for, where the
  // restart's 0.1 s would be most of a small command's time.
  bool works_on_images = false;
};

// Commands register themselves from their <name>_cmd.cc with a static
// CommandRegistration; the list is sorted by name.
std::vector<Command>& Registry();
struct CommandRegistration {
  explicit CommandRegistration(Command c);
};

}  // namespace roofsweep::cli
