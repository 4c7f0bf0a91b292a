#pragma once

#include <functional>
#include <string>
#include <vector>

namespace roofsweep::cli {

// Wrong usage: an unknown option, a missing or malformed value. The program
// prints "ERROR 6: <message>" and the command's usage, and exits 1.
struct UsageError {
  explicit UsageError(std::string m, std::string s = {})
      : message(std::move(m)), synopsis(std::move(s)) {}
  std::string message;
  std::string synopsis;  // the command's one-line usage, filled by ArgParser
};

// A small declarative parser for GDAL-style command lines: single-dash
// multi-letter options (-of GPKG, -overwrite, -co NAME=VALUE repeatable),
// positional arguments, and generated --help text.
//
// Every command also takes `-options FILE.json`: a JSON object whose keys
// are option names without the leading dash ({"min_length": 20,
// "overwrite": true, "lco": ["FID=fid"]}), applied as if given on the
// command line; an option given on the command line wins over the file.
// Values: true/false for flags (false leaves the flag off), numbers for
// numeric options, strings for the others, an array of strings (or an
// object {"NAME": value}) for repeatable ones. An unknown key, a wrong type
// or malformed JSON is a UsageError naming the file and the JSON pointer
// (or line).
//
// Written here rather than taken from CLI11 (which Debian has) because CLI11
// reads "-of" as the two short flags -o -f; GDAL's utilities, whose
// conventions roofsweep follows, parse their argv by hand in the same way.
class ArgParser {
 public:
  ArgParser(std::string command, std::string purpose);

  // A boolean switch, e.g. "-overwrite".
  ArgParser& Flag(const std::string& names, bool* out, const std::string& help);
  // An option with one value; names may list aliases: "-of|-f".
  ArgParser& Option(const std::string& names, std::string* out, const std::string& metavar,
                    const std::string& help);
  ArgParser& Option(const std::string& names, double* out, const std::string& metavar,
                    const std::string& help);
  ArgParser& Option(const std::string& names, int* out, const std::string& metavar,
                    const std::string& help);
  // A repeatable option collecting every value, e.g. "-co NAME=VALUE".
  ArgParser& Repeated(const std::string& names, std::vector<std::string>* out,
                      const std::string& metavar, const std::string& help);
  // A repeatable "NAME=VALUE" option (-co, -lco, -dsco); a value without
  // '=' or without a name is a UsageError.
  ArgParser& KeyValues(const std::string& names, std::vector<std::string>* out,
                       const std::string& help);
  // Positional arguments in order; the last may take several values.
  ArgParser& Positional(const std::string& name, std::string* out, const std::string& help,
                        bool required = true);
  ArgParser& Positionals(const std::string& name, std::vector<std::string>* out,
                         const std::string& help, int min_count = 1);
  ArgParser& Example(const std::string& line);
  ArgParser& Note(const std::string& text);

  // Parses args (without the program and command names). Throws UsageError.
  // Returns false when --help was given (usage already printed to stdout).
  bool Parse(const std::vector<std::string>& args);

  std::string Usage() const;     // the full --help text
  std::string Synopsis() const;  // one line: "Usage: roofsweep cmd [-x ...] IN OUT"
  const std::string& command() const { return command_; }
  const std::string& purpose() const { return purpose_; }
  // The options given on the command line, in order, for reports.
  bool Given(const std::string& name) const;

 private:
  enum class Kind { kFlag, kString, kNumber, kRepeated };
  struct Opt {
    std::vector<std::string> names;
    std::string metavar;  // empty for flags
    std::string help;
    std::function<void(const std::string&)> set;
    bool repeated = false;
    Kind kind = Kind::kString;
  };
  struct Pos {
    std::string name;
    std::string help;
    std::string* single = nullptr;
    std::vector<std::string>* many = nullptr;
    bool required = true;
    int min_count = 1;
  };
  const Opt* Find(const std::string& name) const;
  bool ParseOrThrow(const std::vector<std::string>& args);
  // Applies the -options file to the options not given on the command line.
  void ApplyOptionsFile(const std::string& path);
  ArgParser& Add(const std::string& names, const std::string& metavar, const std::string& help,
                 std::function<void(const std::string&)> set, Kind kind);

  std::string command_;
  std::string purpose_;
  std::vector<Opt> opts_;
  std::vector<Pos> pos_;
  std::vector<std::string> examples_;
  std::vector<std::string> notes_;
  std::vector<std::string> given_;
};

// Splits "NAME=VALUE"; throws UsageError naming the option when there is no '='.
std::pair<std::string, std::string> SplitKeyValue(const std::string& option,
                                                  const std::string& text);

}  // namespace roofsweep::cli
