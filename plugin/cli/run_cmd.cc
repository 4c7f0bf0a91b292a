#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/match_flags.h"
#include "plugin/cli/run_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

// Options shared by `run` and `sweep`, with the papers' defaults.
void AddProcessingOptions(ArgParser& p, RunRequest& r, MatchFlags* flags, std::string* window) {
  flags->Add(p, &r.match, &r.edges);
  p.Option("-theta_min", &r.sweep.theta_min_deg, "DEG", "swept angle range start (default -75)")
      .Option("-theta_max", &r.sweep.theta_max_deg, "DEG", "swept angle range end (default 75)")
      .Option("-min_similarity", &r.sweep.min_similarity, "S",
              "accept a half-plane when Sim >= S (default 0.4)")
      .Option("-min_curvature", &r.sweep.min_curvature, "C",
              "... and |Sim''| >= C per rad^2 (default 4.0)")
      .Option("-band_width", &r.sweep.band_width_px, "PX",
              "neighbourhood of a line side in the reference view (default 100)")
      .Option("-ncc_window", window, "auto|PX",
              "side of the sweep's correlation window: auto (default) sweeps with 7 and again "
              "with 11 where the block's images correlate poorly (haze, blur, noise); an odd PX "
              "(3-31) fixes it, so that the tiles of a tiled run sweep alike")
      .Option(
          "-verify_score", &r.verify.min_score, "S",
          "a roof plane's patch must correlate with mean Cor+ >= S over the views (default 0.3; "
          "lowered for hazy, blurred or noisy images unless -fixed_verify_score)")
      .Option("-verify_margin", &r.verify.min_margin, "S",
              "... and beat the plane moved up and down by S (default 0.1)")
      .Option("-verify_samples", &r.verify.min_samples, "N",
              "... over at least N textured samples (default 32)");
}

