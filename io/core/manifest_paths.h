#pragma once

// Path rules of the block manifest (internal to io/core).

#include <filesystem>
#include <string>

namespace roofsweep::manifest_paths {

// A manifest path made usable: absolute ones stay, relative ones are taken
// below base_dir (or left relative to the working folder without one).
inline std::string Resolve(const std::string& path, const std::string& base_dir) {
  namespace fs = std::filesystem;
  if (path.empty()) return path;
  const fs::path p(path);
  if (p.is_absolute() || base_dir.empty()) return p.lexically_normal().string();
  return (fs::path(base_dir) / p).lexically_normal().string();
}

// How a path is written into a manifest stored in manifest_dir (absolute):
// relative when the file lies below that folder, else absolute.
inline std::string ForManifest(const std::string& path, const std::string& base_dir,
                               const std::filesystem::path& manifest_dir) {
  namespace fs = std::filesystem;
  if (path.empty()) return path;
  fs::path abs(Resolve(path, base_dir));
  if (abs.is_relative()) abs = (fs::current_path() / abs).lexically_normal();
  const fs::path rel = abs.lexically_relative(manifest_dir);
  if (!rel.empty() && *rel.begin() != ".." && rel.is_relative()) return rel.generic_string();
  return abs.string();
}

}  // namespace roofsweep::manifest_paths
