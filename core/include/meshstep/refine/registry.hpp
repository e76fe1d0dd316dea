// The named refinement algorithms and the parts they are made of, in one table that the
// command line, the viewer and the tests all read (meshstep list prints it).
#pragma once

#include <optional>
#include <string>
#include <span>
#include <string_view>
#include <vector>

#include "meshstep/refine/refine.hpp"

namespace meshstep {

struct AlgorithmInfo {
  std::string_view name;
  std::string_view description;
  Selection selection;
  double default_min_angle_deg;  // when the command line gives no bound at all (0: none)
  RefineInsertion insertion = RefineInsertion::delaunay;
  double default_max_aspect = 0.0;  // likewise (0: none)
  // Runs in two phases: an aspect-ratio phase, then a min-angle phase (combined criteria).
  bool aspect_then_angle = false;
  // Removes Steiner vertices after refining (improvement + refinement, RefineOptions::improve).
  bool improve = false;
  // The highest angle bound it ended at on every input of the corpus where Triangle 1.6 ends
  // (../shared/data/pslg at 20-34 degrees; docs/refinement.md); above it the command warns
  // and relies on a cap. 0: not meant for an angle bound.
  double known_to_end_deg = 34.0;
};

// The refinement meshstep refine runs without --algorithm (Triangle's own choice).
inline constexpr std::string_view kDefaultAlgorithm = "offcenter";

// 1 / sin(20.7 degrees): a triangle whose aspect ratio (longest edge over shortest altitude,
// which is at least 1 / sin of the smallest angle) is below it has no angle under 20.7.
inline constexpr double kDefaultMaxAspect = 2.83;

// Every registered algorithm, in the order `meshstep list` shows them.
std::span<const AlgorithmInfo> algorithms();
const AlgorithmInfo* find_algorithm(std::string_view name);

// The other parts, by name, with a line of description each.
struct PartInfo {
  std::string_view name;
  std::string_view description;
};

// The pseudo-code of the refinement program a selection makes (the viewer's pseudo-code
// panel, scene/pseudocode.hpp): Ruppert's loop, or Rivara's Lepp loop, round the lines that
// choose the new point, which are the selection's own.
struct SelectionProgram {
  std::string_view title;      // "Off-center refinement (Üngör 2004/2009)"
  std::string_view reference;  // the paper(s), one line
  // The point comes from the terminal edge of Lepp(t), inside Rivara's loop ("p" there,
  // "c" in Ruppert's).
  bool lepp = false;
  // The lines that choose it, indented as in the loop (4 spaces in Ruppert's, 8 in Lepp's).
  std::span<const std::string_view> choose_point;
};

// A point selection: where a bad triangle asks for its new vertex. Adding one means its
// function in the refiner (refiner.hpp, the Selection enum) and its record here: every
// parser, the help, `meshstep list`, the step story, the log's dumps and the pseudo-code
// panel read the records.
struct SelectionInfo {
  std::string_view name;  // as the command line and the log header spell it
  std::string_view description;
  Selection selection;
  Encroachment encroachment;  // its default encroachment rule (default_encroachment)
  // What the step story calls its point ("off-center"), and, where the terminal edge of a
  // Lepp lies on the boundary (one terminal triangle), what it takes there instead.
  std::string_view point_name;
  std::string_view boundary_point_name = {};
  SelectionProgram program;
};
std::span<const SelectionInfo> selections();
const SelectionInfo* find_selection(std::string_view name);
const SelectionInfo& selection_info(Selection selection);

// A refinement option: the command line's --NAME and a run description's word alike
// (refine/run_spec.hpp), with what it accepts.
enum class ParameterKind {
  number,  // a real number in `range`
  count,   // a whole number, 0 or more
  flag,    // present or not
  choice,  // one of choices()
  text,    // free text checked by its user (--size: a number or a grid file)
};
enum class NumberRange {
  any,
  positive,      // > 0
  non_negative,  // >= 0
  degrees,       // 0 to 180
};
// Where a choice parameter's words come from: its own list, or a table of the registry.
enum class ChoiceSource { own, algorithms, selections };

struct ParameterInfo {
  std::string_view name;        // without the dashes: "min-angle"
  std::string_view short_name;  // a one-letter alias on the command line, or empty
  ParameterKind kind;
  std::string_view type_name;  // "DEG", shown in the help
  std::string_view help;       // the command line's help ("" for a choice: made from its words)
  NumberRange range = NumberRange::any;
  // A stopping bound: a run given none gets its algorithm's defaults.
  bool bound = false;
  std::string_view default_text = {};  // shown as the default in the help ("" none)
  ChoiceSource choice_source = ChoiceSource::own;
  std::span<const std::string_view> own_choices = {};
};

// The refinement's parameters, in the order the help and the printed description give them.
std::span<const ParameterInfo> refine_parameters();
const ParameterInfo* find_parameter(std::string_view name);
// The words a choice parameter accepts, in the table's order.
std::vector<std::string> choices(const ParameterInfo& parameter);
// What is wrong with `text` as the value of `parameter` ("must be a positive number, not
// -3"), or empty when it is acceptable. Text that is no number passes a number's range
// check (the reader of the number refuses it in its own words).
std::string range_problem(const ParameterInfo& parameter, std::string_view text);
std::span<const PartInfo> insertions();
// The words of --split-segments (SegmentSplits, in its order) and what each keeps whole.
std::span<const PartInfo> segment_splits_modes();
std::span<const PartInfo> data_structures();

// The selection of that name (selections()), or nothing.
std::optional<Selection> parse_selection(std::string_view name);

// Options that run `algorithm` with its own parts (criteria and triangulation options are
// the caller's).
RefineOptions options_for(const AlgorithmInfo& algorithm);

// The two phases of an aspect_then_angle algorithm from the caller's criteria: the aspect
// phase to criteria.max_aspect (or kDefaultMaxAspect), then the min-angle phase to
// criteria.min_angle_deg (or the algorithm's default); size bounds and caps in both.
std::vector<RefinePhase> aspect_then_angle_phases(const RefineCriteria& criteria, const AlgorithmInfo& algorithm);

}  // namespace meshstep
