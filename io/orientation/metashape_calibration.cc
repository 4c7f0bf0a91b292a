// Metashape calibration XML (Tools > Camera Calibration > Export, or the
// <sensor> elements of a camera export), read with libxml2.
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <map>

#include "algorithms/core/error.h"
#include "io/orientation/camera_file_reader.h"
#include "io/orientation/text_fields.h"

namespace roofsweep::orientation {
namespace {

std::string Name(const xmlNode* n) { return reinterpret_cast<const char*>(n->name); }

std::string Content(const xmlNode* n) {
  xmlChar* c = xmlNodeGetContent(n);
  std::string s = c ? reinterpret_cast<const char*>(c) : "";
  xmlFree(c);
  return Trim(s);
}

std::string Attribute(const xmlNode* n, const char* name) {
  xmlChar* a = xmlGetProp(n, reinterpret_cast<const xmlChar*>(name));
  std::string s = a ? reinterpret_cast<const char*>(a) : "";
  xmlFree(a);
  return s;
}

void Collect(xmlNode* node, std::vector<xmlNode*>* calibrations) {
  for (xmlNode* n = node; n; n = n->next) {
    if (n->type == XML_ELEMENT_NODE && Name(n) == "calibration") {
      // A camera export has adjusted and initial calibrations per sensor;
      // take the adjusted one (class="adjusted") or the only one.
      const std::string cls = Attribute(n, "class");
      if (cls.empty() || cls == "adjusted") calibrations->push_back(n);
      continue;
    }
    if (n->children) Collect(n->children, calibrations);
  }
}

}  // namespace

std::vector<Camera> ReadMetashapeCalibration(const std::string& path) {
  xmlDocPtr doc =
      xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
  if (!doc) {
    const xmlError* e = xmlGetLastError();
    throw Error(AtLine(path, e ? e->line : 0,
                       "invalid XML" + (e && e->message ? ": " + Trim(e->message) : "")));
  }
  std::vector<Camera> out;
  try {
    std::vector<xmlNode*> calibrations;
    Collect(xmlDocGetRootElement(doc), &calibrations);
    for (xmlNode* cal : calibrations) {
      const int line = static_cast<int>(xmlGetLineNo(cal));
      std::map<std::string, std::pair<std::string, int>> v;
      int width = 0, height = 0;
      for (xmlNode* n = cal->children; n; n = n->next) {
        if (n->type != XML_ELEMENT_NODE) continue;
        const int l = static_cast<int>(xmlGetLineNo(n));
        if (Name(n) == "resolution") {
          width = ParseInt(Attribute(n, "width"), path, l, "resolution width");
          height = ParseInt(Attribute(n, "height"), path, l, "resolution height");
        } else {
          v[Name(n)] = {Content(n), l};
        }
      }
      auto number = [&](const std::string& key, double fallback) {
        const auto it = v.find(key);
        if (it == v.end()) return fallback;
        return ParseNumber(it->second.first, path, it->second.second, key);
      };
      if (v.count("projection") && v["projection"].first != "frame") {
        throw Error(AtLine(
            path, v["projection"].second,
            "projection '" + v["projection"].first + "' is not supported (frame cameras only)"));
      }
      if (v.count("width")) width = ParseInt(v["width"].first, path, v["width"].second, "width");
      if (v.count("height"))
        height = ParseInt(v["height"].first, path, v["height"].second, "height");
      if (!v.count("f")) throw Error(AtLine(path, line, "<calibration> without <f>"));
      if (width <= 0 || height <= 0) {
        throw Error(AtLine(path, line, "<calibration> without a positive <width>/<height>"));
      }
      const double f = number("f", 0);
      if (!(f > 0)) throw Error(AtLine(path, v["f"].second, "zero or negative focal length"));
      for (const char* key : {"k4", "p3", "p4"}) {
        if (number(key, 0) != 0) {
          throw Error(AtLine(path, v[key].second,
                             std::string(key) + " is not zero: roofsweep's camera has the Brown "
                                                "model only (k1 k2 k3 p1 p2)"));
        }
      }
      Camera c;
      const xmlNode* parent = cal->parent;
      std::string id = parent && parent->type == XML_ELEMENT_NODE && Name(parent) == "sensor"
                           ? Attribute(parent, "label")
                           : "";
      if (id.empty()) id = "metashape_" + std::to_string(out.size() + 1);
      c.id = id;
      c.width = width;
      c.height = height;
      // Metashape: u = w/2 + cx + x'(f + b1) + y' b2, v = h/2 + cy + y' f,
      // pixel origin at the top-left corner (as roofsweep).
      c.fx = f + number("b1", 0);
      c.skew = number("b2", 0);
      c.fy = f;
      c.cx = width / 2.0 + number("cx", 0);
      c.cy = height / 2.0 + number("cy", 0);
      c.k1 = number("k1", 0);
      c.k2 = number("k2", 0);
      c.k3 = number("k3", 0);
      // Metashape's P1 multiplies (r² + 2x²), OpenCV's p2 does: swap.
      c.p1 = number("p2", 0);
      c.p2 = number("p1", 0);
      out.push_back(c);
    }
  } catch (...) {
    xmlFreeDoc(doc);
    throw;
  }
  xmlFreeDoc(doc);
  if (out.empty()) throw Error(path + ": no <calibration> element");
  return out;
}

}  // namespace roofsweep::orientation
