#include "plugin/cli/arg_parser.h"

#include <gtest/gtest.h>

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

TEST(ArgParser, KeyValue) {
  EXPECT_EQ(SplitKeyValue("-co", "A=b=c").second, "b=c");
  EXPECT_THROW(SplitKeyValue("-co", "novalue"), UsageError);
}

}  // namespace
}  // namespace roofsweep::cli
