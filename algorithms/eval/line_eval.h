#pragma once

#include <limits>
#include <vector>

#include "algorithms/buildings/city_model.h"
#include "algorithms/geometry/block.h"
#include "algorithms/geometry/segment3.h"

namespace roofsweep::eval {

struct LineEvalOptions {
  // A point of one segment "lies on" a segment of the other set when it is
  // within this 3D distance of it...
  double distance_m = 0.10;
  // ... and the two directions differ by at most this (undirected).
  double angle_deg = 10.0;
  // Segments are measured by sampling at most this far apart (length-based
  // fractions, exact to about this step at segment ends).
  double sample_step_m = 0.02;
  // Roof edges of one building closer than this are one edge (a ridge is in
  // both its roof polygons).
  double merge_m = 0.001;
  // Edges between two polygons this close to coplanar are not roof edges
  // (triangulated roof faces in real LoD2 data).
  double coplanar_angle_deg = 2.0;
  // The terrain in the models' coordinates: a constant height or a DTM
  // grid (unknown: none). Result lines within distance_m of it, or of a
  // reference surface polygon, count as on a true surface.
  GroundModel ground;
};

// The distinct edges of the roof polygons (exterior rings and holes) of all
// buildings: shared edges once, edges between coplanar polygons left out.
// Only exact (within merge_m) shared edges are recognised; T-junctions are not.
std::vector<Segment3> RoofEdges(const CityModel& model, const LineEvalOptions& options);

struct LineScores {
  int segments = 0;                  // reconstructed segments given
  double result_length_m = 0;        // their total length
  double reference_length_m = 0;     // roof edges + extra reference segments
  double roof_edge_length_m = 0;     // roof edges only
  double result_on_reference_m = 0;  // result length within tolerance of a reference segment
  double reference_covered_m = 0;    // reference length covered by a result segment
  double roof_edge_covered_m = 0;    // roof-edge length covered
  // Result length on no reference segment but within distance_m of a
  // reference surface or the terrain: lines of texture, tile courses,
  // shadow borders or markings lying on the scene (geometrically right, yet
  // no edge of the model), as against lines off every surface (mismatches,
  // trees). Zero when no surfaces were given.
  double result_on_surface_m = 0;
  // Result length on a clutter segment and on no reference segment (part of
  // result_on_reference_m).
  double result_on_clutter_m = 0;
  // Covered length of each reference segment: the roof edges, then the
  // extra reference segments, in their order.
  std::vector<double> reference_covered_each_m;
};

// Length-based comparison. precision = result_on_reference_m / result_length_m,
// completeness = reference_covered_m / reference_length_m,
// roof_edge_completeness = roof_edge_covered_m / roof_edge_length_m.
// `surfaces`: the reference's polygons (roofs, walls, ground), optional.
// `clutter`: true edges of objects that are not part of the model (a
// simulated scene's cars, chimneys, solar panels), optional: a result line
// on one is correct, but the clutter is not there to be completed, so it
// counts towards precision only.
LineScores EvaluateLines(const std::vector<Segment3>& result,
                         const std::vector<Segment3>& roof_edges,
                         const std::vector<Segment3>& extra_reference,
                         const LineEvalOptions& options,
                         const std::vector<Polygon3>* surfaces = nullptr,
                         const std::vector<Segment3>* clutter = nullptr);

}  // namespace roofsweep::eval
