#include "io/orientation/import_common.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "algorithms/core/error.h"
#include "io/core/image_io.h"
#include "io/orientation/text_fields.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {

bool IsImageExtension(const std::string& ext_with_dot) {
  static const std::set<std::string> kExt = {".tif", ".tiff", ".jpg", ".jpeg",
                                             ".png", ".pgm",  ".ppm", ".bmp"};
  return kExt.count(Lower(ext_with_dot)) > 0;
}

std::string ImageStem(const std::string& name) {
  const fs::path p(name);
  if (IsImageExtension(p.extension().string())) return p.stem().string();
  return p.filename().string();
}

namespace {

// Fixed preference when one stem exists with several extensions.
int ExtensionRank(const std::string& ext) {
  static const std::vector<std::string> kOrder = {".tif", ".tiff", ".jpg", ".jpeg",
                                                  ".png", ".pgm",  ".ppm", ".bmp"};
  const auto it = std::find(kOrder.begin(), kOrder.end(), Lower(ext));
  return static_cast<int>(it - kOrder.begin());
}

std::string Absolute(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p, ec);
  return (ec ? p : a).lexically_normal().string();
}

}  // namespace

ImageFinder::ImageFinder(const std::vector<std::string>& folders, bool recursive) {
  for (const auto& folder : folders) {
    if (folder.empty()) continue;
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) continue;
    folders_.push_back(folder);
    std::vector<fs::path> files;
    if (recursive) {
      for (auto it = fs::recursive_directory_iterator(folder, ec);
           !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it->is_regular_file(ec)) files.push_back(it->path());
      }
    } else {
      for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator();
           it.increment(ec)) {
        if (it->is_regular_file(ec)) files.push_back(it->path());
      }
    }
    // Directory order is arbitrary: sort so that the result is deterministic.
    std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
      const int ra = ExtensionRank(a.extension().string());
      const int rb = ExtensionRank(b.extension().string());
      if (ra != rb) return ra < rb;
      return a.string() < b.string();
    });
    for (const auto& f : files) {
      if (!IsImageExtension(f.extension().string())) continue;
      by_stem_[f.stem().string()].push_back(Absolute(f));
      by_filename_.emplace(f.filename().string(), Absolute(f));
    }
  }
}

std::string ImageFinder::Find(const std::string& name) const {
  std::error_code ec;
  // A name with folders (COLMAP "sub/a.jpg") or an exact file in a folder.
  for (const auto& folder : folders_) {
    const fs::path p = fs::path(folder) / name;
    if (fs::is_regular_file(p, ec)) return Absolute(p);
  }
  if (fs::path(name).is_absolute() && fs::is_regular_file(name, ec)) return Absolute(name);
  const std::string filename = fs::path(name).filename().string();
  if (const auto it = by_filename_.find(filename); it != by_filename_.end()) return it->second;
  if (const auto it = by_stem_.find(ImageStem(filename)); it != by_stem_.end()) {
    return it->second.front();
  }
  return "";
}

void AddImages(const std::vector<PendingImage>& images, const ImageFinder& finder,
               bool check_images, BlockManifest* manifest) {
  std::map<std::string, std::string> seen;  // name -> file:line of the first record
  for (const auto& pending : images) {
    const std::string where = AtLine(pending.file, pending.line, "");
    const std::string name = ImageStem(pending.name);
    if (name.empty()) throw Error(AtLine(pending.file, pending.line, "empty image name"));
    if (const auto it = seen.find(name); it != seen.end()) {
      throw Error(AtLine(pending.file, pending.line,
                         "duplicate image name '" + name + "' (first at " + it->second + ")"));
    }
    seen[name] = pending.file + ":" + std::to_string(pending.line);
    const int cam = manifest->FindCamera(pending.camera);
    if (cam < 0) {
      throw Error(AtLine(pending.file, pending.line, "unknown camera id '" + pending.camera + "'"));
    }
    if (!pending.position.allFinite() || !pending.rotation.allFinite()) {
      throw Error(AtLine(pending.file, pending.line, "NaN or infinite orientation"));
    }
    ManifestImage image;
    image.name = name;
    image.camera = pending.camera;
    image.position = pending.position;
    image.rotation = pending.rotation;
    image.path = finder.Find(pending.name);
    Camera& camera = manifest->cameras[static_cast<size_t>(cam)];
    if (image.path.empty()) {
      if (check_images || camera.width <= 0) {
        throw Error(AtLine(pending.file, pending.line,
                           "missing image file for '" + pending.name +
                               "' (looked for .tif/.tiff/.jpg/.jpeg/.png of that name; use "
                               "-image_dir, or disable the image check)"));
      }
      image.path = pending.name;
    }
    if (camera.width <= 0 || camera.height <= 0) {
      // Formats that give the interior orientation in mm (Pix4D .cam) need
      // the image to know the size in pixels; readers scale afterwards.
      const ImageInfo info = ProbeImage(image.path);
      camera.width = info.width;
      camera.height = info.height;
    }
    manifest->images.push_back(image);
  }
}

std::string CrsFromText(const std::string& text) {
  std::string t = Trim(text);
  if (StartsWith(t, "+") && t.find("+type=crs") == std::string::npos) t += " +type=crs";
  return t;
}

std::string ResolveCrs(const ImportOptions& options, const std::vector<std::string>& candidates) {
  if (!options.crs.empty()) return options.crs;
  std::error_code ec;
  for (const auto& c : candidates) {
    if (fs::is_regular_file(c, ec)) {
      const std::string crs = CrsFromText(ReadTextFile(c));
      if (crs.empty()) throw Error(c + ": empty CRS file");
      return crs;
    }
  }
  return "";
}

std::string FolderOf(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

std::string ReplaceExtension(const std::string& path, const std::string& ext) {
  return fs::path(path).replace_extension(ext).string();
}

std::vector<std::string> ImageFolders(const ImportOptions& options, const std::string& beside) {
  std::vector<std::string> folders;
  if (!options.image_dir.empty()) {
    std::error_code ec;
    if (!fs::is_directory(options.image_dir, ec)) {
      throw Error(options.image_dir + ": image folder does not exist");
    }
    folders.push_back(options.image_dir);
  }
  folders.push_back(beside);
  return folders;
}

void ApplyCommonOptions(const ImportOptions& options, const std::string& source,
                        BlockManifest* manifest) {
  manifest->source = source;
  manifest->base_dir = FolderOf(source);
  if (options.ground_height) manifest->ground_height = options.ground_height;
  if (!options.dtm.empty()) manifest->dtm = options.dtm;
  if (!options.dsm.empty()) manifest->dsm = options.dsm;
  if (options.terrain_window_m) manifest->terrain_window_m = *options.terrain_window_m;
}

}  // namespace roofsweep::orientation
