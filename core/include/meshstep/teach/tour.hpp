// A guided tour of a run (docs/tours.md): a text file that names its input and its run, then
// the stops a lecturer makes on the way, each a moment of the run with a caption of one to
// three sentences, and optionally the layers, the colouring and a camera box.
//
//   title Ruppert's algorithm
//   input ../examples/lesson.poly          # relative to the tour file
//   run refine --algorithm circumcenter --min-angle 25
//   stop step 0
//   caption The input: a plate with a hole, a crack and a sharp tooth.
//   stop next segment-split
//   caption A vertex lies inside this segment's diametral circle, so the segment is split.
//   layers -labels
//   camera 11 2.5 15.5 6
//
// A stop names a step (the one numbering: step K is the mesh after K steps, step_numbers.hpp)
// or a rule that the run's log resolves: "end", or "next KIND", the first step after the
// previous stop's that does KIND (a segment split, a flip, a Lepp path...). No GL: the
// viewer and `meshstep export` read the same tours.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "meshstep/refine/run_spec.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::teach {

// What a "next KIND" rule looks for in a step's events.
enum class Happening : std::uint8_t {
  segment_split,  // a segment split because it was encroached (split_edge, reason encroached)
  encroached,     // a segment found encroached (an encroached event)
  rejected,       // a new point rejected because it would encroach a segment
  flip,           // an edge flipped to make the triangulation Delaunay again (Lawson)
  lepp,           // a Lepp path followed to its terminal edge
  refine,         // a bad triangle fixed by a new point (a refinement step)
  insert,         // an input vertex inserted
  recover,        // an input segment recovered
  carve,          // holes and the outside carved away
  count_
};
inline constexpr std::size_t kHappeningCount = static_cast<std::size_t>(Happening::count_);
// The rule's word ("segment-split"); parse_happening also takes spaces for the dashes.
const char* name(Happening h);
std::optional<Happening> parse_happening(std::string_view words);

// What every step of a run does: bit h of steps[K - 1] is set when step K does happening h.
struct StepHappenings {
  std::vector<std::uint16_t> steps;
  bool has(std::uint64_t step, Happening h) const {
    return step >= 1 && step <= steps.size() && (steps[step - 1] >> static_cast<unsigned>(h) & 1u);
  }
};
StepHappenings step_happenings(const replay::LogReader& log);

// A layer switched on or off by a stop ("+labels", "-fill"), or the layers listed exactly.
struct LayerChoice {
  bool exact = false;  // true: the listed layers on, every other off
  std::vector<std::pair<scene::Layer, bool>> changes;
  scene::LayerSet apply(scene::LayerSet from) const;
};

// A world box: the camera shows at least this, centred.
struct CameraBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

struct TourStop {
  int line = 0;  // of its `stop` line, for messages
  enum class Where : std::uint8_t { step, end, next } where = Where::step;
  std::uint64_t step = 0;                        // Where::step
  Happening next = Happening::segment_split;     // Where::next
  std::string caption;                           // one to three sentences
  std::optional<LayerChoice> layers;             // none: the tour's
  std::optional<scene::ColorBy> color_by;        // none: the tour's
  std::optional<CameraBox> camera;               // none: the whole run
  std::optional<double> hold_seconds;            // none: the tour's (an export holds it so long)
};

struct Tour {
  std::string path;   // the tour file, as given
  std::string title;  // may be empty
  std::string input;  // the input's path, resolved against the tour file's folder
  // The run: a refinement (one operation, or a recipe's several), or a triangulation alone
  // when there is none.
  std::vector<Operation> operations;
  std::string recipe;  // the recipe file the operations came from (resolved), or ""
  int run_line = 0;    // of the `run` or `recipe` line, for a run that fails
  // Defaults for every stop, set before the first stop.
  std::optional<LayerChoice> layers;
  std::optional<scene::ColorBy> color_by;
  double hold_seconds = 4.0;
  std::vector<TourStop> stops;
};

inline constexpr std::size_t kMaxCaptionChars = 400;
inline constexpr double kMaxHoldSeconds = 60.0;

// Reads a tour; throws InputError("TOUR:LINE: what is wrong") for a file that cannot be read
// or says something wrong, and for a recipe that does ("RECIPE:LINE: ...").
Tour read_tour(const std::string& path);
// The same from its text; `path` names it in messages and locates the input and the recipe.
Tour parse_tour(std::string_view text, const std::string& path);

// The step each stop shows, in order, resolved against the run's log: a step number as
// given, "end" the last, "next KIND" the first step after the previous stop's step that does
// KIND. Throws InputError("TOUR:LINE: ...") for a step past the run's end or a rule that
// finds nothing ("no segment split after step 12: the run has 48 steps").
std::vector<std::uint64_t> resolve_stops(const Tour& tour, const replay::LogReader& log);

// The sentences of a caption: runs of text ending in '.', '!' or '?' followed by a blank or
// the end. A caption has one to three and ends with one.
std::size_t count_sentences(std::string_view caption);

}  // namespace meshstep::teach
