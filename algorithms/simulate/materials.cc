#include "algorithms/simulate/materials.h"

#include <algorithm>
#include <cmath>

#include "algorithms/simulate/noise.h"

namespace roofsweep {
namespace sim {

const char* PatternName(Pattern p) {
  switch (p) {
    case Pattern::kClayTiles:
      return "clay_tiles";
    case Pattern::kSlate:
      return "slate";
    case Pattern::kStandingSeam:
      return "standing_seam";
    case Pattern::kBitumen:
      return "bitumen";
    case Pattern::kGravel:
      return "gravel";
    case Pattern::kConcrete:
      return "concrete";
    case Pattern::kPlaster:
      return "plaster";
    case Pattern::kBrick:
      return "brick";
    case Pattern::kGrass:
      return "grass";
    case Pattern::kAsphalt:
      return "asphalt";
    case Pattern::kPaving:
      return "paving";
    case Pattern::kPaint:
      return "paint";
    case Pattern::kFoliage:
      return "foliage";
    case Pattern::kBark:
      return "bark";
  }
  return "?";
}

Eigen::Vector3f SrgbToLinear(int r, int g, int b) {
  auto f = [](int c) {
    const float s = c / 255.0f;
    return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
  };
  return {f(r), f(g), f(b)};
}

float LinearToSrgb(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float Luminance(const Eigen::Vector3f& c) {
  return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z();
}

namespace {

inline float Smooth(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

// Weight of a pattern whose smallest feature is `size` metres: 1 while a
// sample resolves it, fading to 0 (the pattern's mean) as it gets finer
// than two samples.
inline float Resolve(float size, float footprint) {
  return std::clamp(2.0f - 3.0f * footprint / size, 0.0f, 1.0f);
}

// Running-bond element grid: element index and position inside it.
struct Cell {
  int i, j;
  float fu, fv;
};
inline Cell Bond(float u, float v, float w, float h) {
  const float rv = v / h;
  const int j = static_cast<int>(std::floor(rv));
  const float ru = u / w + ((j & 1) ? 0.5f : 0.0f);
  const int i = static_cast<int>(std::floor(ru));
  return {i, j, ru - i, rv - j};
}

}  // namespace

Eigen::Vector3f EvaluateAlbedo(const Material& m, float u, float v, float footprint,
                               uint32_t seed) {
  seed ^= m.seed * 0x9e3779b9u;
  const float s = m.element_size;
  // Large-scale staining common to all patterns.
  const float stain = FractalNoise(u, v, 0.12f, 3, 0.55f, footprint, seed + 7);
  float factor = 1.0f + m.weathering * stain;
  float mix2 = 0.0f;  // share of albedo2
  switch (m.pattern) {
    case Pattern::kClayTiles: {
      const Cell c = Bond(u, v, 0.75f * s, s);
      const float tile = (CellRandom(c.i, c.j, seed) - 0.5f) * 2.0f * m.variation;
      // Pan tiles: rounded across, the lower end of each row shadows the row
      // below it (v runs down the slope).
      const float across = 0.08f * std::cos(6.2831853f * c.fu);
      const float lip = -0.45f * Smooth(0.78f, 0.95f, c.fv) + 0.08f * (0.5f - c.fv);
      factor *= 1.0f + Resolve(0.2f * s, footprint) * (lip + across) + Resolve(s, footprint) * tile;
      mix2 = m.secondary *
             Smooth(0.35f, 0.75f, FractalNoise(u, v, 0.5f, 4, 0.5f, footprint, seed + 3));
      break;
    }
    case Pattern::kSlate: {
      const Cell c = Bond(u, v, 1.3f * s + 0.0f, s);
      const float tile = (CellRandom(c.i, c.j, seed) - 0.5f) * 2.0f * m.variation;
      const float joint = -0.35f * Smooth(0.88f, 0.97f, c.fv) - 0.25f * Smooth(0.94f, 0.99f, c.fu);
      factor *= 1.0f + Resolve(0.15f * s, footprint) * joint + Resolve(s, footprint) * tile;
      break;
    }
    case Pattern::kStandingSeam: {
      const float ru = u / s;
      const float fu = ru - std::floor(ru);
      const float seam = 0.35f * (1.0f - Smooth(0.0f, 0.05f, fu)) -
                         0.18f * Smooth(0.05f, 0.1f, fu) * (1.0f - Smooth(0.1f, 0.16f, fu));
      const float sheet =
          (CellRandom(static_cast<int>(std::floor(ru)), 0, seed) - 0.5f) * m.variation;
      factor *= 1.0f + Resolve(0.1f * s, footprint) * seam + Resolve(s, footprint) * sheet;
      mix2 =
          m.secondary * Smooth(0.2f, 0.7f, FractalNoise(u, v, 0.3f, 4, 0.5f, footprint, seed + 5));
      break;
    }
    case Pattern::kBitumen:
      factor *= 1.0f + 0.08f * FractalNoise(u, v, 2.0f, 5, 0.6f, footprint, seed + 11);
      mix2 =
          m.secondary * Smooth(0.3f, 0.6f, FractalNoise(u, v, 0.2f, 3, 0.5f, footprint, seed + 2));
      break;
    case Pattern::kGravel:
      factor *= 1.0f + 0.25f * FractalNoise(u, v, 12.0f, 4, 0.7f, footprint, seed + 13);
      break;
    case Pattern::kConcrete: {
      const Cell c = Bond(u, v, 3.0f, 3.0f);
      const float joint =
          -0.3f * (1.0f - Smooth(0.0f, 0.01f, c.fu)) - 0.3f * (1.0f - Smooth(0.0f, 0.01f, c.fv));
      factor *= 1.0f + Resolve(0.05f, footprint) * joint +
                (CellRandom(c.i, c.j, seed) - 0.5f) * m.variation +
                0.06f * FractalNoise(u, v, 4.0f, 4, 0.6f, footprint, seed + 17);
      break;
    }
    case Pattern::kPlaster:
      factor *= 1.0f + 0.05f * FractalNoise(u, v, 3.0f, 4, 0.6f, footprint, seed + 19);
      break;
    case Pattern::kBrick: {
      const Cell c = Bond(u, v, 0.25f, 0.075f);
      const float mortar = 1.0f - Smooth(0.0f, 0.12f, c.fv) * Smooth(0.0f, 0.04f, c.fu);
      mix2 = Resolve(0.01f, footprint) * mortar + (1 - Resolve(0.01f, footprint)) * 0.15f;
      factor *=
          1.0f + Resolve(0.075f, footprint) * (CellRandom(c.i, c.j, seed) - 0.5f) * m.variation;
      break;
    }
    case Pattern::kGrass: {
      factor *= 1.0f + 0.18f * FractalNoise(u, v, 6.0f, 3, 0.6f, footprint, seed + 23);
      mix2 = m.secondary *
             Smooth(-0.1f, 0.6f, FractalNoise(u, v, 0.08f, 4, 0.55f, footprint, seed + 29));
      break;
    }
    case Pattern::kAsphalt:
      factor *= 1.0f + 0.12f * FractalNoise(u, v, 10.0f, 3, 0.7f, footprint, seed + 31);
      mix2 = m.secondary *
             Smooth(0.35f, 0.45f, FractalNoise(u, v, 0.15f, 3, 0.5f, footprint, seed + 37));
      break;
    case Pattern::kPaving: {
      const Cell c = Bond(u, v, s, 0.5f * s);
      const float joint = (1.0f - Smooth(0.0f, 0.06f, c.fv)) + (1.0f - Smooth(0.0f, 0.03f, c.fu));
      mix2 = Resolve(0.02f, footprint) * std::min(1.0f, joint) +
             (1 - Resolve(0.02f, footprint)) * 0.08f;
      factor *=
          1.0f + Resolve(0.5f * s, footprint) * (CellRandom(c.i, c.j, seed) - 0.5f) * m.variation;
      break;
    }
    case Pattern::kPaint:
      factor *=
          1.0f - 0.12f * std::max(0.0f, FractalNoise(u, v, 3.0f, 4, 0.6f, footprint, seed + 41));
      break;
    case Pattern::kFoliage: {
      // Leaf clusters: bright sunlit clumps with dark gaps between them.
      const float clumps = FractalNoise(u, v, 1.6f, 5, 0.6f, footprint, seed + 43);
      factor *= 0.75f + 0.6f * Smooth(-0.5f, 0.6f, clumps);
      mix2 =
          m.secondary * Smooth(0.0f, 0.8f, FractalNoise(u, v, 0.4f, 2, 0.5f, footprint, seed + 47));
      break;
    }
    case Pattern::kBark:
      factor *= 1.0f + 0.15f * FractalNoise(u, v, 8.0f, 3, 0.6f, footprint, seed + 53);
      break;
  }
  const Eigen::Vector3f base = (1.0f - mix2) * m.albedo + mix2 * m.albedo2;
  return (base * std::max(0.05f, factor)).cwiseMin(0.95f);
}

namespace {
Material Make(const char* name, Pattern p, Eigen::Vector3f a, Eigen::Vector3f a2, float size,
              float variation, float weathering, float secondary, uint32_t seed) {
  Material m;
  m.name = name;
  m.pattern = p;
  m.albedo = a;
  m.albedo2 = a2;
  m.element_size = size;
  m.variation = variation;
  m.weathering = weathering;
  m.secondary = secondary;
  m.seed = seed;
  return m;
}
}  // namespace

// Colours are typical sRGB values of the materials in aerial images of
// central European towns (clay tiles terracotta to brown, anthracite glazed
// tiles, slate, copper patina, zinc, bitumen, gravel, concrete).
int RoofMaterialCount(bool flat) { return flat ? 4 : 8; }

Material RoofMaterial(int index, bool flat, uint32_t seed) {
  const Eigen::Vector3f moss = SrgbToLinear(95, 100, 62);
  if (flat) {
    switch (index % 4) {
      case 0:
        return Make("bitumen", Pattern::kBitumen, SrgbToLinear(74, 74, 76),
                    SrgbToLinear(100, 98, 95), 1, 0.05f, 0.1f, 0.3f, seed);
      case 1:
        return Make("gravel", Pattern::kGravel, SrgbToLinear(165, 160, 150),
                    SrgbToLinear(120, 118, 110), 1, 0.05f, 0.12f, 0.1f, seed);
      case 2:
        return Make("concrete", Pattern::kConcrete, SrgbToLinear(150, 148, 140), moss, 3, 0.08f,
                    0.15f, 0.1f, seed);
      default:
        return Make("green_roof", Pattern::kGrass, SrgbToLinear(95, 110, 60),
                    SrgbToLinear(130, 120, 80), 1, 0.1f, 0.1f, 0.5f, seed);
    }
  }
  switch (index % 8) {
    case 0:
      return Make("terracotta_tiles", Pattern::kClayTiles, SrgbToLinear(172, 82, 56), moss, 0.33f,
                  0.12f, 0.12f, 0.15f, seed);
    case 1:
      return Make("red_brown_tiles", Pattern::kClayTiles, SrgbToLinear(128, 62, 48), moss, 0.33f,
                  0.12f, 0.12f, 0.15f, seed);
    case 2:
      return Make("dark_brown_tiles", Pattern::kClayTiles, SrgbToLinear(92, 62, 52), moss, 0.30f,
                  0.10f, 0.10f, 0.1f, seed);
    case 3:
      return Make("anthracite_tiles", Pattern::kClayTiles, SrgbToLinear(60, 62, 66),
                  SrgbToLinear(90, 90, 85), 0.30f, 0.08f, 0.10f, 0.1f, seed);
    case 4:
      return Make("slate", Pattern::kSlate, SrgbToLinear(88, 94, 102), SrgbToLinear(110, 112, 110),
                  0.20f, 0.10f, 0.08f, 0.0f, seed);
    case 5:
      return Make("copper_green", Pattern::kStandingSeam, SrgbToLinear(100, 152, 130),
                  SrgbToLinear(80, 110, 90), 0.55f, 0.06f, 0.12f, 0.3f, seed);
    case 6:
      return Make("zinc", Pattern::kStandingSeam, SrgbToLinear(146, 150, 156),
                  SrgbToLinear(120, 124, 128), 0.5f, 0.05f, 0.08f, 0.2f, seed);
    default:
      return Make("weathered_concrete_tiles", Pattern::kSlate, SrgbToLinear(132, 130, 124), moss,
                  0.33f, 0.1f, 0.18f, 0.2f, seed);
  }
}

int WallMaterialCount() { return 5; }

Material WallMaterial(int index, uint32_t seed) {
  switch (index % 5) {
    case 0:
      return Make("white_plaster", Pattern::kPlaster, SrgbToLinear(230, 226, 214),
                  SrgbToLinear(200, 200, 190), 1, 0.05f, 0.06f, 0, seed);
    case 1:
      return Make("cream_plaster", Pattern::kPlaster, SrgbToLinear(226, 210, 176),
                  SrgbToLinear(200, 190, 160), 1, 0.05f, 0.06f, 0, seed);
    case 2:
      return Make("ochre_plaster", Pattern::kPlaster, SrgbToLinear(210, 176, 126),
                  SrgbToLinear(190, 160, 110), 1, 0.05f, 0.06f, 0, seed);
    case 3:
      return Make("grey_plaster", Pattern::kPlaster, SrgbToLinear(188, 188, 184),
                  SrgbToLinear(160, 160, 155), 1, 0.05f, 0.06f, 0, seed);
    default:
      return Make("brick", Pattern::kBrick, SrgbToLinear(150, 76, 56), SrgbToLinear(200, 195, 185),
                  0.25f, 0.15f, 0.05f, 0, seed);
  }
}

Material GrassMaterial(uint32_t seed) {
  return Make("grass", Pattern::kGrass, SrgbToLinear(88, 120, 58), SrgbToLinear(138, 136, 78), 1,
              0.1f, 0.08f, 0.45f, seed);
}
Material AsphaltMaterial(uint32_t seed) {
  return Make("asphalt", Pattern::kAsphalt, SrgbToLinear(80, 80, 82), SrgbToLinear(62, 62, 64), 1,
              0.05f, 0.08f, 0.6f, seed);
}
Material PavingMaterial(uint32_t seed) {
  return Make("paving", Pattern::kPaving, SrgbToLinear(158, 152, 142), SrgbToLinear(105, 100, 95),
              0.2f, 0.12f, 0.08f, 0, seed);
}
Material PaintMaterial(uint32_t seed) {
  return Make("road_paint", Pattern::kPaint, SrgbToLinear(232, 232, 226),
              SrgbToLinear(200, 200, 200), 1, 0, 0.03f, 0, seed);
}
Material FoliageMaterial(int index, uint32_t seed) {
  if (index % 2 == 0)
    return Make("deciduous", Pattern::kFoliage, SrgbToLinear(70, 102, 44),
                SrgbToLinear(100, 115, 50), 1, 0.1f, 0.05f, 0.3f, seed);
  return Make("conifer", Pattern::kFoliage, SrgbToLinear(42, 68, 40), SrgbToLinear(60, 80, 45), 1,
              0.1f, 0.05f, 0.2f, seed);
}
Material BarkMaterial(uint32_t seed) {
  return Make("bark", Pattern::kBark, SrgbToLinear(85, 70, 55), SrgbToLinear(70, 60, 50), 1, 0.1f,
              0.05f, 0, seed);
}

}  // namespace sim
}  // namespace roofsweep
