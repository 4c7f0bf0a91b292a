#pragma once

#include <gtest/gtest.h>

#include <string>

namespace roofsweep::testing {

// Folder of the shared data set (../shared beside the checkout), from
// ROOFSWEEP_SHARED_DIR, else the build's default; empty when absent.
std::string SharedDir();
// True when ROOFSWEEP_REQUIRE_SHARED=1: missing shared data is a failure.
bool SharedRequired();
// `rel` below the shared folder when it exists there, else empty.
std::string SharedPath(const std::string& rel);
// A fresh, empty temporary folder for the running test.
std::string TempDir(const std::string& tag = "t");
// The project's source and build folders (set by CTest).
std::string SourceDir();
std::string BinaryDir();

}  // namespace roofsweep::testing

// Resolves `rel` below the shared folder into a new variable `var`, or skips
// the test with a visible message; fails instead when
// ROOFSWEEP_REQUIRE_SHARED=1 (CI).
#define ROOFSWEEP_SHARED_PATH_OR_SKIP(var, rel)                                      \
  const std::string var = ::roofsweep::testing::SharedPath(rel);                     \
  if (var.empty()) {                                                                 \
    if (::roofsweep::testing::SharedRequired()) {                                    \
      FAIL() << "shared data missing: " << (rel) << " (ROOFSWEEP_REQUIRE_SHARED=1)"; \
    }                                                                                \
    GTEST_SKIP() << "shared data not found: " << (rel) << " -- skipping";            \
  }
