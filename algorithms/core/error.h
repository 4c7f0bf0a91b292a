#pragma once

#include <stdexcept>
#include <string>

namespace roofsweep {

// The one exception type roofsweep throws for bad input or an impossible
// request. The message is a single line that names the file (and line or
// JSON pointer) at fault, so the command line can print it as it is.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Builds "FILE:LINE: message" (LINE omitted when 0), the form compilers use
// and editors jump to.
std::string AtLine(const std::string& file, int line, const std::string& message);

}  // namespace roofsweep
