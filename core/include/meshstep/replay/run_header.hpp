// What a log's header says of its run, typed: read once from the header's "key=value"
// parameters (LogReader::run()), so that no reader of a log parses header text itself.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/region.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/terrain/tin.hpp"

namespace meshstep::replay {

struct RunHeader {
  // The input's vertices come first among the run's vertices, numbered from first_index in
  // its files; the rest are Steiner vertices.
  std::uint64_t input_vertices = 0;
  int first_index = 0;
  // A refinement's selection, insertion ("flip", "cavity" or "bisection": the parameters'
  // own, else the triangulation's) and encroachment rule, as the run recorded them.
  std::optional<Selection> selection;
  std::string insertion;
  std::optional<Encroachment> encroachment;
  std::optional<double> lens_angle;  // degrees, under the lens rule
  // The bounds as numbers (none: not set, written as 0, or not a number: a --size grid's name).
  std::optional<double> min_angle, max_angle, max_aspect, max_area, size, max_error;
  // Which segments the refinement could split (split_segments=, written only when not all;
  // a word that is none of the modes reads as all, as a header without it does).
  SegmentSplits segment_splits = SegmentSplits::all;
  // The part of the plane the refinement was limited to (region=box:... or polygon:...).
  std::optional<RefineRegion> region;
  // A recipe's operations in the order they ran (empty: a run of one, described above).
  // Each ran its phases after the one before: refine_phases(op) refinement phases, then an
  // improvement phase when it improves and was not capped.
  std::vector<Operation> operations;
};

// Reads the header's run description. Throws InputError ("PATH: the header's parameter
// input_vertices=x is not a number") for a vertex count or first index that is no number,
// and for a region= that is no region.
RunHeader read_run_header(const LogHeader& header, const std::string& path);

// The run as a recipe to run again (the workbench's re-runs): a recipe's operations, or a
// refinement's one operation rebuilt from what its header records (algorithm, selection,
// bounds as written, size, caps, order, insertion, encroachment, kept segments, data
// structure, convex hull, region); empty for a triangulation. What the header does not keep
// (--improve, free-vertex deletion) stays at its default.
std::vector<Operation> recorded_recipe(const LogHeader& header, const RunHeader& run);

// The header parameters each kind of run records, which read_run_header reads back.
// A triangulation: the convex hull flag and the input's numbering.
std::string triangulate_parameters(bool convex_hull, std::uint64_t input_vertices, int first_index);
// A planar refinement: its selection, bounds, caps, order, insertion and encroachment;
// `size_text` is --size as given (a number or a grid's name; empty: none).
std::string refine_parameters(const RefineOptions& options, const std::string& size_text,
                              std::uint64_t input_vertices, int first_index);
// A 3D surface's bisection (and flips: flip_dihedral < 0 for none).
std::string surface_parameters(double max_edge, double max_area, std::uint64_t input_vertices,
                               std::size_t max_triangles, double flip_dihedral);

// A terrain approximation: its bound, the grid's shape and spacing (a step's sample is a
// grid index), and the choices made.
std::string terrain_parameters(const terrain::TerrainOptions& options, const terrain::HeightGrid& grid);

// The run in a few words, for a caption or a column: the algorithm, its bounds, and the
// parts that are not the defaults (segments kept whole, a dcel, cavities), so that two runs'
// descriptions say how they differ: "offcenter, min angle 30", "offcenter, min angle 30,
// split segments interior", "triangulate, dcel, cavity".
std::string describe_run(const LogHeader& header, const RunHeader& run);

// A value from the header's "key=value" parameters, or `fallback` (what read_run_header
// reads; for showing the header's words as they are).
std::string header_parameter(const LogHeader& header, const std::string& key, const std::string& fallback = "");

}  // namespace meshstep::replay
