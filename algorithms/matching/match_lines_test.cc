#include "algorithms/matching/match_lines.h"

#include <gtest/gtest.h>

namespace roofsweep {
namespace {
TEST(MatchLines, Placeholder) {}
}  // namespace
}  // namespace roofsweep
