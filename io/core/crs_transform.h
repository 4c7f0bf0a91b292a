#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

namespace roofsweep {

// What kind of CRS a definition names (a bound CRS counts as its base).
enum class CrsKind { kProjected, kGeographic2D, kGeographic3D, kCompound, kGeocentric, kOther };

struct CrsTransformOptions {
  // Appended to the refusal of a ballpark height step; says what the user
  // can do instead. Default: a hint for output reprojection.
  std::string ballpark_hint =
      "use CRSs with ellipsoidal heights on both sides (a 2D CRS is taken with ellipsoidal "
      "heights), or install the geoid grid PROJ names";
  // Longitude/latitude box (west, south, east, north, degrees) of the data:
  // the operation chosen is valid there. Empty: PROJ's first choice.
  std::optional<Eigen::Vector4d> area_of_interest;
};

// A 3D coordinate operation between two CRSs through PROJ, chosen once:
// the most relevant instantiable operation, missing grids discarded.
// Operations containing a "ballpark" step (heights passed through unchanged
// between different vertical datums, or a datum shift PROJ does not know)
// are refused with a one-line roofsweep::Error, as are unknown CRSs.
//
// A 2D projected or geographic CRS is promoted to 3D, so its heights are
// ellipsoidal on its own datum and change with a datum shift; compound CRSs
// keep their vertical datum. Points are (easting, northing, height) for
// projected CRSs and (longitude, latitude, height) in degrees for geographic
// ones, whatever the CRS's own axis order.
//
// Every method may be called from several threads at once (each object owns
// its PROJ context and serialises its PROJ calls).
class CrsTransform {
 public:
  // source, target: PROJ-readable definitions ("EPSG:25833", WKT, PROJ
  // strings, and what GDAL's SetFromUserInput reads: ESRI WKT, URNs, URLs).
  CrsTransform(const std::string& source, const std::string& target,
               const CrsTransformOptions& options = {});
  // From `crs` to the geographic 3D CRS of its own datum (lon, lat,
  // ellipsoidal h): what LocalFrame builds its frame on. Error messages name
  // the CRS as "CRS '<crs>': ...".
  static CrsTransform ToOwnGeographic3D(const std::string& crs,
                                        const CrsTransformOptions& options = {});
  // Parses `crs` only; throws for an unknown CRS. `horizontal` (optional)
  // receives the kind of a compound CRS's horizontal part (else the kind).
  static CrsKind KindOf(const std::string& crs, CrsKind* horizontal = nullptr);

  ~CrsTransform();
  CrsTransform(CrsTransform&&) noexcept;
  CrsTransform& operator=(CrsTransform&&) noexcept;

  // Throws roofsweep::Error naming the point when PROJ cannot transform it.
  Eigen::Vector3d Forward(const Eigen::Vector3d& p) const;
  Eigen::Vector3d Inverse(const Eigen::Vector3d& p) const;

  CrsKind source_kind() const;
  CrsKind target_kind() const;
  // Semi-major axis (m) and flattening of the source's ellipsoid.
  double source_semi_major() const;
  double source_flattening() const;
  // PROJ's name of the chosen operation, e.g. "Inverse of UTM zone 33N +
  // UTM zone 32N", for reports.
  std::string operation_name() const;

 private:
  struct Impl;
  CrsTransform();
  std::unique_ptr<Impl> impl_;
};

}  // namespace roofsweep
