#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace roofsweep {

// printf-style formatting into a std::string, for one-line messages and
// table rows (libfmt/std::format are not available on Debian 12's GCC 12
// without an extra dependency). Truncates at 511 characters.
inline std::string StrFormat(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
inline std::string StrFormat(const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  return buf;
}

}  // namespace roofsweep
