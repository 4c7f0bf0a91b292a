#include "tests/support/shared_data.h"

#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace roofsweep::testing {

static std::string Env(const char* name) {
  const char* v = std::getenv(name);
  return v ? v : "";
}

std::string SharedDir() {
  for (const char* name : {"ROOFSWEEP_SHARED_DIR", "ROOFSWEEP_SHARED_DIR_DEFAULT"}) {
    const std::string d = Env(name);
    if (!d.empty() && fs::is_directory(d)) return fs::canonical(d).string();
  }
  return "";
}

bool SharedRequired() { return Env("ROOFSWEEP_REQUIRE_SHARED") == "1"; }

std::string SharedPath(const std::string& rel) {
  const std::string dir = SharedDir();
  if (dir.empty()) return "";
  const fs::path p = fs::path(dir) / rel;
  return fs::exists(p) ? p.string() : "";
}

std::string TempDir(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = tag;
  if (info) name += std::string("_") + info->test_suite_name() + "_" + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  const fs::path p = fs::temp_directory_path() / ("roofsweep_test_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

std::string SourceDir() { return Env("ROOFSWEEP_SOURCE_DIR"); }
std::string BinaryDir() { return Env("ROOFSWEEP_BINARY_DIR"); }

}  // namespace roofsweep::testing
