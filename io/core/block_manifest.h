#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/geometry/block.h"
#include "algorithms/geometry/camera.h"
#include "io/core/local_frame.h"

namespace roofsweep {

// One image of a block manifest, in the block CRS (or the block's own frame
// when it has no CRS), as photogrammetrists store it.
struct ManifestImage {
  std::string name;    // unique; the image file stem by default
  std::string path;    // as written in the manifest (relative to it, or absolute)
  std::string camera;  // Camera::id
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // projection centre, CRS units
  // Camera-to-world rotation in PATB axes (x right, y up, z back) with
  // respect to the CRS grid axes (E, N, up). Written as omega/phi/kappa.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

// The block manifest (schemas/block.schema.json): the one document every
// roofsweep command reads. `import` writes it from other formats.
struct BlockManifest {
  std::string crs;  // PROJ-readable definition, empty for a local block
  // Heights of positions and ground: "ellipsoidal" (default) or
  // "orthometric" with a constant geoid_undulation N (h = H + N).
  std::string height_type = "ellipsoidal";
  double geoid_undulation = 0;
  std::vector<Camera> cameras;
  std::vector<ManifestImage> images;
  std::optional<double> ground_height;  // CRS height units
  std::string dtm;                      // raster path, optional
  // A surface model (roofs, trees) instead of a DTM: the ground is derived
  // from it by TerrainFromSurfaceModel over terrain_window_m.
  std::string dsm;
  double terrain_window_m = 30.0;
  double max_building_height = 60.0;
  std::string footprints;  // OGR dataset, optional
  std::string footprints_layer;
  std::optional<Eigen::Vector4d> aoi;  // min x, min y, max x, max y, CRS units
  std::string base_dir;                // folder relative paths refer to (not serialised)
  std::string source;                  // file it was read from (not serialised)

  int FindCamera(const std::string& id) const;  // -1 when absent
};

// Reads and validates a manifest against schemas/block.schema.json. Errors
// name the file and the JSON pointer ("block.json: /images/3/camera: ...").
BlockManifest ReadManifest(const std::string& path);

// Serialises the manifest as JSON. Image paths are written relative to the
// manifest's folder when they lie below it.
std::string ManifestToJson(const BlockManifest& manifest, const std::string& manifest_path);

// Writes atomically (temporary name + rename). Refuses an existing file
// unless overwrite is set.
void WriteManifest(const BlockManifest& manifest, const std::string& path, bool overwrite);

// Checks what a manifest promises: unique image names, known cameras, valid
// cameras, finite numbers, and (when check_images) that every image exists
// and GDAL can read its header with the size the camera says.
void ValidateManifest(const BlockManifest& manifest, bool check_images);

// Turns a manifest into a Block in the local frame (ENU at the block centre
// when there is a CRS): positions through PROJ, rotations from grid to ENU,
// ground height or DTM resampled into the local frame.
Block ManifestToBlock(const BlockManifest& manifest);

// The manifest's ground in its CRS's own coordinates over `bbox` (min x,
// min y, max x, max y): the constant height, or the DTM (the terrain
// derived from the DSM) on a north-up grid at its cell size; unknown when the
// manifest has neither. For comparing results with a reference model in the
// CRS (eval), which never goes through the local frame.
GroundModel ManifestGroundInCrs(const BlockManifest& manifest, const Eigen::Vector4d& bbox);

// The local frame ManifestToBlock uses for this manifest (same CRS, origin
// and undulation), to take results back to CRS coordinates.
LocalFrame ManifestLocalFrame(const BlockManifest& manifest);

}  // namespace roofsweep
