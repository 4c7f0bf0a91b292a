#include <iostream>

#include "plugin/cli/arg_parser.h"
#include "plugin/cli/command.h"
#include "plugin/cli/eval_lib.h"
#include "plugin/cli/usage_checks.h"

namespace roofsweep::cli {
namespace {

int Eval(const std::vector<std::string>& args, Context&) {
  EvalRequest r;
  bool json = false;
  ArgParser p("eval",
              "Scores a LoD2 reconstruction against ground truth like the ISPRS benchmark: roof "
              "plane completeness/correctness/quality (each false or missed plane told by what "
              "covers it: nothing, a plane at another slope, or only several planes together), "
              "normal-angle, vertex and height errors, buildings, roof types, and 3D lines when "
              "given. Against a folder of roofsweep simulate, also the completeness over the roof "
              "planes the images show (two views each seeing half of the plane): a shed under a "
              "tree is in the reference, but no method finds it.");
  p.Positional("RESULT", &r.result, "reconstructed model (CityGML, CityJSON, GPKG)")
      .Positional("GROUNDTRUTH", &r.truth,
                  "ground-truth model, or a folder written by roofsweep simulate")
      .Flag("--json|-json", &json, "print one JSON object instead of the table")
      .Option("-lines", &r.lines, "FILE", "3D lines to score (GPKG lines3d layer or segments JSON)")
      .Option("-png", &r.png, "FILE", "write a plan-view overlay (ground truth vs result)")
      .Option("-vertices", &r.vertices, "FILE",
              "write the matched roof planes' vertices as a point layer (GPKG, ...): distance "
              "to the reference outline and where each lies (on it, inside, over another roof, "
              "over no roof)")
      .Option("-planes", &r.planes, "FILE",
              "roof plane hypotheses of the run (run -planes): tell the missed reference planes "
              "by where they were lost")
      .Option("-gsd", &r.options.gsd_m, "M",
              "GSD for the vertex RMS in pixels (from the simulation)")
      .Option("-overlap", &r.options.plane_overlap_fraction, "F",
              "plan-view overlap for a roof plane to count (0.5)")
      .Option("-max_angle", &r.options.max_normal_angle_deg, "DEG",
              "normal-angle agreement for a roof plane to count (10)")
      .Option("-large_plane", &r.options.large_plane_m2, "M2",
              "also score planes of at least this plan area alone (10, as ISPRS)")
      .Option("-line_tolerance", &r.options.lines.distance_m, "M",
              "distance for a 3D line to count (0.10)")
      .Flag("-overwrite", &r.overwrite, "replace an existing -png or -vertices file")
      .Example("roofsweep eval out/buildings.gml out/block")
      .Example("roofsweep eval buildings.gpkg groundtruth.gml -lines lines3d.gpkg --json");
  if (!p.Parse(args)) return 0;
  RequireNewOutput(p, r.png, r.overwrite);
  RequireNewOutput(p, r.vertices, r.overwrite);
  const EvalReport rep = RunEval(r);
  if (json) {
    std::cout << rep.json.dump(2) << "\n";
  } else {
    std::cout << rep.table;
  }
  return 0;
}

const CommandRegistration kRegistration{
    {"eval", "score a reconstruction against ground truth (ISPRS-style table or JSON)", Eval}};

}  // namespace
}  // namespace roofsweep::cli
