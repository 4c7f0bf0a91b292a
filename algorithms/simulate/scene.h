#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/geometry/camera.h"
#include "algorithms/geometry/view.h"
#include "algorithms/simulate/materials.h"
#include "algorithms/simulate/scene_truth.h"

namespace roofsweep {
namespace sim {

// A tree: trunk plus an ellipsoidal crown; occludes and casts shadows.
struct Tree {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();  // trunk foot on the ground
  double trunk_height = 3;
  double crown_radius = 3;
  double crown_height = 5;  // vertical extent of the crown
  int material = -1;        // foliage, index into Scene::materials
  uint32_t seed = 1;
};

// Oriented rectangle of ground material (road, sidewalk, yard, paint).
struct GroundRegion {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  Eigen::Vector2d axis = Eigen::Vector2d::UnitX();  // unit, along half_size.x()
  Eigen::Vector2d half_size = Eigen::Vector2d::Ones();
  int material = -1;
  bool Contains(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d d = p - center;
    const double a = d.dot(axis), b = d.x() * -axis.y() + d.y() * axis.x();
    return std::abs(a) <= half_size.x() && std::abs(b) <= half_size.y();
  }
};

// A smooth hill (a hollow when the amplitude is negative) on the terrain:
// amplitude x exp(-|p - centre|^2 / (2 sigma^2)).
struct Hill {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double sigma = 50;
  double amplitude = 0;
};

// Terrain: a plane through height z at the origin rising by `slope` (dz/dx,
// dz/dy; zero: flat), with smooth hills on it, a base material and regions
// on top (a later region wins where they overlap). Every point has its own
// ground height, which a block on a hillside needs tested; the hills make
// that height vary across a building as real relief does, so that no plane
// fitted to the ground explains the block.
struct GroundLayout {
  double z = 0;
  Eigen::Vector2d slope = Eigen::Vector2d::Zero();
  std::vector<Hill> hills;
  double HeightAt(const Eigen::Vector2d& p) const {
    double h = z + slope.dot(p);
    for (const Hill& k : hills)
      h += k.amplitude * std::exp(-(p - k.centre).squaredNorm() / (2 * k.sigma * k.sigma));
    return h;
  }
  // d HeightAt / d (x, y).
  Eigen::Vector2d GradientAt(const Eigen::Vector2d& p) const {
    Eigen::Vector2d g = slope;
    for (const Hill& k : hills) {
      const Eigen::Vector2d r = p - k.centre;
      const double s2 = k.sigma * k.sigma;
      g -= k.amplitude * std::exp(-r.squaredNorm() / (2 * s2)) / s2 * r;
    }
    return g;
  }
  bool Planar() const { return hills.empty(); }
  int base_material = -1;
  std::vector<GroundRegion> regions;
  int MaterialAt(const Eigen::Vector2d& p) const;  // linear scan; renderer indexes it
};

// Small objects that are not LoD2 buildings: cars, hedges, chimneys, solar
// panels, roof windows, roof-top boxes. They occlude and cast shadows but are
// NOT part of the ground truth (clutter the pipeline must ignore); roof
// objects stand on roof planes without changing them.
enum class PropKind { kCar, kHedge, kChimney, kSolarPanel, kSkylight, kRoofBox };
const char* PropKindName(PropKind k);

// An oriented box: centre, unit axes (columns of `axes`), half extents.
struct Prop {
  PropKind kind = PropKind::kCar;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half = Eigen::Vector3d::Constant(0.5);
  int material = -1;
  uint32_t seed = 1;
};

struct Scene {
  CityModel city;
  std::vector<Prop> props;
  std::vector<Material> materials;
  // Material of every surface: surface_materials[building][surface].
  std::vector<std::vector<int>> surface_materials;
  std::vector<Tree> trees;
  GroundLayout ground;
  Eigen::Vector4d area = Eigen::Vector4d::Zero();  // min x, min y, max x, max y of the content
};

struct SceneOptions {
  double extent_x = 160;  // m, area centred on the origin
  double extent_y = 160;
  // Upper bound on the number of buildings. Lots are filled from the centre
  // of the area outwards; lots beyond the bound stay gardens. Sheds and
  // garages are buildings too (they are LoD2 solids in the truth).
  int building_count = 30;
  double min_length = 6;  // footprint length range, m
  double max_length = 40;
  // Relative frequency of each RoofShape (flat, shed, gable, hip, half-hip,
  // pyramid, mansard, L, T).
  std::array<double, 9> shape_weights = {2, 1, 4, 2, 1, 0.7, 0.7, 1.2, 0.8};
  double aligned_fraction = 0.8;  // buildings parallel to the streets (else any yaw)
  int tree_count = 20;
  // Street grid: axes of the streets along x are street_spacing apart (the
  // block depth: two rows of lots back to back), those along y
  // block_length apart.
  // Each gap between streets along x is drawn from 0.8..1.2 x street_spacing.
  double street_spacing = 56;
  double block_length = 90;
  // Relative frequency of block types: detached houses, terraced rows,
  // apartment bars, urban perimeter rows (tall attached houses), commercial
  // halls with parking.
  std::array<double, 5> block_weights = {3, 2.5, 1.2, 1.5, 0.8};
  double street_width = 7;
  double sidewalk_width = 2;
  // Probability that all faces of a roof share one material (the hard case
  // where only shading shows the ridge); otherwise faces differ slightly.
  double same_roof_material = 0.85;
  // Share of pitched roofs coloured to match the lawn's luminance (red on
  // green, visible only in hue).
  double isoluminant_fraction = 0.15;
  // 1 = natural palette; < 1 pulls roof colours towards the ground colour
  // (low contrast scenes).
  double roof_contrast = 1.0;
  double ground_z = 0;
  // Rise of the terrain per metre east and north (0: flat). Each building
  // stands on the lowest ground under its footprint, so its walls reach the
  // terrain all round; cars, hedges and trees stand on the ground under them.
  Eigen::Vector2d ground_slope = Eigen::Vector2d::Zero();
  // Relief on top of that plane: smooth hills and hollows (Hill) whose
  // heights span up to terrain_relief_m, 35-90 m wide (sigma), so that the
  // ground under one building varies by centimetres to a metre, as on a
  // real hillside town. 0: none.
  double terrain_relief_m = 0;
  // Cars, hedges, garden beds, paths, drains (clutter on the ground).
  bool clutter = true;
  // Chimneys, solar panels, roof windows, roof-top boxes (not roof planes).
  bool roof_objects = true;
  // When given, a building is only placed if its whole footprint, at ground
  // and at roof top, lies inside at least `min_views` of these images (so
  // every building of the truth can be reconstructed); elsewhere its lot
  // stays a garden.
  std::vector<std::pair<Camera, Pose>> visibility_views;
  int min_views = 2;
};

// A random town quarter filling the area: a street grid with markings and
// sidewalks; blocks of detached houses with garages and sheds, terraced
// rows sharing walls, apartment bars, tall urban rows, commercial halls with
// parking lots; front gardens, driveways, hedges, cars, trees (some over
// roofs), roof objects.
Scene GenerateScene(const SceneOptions& options, uint64_t seed);

// A scene around given buildings (e.g. a real CityGML LoD2 model read by
// io): materials by surface type, flat ground at the lowest ground surface,
// trees kept off the footprints. Street layout is not inferred; a ground
// slope is refused (the model's own ground heights would not follow it).
Scene SceneFromCityModel(const CityModel& city, const SceneOptions& options, uint64_t seed);

// Buildings, their classified edges, roof planes, the ground markings
// (borders between ground materials, as 3D segments) and the props' edges
// in the open air (PropEdges).
SceneTruth TruthOf(const Scene& scene);

}  // namespace sim
}  // namespace roofsweep
