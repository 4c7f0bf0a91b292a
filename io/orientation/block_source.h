#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/core/block_manifest.h"

namespace roofsweep {

// Options for reading other formats into a manifest (`roofsweep import`).
struct ImportOptions {
  std::string crs;          // -a_srs: CRS of the positions, when the format has none
  std::string camera_file;  // interior orientation for OPK files (Pix4D .cam, YAML, ...)
  std::string image_dir;    // where the images are, when not beside the orientation
  std::optional<double> ground_height;     // -ground
  std::string dtm;                         // -dtm
  std::string dsm;                         // -dsm
  std::optional<double> terrain_window_m;  // -terrain_window
  bool check_images = true;
};

// The formats `roofsweep import` reads.
const std::vector<std::string>& ImportFormats();

// Reads `sources` (files or folders) of the given format into a manifest.
// Throws roofsweep::Error naming file and line on bad input.
BlockManifest ImportBlock(const std::string& format, const std::vector<std::string>& sources,
                          const ImportOptions& options);

// What every command accepts as BLOCK: a manifest, a folder holding
// block.json, or "FORMAT:SOURCE" / a source `import` recognises by itself.
BlockManifest OpenBlockManifest(const std::string& block);
Block OpenBlock(const std::string& block);

}  // namespace roofsweep
