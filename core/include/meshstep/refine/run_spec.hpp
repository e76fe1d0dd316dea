// The description of a run as a value: its input, then the operations done to it in order,
// each an algorithm with its bounds and options. One parser reads it from the command
// line's own words ("refine --algorithm lepp-centroid --min-angle 25 --max-area 2e-05"),
// one printer writes it back (print(parse(text)) is text for a printed description), and
// refine_options() turns an operation into what refine() runs. The option names, their
// ranges and their words come from the registry's records (refine/registry.hpp).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/geometry/point.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/region.hpp"
#include "meshstep/refine/registry.hpp"

namespace meshstep {

// Where an operation applies, as the command line names it: --region X0,Y0,X1,Y1 (a box,
// checked when parsed), --region-polygon X0,Y0,X1,Y1,X2,Y2,... (a polygon written out, so
// that a recipe stays one file; checked simple when parsed) or --region-poly FILE.poly (a
// polygon, read by region_of()). One of the three.
struct RegionSpec {
  std::optional<std::pair<Point, Point>> box;  // its two corners, low then high
  std::string polygon_file;
  std::vector<Point> polygon;  // --region-polygon's vertices, in the order given
  bool operator==(const RegionSpec&) const = default;
};

enum class OperationKind { triangulate, refine };

// How the points go in, as the command line says it: the triangulation's flips or cavity,
// or Lepp longest-edge bisection (refinement only).
enum class PointInsertion { flip, cavity, bisection };

struct Operation {
  OperationKind kind = OperationKind::refine;
  std::string algorithm{kDefaultAlgorithm};  // a registered refinement algorithm
  std::optional<Selection> selection;        // none: the algorithm's own
  // The bounds as given; none given at all: the algorithm's defaults (AlgorithmInfo).
  std::optional<double> min_angle, max_angle, max_aspect, max_area;
  std::optional<std::string> size;  // a length, or an ESRI ASCII grid of lengths
  std::size_t max_triangles = 0, max_steiner = 0;  // caps; 0: none
  std::optional<double> flip_dihedral;              // 3D surfaces only
  PointInsertion insertion = PointInsertion::flip;
  RefineOrder order = RefineOrder::smallest_first;
  std::optional<Encroachment> encroachment;  // none: the selection's own
  SegmentSplits segment_splits = SegmentSplits::all;
  DataStructure data_structure = DataStructure::tds;
  bool convex_hull = false, improve = false, delete_free = false, keep_free = false;
  std::optional<RegionSpec> region;  // none: the whole domain
  bool operator==(const Operation&) const = default;
};

struct RunSpec {
  std::string input;
  std::vector<Operation> operations;
  bool operator==(const RunSpec&) const = default;
};

// A description that cannot be run: what is wrong, in the command line's words
// ("--min-angle: must be zero or a positive number, not -3").
class RunSpecError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Whether an operation of `kind` takes the parameter; the words of a choice it accepts
// there; its help there (a triangulation's options say less than a refinement's).
bool takes(OperationKind kind, const ParameterInfo& parameter);
std::vector<std::string> accepted_words(OperationKind kind, const ParameterInfo& parameter);
std::string_view help_for(OperationKind kind, const ParameterInfo& parameter);

// Sets one option of `op` from its text: `name` without the dashes, `text` empty for a
// flag. Throws RunSpecError for an unknown name, a word not among its choices, a number
// that is not one or out of range, or an option the operation's kind does not take.
void set_option(Operation& op, std::string_view name, std::string_view text);

// An operation from its words: "refine" or "triangulate", then --NAME VALUE and --FLAG
// words (the command line's, short aliases included). Throws RunSpecError.
Operation parse_operation(const std::vector<std::string>& words);
// The same from one line of text, split at spaces.
Operation parse_operation(std::string_view line);

// The operation in the words parse_operation reads: its kind, then every option that
// differs from the default, in the registry's order, each number in its shortest exact text.
std::string print_operation(const Operation& op);

// --size as a length, or nothing: none given, or the name of a grid of lengths.
std::optional<double> size_length(const Operation& op);

// Whether the description gives any bound (--min-angle, --max-angle, --max-aspect,
// --max-area, --size); without one the algorithm's defaults apply.
bool has_bound(const Operation& op);

// What refine() runs for a refine operation: the algorithm's parts with the selection,
// insertion, order, encroachment, data structure and flags of the description, and its
// criteria (the algorithm's defaults when no bound is given), in phases for an
// aspect_then_angle algorithm. A --size that is no number is a grid: `size_from_grid` is
// its reader's lookup (none given: RunSpecError). Throws RunSpecError for options that
// contradict each other.
RefineOptions refine_options(const Operation& op, std::function<double(const Point&)> size_from_grid = {});

// The insertion as the log header and the statistics name it: "bisection", or the
// triangulation's "flip" or "cavity".
std::string insertion_name(const RefineOptions& options);

// The phases an operation records in a log, capped or not: one refinement phase per phase
// of its algorithm (two for aspect-then-angle), each followed by an improvement phase when
// it improves. A recipe's log holds its operations' phases in order after the
// triangulation's, so that this count says where each operation begins and ends.
std::size_t recorded_phases(const Operation& op);

// The region an operation names, or none: the box or the polygon as parsed, or the polygon
// its --region-poly file's segments make. Throws InputError ("FILE: a region polygon's segment 1 and ...") for
// a file that cannot be read or makes no simple polygon.
std::optional<RefineRegion> region_of(const Operation& op);

}  // namespace meshstep
