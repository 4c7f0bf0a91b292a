#include "io/orientation/json_errors.h"

#include <algorithm>
#include <cmath>

#include "algorithms/core/error.h"
#include "io/orientation/text_fields.h"

namespace roofsweep::orientation {

nlohmann::json ParseJsonFile(const std::string& path) {
  const std::string text = ReadTextFile(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    const size_t at = std::min(e.byte, text.size());
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    std::string what = e.what();
    // nlohmann's message starts with "[json.exception.parse_error.101] parse error at ...".
    if (const size_t p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    throw Error(AtLine(path, line, "invalid JSON: " + what));
  }
}

std::string PointerToken(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

double JsonNumber(const nlohmann::json& object, const std::string& key, const std::string& file,
                  const std::string& pointer) {
  const std::string where = file + ": " + pointer + "/" + PointerToken(key);
  if (!object.is_object() || !object.contains(key)) throw Error(where + ": missing");
  const auto& v = object.at(key);
  if (!v.is_number()) throw Error(where + ": expected a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw Error(where + ": not a finite number");
  return d;
}

double JsonNumberOr(const nlohmann::json& object, const std::string& key, double fallback,
                    const std::string& file, const std::string& pointer) {
  if (!object.is_object() || !object.contains(key) || object.at(key).is_null()) return fallback;
  return JsonNumber(object, key, file, pointer);
}

}  // namespace roofsweep::orientation
