#include "io/orientation/vgg_reader.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "algorithms/core/error.h"
#include "algorithms/geometry/rotation.h"
#include "algorithms/geometry/view.h"
#include "io/core/image_io.h"
#include "io/orientation/import_common.h"
#include "io/orientation/text_fields.h"

namespace fs = std::filesystem;

namespace roofsweep::orientation {
namespace {

std::vector<fs::path> FindProjectionFiles(const std::string& folder) {
  std::vector<fs::path> out;
  for (const std::string& f : VggFilesEndingWith(folder, ".P")) out.emplace_back(f);
  return out;
}

Matrix34d ReadProjection(const std::string& path) {
  std::vector<TextLine> rows;
  for (const auto& l : ReadTextLines(path))
    if (!Trim(l.text).empty()) rows.push_back(l);
  if (rows.size() != 3) {
    throw Error(
        AtLine(path, rows.size() > 3 ? rows[3].number : 0,
               "expected 3 rows of 4 numbers, found " + std::to_string(rows.size()) + " rows"));
  }
  Matrix34d P;
  for (int r = 0; r < 3; ++r) {
    const auto v = ParseNumbers(rows[static_cast<size_t>(r)], path, 4, "projection matrix row");
    for (int c = 0; c < 4; ++c) P(r, c) = v[static_cast<size_t>(c)];
  }
  if (std::abs(P.leftCols<3>().determinant()) < 1e-12 * std::pow(P.leftCols<3>().norm(), 3)) {
    throw Error(AtLine(path, rows[0].number, "projection matrix is singular (det M = 0)"));
  }
  return P;
}

// 3D points of the set (p3d rows "X Y Z", l3d rows "X0 Y0 Z0 X1 Y1 Z1"),
// used only to tell which side of each camera the scene is on.
std::vector<Eigen::Vector3d> ScenePoints(const std::string& folder) {
  std::vector<Eigen::Vector3d> points;
  for (const char* kind : {"p3d", "l3d"}) {
    const size_t per_row = kind[0] == 'p' ? 3 : 6;
    for (const std::string& path : VggFilesEndingWith(folder, kind))
      for (const auto& line : ReadTextLines(path)) {
        const auto t = SplitWhitespace(line.text);
        if (t.size() != per_row) continue;
        for (size_t k = 0; k < t.size(); k += 3)
          points.emplace_back(ParseNumber(t[k], path, line.number, "point"),
                              ParseNumber(t[k + 1], path, line.number, "point"),
                              ParseNumber(t[k + 2], path, line.number, "point"));
      }
  }
  return points;
}

// +1 when P = s K [R | -R C] with a proper rotation sees the scene in front,
// -1 when only a mirrored world does. P's overall sign is arbitrary, so the
// test is the sign of det(M) times the depth w of the scene points (the
// majority: points not seen by this view may lie behind it). Without
// points, P is taken to have a positive scale.
int Handedness(const Matrix34d& P, const std::vector<Eigen::Vector3d>& points) {
  const double det = P.leftCols<3>().determinant();
  if (points.empty()) return det > 0 ? 1 : -1;
  long votes = 0;
  for (const auto& X : points) {
    const double w = P.row(2).head<3>().dot(X) + P(2, 3);
    votes += (det * w > 0) ? 1 : -1;
  }
  return votes >= 0 ? 1 : -1;
}

}  // namespace

std::vector<std::string> VggFilesEndingWith(const std::string& folder, const std::string& suffix) {
  std::vector<std::string> out;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->is_regular_file(ec) && EndsWith(it->path().filename().string(), suffix))
      out.push_back(it->path().string());
  std::sort(out.begin(), out.end());
  return out;
}

bool VggWorldIsMirrored(const std::string& folder) {
  const auto files = FindProjectionFiles(folder);
  if (files.empty()) throw Error(folder + ": no *.P projection matrices below it");
  const auto points = ScenePoints(folder);
  int mirrored = 0;
  for (const auto& f : files) mirrored += Handedness(ReadProjection(f.string()), points) < 0;
  if (mirrored != 0 && mirrored != static_cast<int>(files.size())) {
    throw Error(folder + ": the P matrices disagree on the handedness of the world (" +
                std::to_string(mirrored) + " of " + std::to_string(files.size()) +
                " see the scene mirrored)");
  }
  return mirrored != 0;
}

bool LooksLikeVggSet(const std::string& folder) {
  std::error_code ec;
  return fs::is_directory(folder, ec) && !FindProjectionFiles(folder).empty();
}

BlockManifest ReadVgg(const std::vector<std::string>& sources, const ImportOptions& options) {
  if (sources.size() != 1) throw Error("vgg: give one set folder");
  const std::string& folder = sources.front();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw Error(folder + ": not a folder");
  const auto files = FindProjectionFiles(folder);
  if (files.empty()) throw Error(folder + ": no *.P projection matrices below it");

  std::vector<std::string> image_folders;
  if (!options.image_dir.empty()) image_folders.push_back(options.image_dir);
  image_folders.push_back(folder);
  const ImageFinder finder(image_folders, /*recursive=*/true);

  // A roofsweep pose is a proper rotation: a set whose P matrices need a
  // left-handed world (corridor, model_house) is imported mirrored, z -> -z.
  const bool mirrored = VggWorldIsMirrored(folder);
  const Eigen::Vector4d mirror(1, 1, mirrored ? -1 : 1, 1);

  BlockManifest manifest;
  std::vector<PendingImage> pending;
  for (const auto& file : files) {
    const Matrix34d P = ReadProjection(file.string()) * mirror.asDiagonal();
    Eigen::Matrix3d K, R;
    Eigen::Vector3d C;
    DecomposeProjection(P, &K, &R, &C);
    Camera camera;
    camera.id = file.stem().string();
    camera.fx = K(0, 0);
    camera.fy = K(1, 1);
    camera.skew = K(0, 1);
    camera.cx = K(0, 2) + 0.5;  // VGG origin: centre of the top-left pixel
    camera.cy = K(1, 2) + 0.5;
    const std::string image = finder.Find(camera.id);
    if (!image.empty()) {
      const ImageInfo info = ProbeImage(image);
      camera.width = info.width;
      camera.height = info.height;
    } else if (!options.check_images) {
      camera.width = std::max(1, static_cast<int>(std::lround(2 * camera.cx)));
      camera.height = std::max(1, static_cast<int>(std::lround(2 * camera.cy)));
    } else {
      throw Error(file.string() + ": no image file '" + camera.id + ".*' below " + folder +
                  " (this set has only annotations; import it with the image check off to get "
                  "cameras of nominal size)");
    }
    camera.Validate(file.string());
    manifest.cameras.push_back(camera);
    PendingImage p;
    p.name = camera.id;
    p.camera = camera.id;
    p.position = C;
    p.rotation = CvToPatb(R);
    p.file = file.string();
    p.line = 1;
    pending.push_back(p);
  }
  manifest.crs = options.crs;
  AddImages(pending, finder, options.check_images, &manifest);
  ApplyCommonOptions(options, folder, &manifest);
  // The set folder itself is the base, not its parent.
  manifest.base_dir = folder;
  return manifest;
}

}  // namespace roofsweep::orientation
