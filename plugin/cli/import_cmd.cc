#include <algorithm>
#include <cmath>
#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/import_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Import(const std::vector<std::string>& args, Context& ctx) {
  ImportRequest r;
  double ground = std::nan("");
  double terrain_window = std::nan("");
  bool no_check = false;
  std::string formats;
  for (const auto& f : ImportFormats()) formats += (formats.empty() ? "" : ", ") + f;
  ArgParser p("import", "Reads an oriented image block from another format into a block manifest.");
  p.Positional("FORMAT", &r.format, "one of: " + formats)
      .Positionals("SRC", &r.sources, "orientation file(s) or folder of that format")
      .Option("-o", &r.output, "BLOCK.json", "block manifest to write (required)")
      .Option("-a_srs", &r.options.crs, "SRS",
              "CRS of the positions when the source has none (EPSG:xxxx, WKT, PROJ string)")
      .Option("-camera", &r.options.camera_file, "FILE",
              "interior orientation for OPK files (orthority YAML, Pix4D .cam or "
              "calibrated_camera_parameters.txt, roofsweep camera JSON)")
      .Option("-images", &r.options.image_dir, "DIR", "folder holding the images")
      .Option("-ground", &ground, "HEIGHT", "ground height (ellipsoidal, CRS units)")
      .Option("-dtm", &r.options.dtm, "RASTER", "ground model raster (GDAL)")
      .Option("-dsm", &r.options.dsm, "RASTER",
              "surface model raster (GDAL), for blocks without a bare-earth DTM: the ground is "
              "derived from it by a morphological opening")
      .Option("-terrain_window", &terrain_window, "M",
              "window of that opening, wider than the widest building (30)")
      .Flag("-no_image_check", &no_check,
            "do not open the images (annotation-only sets); other commands will need them")
      .Flag("-overwrite", &r.overwrite, "replace an existing output")
      .Example("roofsweep import opk camera_pos_ori.txt -camera ngi_int_param.yaml -o block.json")
      .Example("roofsweep import colmap sparse/0 -images images -a_srs EPSG:25832 -o block.json")
      .Example("roofsweep import vgg merton1 -o merton1.json");
  if (!p.Parse(args)) return 0;
  if (r.output.empty()) throw UsageError{"Missing option -o BLOCK.json", p.Synopsis()};
  std::string lower = r.format;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  const auto& known = ImportFormats();
  if (std::find(known.begin(), known.end(), lower) == known.end())
    throw UsageError{"Unknown import format '" + r.format + "' (one of: " + formats + ")",
                     p.Synopsis()};
  RequireNewOutput(p, r.output, r.overwrite);
  if (!std::isnan(ground)) r.options.ground_height = ground;
  if (!r.options.dtm.empty() && !r.options.dsm.empty())
    throw UsageError{"Options -dtm and -dsm exclude each other", p.Synopsis()};
  if (!std::isnan(terrain_window)) {
    if (!(terrain_window > 0))
      throw UsageError{"Option -terrain_window expects a positive width in metres", p.Synopsis()};
    if (r.options.dsm.empty())
      throw UsageError{"Option -terrain_window goes with -dsm", p.Synopsis()};
    r.options.terrain_window_m = terrain_window;
  }
  r.options.check_images = !no_check;
  const ImportSummary s = RunImport(r, *ctx.progress);
  if (!ctx.quiet) {
    std::cout << "Wrote " << r.output << ": " << s.images << " images, " << s.cameras
              << " cameras, CRS " << (s.crs.empty() ? "none (local frame)" : s.crs) << "\n";
  }
  return 0;
}

const CommandRegistration kRegistration{
    {"import", "read COLMAP/Pix4D/Metashape/OPK/OpenSfM/Oxford orientations into a block", Import}};

}  // namespace
}  // namespace roofsweep::cli
