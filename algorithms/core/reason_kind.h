#pragma once

#include <string>

namespace roofsweep {

// The kind of a reason why something was not built, for counting: numbers
// become '#', a parenthesised tail is cut, and with `has_subject` the
// subject before the first ": " goes ("plane 7 (line 3): slope 71.4 deg >
// 70.0 deg (a wall?)" -> "slope # deg > # deg").
std::string ReasonKind(const std::string& reason, bool has_subject = true);

}  // namespace roofsweep
