#ifndef ROOFSWEEP_ALGORITHMS_BUILDINGS_CLASSIFY_ROOF_TYPE_H_
#define ROOFSWEEP_ALGORITHMS_BUILDINGS_CLASSIFY_ROOF_TYPE_H_

#include <vector>

#include "algorithms/buildings/city_model.h"

namespace roofsweep {

// Roof type (roof_type:: code, as CityGML's bldg:roofType) from the roof
// faces of one building: flat, monopitch, gabled, half-hipped, hipped,
// pavilion (pyramid), mansard or combination.
//
// Faces under 5 % of the roof area are slivers of the envelope and dormers,
// and are ignored, but for the small end faces of a half-hipped roof. A
// face is a triangle (pavilion against hipped) when it has three corners
// once its vertices within 0.5 m are merged and turns under 15 deg are
// ignored.
//
// - mansard: on two opposite sides, a face with a shallower face of the
//   same aspect above it (slope at least 20 deg less, starting where the
//   lower one ends). A mansard with a flat top is not told apart
//   (combination).
// - hipped: four faces at right angles; a cross gable (L or T-shaped
//   house, four quadrilaterals) is taken for one.
// - half-hipped: a gable, or a hipped roof, whose end faces are triangles
//   at the ridge that stop above the eaves (by a fifth of the roof's
//   height, and 0.5 m at least); a hipped roof's end faces reach them.
int ClassifyRoofType(const std::vector<Polygon3>& roof_faces);

}  // namespace roofsweep

#endif  // ROOFSWEEP_ALGORITHMS_BUILDINGS_CLASSIFY_ROOF_TYPE_H_
