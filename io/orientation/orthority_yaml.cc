// orthority's interior parameter file (e.g. ngi_int_param.yaml):
//
//   Integraph DMC:
//       type: pinhole
//       im_size: [640, 1152]
//       focal_len: 120.0
//       sensor_size: [92.16, 165.888]
//       cx: 0.0
//       cy: 0.0
//
// Only this two-level subset of YAML is read (camera id -> scalar or flow
// list values): it is all orthority writes, and pulling in a YAML library
// (yaml-cpp is not among roofsweep's dependencies) for it is not worth it.
#include <map>

#include "algorithms/core/error.h"
#include "io/orientation/camera_file_reader.h"
#include "io/orientation/text_fields.h"

namespace roofsweep::orientation {
namespace {

struct YamlValue {
  std::vector<std::string> items;  // one for a scalar, several for [a, b]
  bool list = false;
  int line = 0;
};
struct YamlCamera {
  std::string id;
  int line = 0;
  std::map<std::string, YamlValue> values;
};

std::string Unquote(std::string s) {
  s = Trim(s);
  if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front()) {
    return s.substr(1, s.size() - 2);
  }
  return s;
}

std::string StripComment(const std::string& s) {
  bool quoted = false;
  char q = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (quoted) {
      if (s[i] == q) quoted = false;
    } else if (s[i] == '"' || s[i] == '\'') {
      quoted = true;
      q = s[i];
    } else if (s[i] == '#' && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '\t')) {
      return s.substr(0, i);
    }
  }
  return s;
}

// The key's colon: the first ':' followed by a blank or the end, outside quotes.
size_t KeyColon(const std::string& s) {
  bool quoted = false;
  char q = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (quoted) {
      if (s[i] == q) quoted = false;
    } else if (s[i] == '"' || s[i] == '\'') {
      quoted = true;
      q = s[i];
    } else if (s[i] == ':' && (i + 1 == s.size() || s[i + 1] == ' ' || s[i + 1] == '\t')) {
      return i;
    }
  }
  return std::string::npos;
}

std::vector<YamlCamera> ParseYaml(const std::string& path) {
  std::vector<YamlCamera> cameras;
  for (const auto& line : ReadTextLines(path)) {
    const std::string raw = StripComment(line.text);
    if (Trim(raw).empty() || Trim(raw) == "---") continue;
    if (raw.find('\t') != std::string::npos && raw.find_first_not_of(" \t") > 0 &&
        raw.substr(0, raw.find_first_not_of(" \t")).find('\t') != std::string::npos) {
      throw Error(AtLine(path, line.number, "tabs are not allowed for YAML indentation"));
    }
    const bool indented = raw[0] == ' ';
    const std::string t = Trim(raw);
    const size_t colon = KeyColon(t);
    if (colon == std::string::npos) {
      throw Error(AtLine(path, line.number, "expected 'key: value', found '" + t + "'"));
    }
    const std::string key = Unquote(t.substr(0, colon));
    const std::string value = Trim(t.substr(colon + 1));
    if (!indented) {
      if (!value.empty()) {
        throw Error(
            AtLine(path, line.number,
                   "expected a camera id followed by indented parameters, found '" + t + "'"));
      }
      cameras.push_back({key, line.number, {}});
      continue;
    }
    if (cameras.empty()) throw Error(AtLine(path, line.number, "parameter outside a camera"));
    YamlValue v;
    v.line = line.number;
    if (!value.empty() && value.front() == '[') {
      if (value.back() != ']') throw Error(AtLine(path, line.number, "unterminated list"));
      v.list = true;
      for (const auto& item : SplitDelimited(value.substr(1, value.size() - 2), ','))
        v.items.push_back(Unquote(item));
    } else {
      v.items.push_back(Unquote(value));
    }
    if (!cameras.back().values.emplace(key, v).second) {
      throw Error(AtLine(path, line.number, "duplicate key '" + key + "'"));
    }
  }
  return cameras;
}

}  // namespace

