#include "io/citymodel/test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validator.hpp>

#include "io/citymodel/citymodel_writer.h"
#include "tests/support/shared_data.h"

namespace roofsweep::testing {

namespace fs = std::filesystem;

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

int XmllintCityGml(const std::string& path, std::string* log) {
  const std::string xsd = SharedPath("schemas/citygml-2.0/CityGML-2.0-all.xsd");
  if (xsd.empty() || std::system("command -v xmllint >/dev/null 2>&1") != 0) return -1;
  const std::string out = path + ".xmllint.txt";
  const std::string cmd =
      "xmllint --noout --nonet --schema '" + xsd + "' '" + path + "' > '" + out + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  *log = ReadText(out);
  fs::remove(out);
  return WEXITSTATUS(rc);
}

int ValidateCityJson(const std::string& json_text, bool feature, std::string* log) {
  const std::string dir = SharedPath("schemas/cityjson/2.0");
  if (dir.empty()) return -1;
  const nlohmann::json schema_doc = nlohmann::json::parse(
      ReadText(dir + (feature ? "/cityjsonfeature.schema.json" : "/cityjson.schema.json")));
  valijson::Schema schema;
  valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
  // The schemas reference their siblings by relative name, which valijson
  // resolves against the $id (https://www.cityjson.org/schemas/2.0.2/...):
  // map every such URI to the local file of the same name (never fetched).
  auto fetch = [dir](const std::string& uri) -> const nlohmann::json* {
    const std::string name = uri.substr(uri.find_last_of('/') + 1);
    const std::string file = dir + "/" + name;
    if (!fs::exists(file)) return nullptr;
    return new nlohmann::json(nlohmann::json::parse(ReadText(file)));
  };
  auto free_doc = [](const nlohmann::json* d) { delete d; };
  valijson::adapters::NlohmannJsonAdapter schema_adapter(schema_doc);
  parser.populateSchema(schema_adapter, schema, fetch, free_doc);
  const nlohmann::json doc = nlohmann::json::parse(json_text);
  valijson::adapters::NlohmannJsonAdapter doc_adapter(doc);
  valijson::Validator validator;
  valijson::ValidationResults results;
  if (validator.validate(schema, doc_adapter, &results)) return 0;
  valijson::ValidationResults::Error e;
  int n = 0;
  while (results.popError(e) && n++ < 10) {
    std::string ctx;
    for (const auto& c : e.context) ctx += c;
    *log += ctx + ": " + e.description + "\n";
  }
  return 1;
}

namespace {
// One building and, recursively, its parts; the largest coordinate
// difference goes to *worst.
void ExpectBuildingsNear(const Building& a, const Building& b, bool surface_ids, double* worst) {
  SCOPED_TRACE("building " + a.id);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.roof_type, b.roof_type);
  EXPECT_EQ(a.lod, b.lod);
  EXPECT_NEAR(a.measured_height, b.measured_height, 1e-3);
  for (const auto& [k, v] : a.double_attributes) {
    auto it = b.double_attributes.find(k);
    ASSERT_NE(it, b.double_attributes.end()) << k;
    EXPECT_NEAR(it->second, v, 1e-6) << k;
  }
  for (const auto& [k, v] : a.string_attributes) {
    if (k == kValidityAttribute) continue;
    auto it = b.string_attributes.find(k);
    ASSERT_NE(it, b.string_attributes.end()) << k;
    EXPECT_EQ(it->second, v) << k;
  }
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (size_t s = 0; s < a.surfaces.size(); ++s) {
    const Surface& sa = a.surfaces[s];
    const Surface& sb = b.surfaces[s];
    EXPECT_EQ(sa.type, sb.type);
    if (surface_ids) {
      EXPECT_EQ(sa.id, sb.id);
    }
    ASSERT_EQ(sa.polygons.size(), sb.polygons.size());
    for (size_t p = 0; p < sa.polygons.size(); ++p) {
      const auto& pa = sa.polygons[p];
      const auto& pb = sb.polygons[p];
      ASSERT_EQ(pa.exterior.size(), pb.exterior.size());
      ASSERT_EQ(pa.holes.size(), pb.holes.size());
      for (size_t v = 0; v < pa.exterior.size(); ++v)
        *worst = std::max(*worst, (pa.exterior[v] - pb.exterior[v]).cwiseAbs().maxCoeff());
      for (size_t h = 0; h < pa.holes.size(); ++h) {
        ASSERT_EQ(pa.holes[h].size(), pb.holes[h].size());
        for (size_t v = 0; v < pa.holes[h].size(); ++v)
          *worst = std::max(*worst, (pa.holes[h][v] - pb.holes[h][v]).cwiseAbs().maxCoeff());
      }
    }
  }
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (size_t k = 0; k < a.parts.size(); ++k)
    ExpectBuildingsNear(a.parts[k], b.parts[k], surface_ids, worst);
}
}  // namespace

void ExpectModelsNear(const CityModel& want, const CityModel& got, double tol, bool surface_ids) {
  ASSERT_EQ(want.buildings.size(), got.buildings.size());
  double worst = 0;
  for (size_t i = 0; i < want.buildings.size(); ++i)
    ExpectBuildingsNear(want.buildings[i], got.buildings[i], surface_ids, &worst);
  EXPECT_LE(worst, tol) << "largest coordinate difference " << worst;
}

int CountTempFiles(const std::string& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) ++n;
  return n;
}

}  // namespace roofsweep::testing
