// roofsweep: the command-line front end. Each subcommand lives in
// <name>_cmd.cc (argument parsing) over <name>_lib.cc (library function).
//
// Exit codes: 0 success; 1 failure (bad input, wrong usage, a refused
// output); 2 interrupted (cancelled).
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "algorithms/core/error.h"
#include "algorithms/core/heap_policy.h"
#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/gdal_progress.h"

namespace roofsweep::cli {

std::vector<Command>& Registry() {
  static std::vector<Command> commands;
  return commands;
}

CommandRegistration::CommandRegistration(Command c) {
  auto& r = Registry();
  r.push_back(std::move(c));
  std::sort(r.begin(), r.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
}

}  // namespace roofsweep::cli

namespace {

using roofsweep::cli::Registry;

void PrintMainUsage(std::FILE* to) {
  std::fprintf(to,
               "Usage: roofsweep COMMAND [options]   (roofsweep COMMAND --help for details)\n\n"
               "Turns oriented aerial colour images into LoD2 building models.\n\nCommands:\n");
  for (const auto& c : Registry())
    std::fprintf(to, "  %-9s %s\n", c.name.c_str(), c.purpose.c_str());
  std::fprintf(
      to,
      "\nGeneral options (GDAL): --version, --formats, --config KEY VALUE, --debug on|off,\n"
      "  --optfile FILE, --help-general; -q on any command silences progress.\n");
}

}  // namespace

int main(int argc, char** argv) {
  // The exec below needs the arguments as they came; the GDAL processor
  // leaves this array alone and hands back a new one.
  char** const given_argv = argv;
  roofsweep::KeepLargeAllocationsOnHeap();
  GDALAllRegister();
  // Handles --version, --formats, --config, --debug, --optfile, --help-general
  // and removes them from argv, exactly as in the GDAL utilities.
  argc = GDALGeneralCmdLineProcessor(argc, &argv, 0);
  if (argc < 1) return -argc;

  std::vector<std::string> args(argv + 1, argv + argc);
  CSLDestroy(argv);

  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    PrintMainUsage(args.empty() ? stderr : stdout);
    return args.empty() ? 1 : 0;
  }
  const std::string name = args[0];
  args.erase(args.begin());
  const auto& reg = Registry();
  const auto it =
      std::find_if(reg.begin(), reg.end(), [&](const auto& c) { return c.name == name; });
  if (it == reg.end()) {
    CPLError(CE_Failure, CPLE_IllegalArg, "Unknown command '%s'", name.c_str());
    PrintMainUsage(stderr);
    return 1;
  }
  // No thread has started yet (GDAL starts its pools on first use).
  if (it->works_on_images) roofsweep::ReexecWithHugePageHeap(given_argv);
  if (const char* t = std::getenv("GLIBC_TUNABLES")) CPLDebug("roofsweep", "GLIBC_TUNABLES=%s", t);

  roofsweep::cli::Context ctx;
  roofsweep::cli::GdalTermProgress term;
  ctx.quiet = std::find(args.begin(), args.end(), "-q") != args.end() ||
              std::find(args.begin(), args.end(), "-quiet") != args.end();
  args.erase(std::remove_if(args.begin(), args.end(),
                            [](const std::string& a) { return a == "-q" || a == "-quiet"; }),
             args.end());
  roofsweep::cli::InterruptibleProgress interruptible(ctx.quiet ? nullptr : &term);
  ctx.progress = &interruptible;
  roofsweep::cli::InstallInterruptHandler();
  try {
    return it->run(args, ctx);
  } catch (const roofsweep::cli::UsageError& e) {
    CPLError(CE_Failure, CPLE_NotSupported, "%s", e.message.c_str());
    std::fprintf(
        stderr, "%s\nTry 'roofsweep %s --help' for details.\n",
        e.synopsis.empty() ? ("Usage: roofsweep " + name + " ...").c_str() : e.synopsis.c_str(),
        name.c_str());
    return 1;
  } catch (const roofsweep::Error& e) {
    CPLError(CE_Failure, CPLE_AppDefined, "%s", e.what());
    return 1;
  } catch (const roofsweep::Cancelled&) {
    CPLError(CE_Failure, CPLE_UserInterrupt, "Interrupted by user");
    return 2;
  } catch (const std::exception& e) {
    CPLError(CE_Failure, CPLE_AppDefined, "internal error: %s", e.what());
    return 1;
  }
}