std::vector<Camera> ReadOrthorityYaml(const std::string& path) {
  std::vector<Camera> out;
  for (const auto& yc : ParseYaml(path)) {
    auto numbers = [&](const std::string& key, size_t min_n, size_t max_n,
                       bool required) -> std::vector<double> {
      const auto it = yc.values.find(key);
      if (it == yc.values.end()) {
        if (required) {
          throw Error(AtLine(path, yc.line, "camera '" + yc.id + "': missing '" + key + "'"));
        }
        return {};
      }
      const auto& v = it->second;
      if (v.items.size() < min_n || v.items.size() > max_n) {
        throw Error(AtLine(path, v.line,
                           key + ": expected " + std::to_string(min_n) +
                               (min_n == max_n ? "" : "-" + std::to_string(max_n)) + " values"));
      }
      std::vector<double> d;
      for (const auto& s : v.items) d.push_back(ParseNumber(s, path, v.line, key));
      return d;
    };
    std::string type = "pinhole";
    if (const auto it = yc.values.find("type"); it != yc.values.end()) {
      type = Lower(it->second.items.front());
    }
    if (type != "pinhole" && type != "brown" && type != "opencv") {
      throw Error(AtLine(path, yc.values.at("type").line,
                         "camera type '" + type +
                             "' is not supported (pinhole, brown, opencv; fisheye images must be "
                             "undistorted first)"));
    }
    const auto im_size = numbers("im_size", 2, 2, true);
    const auto focal = numbers("focal_len", 1, 2, true);
    const auto sensor = numbers("sensor_size", 2, 2, false);
    Camera c;
    c.id = yc.id;
    c.width = static_cast<int>(im_size[0]);
    c.height = static_cast<int>(im_size[1]);
    if (c.width != im_size[0] || c.height != im_size[1] || c.width <= 0 || c.height <= 0) {
      throw Error(AtLine(path, yc.values.at("im_size").line, "im_size must be positive integers"));
    }
    const double f_x = focal[0], f_y = focal.size() > 1 ? focal[1] : focal[0];
    if (!(f_x > 0) || !(f_y > 0)) {
      throw Error(AtLine(path, yc.values.at("focal_len").line, "zero or negative focal length"));
    }
    if (!sensor.empty()) {
      if (!(sensor[0] > 0) || !(sensor[1] > 0)) {
        throw Error(AtLine(path, yc.values.at("sensor_size").line, "sensor_size must be positive"));
      }
      c.fx = f_x * c.width / sensor[0];
      c.fy = f_y * c.height / sensor[1];
      // orthority asks focal_len and sensor_size in the same unit; the mm
      // are the photogrammetric habit (ngi: 120 mm on 92.16 mm).
      c.pixel_size_mm = sensor[0] / c.width;
    } else {
      // orthority: without sensor_size, focal_len is normalised by the image
      // width (camera.py multiplies by im_size[0], whatever the docstring says).
      c.fx = f_x * c.width;
      c.fy = f_y * c.width;
    }
    // orthority: principal point = (im_size - 1) / 2 + max(w, h) (cx, cy)
    // with the origin at the centre of the top-left pixel; +0.5 for corners.
    const double s = std::max(c.width, c.height);
    const auto cx = numbers("cx", 1, 1, false), cy = numbers("cy", 1, 1, false);
    c.cx = (c.width - 1) / 2.0 + s * (cx.empty() ? 0.0 : cx[0]) + 0.5;
    c.cy = (c.height - 1) / 2.0 + s * (cy.empty() ? 0.0 : cy[0]) + 0.5;
    auto coeff = [&](const std::string& key) {
      const auto v = numbers(key, 1, 1, false);
      return v.empty() ? 0.0 : v[0];
    };
    if (type != "pinhole") {
      c.k1 = coeff("k1");
      c.k2 = coeff("k2");
      c.k3 = coeff("k3");
      c.p1 = coeff("p1");
      c.p2 = coeff("p2");
    }
    if (type == "opencv") {
      for (const char* key : {"k4", "k5", "k6", "s1", "s2", "s3", "s4", "tx", "ty"}) {
        if (coeff(key) != 0) {
          throw Error(AtLine(path, yc.values.at(key).line,
                             std::string(key) +
                                 " is not zero: roofsweep's camera has the Brown model only "
                                 "(k1 k2 k3 p1 p2)"));
        }
      }
    }
    out.push_back(c);
  }
  if (out.empty()) throw Error(path + ": no camera found");
  return out;
}

}  // namespace roofsweep::orientation
