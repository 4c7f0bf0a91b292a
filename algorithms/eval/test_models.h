#pragma once

#include <functional>
#include <string>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/geometry/camera.h"
#include "algorithms/geometry/segment3.h"
#include "algorithms/geometry/view.h"

// Small LoD2 fixtures for the evaluator's tests: closed solids with outward
// rings (exterior counter-clockwise seen from outside). Independent of
// algorithms/simulate on purpose.

namespace roofsweep::eval_test {

// Flat roof over [x0, x0+l] x [y0, y0+w], ground at z0, roof at z0+h.
Building Box(const std::string& id, double x0, double y0, double l, double w, double z0, double h);
// Gable roof, ridge along x at y0 + ridge_fraction*w, ridge rise above the eaves.
Building Gable(const std::string& id, double x0, double y0, double l, double w, double z0, double h,
               double rise, double ridge_fraction = 0.5);
// Hip roof, ridge along x from x0+w/2 to x0+l-w/2 (45° hips in plan); l > w.
Building Hip(const std::string& id, double x0, double y0, double l, double w, double z0, double h,
             double rise);

// Box 10x8 at x=0, gable 12x8 (rise 3) at x=40, hip 14x10 (rise 4) at x=80,
// all at y=0, ground z=30, eaves 6 m up: 7 roof planes.
CityModel ThreeHouses();

// A 200 x 200 px camera (focal 500 px, principal point in the middle)
// looking straight down from 100 m above (x, y, 0): world (X, Y, 0) images
// at pixel (100 + 5 (X - x), 100 - 5 (Y - y)), at depth 100 - Z.
Camera NadirTestCamera();
Pose NadirTestPose(double x = 0, double y = 0);

// Every vertex mapped through f.
CityModel Transformed(const CityModel& m,
                      const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& f);

// All exterior-ring edges of the roof polygons, each shared edge once.
std::vector<Segment3> UniqueRoofEdges(const CityModel& m);

}  // namespace roofsweep::eval_test
