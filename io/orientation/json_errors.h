#pragma once

#include <nlohmann/json.hpp>
#include <string>

// JSON helpers for the readers of JSON formats (OpenSfM): parse errors carry
// the line, structural errors the JSON pointer ("FILE: /0/shots/x: ...").
namespace roofsweep::orientation {

nlohmann::json ParseJsonFile(const std::string& path);

// Value at `key` of `object` as a finite number; throws naming `pointer`.
double JsonNumber(const nlohmann::json& object, const std::string& key, const std::string& file,
                  const std::string& pointer);
double JsonNumberOr(const nlohmann::json& object, const std::string& key, double fallback,
                    const std::string& file, const std::string& pointer);

// Escapes '~' and '/' for use in a JSON pointer.
std::string PointerToken(const std::string& key);

}  // namespace roofsweep::orientation
