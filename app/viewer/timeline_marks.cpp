#include "timeline_marks.hpp"

#include <array>

#include "session.hpp"

namespace meshstep::viewer {

namespace {

using replay::StepKind;

constexpr std::array<const char*, kMarkCount> kNames = {"splits", "rejected", "cavities", "flips", "refine",
                                                        "triangulate"};
constexpr std::array<const char*, kMarkCount> kLabels = {
    "segment splits",      "rejected points (encroaching)", "cavities of more than 10 faces", "flips",
    "refinement steps", "triangulation steps"};

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

const char* name(Mark mark) { return kNames[static_cast<std::size_t>(mark)]; }
const char* label(Mark mark) { return kLabels[static_cast<std::size_t>(mark)]; }

std::optional<Mark> parse_mark(std::string_view text) {
  for (std::size_t i = 0; i < kMarkCount; ++i)
    if (text == kNames[i]) return static_cast<Mark>(i);
  return std::nullopt;
}

bool marks_steps(Mark mark) { return mark == Mark::splits || mark == Mark::refine || mark == Mark::triangulate; }

bool marks_step(Mark mark, StepKind kind) {
  switch (mark) {
    case Mark::splits: return kind == StepKind::split_segment;
    case Mark::refine: return kind == StepKind::refine;
    case Mark::triangulate:
      return kind == StepKind::start || kind == StepKind::insert_vertex || kind == StepKind::recover_segment ||
             kind == StepKind::carve;
    default: return false;
  }
}

bool marks_event(Mark mark, const replay::Event& event) {
  switch (mark) {
    // The same tests as the keys that jump to them, so that a mark is where a jump stops.
    case Mark::rejected: return is_rejected_point(event);
    case Mark::cavities: return is_big_cavity(event);
    case Mark::flips: return event.type == replay::EventType::flip;
    default: return false;
  }
}

bool MarkSet::any_event_kind() const {
  for (std::size_t i = 0; i < kMarkCount; ++i)
    if (has(static_cast<Mark>(i)) && !marks_steps(static_cast<Mark>(i))) return true;
  return false;
}

std::string format_marks(MarkSet marks) {
  std::string out;
  for (std::size_t i = 0; i < kMarkCount; ++i) {
    if (!marks.has(static_cast<Mark>(i))) continue;
    if (!out.empty()) out += ", ";
    out += kNames[i];
  }
  return out;
}

std::optional<MarkSet> parse_marks(std::string_view text, std::string& bad) {
  MarkSet marks = MarkSet::none();
  if (trimmed(text).empty()) return marks;
  while (true) {
    const std::size_t comma = text.find(',');
    const std::string_view item = trimmed(text.substr(0, comma));
    const std::optional<Mark> mark = parse_mark(item);
    if (!mark) {
      bad = std::string(item);
      return std::nullopt;
    }
    marks.set(*mark);
    if (comma == std::string_view::npos) return marks;
    text.remove_prefix(comma + 1);
  }
}

}  // namespace meshstep::viewer
