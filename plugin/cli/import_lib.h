#pragma once

#include <string>
#include <vector>

#include "algorithms/core/progress.h"
#include "io/orientation/block_source.h"

namespace roofsweep {

struct ImportRequest {
  std::string format;                // one of ImportFormats()
  std::vector<std::string> sources;  // files or folders of that format
  ImportOptions options;
  std::string output;  // block manifest to write
  bool overwrite = false;
};

struct ImportSummary {
  int images = 0;
  int cameras = 0;
  std::string crs;
};

// `roofsweep import`: reads the sources, checks everything the manifest
// promises (images readable, sizes as the cameras say) and writes the
// manifest atomically. Nothing is written when any check fails.
ImportSummary RunImport(const ImportRequest& request, Progress& progress);

}  // namespace roofsweep
