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
    case Pattern::kSoil:
      return "soil";
    case Pattern::kSolarPanel:
      return "solar_panel";
    case Pattern::kGlass:
      return "glass";
    case Pattern::kMetal:
      return "metal";
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
inline int Floor(float x) { return static_cast<int>(std::floor(x)); }

// Brightness of one random element of size `size` m around (u, v), faded
// to 0 when the sample footprint cannot resolve it (aggregate, blades).
inline float Speckle(float u, float v, float size, float footprint, uint32_t seed) {
  return Resolve(size, footprint) * (CellRandom(Floor(u / size), Floor(v / size), seed) - 0.5f);
}

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
  const float stain = FractalNoise(u, v, 0.12f, 2, 0.55f, footprint, seed + 7);
  float factor = 1.0f + m.weathering * stain;
  float mix2 = 0.0f;  // share of albedo2
  Eigen::Vector3f tint = Eigen::Vector3f::Ones();
  float mix3 = 0.0f;  // share of a third colour (bare soil in lawns, oil on asphalt)
  Eigen::Vector3f third = Eigen::Vector3f::Zero();
  switch (m.pattern) {
    case Pattern::kClayTiles: {
      const Cell c = Bond(u, v, 0.75f * s, s);
      const float tile = (CellRandom(c.i, c.j, seed) - 0.5f) * 2.0f * m.variation;
      // Pan tiles: rounded across, the lower end of each row shadows the row
      // below it (v runs down the slope).
      const float across = 0.08f * std::cos(6.2831853f * c.fu);
      // The shadowed lower lip covers about a quarter of the row so that
      // courses show at 5-10 cm GSD as on real images.
      const float lip = -0.4f * Smooth(0.62f, 0.9f, c.fv) + 0.1f * (0.5f - c.fv);
      // Dirt streaks run down the slope (stretched along v).
      const float streak = FractalNoise(4.0f * u, 0.3f * v, 1.0f, 3, 0.5f, footprint, seed + 9);
      factor *= 1.0f + Resolve(0.2f * s, footprint) * (lip + across) +
                Resolve(s, footprint) * tile + 0.07f * streak;
      // Replaced or differently fired tiles differ in hue, not only brightness.
      const float hue = Resolve(s, footprint) * (CellRandom(c.i, c.j, seed + 1) - 0.5f);
      tint = Eigen::Vector3f(1.0f + 0.12f * hue, 1.0f - 0.04f * hue, 1.0f - 0.1f * hue);
      mix2 = m.secondary *
             Smooth(0.35f, 0.75f, FractalNoise(u, v, 0.5f, 4, 0.5f, footprint, seed + 3));
      // Lichen spots on single tiles.
      if (CellRandom(c.i, c.j, seed + 2) < 0.04f)
        mix2 = std::max(mix2, 0.5f * Resolve(s, footprint));
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
    case Pattern::kBitumen: {
      factor *= 1.0f + 0.08f * FractalNoise(u, v, 2.0f, 5, 0.6f, footprint, seed + 11);
      // Membrane strips 1 m wide with lighter welded overlaps, patched areas.
      const float fu = u - std::floor(u);
      factor *= 1.0f + 0.12f * Resolve(0.05f, footprint) * (1.0f - Smooth(0.0f, 0.05f, fu));
      const int pi = Floor(u / 3.0f), pj = Floor(v / 3.0f);
      if (CellRandom(pi, pj, seed + 12) < 0.15f) factor *= 0.85f;
      mix2 =
          m.secondary * Smooth(0.3f, 0.6f, FractalNoise(u, v, 0.2f, 3, 0.5f, footprint, seed + 2));
      break;
    }
    case Pattern::kGravel:
      factor *= 1.0f + 0.25f * FractalNoise(u, v, 12.0f, 4, 0.7f, footprint, seed + 13) +
                0.5f * Speckle(u, v, 0.05f, footprint, seed + 14);
      // Dark puddle marks and algae where the ballast is thin.
      mix2 = 0.6f * Smooth(0.3f, 0.6f, FractalNoise(u, v, 0.3f, 3, 0.5f, footprint, seed + 15));
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
      factor *= 1.0f + 0.18f * FractalNoise(u, v, 6.0f, 3, 0.6f, footprint, seed + 23) +
                0.45f * Speckle(u, v, 0.07f, footprint, seed + 24);
      // Mowing stripes 0.8 m wide, their direction and presence per 23 m
      // cell (roughly one lawn).
      const int ci = Floor(u / 23.0f), cj = Floor(v / 23.0f);
      if (CellRandom(ci, cj, seed + 25) < 0.65f) {
        // One of four directions (no trigonometry per sample).
        static const float kDir[4][2] = {{1, 0}, {0.7071f, 0.7071f}, {0, 1}, {0.7071f, -0.7071f}};
        const float* a = kDir[static_cast<int>(4 * CellRandom(ci, cj, seed + 26)) & 3];
        const float lane = (a[0] * u + a[1] * v) / 0.8f;
        factor *= 1.0f + 0.06f * Resolve(0.8f, footprint) * ((Floor(lane) & 1) ? 1.0f : -1.0f);
      }
      mix2 = m.secondary *
             Smooth(-0.1f, 0.6f, FractalNoise(u, v, 0.08f, 3, 0.55f, footprint, seed + 29));
      // Worn and bare patches (paths across the lawn, under play areas).
      third = Eigen::Vector3f(0.16f, 0.11f, 0.065f);
      mix3 = 0.85f * Smooth(0.45f, 0.6f, FractalNoise(u, v, 0.25f, 3, 0.55f, footprint, seed + 27));
      break;
    }
    case Pattern::kAsphalt: {
      factor *= 1.0f + 0.10f * FractalNoise(u, v, 10.0f, 3, 0.7f, footprint, seed + 31) +
                0.5f * Speckle(u, v, 0.05f, footprint, seed + 32);
      mix2 = m.secondary *
             Smooth(0.35f, 0.45f, FractalNoise(u, v, 0.15f, 3, 0.5f, footprint, seed + 37));
      // Patched repairs: a rectangle of other asphalt in some 6 m cells.
      const int pi = Floor(u / 6.0f), pj = Floor(v / 6.0f);
      if (CellRandom(pi, pj, seed + 33) < 0.12f) {
        const float fu = u / 6.0f - pi, fv = v / 6.0f - pj;
        const float a = 0.5f * CellRandom(pi, pj, seed + 34),
                    b = 0.5f * CellRandom(pi, pj, seed + 35);
        if (fu > a && fu < a + 0.45f && fv > b && fv < b + 0.4f)
          factor *= CellRandom(pi, pj, seed + 36) < 0.5f ? 0.78f : 1.15f;
      }
      // Cracks along the zero set of a warped noise, only in worn parts.
      const float warp = 0.4f * GradientNoise(1.3f * u, 1.3f * v, seed + 38);
      const float cn = GradientNoise(0.35f * u + warp, 0.35f * v - warp, seed + 39);
      const float worn = Smooth(0.0f, 0.3f, GradientNoise(0.05f * u, 0.05f * v, seed + 40));
      factor *= 1.0f - 0.5f * worn * Resolve(0.03f, footprint) *
                           (1.0f - Smooth(0.0f, 0.012f, std::abs(cn)));
      // Oil and tyre stains.
      third = Eigen::Vector3f(0.018f, 0.018f, 0.02f);
      mix3 = 0.6f * Smooth(0.62f, 0.8f, FractalNoise(u, v, 1.4f, 2, 0.5f, footprint, seed + 42));
      break;
    }
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
    case Pattern::kSoil:
      factor *= 1.0f + 0.2f * FractalNoise(u, v, 5.0f, 4, 0.6f, footprint, seed + 57) +
                0.4f * Speckle(u, v, 0.06f, footprint, seed + 58);
      // Plants in the bed.
      mix2 = Smooth(0.1f, 0.5f, FractalNoise(u, v, 1.5f, 3, 0.5f, footprint, seed + 59));
      break;
    case Pattern::kSolarPanel: {
      // Modules 1.0 x 1.7 m in a light frame, cells 0.17 m with thin gaps.
      const float fu = u - std::floor(u), fv = v / 1.7f - std::floor(v / 1.7f);
      const float frame = 1.0f - Smooth(0.02f, 0.035f, std::min(fu, 1.0f - fu)) *
                                     Smooth(0.012f, 0.02f, std::min(fv, 1.0f - fv));
      const float cu = u / 0.166f - std::floor(u / 0.166f), cv = v / 0.17f - std::floor(v / 0.17f);
      const float gap = 1.0f - Smooth(0.0f, 0.06f, std::min(cu, cv));
      mix2 = Resolve(0.03f, footprint) * frame + (1.0f - Resolve(0.03f, footprint)) * 0.08f;
      factor *= 1.0f + 0.5f * Resolve(0.02f, footprint) * gap +
                0.06f * (CellRandom(Floor(u), Floor(v / 1.7f), seed + 61) - 0.5f);
      break;
    }
    case Pattern::kGlass:
      factor *= 1.0f + 0.35f * FractalNoise(u, v, 0.7f, 2, 0.5f, footprint, seed + 63);
      break;
    case Pattern::kMetal:
      factor *= 1.0f + 0.05f * FractalNoise(u, v, 3.0f, 3, 0.5f, footprint, seed + 67);
      break;
  }
  Eigen::Vector3f base = ((1.0f - mix2) * m.albedo + mix2 * m.albedo2).cwiseProduct(tint);
  base = (1.0f - mix3) * base + mix3 * third;
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

