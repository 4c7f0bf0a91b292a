#include "plugin/cli/import_lib.h"

#include "algorithms/core/error.h"
#include "io/core/block_manifest.h"

namespace roofsweep {

ImportSummary RunImport(const ImportRequest& request, Progress& progress) {
  if (request.output.empty()) throw Error("import: no output given (-o block.json)");
  ReportOrCancel(progress, 0.0);
  BlockManifest m = ImportBlock(request.format, request.sources, request.options);
  ReportOrCancel(progress, 0.5);
  // ImportBlock has validated the manifest and its images. Building the local frame checks what the
  // manifest alone cannot: that PROJ knows the CRS, that heights are usable, that the DTM reads.
  ManifestToBlock(m);
  ReportOrCancel(progress, 0.9);
  WriteManifest(m, request.output, request.overwrite);
  ReportOrCancel(progress, 1.0);
  return {static_cast<int>(m.images.size()), static_cast<int>(m.cameras.size()), m.crs};
}

}  // namespace roofsweep
