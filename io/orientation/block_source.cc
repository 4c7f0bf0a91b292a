#include "io/orientation/block_source.h"

#include <filesystem>

#include "algorithms/core/error.h"
#include "io/orientation/colmap_reader.h"
#include "io/orientation/import_common.h"
#include "io/orientation/opensfm_reader.h"
#include "io/orientation/opk_reader.h"
#include "io/orientation/pix4d_reader.h"
#include "io/orientation/text_fields.h"
#include "io/orientation/vgg_reader.h"

namespace fs = std::filesystem;

namespace roofsweep {

const std::vector<std::string>& ImportFormats() {
  static const std::vector<std::string> kFormats = {"opk",    "pix4d",   "metashape",
                                                    "colmap", "opensfm", "vgg"};
  return kFormats;
}

namespace {

std::string FormatList() {
  std::string s;
  for (const auto& f : ImportFormats()) s += (s.empty() ? "" : ", ") + f;
  return s;
}

bool IsFormat(const std::string& name) {
  const auto& f = ImportFormats();
  return std::find(f.begin(), f.end(), name) != f.end();
}

// The format a bare path is recognisable as, or "" for a manifest.
std::string DetectFormat(const std::string& path) {
  using orientation::EndsWith;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    if (fs::is_regular_file(fs::path(path) / "block.json", ec)) return "";
    if (fs::is_regular_file(fs::path(path) / "cameras.txt", ec)) return "colmap";
    if (fs::is_regular_file(fs::path(path) / "reconstruction.json", ec)) return "opensfm";
    if (orientation::LooksLikeVggSet(path)) return "vgg";
    throw Error(path +
                ": folder holds no block.json, COLMAP model, OpenSfM reconstruction.json or "
                "VGG *.P files");
  }
  const std::string name = fs::path(path).filename().string();
  if (name == "cameras.txt" || name == "images.txt") return "colmap";
  if (EndsWith(name, "calibrated_camera_parameters.txt")) return "pix4d";
  if (EndsWith(name, "calibrated_external_camera_parameters.txt")) return "opk";
  if (orientation::Lower(fs::path(path).extension().string()) == ".json" &&
      fs::is_regular_file(path, ec)) {
    // An OpenSfM reconstruction is a JSON list; a manifest is an object.
    const std::string text = orientation::Trim(orientation::ReadTextFile(path));
    if (!text.empty() && text[0] == '[') return "opensfm";
  }
  return "";
}

}  // namespace

BlockManifest ImportBlock(const std::string& format, const std::vector<std::string>& sources,
                          const ImportOptions& options) {
  const std::string f = orientation::Lower(format);
  if (sources.empty()) throw Error("import " + f + ": no source given");
  BlockManifest manifest;
  if (f == "opk" || f == "metashape") {
    manifest = orientation::ReadOpk(sources, options);
  } else if (f == "pix4d") {
    manifest = orientation::ReadPix4d(sources, options);
  } else if (f == "colmap") {
    manifest = orientation::ReadColmap(sources, options);
  } else if (f == "opensfm") {
    manifest = orientation::ReadOpenSfm(sources, options);
  } else if (f == "vgg") {
    manifest = orientation::ReadVgg(sources, options);
  } else {
    throw Error("unknown import format '" + format + "' (known: " + FormatList() + ")");
  }
  ValidateManifest(manifest, options.check_images);
  return manifest;
}

BlockManifest OpenBlockManifest(const std::string& block) {
  // "FORMAT:PATH"
  if (const size_t colon = block.find(':'); colon != std::string::npos && colon > 1) {
    const std::string format = orientation::Lower(block.substr(0, colon));
    if (IsFormat(format)) return ImportBlock(format, {block.substr(colon + 1)}, ImportOptions());
    std::error_code ec;
    if (!fs::exists(block, ec)) {
      throw Error(block + ": unknown block format '" + block.substr(0, colon) +
                  "' (known: " + FormatList() + ")");
    }
  }
  std::error_code ec;
  if (!fs::exists(block, ec)) throw Error(block + ": no such file or folder");
  const std::string format = DetectFormat(block);
  if (!format.empty()) return ImportBlock(format, {block}, ImportOptions());
  if (fs::is_directory(block, ec)) return ReadManifest((fs::path(block) / "block.json").string());
  return ReadManifest(block);
}

Block OpenBlock(const std::string& block) { return ManifestToBlock(OpenBlockManifest(block)); }

}  // namespace roofsweep
