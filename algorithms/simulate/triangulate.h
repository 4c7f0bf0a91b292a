#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace roofsweep {
namespace sim {

// Triangles (index triples into `ring`, counter-clockwise like the ring)
// covering a simple planar polygon, by ear clipping in the projection along
// the dominant normal axis. Holes are not supported. Own code because LoD2
// faces have a handful of vertices and CGAL's constrained triangulation
// would cost far more to compile than it saves.
std::vector<std::array<int, 3>> TriangulatePolygon(const std::vector<Eigen::Vector3d>& ring);

}  // namespace sim
}  // namespace roofsweep