Material SoilMaterial(uint32_t seed) {
  return Make("soil", Pattern::kSoil, SrgbToLinear(96, 76, 58), SrgbToLinear(70, 96, 50), 1, 0.1f,
              0.1f, 0.4f, seed);
}
Material SolarPanelMaterial(uint32_t seed) {
  return Make("solar_panel", Pattern::kSolarPanel, SrgbToLinear(34, 40, 58),
              SrgbToLinear(170, 172, 176), 1, 0.05f, 0.03f, 0, seed);
}
Material GlassMaterial(uint32_t seed) {
  return Make("glass", Pattern::kGlass, SrgbToLinear(40, 46, 52), SrgbToLinear(40, 46, 52), 1,
              0.05f, 0.02f, 0, seed);
}
int CarMaterialCount() { return 8; }
Material CarMaterial(int index, uint32_t seed) {
  // Common car colours: white, silver, black, grey, blue, red, dark green, beige.
  static const int kRgb[8][3] = {{228, 228, 226}, {176, 178, 182}, {22, 22, 24}, {92, 94, 98},
                                 {34, 58, 110},   {150, 24, 26},   {30, 60, 44}, {196, 180, 150}};
  const int* c = kRgb[((index % 8) + 8) % 8];
  return Make("car_paint", Pattern::kMetal, SrgbToLinear(c[0], c[1], c[2]),
              SrgbToLinear(c[0], c[1], c[2]), 1, 0.02f, 0.02f, 0, seed);
}
Material MetalMaterial(int index, uint32_t seed) {
  if (index % 2 == 0)
    return Make("sheet_metal", Pattern::kMetal, SrgbToLinear(170, 172, 170),
                SrgbToLinear(150, 150, 150), 1, 0.05f, 0.08f, 0, seed);
  return Make("cast_iron", Pattern::kMetal, SrgbToLinear(48, 46, 44), SrgbToLinear(48, 46, 44), 1,
              0.05f, 0.1f, 0, seed);
}
Material HedgeMaterial(uint32_t seed) {
  return Make("hedge", Pattern::kFoliage, SrgbToLinear(52, 84, 38), SrgbToLinear(80, 100, 44), 1,
              0.1f, 0.05f, 0.25f, seed);
}
Material ChimneyMaterial(int index, uint32_t seed) {
  return index % 2 == 0 ? WallMaterial(4, seed) : WallMaterial(3, seed);
}

}  // namespace sim
}  // namespace roofsweep
