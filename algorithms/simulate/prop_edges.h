#pragma once

#include <vector>

#include "algorithms/simulate/scene.h"
#include "algorithms/simulate/scene_truth.h"

namespace roofsweep {
namespace sim {

// The edges of the props (cars, hedges, chimneys, solar panels, roof
// windows, roof-top boxes) where they stand in the open air, as kProp
// truth edges. The props are not LoD2, but their edges are real: a 3D line
// on a chimney's top or a solar array's border is a correct line, and an
// evaluator that counted it as a mismatch would understate precision by
// what the scene happens to hold. A box edge is cut where it runs below the
// terrain or below a roof (a chimney's foot, a roof box's base, a roof
// window's underside); where a box sinks into a roof, the line where the
// two meet is not added (it is short, and lies within centimetres of the
// roof, on which a line counts as on a surface).
// `roof_planes`: the truth's roof faces (SceneTruth::roof_planes).
std::vector<TrueEdge> PropEdges(const Scene& scene, const std::vector<RoofPlane>& roof_planes);

}  // namespace sim
}  // namespace roofsweep
