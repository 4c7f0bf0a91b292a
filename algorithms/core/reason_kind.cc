#include "algorithms/core/reason_kind.h"

namespace roofsweep {

std::string ReasonKind(const std::string& reason, bool has_subject) {
  const size_t colon = has_subject ? reason.find(": ") : std::string::npos;
  const std::string s = colon == std::string::npos ? reason : reason.substr(colon + 2);
  std::string out;
  for (char c : s) {
    if ((c >= '0' && c <= '9') || c == '.' || c == '-') {
      if (out.empty() || out.back() != '#') out += '#';
    } else {
      out += c;
    }
  }
  const size_t paren = out.find(" (");
  return paren == std::string::npos ? out : out.substr(0, paren);
}

}  // namespace roofsweep
