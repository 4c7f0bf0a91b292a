#pragma once

#include <string>
#include <vector>

#include "io/core/block_manifest.h"
#include "io/orientation/block_source.h"

namespace roofsweep::orientation {

// `opk` and `metashape`: one OPK text file, recognised by its header:
//  - Pix4D *_calibrated_external_camera_parameters.txt
//    "imageName X Y Z Omega Phi Kappa [X_sigma ...]", space separated;
//  - Metashape "Omega Phi Kappa" export: "# Cameras (N)" /
//    "# PhotoID, X, Y, Z, Omega, Phi, Kappa, r11, ..., r33", TAB separated;
//    the r matrix must equal R(omega, phi, kappa) or its transpose;
//  - CSV/space/TAB with a header naming filename|image|name, x, y, z, omega,
//    phi, kappa [, camera] (orthority), quotes allowed;
//  - headerless "name X Y Z omega phi kappa" (orthority camera_pos_ori.txt).
// Angles in degrees, PATB (camera x right, y up, z back) to grid axes.
// Interior orientation: an .xml/.yaml/.cam/.json/.txt among `sources` or
// options.camera_file (see ReadCameraFile); without one, Pix4D's
// calibrated_camera_parameters.txt or .cam beside a Pix4D file is used.
// CRS: options.crs, else FILE.prj beside the file.
BlockManifest ReadOpk(const std::vector<std::string>& sources, const ImportOptions& options);

}  // namespace roofsweep::orientation
