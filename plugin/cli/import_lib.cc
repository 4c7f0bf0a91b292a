#include "plugin/cli/import_lib.h"

#include "algorithms/core/error.h"
#include "io/core/block_manifest.h"

namespace roofsweep {

ImportSummary RunImport(const ImportRequest& request, Progress& progress) {
  if (request.output.empty()) throw Error("import: no output given (-o block.json)");
  ReportOrCancel(progress, 0.0);
  BlockManifest m = ImportBlock(request.format, request.sources, request.options);
  ReportOrCancel(progress, 0.5);
  ValidateManifest(m, request.options.check_images);
  ReportOrCancel(progress, 0.9);
  WriteManifest(m, request.output, request.overwrite);
  ReportOrCancel(progress, 1.0);
  return {static_cast<int>(m.images.size()), static_cast<int>(m.cameras.size()), m.crs};
}

}  // namespace roofsweep