// -ncc_window: "auto" keeps the sweep's choice by the imagery
// (SweepOptions::wide_ncc_radius); a size fixes the window and turns the
// choice off. Each tile of a tiled run measures its own images, and a tile
// of clean roofs beside a hazy one would otherwise sweep with the other
// window.
void ApplyWindowOption(const ArgParser& p, const std::string& window, SweepOptions* sweep) {
  if (window.empty() || window == "auto") return;
  int px = 0;
  size_t used = 0;
  try {
    px = std::stoi(window, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != window.size() || px < 3 || px > 31 || px % 2 == 0)
    throw UsageError(
        "Option -ncc_window expects auto or an odd size from 3 to 31 px, not '" + window + "'",
        p.Synopsis());
  sweep->ncc_radius = px / 2;
  sweep->wide_ncc_radius = 0;
}

int Run(const std::vector<std::string>& args, Context& ctx) {
  RunRequest r;
  bool sweep_only = false;
  bool no_mirror = false, no_hip_ends = false, no_footprint_mirror = false,
       no_colour_breaks = false, no_growth = false, no_merge = false, no_lift = false,
       no_level = false, no_eaves = false, no_border_clip = false, flat_only = false,
       no_beyond = false, no_pieces = false, no_fall_pieces = false, no_lod1 = false,
       models_apart = false, fixed_verify_score = false;
  bool keep_eave_planes = false;
  std::string aoi;
  ArgParser p("run",
              "Reconstructs LoD2 buildings from an oriented block: colour segments, 3D lines, "
              "half-plane sweep, grouping into roof planes, conflict management and closed "
              "solids with walls down to the ground (Scholze et al. 2000; Baillard & Zisserman "
              "2000). Prints a table of counts and times per stage.");
  p.Positional("BLOCK", &r.block, "block manifest, folder holding block.json, or FORMAT:SOURCE")
      .Option("-o", &r.output, "FILE", "LoD2 output (.gml, .city.json, .city.jsonl, .gpkg, ...)")
      .Option("-of|-f", &r.format, "FORMAT", "CityGML, CityJSON, CityJSONSeq or a GDAL driver")
      .Flag("-overwrite", &r.overwrite, "replace existing output files")
      .Option("-t_srs", &r.target_crs, "SRS", "reproject the LoD2 output to SRS (PROJ)")
      .Option("-aoi", &aoi, "MINX,MINY,MAXX,MAXY",
              "one tile of a tiled run, in the block CRS (default: the block's aoi, if any): "
              "read only the views and image windows that see it and its buffer, and write only "
              "the buildings whose ground centre lies in it (min <= x < max), ids prefixed with "
              "t<MINX>_<MINY>_; the tiles of a grid then hold every building once")
      .Option("-tile_buffer", &r.tile_buffer_m, "M",
              "reconstruct this far around the tile, so that its buildings that cross the "
              "border come out whole (default 30)")
      .Option("-lines", &r.lines_in, "FILE",
              "start from these 3D lines (OGR line layer or segments JSON) instead of matching; "
              "lines in another CRS are reprojected to the block's")
      .Option("-lines3d", &r.lines3d, "FILE",
              "also write the 3D lines (layer lines3d, as match writes it; -lines reads it back)")
      .Option("-half_planes", &r.half_planes, "FILE",
              "also write the half-planes (layer half_planes)")
      .Option("-planes", &r.planes, "FILE",
              "also write every roof plane hypothesis that was verified, with its patch, "
              "whether it was built and why not (layer roof_planes)")
      .Option("-report", &r.report, "FILE",
              "JSON report: the stage table and why each rejected plane or building was not built")
      .Option("-footprints", &r.footprints, "FILE",
              "building footprints (any OGR polygon layer) that restrict and label the buildings; "
              "default: the block's")
      .Option("-footprints_layer", &r.footprints_layer, "NAME",
              "layer of -footprints (default: the first polygon layer)")
      .Option("-footprints_id", &r.footprints_id_field, "FIELD",
              "field giving each footprint's id (default: id, identificatie, gml_id or fid, else "
              "the FID)")
      .Option("-min_height", &r.assembly.min_height_m, "M",
              "lowest roof plane above the ground (default 2.0)")
      .Option("-footprint_min_height", &r.assembly.footprint_min_height_m, "M",
              "... over a footprint, when footprints are given (default 1.5)")
      .Option("-max_slope", &r.assembly.max_roof_slope_deg, "DEG",
              "steepest roof plane (default 70)")
      .Option("-min_lines", &r.grouping.min_lines, "N",
              "a roof plane needs N supporting 3D lines, one of them may be virtual: its "
              "intersection with a neighbouring plane (default 2, as in the paper)")
      .Flag("-sweep_planes_only", &sweep_only,
            "planes from the sweep only, not also from pairs of coplanar lines")
      .Flag("-no_colour_breaks", &no_colour_breaks,
            "without footprints, do not cut terraced houses apart where their shared roof "
            "changes colour across its whole depth (only where a 3D line runs down the party "
            "wall)")
      .Flag("-no_mirror_faces", &no_mirror,
            "do not propose, beyond a ridge line, the mirror image of a roof face found from "
            "one side of it only (completion by symmetry, verified like any plane)")
      .Flag("-no_hip_ends", &no_hip_ends,
            "do not propose, at the other end of a ridge, the mirror image of a hip end found "
            "at one end only (completion by symmetry, verified like any plane)")
      .Flag("-no_footprint_mirror", &no_footprint_mirror,
            "with footprints, do not propose the mirror image of a roof face across the axis "
            "of a rectangular footprint (completion by symmetry, verified like any plane)")
      .Flag("-no_lift_lines", &no_lift,
            "one pass only: do not lift the image segments no 3D line explains onto the roof "
            "planes found (where a view across them confirms the depth) and sweep again with "
            "those that bound a plane")
      .Flag("-no_level_lines", &no_level,
            "in the second pass, do not place the image segments along the epipolar lines of "
            "every view that sees them (eaves and ridges along the flight line seen from one "
            "strip) by sweeping their faces over height and angle together")
      .Flag("-no_border_clip", &no_border_clip,
            "let a face's patch run on past the eave or verge line that bounds its lines (a "
            "hip's or verge's sweep strip over the wall and the ground), or a flat roof's past "
            "its edge line (over a lower neighbour); and do not cut a face found from a hip at "
            "the hip's foot, where the next face's eave ends")
      .Flag("-no_eave_search", &no_eaves,
            "do not grow a sloped face whose patch stops short of its eave to the level line "
            "of its plane where image segments of two views lifted onto the plane agree")
      .Flag("-no_footprint_growth", &no_growth,
            "with footprints, do not grow a sloped face seen over part of its footprint along "
            "its contour lines, nor into the corners of its rectangle that its patch leaves out, "
            "by the strips of the footprint the images confirm")
      .Flag("-flat_bare_footprints", &flat_only,
            "with footprints, propose only flat roofs over footprints no plane covers (not the "
            "shed, gable and hipped models)")
      .Flag("-no_footprint_pieces", &no_pieces,
            "with footprints, keep a plane that spans several footprints whole: do not verify "
            "its piece over each footprint apart and cut away those the images refute (a face "
            "running on over a neighbour's roof)")
      .Flag("-no_fall_line_pieces", &no_fall_pieces,
            "without footprints, keep a sloped face whole: do not verify its pieces between its "
            "lines down the fall line (verges, party walls) apart and cut away those the images "
            "refute (a terraced row's gables joined across a flat-roofed house)")
      .Flag("-fixed_verify_score", &fixed_verify_score,
            "do not scale the verification's score threshold (-verify_score) by the block's "
            "imagery as the sweep measured it (hazy, blurred or noisy images correlate less)")
      .Flag("-roof_model_faces_apart", &models_apart,
            "with footprints, judge each face of a roof model over a footprint on its own: do "
            "not accept a face refused on thin evidence when the model's faces together pass "
            "(one face of a gable then stands alone, a shed over half the footprint)")
      .Flag("-no_roofs_beyond_ridges", &no_beyond,
            "with footprints, do not propose roof models over the part of a footprint beyond the "
            "top of the one sloped face found over it (the other side of a gable)")
      .Option("-min_edge_support", &r.min_edge_support, "F",
              "drop buildings with less than this share of their visible roof-edge length on an "
              "image edge (attribute edge_support; default 0: keep all)")
      .Option("-min_edge_support_unlined", &r.min_edge_support_unlined, "F",
              "drop buildings whose roof no 3D line supports (roof models over bare footprints) "
              "with less than this share of their roof-edge length on an image edge (default 0.5: "
              "over a shed hidden under a tree the views agree on the crown, whose outline is no "
              "image edge; 0 keeps all)")
      .Flag("-no_lod1", &no_lod1,
            "with footprints, leave out a footprint whose roof was not reconstructed (with its "
            "reason) instead of writing an LoD1 block over it at the height of the 3D lines "
            "over it (lod 1, attribute lod1_reason)")
      .Flag("-no_eave_filter", &keep_eave_planes,
            "keep flat planes that only continue the eaves of sloped faces outwards (the yard "
            "in the inner corner of an L-shaped house, joined from its two eaves)")
      .Flag("-no_coplanar_merge", &no_merge,
            "do not merge two roof planes a few degrees apart that meet without a step (one "
            "face fitted twice), even where the images confirm the merged plane; nor keep only "
            "the better of two such planes that meet in a concave crease and are not one face");
  MatchFlags flags;
  std::string window;
  AddProcessingOptions(p, r, &flags, &window);
  p.Example("roofsweep run sim/block.json -o buildings.gml")
      .Example("roofsweep run out/block -o b.gpkg -lines3d l.gpkg -report run.json -overwrite")
      .Example("roofsweep run out/block -o b.city.json -footprints out/block/footprints.gpkg")
      .Example("roofsweep run city/block.json -aoi 391800,5819000,392000,5819200 -o t.gml");
  if (!p.Parse(args)) return 0;
  r.aoi = ParseTileOptions(p, aoi, r.tile_buffer_m);
  ApplyWindowOption(p, window, &r.sweep);
  if (!(r.min_edge_support >= 0 && r.min_edge_support <= 1))
    throw UsageError("Option -min_edge_support expects a share from 0 to 1", p.Synopsis());
  if (!(r.min_edge_support_unlined >= 0 && r.min_edge_support_unlined <= 1))
    throw UsageError("Option -min_edge_support_unlined expects a share from 0 to 1", p.Synopsis());
  r.line_planes = !sweep_only;
  r.drop_eave_planes = !keep_eave_planes;
  r.mirror_faces = !no_mirror;
  r.hip_ends = !no_hip_ends;
  r.footprint_mirror = !no_footprint_mirror;
  r.lift_lines = !no_lift;
  r.level_lines = !no_level;
  r.eave_search = !no_eaves;
  r.border_clip = !no_border_clip;
  r.footprint_growth = !no_growth;
  r.roof_models_over_footprints = !flat_only;
  r.roofs_beyond_ridges = !no_beyond;
  r.roof_models_whole = !models_apart;
  r.verify_follows_sweep = !fixed_verify_score;
  r.footprint_pieces = !no_pieces;
  r.fall_line_pieces = !no_fall_pieces;
  r.merge_coplanar = !no_merge;
  r.colour_breaks = !no_colour_breaks;
  r.lod1_fallback = !no_lod1;
  flags.Apply(p);
  const RunSummary s = RunPipeline(r, *ctx.progress);
  if (!ctx.quiet) {
    std::cout << FormatRunSummary(s);
    std::cout << "Wrote " << r.output << ": " << s.buildings << " buildings\n";
  } else {
    for (const std::string& m : s.messages) std::cerr << m << "\n";
  }
  return 0;
}

int Sweep(const std::vector<std::string>& args, Context& ctx) {
  RunRequest r;
  r.stop_after_sweep = true;
  std::string aoi;
  ArgParser p("sweep",
              "Runs the pipeline up to the half-plane sweep (Baillard & Zisserman 2000, section 3) "
              "and writes every swept line side as a polygon on its best plane, with the angle, "
              "similarity, curvature, how far the peak stands out, whether it proposes a plane "
              "(candidate) and why it was not accepted, for inspection.");
  p.Positional("BLOCK", &r.block, "block manifest, folder holding block.json, or FORMAT:SOURCE")
      .Option("-o", &r.output, "FILE", "output with a MultiPolygonZ layer half_planes (.gpkg, ...)")
      .Option("-of|-f", &r.format, "FORMAT", "GDAL vector driver, when the extension does not tell")
      .Flag("-overwrite", &r.overwrite, "replace existing output files")
      .Option("-lines3d", &r.lines3d, "FILE",
              "also write the 3D lines (layer lines3d, as match writes it; -lines reads it back)")
      .Option("-report", &r.report, "FILE", "JSON report with the stage table")
      .Option("-aoi", &aoi, "MINX,MINY,MAXX,MAXY",
              "sweep one tile, in the block CRS (default: the block's aoi, if any): read only the "
              "views and image windows that see it and its buffer, as `run -aoi` does")
      .Option("-tile_buffer", &r.tile_buffer_m, "M", "sweep this far around the tile (default 30)");
  MatchFlags flags;
  std::string window;
  AddProcessingOptions(p, r, &flags, &window);
  p.Example("roofsweep sweep out/block -o half_planes.gpkg");
  if (!p.Parse(args)) return 0;
  flags.Apply(p);
  r.aoi = ParseTileOptions(p, aoi, r.tile_buffer_m);
  ApplyWindowOption(p, window, &r.sweep);
  const RunSummary s = RunPipeline(r, *ctx.progress);
  if (!ctx.quiet) {
    std::cout << FormatRunSummary(s);
    std::cout << "Wrote " << r.output << ": " << s.sides << " half-planes, " << s.accepted
              << " accepted\n";
  }
  return 0;
}

const CommandRegistration kRun{
    {"run", "reconstruct LoD2 buildings from an oriented block (the whole pipeline)", Run, true}};
const CommandRegistration kSweep{
    {"sweep", "sweep half-planes about the 3D lines and write them for inspection", Sweep, true}};

}  // namespace
}  // namespace roofsweep::cli
