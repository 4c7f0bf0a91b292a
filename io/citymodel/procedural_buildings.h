#pragma once

#include <string>

#include "algorithms/buildings/city_model.h"

namespace roofsweep::testing {

// Small LoD2 fixtures with correct outward rings (exterior counter-clockwise
// seen from outside), for the io tests and the benchmark. Footprint corner
// (x0, y0) at ground height z0; width w along x, depth d along y.
Building MakeBox(const std::string& id, double x0, double y0, double z0, double w, double d,
                 double h);
// Ridge along x at mid-depth, eaves at z0 + eave, ridge at z0 + ridge.
Building MakeGable(const std::string& id, double x0, double y0, double z0, double w, double d,
                   double eave, double ridge);
// As MakeGable with the ridge shortened by `inset` at both ends (hip roof).
Building MakeHip(const std::string& id, double x0, double y0, double z0, double w, double d,
                 double eave, double ridge, double inset);
// `n` buildings cycling box/gable/hip on a 20 m grid near (x0, y0), with
// generic attributes, in `crs`.
// Building `i` of MakeCity (grid with `cols` columns), for streaming without
// holding the model.
Building MakeCityBuilding(int i, int cols, double x0 = 500000, double y0 = 5400000,
                          double z0 = 100);
int CityColumns(int n);
CityModel MakeCity(int n, double x0 = 500000, double y0 = 5400000, double z0 = 100,
                   const std::string& crs = "EPSG:25832");

}  // namespace roofsweep::testing
