#include "plugin/cli/arg_parser.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "algorithms/core/error.h"

namespace roofsweep::cli {
namespace {

const char* const kOptionsFlag = "-options";

std::vector<std::string> SplitNames(const std::string& names) {
  std::vector<std::string> out;
  std::stringstream ss(names);
  std::string n;
  while (std::getline(ss, n, '|')) out.push_back(n);
  return out;
}

double ParseDouble(const std::string& opt, const std::string& v) {
  errno = 0;
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(d)) {
    throw UsageError{"Option " + opt + " expects a number, got '" + v + "'"};
  }
  return d;
}

}  // namespace

ArgParser::ArgParser(std::string command, std::string purpose)
    : command_(std::move(command)), purpose_(std::move(purpose)) {}

ArgParser& ArgParser::Add(const std::string& names, const std::string& metavar,
                          const std::string& help, std::function<void(const std::string&)> set,
                          Kind kind) {
  opts_.push_back(
      {SplitNames(names), metavar, help, std::move(set), kind == Kind::kRepeated, kind});
  return *this;
}

ArgParser& ArgParser::Flag(const std::string& names, bool* out, const std::string& help) {
  return Add(
      names, "", help, [out](const std::string&) { *out = true; }, Kind::kFlag);
}

ArgParser& ArgParser::Option(const std::string& names, std::string* out, const std::string& metavar,
                             const std::string& help) {
  return Add(
      names, metavar, help, [out](const std::string& v) { *out = v; }, Kind::kString);
}

ArgParser& ArgParser::Option(const std::string& names, double* out, const std::string& metavar,
                             const std::string& help) {
  const std::string first = SplitNames(names).front();
  return Add(
      names, metavar, help, [out, first](const std::string& v) { *out = ParseDouble(first, v); },
      Kind::kNumber);
}

ArgParser& ArgParser::Option(const std::string& names, int* out, const std::string& metavar,
                             const std::string& help) {
  const std::string first = SplitNames(names).front();
  return Add(
      names, metavar, help,
      [out, first](const std::string& v) {
        const double d = ParseDouble(first, v);
        if (d != std::floor(d) || std::abs(d) > 2e9) {
          throw UsageError{"Option " + first + " expects a whole number, got '" + v + "'"};
        }
        *out = static_cast<int>(d);
      },
      Kind::kNumber);
}

ArgParser& ArgParser::Repeated(const std::string& names, std::vector<std::string>* out,
                               const std::string& metavar, const std::string& help) {
  return Add(
      names, metavar, help, [out](const std::string& v) { out->push_back(v); }, Kind::kRepeated);
}

ArgParser& ArgParser::KeyValues(const std::string& names, std::vector<std::string>* out,
                                const std::string& help) {
  const std::string first = SplitNames(names).front();
  return Add(
      names, "NAME=VALUE", help,
      [out, first](const std::string& v) {
        SplitKeyValue(first, v);
        out->push_back(v);
      },
      Kind::kRepeated);
}

ArgParser& ArgParser::Positional(const std::string& name, std::string* out, const std::string& help,
                                 bool required) {
  Pos p;
  p.name = name;
  p.help = help;
  p.single = out;
  p.required = required;
  pos_.push_back(p);
  return *this;
}

ArgParser& ArgParser::Positionals(const std::string& name, std::vector<std::string>* out,
                                  const std::string& help, int min_count) {
  Pos p;
  p.name = name;
  p.help = help;
  p.many = out;
  p.min_count = min_count;
  p.required = min_count > 0;
  pos_.push_back(p);
  return *this;
}

ArgParser& ArgParser::Example(const std::string& line) {
  examples_.push_back(line);
  return *this;
}

ArgParser& ArgParser::Note(const std::string& text) {
  notes_.push_back(text);
  return *this;
}

const ArgParser::Opt* ArgParser::Find(const std::string& name) const {
  for (const Opt& o : opts_)
    for (const std::string& n : o.names)
      if (n == name) return &o;
  return nullptr;
}

bool ArgParser::Given(const std::string& name) const {
  for (const auto& g : given_)
    if (g == name) return true;
  return false;
}

bool ArgParser::Parse(const std::vector<std::string>& args) {
  try {
    return ParseOrThrow(args);
  } catch (UsageError& e) {
    e.synopsis = Synopsis();
    throw;
  }
}

bool ArgParser::ParseOrThrow(const std::vector<std::string>& args) {
  std::vector<std::string> positionals;
  std::string options_file;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h" || a == "-help") {
      std::cout << Usage();
      return false;
    }
    if (a == kOptionsFlag) {
      if (i + 1 >= args.size()) throw UsageError{"Option -options needs a value (FILE.json)"};
      if (!options_file.empty()) throw UsageError{"Option -options given twice"};
      options_file = args[++i];
      continue;
    }
    // A lone "-" and negative numbers are values, not options.
    const bool looks_like_option = a.size() > 1 && a[0] == '-' &&
                                   !(std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.');
    if (!looks_like_option) {
      positionals.push_back(a);
      continue;
    }
    const Opt* o = Find(a);
    if (!o) throw UsageError{"Unknown option name '" + a + "'"};
    given_.push_back(o->names.front());
    if (o->metavar.empty()) {
      o->set("");
    } else {
      if (i + 1 >= args.size())
        throw UsageError{"Option " + a + " needs a value (" + o->metavar + ")"};
      o->set(args[++i]);
    }
  }
  if (!options_file.empty()) ApplyOptionsFile(options_file);
  size_t next = 0;
  for (const Pos& p : pos_) {
    if (p.single) {
      if (next < positionals.size()) {
        *p.single = positionals[next++];
      } else if (p.required) {
        throw UsageError{"Missing argument " + p.name};
      }
    } else {
      while (next < positionals.size()) p.many->push_back(positionals[next++]);
      if (static_cast<int>(p.many->size()) < p.min_count) {
        throw UsageError{"Missing argument " + p.name};
      }
    }
  }
  if (next < positionals.size()) {
    throw UsageError{"Too many arguments: '" + positionals[next] + "'"};
  }
  return true;
}

