#include "algorithms/core/error.h"

namespace roofsweep {

std::string AtLine(const std::string& file, int line, const std::string& message) {
  if (line > 0) return file + ":" + std::to_string(line) + ": " + message;
  return file + ": " + message;
}

}  // namespace roofsweep
