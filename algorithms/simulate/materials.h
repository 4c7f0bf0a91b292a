#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>

namespace roofsweep {
namespace sim {

// Procedural surface patterns. Coordinates (u, v) are metres in the
// surface: u horizontal, v down the slope (roofs, walls) or (x, y) on the
// ground, so tile rows run parallel to the eave as on real roofs.
enum class Pattern {
  kClayTiles,     // rows of tiles with shadowed overlaps and per-tile colour
  kSlate,         // small rectangular slates / fibre-cement
  kStandingSeam,  // metal sheets with seams down the slope (copper, zinc)
  kBitumen,       // flat-roof membrane
  kGravel,        // flat-roof gravel ballast
  kConcrete,      // weathered slabs with joints
  kPlaster,       // rendered walls
  kBrick,         // brick walls
  kGrass,
  kAsphalt,
  kPaving,  // concrete pavers, running bond
  kPaint,   // road markings
  kFoliage,
  kBark,
  kSoil,        // garden beds, bare patches
  kSolarPanel,  // photovoltaic modules: dark cells in a light frame
  kGlass,       // roof windows, car windows
  kMetal,       // car paint, roof-top boxes, manhole covers
};
const char* PatternName(Pattern p);

struct Material {
  std::string name;
  Pattern pattern = Pattern::kPlaster;
  Eigen::Vector3f albedo = Eigen::Vector3f::Constant(0.5f);   // linear RGB, mean
  Eigen::Vector3f albedo2 = Eigen::Vector3f::Constant(0.3f);  // moss, mortar, joints, dry grass
  float element_size = 0.33f;  // tile row spacing, paver length, seam spacing (m)
  float variation = 0.12f;     // relative brightness spread between elements
  float weathering = 0.12f;    // amplitude of large-scale fractal staining
  float secondary = 0.1f;      // share of albedo2 patches (moss, dry grass)
  uint32_t seed = 1;
};

// Linear reflectance at (u, v). `footprint` is the size of one sample on
// the surface (m); pattern detail finer than that is faded to its mean.
Eigen::Vector3f EvaluateAlbedo(const Material& m, float u, float v, float footprint, uint32_t seed);

// sRGB (0..255) to linear reflectance and back.
Eigen::Vector3f SrgbToLinear(int r, int g, int b);
float LinearToSrgb(float linear);  // 0..1 -> 0..1
float Luminance(const Eigen::Vector3f& linear_rgb);

// Palettes of real roof, wall and ground colours (see materials.cc).
Material RoofMaterial(int index, bool flat, uint32_t seed);  // index wraps
int RoofMaterialCount(bool flat);
Material WallMaterial(int index, uint32_t seed);
int WallMaterialCount();
Material GrassMaterial(uint32_t seed);
Material AsphaltMaterial(uint32_t seed);
Material PavingMaterial(uint32_t seed);
Material PaintMaterial(uint32_t seed);
Material FoliageMaterial(int index, uint32_t seed);
Material BarkMaterial(uint32_t seed);
Material SoilMaterial(uint32_t seed);
Material SolarPanelMaterial(uint32_t seed);
Material GlassMaterial(uint32_t seed);
Material CarMaterial(int index, uint32_t seed);  // index wraps over common car colours
int CarMaterialCount();
Material MetalMaterial(int index, uint32_t seed);  // 0 roof boxes, 1 cast iron covers
Material HedgeMaterial(uint32_t seed);
Material ChimneyMaterial(int index, uint32_t seed);

}  // namespace sim
}  // namespace roofsweep