void ArgParser::ApplyOptionsFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError{path + ": cannot read the options file"};
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(s);
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann reports a byte offset; editors want a line.
    const size_t at = std::min<size_t>(e.byte, s.size());
    const int line = 1 + static_cast<int>(std::count(s.begin(), s.begin() + at, '\n'));
    std::string what = e.what();
    const auto colon = what.find("syntax error");
    if (colon != std::string::npos) what = what.substr(colon);
    throw UsageError{AtLine(path, line, "malformed JSON: " + what)};
  }
  if (!j.is_object())
    throw UsageError{path + ": expected a JSON object {\"option_name\": value, ...}"};
  auto fail = [&](const std::string& key, const std::string& msg) {
    throw UsageError{path + ": " + nlohmann::json::json_pointer("/" + key).to_string() + ": " +
                     msg};
  };
  auto scalar_text = [](const nlohmann::json& v) {
    return v.is_string() ? v.get<std::string>() : v.dump();
  };
  for (const auto& [key, value] : j.items()) {
    const Opt* o = nullptr;
    if (!key.empty() && key[0] != '-') {
      o = Find("-" + key);
      if (!o) o = Find("--" + key);
    }
    if (!o || o->names.front() == kOptionsFlag)
      fail(key, "unknown option '" + key + "' for roofsweep " + command_ +
                    " (keys are option names without the dash)");
    // The command line wins: a file sets only what it left out.
    if (Given(o->names.front())) continue;
    try {
      switch (o->kind) {
        case Kind::kFlag:
          if (!value.is_boolean()) fail(key, "expects true or false, got " + value.dump());
          if (value.get<bool>()) o->set("");
          break;
        case Kind::kNumber:
          if (!value.is_number()) fail(key, "expects a number, got " + value.dump());
          o->set(value.dump());
          break;
        case Kind::kString:
          // A number is its text: "-ncc_window auto|PX" is written 11 in
          // JSON as naturally as "auto".
          if (!value.is_string() && !value.is_number())
            fail(key, "expects a string, got " + value.dump());
          o->set(scalar_text(value));
          break;
        case Kind::kRepeated:
          if (value.is_string()) {
            o->set(value.get<std::string>());
          } else if (value.is_array()) {
            for (size_t i = 0; i < value.size(); ++i) {
              if (!value[i].is_string())
                fail(key + "/" + std::to_string(i), "expects a string, got " + value[i].dump());
              o->set(value[i].get<std::string>());
            }
          } else if (value.is_object()) {
            for (const auto& [name, v] : value.items()) {
              if (!v.is_string() && !v.is_number() && !v.is_boolean())
                fail(key + "/" + name, "expects a string or number, got " + v.dump());
              o->set(name + "=" + scalar_text(v));
            }
          } else {
            fail(key, "expects a string, an array of strings or an object, got " + value.dump());
          }
          break;
      }
    } catch (const UsageError& e) {
      if (e.message.rfind(path + ": ", 0) == 0) throw;
      fail(key, e.message);  // the setter's own check, e.g. a whole number
    }
    given_.push_back(o->names.front());
  }
}

std::string ArgParser::Synopsis() const {
  std::ostringstream s;
  s << "Usage: roofsweep " << command_ << " [--help] [-options FILE.json]";
  for (const Opt& o : opts_) {
    s << " [" << o.names.front();
    if (!o.metavar.empty()) s << " " << o.metavar;
    s << "]";
    if (o.repeated) s << "*";
  }
  for (const Pos& p : pos_) {
    const std::string n = p.many ? p.name + "..." : p.name;
    s << " " << (p.required ? n : "[" + n + "]");
  }
  return s.str();
}

std::string ArgParser::Usage() const {
  std::ostringstream s;
  s << Synopsis() << "\n\n" << purpose_ << "\n";
  if (!pos_.empty()) {
    s << "\nArguments:\n";
    for (const Pos& p : pos_)
      s << "  " << p.name << (p.many ? "..." : "") << "\n      " << p.help << "\n";
  }
  if (!opts_.empty()) {
    s << "\nOptions:\n";
    for (const Opt& o : opts_) {
      s << "  ";
      for (size_t i = 0; i < o.names.size(); ++i) s << (i ? ", " : "") << o.names[i];
      if (!o.metavar.empty()) s << " " << o.metavar;
      s << "\n      " << o.help << (o.repeated ? " (repeatable)" : "") << "\n";
    }
  }
  s << "\n  -options FILE.json\n"
       "      options from a JSON object, keys without the dash: {\"overwrite\": true, "
       "\"of\": \"GPKG\", \"min_length\": 20, \"lco\": [\"FID=fid\"]}; "
       "options on the command line win\n";
  s << "\nGeneral options (GDAL): --version, --formats, --config KEY VALUE, --debug on|off,\n"
       "  --optfile FILE, --help-general\n";
  for (const auto& n : notes_) s << "\n" << n << "\n";
  if (!examples_.empty()) {
    s << "\nExample" << (examples_.size() > 1 ? "s" : "") << ":\n";
    for (const auto& e : examples_) s << "  " << e << "\n";
  }
  return s.str();
}

std::pair<std::string, std::string> SplitKeyValue(const std::string& option,
                                                  const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw UsageError{"Option " + option + " expects NAME=VALUE, got '" + text + "'"};
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace roofsweep::cli
