// The schema of every event type, and the names the dumps and the viewer show.
#include "meshstep/replay/event.hpp"

#include <stdexcept>

namespace meshstep::replay {
namespace {

using K = IdKind;
constexpr K V = K::vertex;

// name, ids, id kinds, id names, point, value, list, points, writes
constexpr EventSchema kSchemas[kEventTypeCount] = {
    {"step_begin", 2, {V, V}, {"subject", "subject2"}, false, false, false, false, false},
    {"phase_begin", 0, {}, {}, false, false, false, false, false},
    {"phase_end", 0, {}, {}, false, false, false, false, false},
    {"locate", 3, {V, K::count, K::slot}, {"vertex", "visited", "face"}, false, false, false, false, false},
    {"vertex", 2, {V, K::input}, {"vertex", "input"}, true, false, false, false, false},
    {"duplicate", 3, {V, V, K::input}, {"vertex", "same_as", "input"}, true, false, false, false, false},
    {"init", 3, {V, V, V}, {"a", "b", "c"}, false, false, false, false, true},
    {"split_face", 1, {V}, {"vertex"}, false, false, false, false, true},
    {"split_edge", 3, {V, V, V}, {"vertex", "a", "b"}, false, false, false, false, true},
    {"flip", 4, {V, V, V, V}, {"a", "b", "c", "d"}, false, false, false, false, true},
    {"cavity", 1, {V}, {"vertex"}, false, false, false, false, true},
    {"constrain", 3, {V, V, K::marker}, {"a", "b", "marker"}, false, false, false, false, true},
    {"remove_face", 0, {}, {}, false, false, false, false, true},
    {"remove_vertex", 1, {V}, {"vertex"}, false, false, false, false, true},
    {"point_selected", 3, {V, V, V}, {"a", "b", "c"}, true, false, true, true, false},
    {"lepp_path", 3, {V, V, K::count}, {"a", "b", "terminal_triangles"}, false, false, true, false, false},
    {"encroached", 3, {V, V, V}, {"a", "b", "vertex"}, true, false, false, false, false},
    {"criterion_test", 3, {V, V, V}, {"a", "b", "c"}, false, true, false, false, false},
};

constexpr const char* kStepNames[] = {"start", "insert_vertex", "recover_segment", "carve",
                                      "refine", "split_segment", "bisect", "remove_vertex"};
constexpr const char* kPhaseNames[] = {"insert_vertices", "recover_segments", "carve", "refine",
                                       "improve"};
constexpr const char* kLocateNames[] = {"in_face", "on_edge", "on_vertex"};
constexpr const char* kSplitNames[] = {"insert", "crossing", "encroached", "bisection"};
constexpr const char* kFlipNames[] = {"delaunay", "segment_recovery"};
constexpr const char* kRemoveNames[] = {"ghost", "hole", "outside"};

static_assert(std::size(kStepNames) == static_cast<std::size_t>(StepKind::count_));
static_assert(std::size(kPhaseNames) == static_cast<std::size_t>(Phase::count_));
static_assert(std::size(kLocateNames) == static_cast<std::size_t>(LocateResult::count_));
static_assert(std::size(kSplitNames) == static_cast<std::size_t>(SplitReason::count_));
static_assert(std::size(kFlipNames) == static_cast<std::size_t>(FlipReason::count_));
static_assert(std::size(kRemoveNames) == static_cast<std::size_t>(RemoveReason::count_));

template <std::size_t N>
std::string pick(const char* const (&names)[N], std::uint8_t code) {
  return code < N ? names[code] : std::to_string(code);
}

}  // namespace

const EventSchema& schema(EventType type) {
  const auto i = static_cast<std::size_t>(type);
  if (i >= kEventTypeCount) throw std::out_of_range("unknown event type");
  return kSchemas[i];
}

const char* name(EventType type) { return schema(type).name; }
const char* name(StepKind kind) {
  const auto i = static_cast<std::size_t>(kind);
  return i < std::size(kStepNames) ? kStepNames[i] : "unknown";
}
const char* name(Phase phase) {
  const auto i = static_cast<std::size_t>(phase);
  return i < std::size(kPhaseNames) ? kPhaseNames[i] : "unknown";
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
    case EventType::criterion_test:
      return std::to_string(code & 0x7F) + ((code & 0x80) ? " passed" : " failed");
    default: return std::to_string(code);
  }
}

}  // namespace meshstep::replay
