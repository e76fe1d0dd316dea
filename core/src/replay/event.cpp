// The schema of every event type, and the names the dumps and the viewer show.
#include "meshstep/replay/event.hpp"

#include <stdexcept>

#include "meshstep/refine/registry.hpp"

namespace meshstep::replay {
namespace {

constexpr const char* kStepNames[] = {"start", "insert_vertex", "recover_segment", "carve",
                                      "refine", "split_segment", "bisect", "remove_vertex", "flip_3d"};
constexpr const char* kPhaseNames[] = {"insert_vertices", "recover_segments", "carve", "refine",
                                       "improve"};
constexpr const char* kLocateNames[] = {"in_face", "on_edge", "on_vertex"};
constexpr const char* kSplitNames[] = {"insert", "crossing", "encroached", "bisection"};
constexpr const char* kFlipNames[] = {"delaunay", "segment_recovery", "vertex_removal", "angles_3d", "load"};
constexpr const char* kRemoveNames[] = {"ghost", "hole", "outside"};
constexpr const char* kCriterionNames[] = {"min_angle", "max_angle", "max_aspect", "max_area", "local_max_area", "size",
                                           "vertical_error"};
constexpr const char* kSampleChoiceNames[] = {"worst_sample", "terminal_worst", "terminal_point", "own_worst"};

static_assert(std::size(kStepNames) == static_cast<std::size_t>(StepKind::count_));
static_assert(std::size(kPhaseNames) == static_cast<std::size_t>(Phase::count_));
static_assert(std::size(kLocateNames) == static_cast<std::size_t>(LocateResult::count_));
static_assert(std::size(kSplitNames) == static_cast<std::size_t>(SplitReason::count_));
static_assert(std::size(kFlipNames) == static_cast<std::size_t>(FlipReason::count_));
static_assert(std::size(kRemoveNames) == static_cast<std::size_t>(RemoveReason::count_));
static_assert(std::size(kCriterionNames) == static_cast<std::size_t>(Criterion::count_));

// A selection is named as its registry record names it (and as the log's header and the
// command line spell it): a new selection needs no name here.
std::string selection_name(std::uint8_t code) {
  for (const SelectionInfo& s : selections())
    if (static_cast<std::uint8_t>(s.selection) == code) return std::string(s.name);
  return std::to_string(code);
}

template <std::size_t N>
std::string pick(const char* const (&names)[N], std::uint8_t code) {
  return code < N ? names[code] : std::to_string(code);
}

}  // namespace

const char* name(EventType type) { return schema(type).name; }
const char* name(StepKind kind) {
  const auto i = static_cast<std::size_t>(kind);
  return i < std::size(kStepNames) ? kStepNames[i] : "unknown";
}
const char* name(Phase phase) {
  const auto i = static_cast<std::size_t>(phase);
  return i < std::size(kPhaseNames) ? kPhaseNames[i] : "unknown";
}
const char* name(SampleChoice choice) {
  const auto i = static_cast<std::size_t>(choice) - kFirstSampleChoice;
  return i < std::size(kSampleChoiceNames) ? kSampleChoiceNames[i] : "unknown";
}
const char* name(Criterion criterion) {
  const auto i = static_cast<std::size_t>(criterion);
  return i < std::size(kCriterionNames) ? kCriterionNames[i] : "unknown";
}

std::string code_name(EventType type, std::uint8_t code) {
  switch (type) {
    case EventType::step_begin: return pick(kStepNames, code);
    case EventType::phase_begin:
    case EventType::phase_end: return pick(kPhaseNames, code);
    case EventType::locate: return pick(kLocateNames, code);
    case EventType::split_edge: return pick(kSplitNames, code);
    case EventType::flip: return pick(kFlipNames, code);
    case EventType::remove_face: return pick(kRemoveNames, code);
    case EventType::constrain: return code ? "set" : "cleared";
    case EventType::criterion_test: {
      const auto criterion = static_cast<std::uint8_t>(code & ~kCriterionPassed);
      return pick(kCriterionNames, criterion) + ((code & kCriterionPassed) ? " passed" : " failed");
    }
    case EventType::point_selected:
      if (code >= kFirstSampleChoice) return pick(kSampleChoiceNames, static_cast<std::uint8_t>(code - kFirstSampleChoice));
      return selection_name(code);
    default: return std::to_string(code);
  }
}

}  // namespace meshstep::replay
