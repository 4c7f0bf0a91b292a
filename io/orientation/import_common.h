#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "io/core/block_manifest.h"
#include "io/orientation/block_source.h"

// Pieces every reader needs once it has parsed its own syntax: finding the
// image files, assembling the manifest with file:line errors, and the CRS.
namespace roofsweep::orientation {

// True for the image extensions import looks for (case-insensitive):
// .tif .tiff .jpg .jpeg .png, plus .pgm/.ppm/.bmp (the Oxford sets).
bool IsImageExtension(const std::string& ext_with_dot);
// "DSC_0157.JPG" -> "DSC_0157"; "house.000" stays (".000" is no image extension).
std::string ImageStem(const std::string& name);

// Looks up images by file name or stem in a list of folders (searched in
// order). Each folder is listed once; with `recursive` its sub-folders too.
class ImageFinder {
 public:
  ImageFinder(const std::vector<std::string>& folders, bool recursive = false);
  // `name` may be a file name with extension, a relative path or a stem.
  // Returns the absolute path, or "" when nothing matches.
  std::string Find(const std::string& name) const;

 private:
  std::vector<std::string> folders_;
  // stem -> paths with an image extension, in deterministic order.
  std::map<std::string, std::vector<std::string>> by_stem_;
  std::map<std::string, std::string> by_filename_;
};

// One image as a reader found it, before images are resolved.
struct PendingImage {
  std::string name;    // as written in the source (with or without extension)
  std::string camera;  // Camera::id
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // PATB camera -> world
  std::string file;                                        // where it was read, for messages
  int line = 0;
};

// Adds `images` to `manifest`: manifest names are image stems; duplicate
// names and (with check_images) missing image files are reported at the
// record's file:line; without check_images a missing file keeps the
// source's name relative to the first search folder. Cameras whose size is
// 0x0 get the size of their first image (needs the file).
void AddImages(const std::vector<PendingImage>& images, const ImageFinder& finder,
               bool check_images, BlockManifest* manifest);

// The CRS text of a .prj/.wkt file: WKT as it is; a PROJ string gets
// "+type=crs" so PROJ reads it as a CRS rather than as an operation.
std::string CrsFromText(const std::string& text);
// options.crs when set; else the contents of the first existing candidate
// file (e.g. "ngi_xyz_opk.prj" beside "ngi_xyz_opk.csv"); else "".
std::string ResolveCrs(const ImportOptions& options, const std::vector<std::string>& candidates);

// Folder of a path ("." for a bare file name), and the path with its last
// extension replaced.
std::string FolderOf(const std::string& path);
std::string ReplaceExtension(const std::string& path, const std::string& ext);

// The folders to look for images in: options.image_dir first, then `beside`.
std::vector<std::string> ImageFolders(const ImportOptions& options, const std::string& beside);

// Common tail of every reader: source, base_dir, ground height, DTM.
void ApplyCommonOptions(const ImportOptions& options, const std::string& source,
                        BlockManifest* manifest);

}  // namespace roofsweep::orientation
