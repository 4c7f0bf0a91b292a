#include "plugin/cli/arg_parser.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/shared_data.h"

namespace roofsweep::cli {
namespace {

TEST(ArgParser, GdalStyleOptionsAndPositionals) {
  std::string of = "GPKG", in, out;
  bool overwrite = false;
  double thr = 0.4;
  int n = 3;
  std::vector<std::string> co;
  ArgParser p("convert", "Converts.");
  p.Option("-of|-f", &of, "FORMAT", "format")
      .Flag("-overwrite", &overwrite, "replace")
      .Option("-thr", &thr, "X", "threshold")
      .Option("-n", &n, "N", "count")
      .Repeated("-co", &co, "NAME=VALUE", "creation option")
      .Positional("IN", &in, "input")
      .Positional("OUT", &out, "output");
  ASSERT_TRUE(p.Parse({"a.gml", "-f", "CityJSON", "-co", "A=1", "-thr", "-0.5", "-co", "B=2",
                       "-overwrite", "-n", "7", "b.json"}));
  EXPECT_EQ(of, "CityJSON");
  EXPECT_TRUE(overwrite);
  EXPECT_DOUBLE_EQ(thr, -0.5);
  EXPECT_EQ(n, 7);
  EXPECT_EQ(co, (std::vector<std::string>{"A=1", "B=2"}));
  EXPECT_EQ(in, "a.gml");
  EXPECT_EQ(out, "b.json");
  EXPECT_TRUE(p.Given("-of"));
}

TEST(ArgParser, WrongUsageThrowsWithSynopsis) {
  std::string in;
  int n = 0;
  auto make = [&] {
    ArgParser p("info", "Tells.");
    p.Option("-n", &n, "N", "count").Positional("BLOCK", &in, "block");
    return p;
  };
  try {
    make().Parse({"-bogus", "x"});
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_EQ(e.message, "Unknown option name '-bogus'");
    EXPECT_NE(e.synopsis.find("Usage: roofsweep info"), std::string::npos);
  }
  EXPECT_THROW(make().Parse({}), UsageError);                  // missing argument
  EXPECT_THROW(make().Parse({"x", "-n"}), UsageError);         // missing value
  EXPECT_THROW(make().Parse({"x", "-n", "1.5"}), UsageError);  // not whole
  EXPECT_THROW(make().Parse({"x", "-n", "nan"}), UsageError);
  EXPECT_THROW(make().Parse({"x", "y"}), UsageError);  // too many
}

TEST(ArgParser, KeyValuesAreCheckedWhenParsed) {
  std::vector<std::string> lco;
  auto parse = [&](std::vector<std::string> args) {
    lco.clear();
    ArgParser p("lines", "Lines.");
    p.KeyValues("-lco", &lco, "layer creation option");
    return p.Parse(args);
  };
  ASSERT_TRUE(parse({"-lco", "FID=fid", "-lco", "DESCRIPTION=a=b"}));
  EXPECT_EQ(lco, (std::vector<std::string>{"FID=fid", "DESCRIPTION=a=b"}));
  try {
    parse({"-lco", "SPATIAL_INDEX"});
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_EQ(e.message, "Option -lco expects NAME=VALUE, got 'SPATIAL_INDEX'");
    EXPECT_NE(e.synopsis.find("[-lco NAME=VALUE]*"), std::string::npos) << e.synopsis;
  }
  EXPECT_THROW(parse({"-lco", "=x"}), UsageError);
}

struct OptionsFileFixture {
  std::string of = "GPKG", in;
  bool overwrite = false, update = false;
  double factor = 8;
  int n = 3;
  std::vector<std::string> lco;
  ArgParser p{"match", "Matches."};
  OptionsFileFixture() {
    p.Option("-of|-f", &of, "FORMAT", "format")
        .Flag("-overwrite", &overwrite, "replace")
        .Flag("-update", &update, "update")
        .Option("-chromatic_factor", &factor, "F", "factor")
        .Option("-min-length|--min-length", &n, "N", "count")
        .KeyValues("-lco", &lco, "layer creation option")
        .Positional("BLOCK", &in, "block");
  }
};

std::string WriteJson(const std::string& name, const std::string& text) {
  const std::string path = roofsweep::testing::TempDir("opts") + "/" + name;
  std::ofstream(path) << text;
  return path;
}

std::string UsageMessage(OptionsFileFixture& f, const std::vector<std::string>& args) {
  try {
    f.p.Parse(args);
  } catch (const UsageError& e) {
    EXPECT_NE(e.synopsis.find("Usage: roofsweep match"), std::string::npos);
    return e.message;
  }
  return "";
}

TEST(ArgParser, OptionsFileAppliesAndCommandLineWins) {
  const std::string path = WriteJson("o.json", R"({
    "chromatic_factor": 6, "min-length": 20, "overwrite": true, "update": false,
    "of": "FlatGeobuf", "lco": ["FID=fid", "SPATIAL_INDEX=NO"]})");
  OptionsFileFixture f;
  ASSERT_TRUE(f.p.Parse({"blk", "-options", path, "-of", "GPKG"}));
  EXPECT_DOUBLE_EQ(f.factor, 6);
  EXPECT_EQ(f.n, 20);
  EXPECT_TRUE(f.overwrite);
  EXPECT_FALSE(f.update);
  EXPECT_EQ(f.of, "GPKG");  // the command line wins, whatever the order
  EXPECT_EQ(f.lco, (std::vector<std::string>{"FID=fid", "SPATIAL_INDEX=NO"}));
  EXPECT_EQ(f.in, "blk");

