#include "io/orientation/text_fields.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "algorithms/core/error.h"

namespace roofsweep::orientation {

std::string ReadTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  if (StartsWith(text, "\xEF\xBB\xBF")) text.erase(0, 3);
  return text;
}

std::vector<TextLine> ReadTextLines(const std::string& path) {
  const std::string text = ReadTextFile(path);
  std::vector<TextLine> lines;
  std::istringstream in(text);
  std::string s;
  int n = 0;
  while (std::getline(in, s)) {
    if (!s.empty() && s.back() == '\r') s.pop_back();
    lines.push_back({++n, s});
  }
  return lines;
}

std::string Trim(const std::string& s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool StartsWith(const std::string& s, const std::string& prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

bool EndsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

namespace {

bool IsBlank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

std::vector<std::string> SplitWhitespace(const std::string& line) {
  std::vector<std::string> out;
  size_t i = 0;
  const size_t n = line.size();
  while (i < n) {
    while (i < n && (IsBlank(line[i]) || line[i] == '\r')) ++i;
    if (i >= n) break;
    std::string field;
    if (line[i] == '\'' || line[i] == '"') {
      const char q = line[i++];
      while (i < n && line[i] != q) field += line[i++];
      if (i < n) ++i;  // closing quote
    }
    while (i < n && !IsBlank(line[i])) field += line[i++];
    out.push_back(field);
  }
  return out;
}

std::vector<std::string> SplitDelimited(const std::string& line, char delimiter) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  char quote = 0;
  for (char c : line) {
    if (quoted) {
      if (c == quote)
        quoted = false;
      else
        field += c;
    } else if ((c == '"' || c == '\'') && Trim(field).empty()) {
      quoted = true;
      quote = c;
      field.clear();
    } else if (c == delimiter) {
      out.push_back(Trim(field));
      field.clear();
    } else {
      field += c;
    }
  }
  out.push_back(Trim(field));
  return out;
}

double ParseNumber(const std::string& token, const std::string& file, int line,
                   const std::string& what) {
  const std::string t = Trim(token);
  char* end = nullptr;
  errno = 0;
  const double v = t.empty() ? 0.0 : std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size()) {
    throw Error(AtLine(file, line, what + ": '" + t + "' is not a number"));
  }
  if (!std::isfinite(v)) {
    throw Error(AtLine(file, line, what + ": '" + t + "' is not a finite number"));
  }
  return v;
}

int ParseInt(const std::string& token, const std::string& file, int line, const std::string& what) {
  const std::string t = Trim(token);
  char* end = nullptr;
  errno = 0;
  const long v = t.empty() ? 0 : std::strtol(t.c_str(), &end, 10);
  if (t.empty() || end != t.c_str() + t.size() || errno == ERANGE || v < -2147483647L ||
      v > 2147483647L) {
    throw Error(AtLine(file, line, what + ": '" + t + "' is not an integer"));
  }
  return static_cast<int>(v);
}

std::vector<double> ParseNumbers(const TextLine& line, const std::string& file, size_t count,
                                 const std::string& what) {
  const std::vector<std::string> tokens = SplitWhitespace(line.text);
  if (tokens.size() != count) {
    throw Error(AtLine(file, line.number,
                       what + ": expected " + std::to_string(count) + " numbers, found " +
                           std::to_string(tokens.size())));
  }
  std::vector<double> v;
  v.reserve(count);
  for (const auto& t : tokens) v.push_back(ParseNumber(t, file, line.number, what));
  return v;
}

}  // namespace roofsweep::orientation
