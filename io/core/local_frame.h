#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>

#include "algorithms/geometry/block.h"

namespace roofsweep {

// The block's local Cartesian frame: east-north-up metres at an origin near
// the block, built from the block CRS through PROJ (CRS -> geographic 3D of
// the same datum) and GeographicLib's LocalCartesian on that ellipsoid.
// Without a CRS it is the identity.
//
// Heights must be ellipsoidal: a compound CRS whose vertical part PROJ can
// only handle by a "ballpark" step (no geoid grid installed) is refused, and
// orthometric heights need an explicit constant undulation.
//
// Projected CRSs take (easting, northing, height) and geographic ones
// (longitude, latitude, height) in degrees, whatever the CRS's own axis
// order. Every method may be called from several threads at once (each
// object owns its PROJ context and serialises its PROJ calls).
class LocalFrame {
 public:
  // crs: PROJ-readable definition ("EPSG:25833", WKT, PROJ string); empty
  // for a block with no CRS. origin: in CRS coordinates. undulation: added
  // to heights to make them ellipsoidal (0 when they already are).
  LocalFrame(const std::string& crs, const Eigen::Vector3d& origin, double undulation = 0.0);
  ~LocalFrame();
  LocalFrame(LocalFrame&&) noexcept;
  LocalFrame& operator=(LocalFrame&&) noexcept;

  bool HasCrs() const;
  // The origin as given, in CRS coordinates.
  const Eigen::Vector3d& OriginCrs() const;
  Eigen::Vector3d ToLocal(const Eigen::Vector3d& crs_xyz) const;
  Eigen::Vector3d ToCrs(const Eigen::Vector3d& local_xyz) const;
  // Rotation taking vectors in CRS grid axes (E, N, up at crs_xyz) into
  // local ENU axes; Rz(-convergence) for a transverse Mercator grid.
  Eigen::Matrix3d GridToLocal(const Eigen::Vector3d& crs_xyz) const;
  // Meridian convergence at crs_xyz in degrees (0 without a CRS).
  double ConvergenceDeg(const Eigen::Vector3d& crs_xyz) const;
  FrameInfo Info() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace roofsweep