  // A repeatable option given on the command line replaces the file's list.
  OptionsFileFixture g;
  ASSERT_TRUE(g.p.Parse({"-lco", "GEOMETRY_NAME=g", "-options", path, "blk"}));
  EXPECT_EQ(g.lco, (std::vector<std::string>{"GEOMETRY_NAME=g"}));
  // An object spells NAME=VALUE pairs.
  OptionsFileFixture h;
  ASSERT_TRUE(
      h.p.Parse({"-options", WriteJson("obj.json", R"({"lco": {"FID": "x", "A": 2}})"), "b"}));
  EXPECT_EQ(h.lco, (std::vector<std::string>{"A=2", "FID=x"}));
  // A string option given a number takes its text ("ncc_window": 11).
  OptionsFileFixture k;
  ASSERT_TRUE(k.p.Parse({"-options", WriteJson("num.json", R"({"of": 11})"), "b"}));
  EXPECT_EQ(k.of, "11");
}

TEST(ArgParser, OptionsFileErrorsNameFileAndPointer) {
  auto message = [](const std::string& name, const std::string& json) {
    OptionsFileFixture f;
    return UsageMessage(f, {"blk", "-options", WriteJson(name, json)});
  };
  std::string m = message("unknown.json", R"({"min_length": 20})");
  EXPECT_NE(m.find("unknown.json: /min_length: unknown option 'min_length'"), std::string::npos)
      << m;
  m = message("type.json", R"({"chromatic_factor": "six"})");
  EXPECT_NE(m.find("type.json: /chromatic_factor: expects a number, got \"six\""),
            std::string::npos)
      << m;
  m = message("flag.json", R"({"overwrite": "yes"})");
  EXPECT_NE(m.find("flag.json: /overwrite: expects true or false"), std::string::npos) << m;
  m = message("whole.json", R"({"min-length": 1.5})");
  EXPECT_NE(m.find("whole.json: /min-length: Option -min-length expects a whole number"),
            std::string::npos)
      << m;
  m = message("str.json", R"({"of": true})");
  EXPECT_NE(m.find("str.json: /of: expects a string, got true"), std::string::npos) << m;
  m = message("item.json", R"({"lco": ["FID=x", 3]})");
  EXPECT_NE(m.find("item.json: /lco/1: expects a string"), std::string::npos) << m;
  m = message("kv.json", R"({"lco": ["FID"]})");
  EXPECT_NE(m.find("kv.json: /lco: Option -lco expects NAME=VALUE"), std::string::npos) << m;
  m = message("bad.json", "{\n  \"overwrite\": true,\n  oops\n}");
  EXPECT_NE(m.find("bad.json:3: malformed JSON"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  m = message("array.json", "[1, 2]");
  EXPECT_NE(m.find("array.json: expected a JSON object"), std::string::npos) << m;
  m = message("self.json", R"({"options": "other.json"})");
  EXPECT_NE(m.find("/options: unknown option"), std::string::npos) << m;
  OptionsFileFixture f;
  m = UsageMessage(f, {"blk", "-options", "/nonexistent/o.json"});
  EXPECT_NE(m.find("/nonexistent/o.json: cannot read"), std::string::npos) << m;
  OptionsFileFixture g;
  m = UsageMessage(g, {"blk", "-options"});
  EXPECT_NE(m.find("-options needs a value"), std::string::npos) << m;
}

TEST(ArgParser, KeyValue) {
  EXPECT_EQ(SplitKeyValue("-co", "A=b=c").second, "b=c");
  EXPECT_THROW(SplitKeyValue("-co", "novalue"), UsageError);
}

}  // namespace
}  // namespace roofsweep::cli
