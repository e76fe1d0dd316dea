// The kinds of thing the timeline can mark, and which of them a person chose to see. No GL
// and no ImGui: the settings file keeps the choice, scripts toggle it, the timeline counts
// and draws the marks (timeline.hpp).
//
// A kind is either a kind of step (marked where the step ends, as the step ticks are) or a
// kind of event (marked just after the event, where the J and K keys stop):
//
//   splits       steps that split a segment (S)
//   rejected     points rejected because they encroached a segment (J; is_rejected_point)
//   cavities     Bowyer-Watson cavities of more than 10 faces (K; is_big_cavity)
//   flips        edge flips (Lawson's, segment recovery's, vertex removal's)
//   refine       refinement steps (R)
//   triangulate  the steps that build the triangulation: its first triangle, vertex
//                insertions, segment recoveries, carving
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "meshstep/replay/event.hpp"

namespace meshstep::viewer {

enum class Mark : std::uint8_t { splits, rejected, cavities, flips, refine, triangulate, count_ };
inline constexpr std::size_t kMarkCount = static_cast<std::size_t>(Mark::count_);

// The word scripts and the settings file use ("splits"), and the words people read
// ("segment splits").
const char* name(Mark mark);
const char* label(Mark mark);
std::optional<Mark> parse_mark(std::string_view text);

// Whether the kind marks steps (else events), and whether it marks this step or event.
bool marks_steps(Mark mark);
bool marks_step(Mark mark, replay::StepKind kind);
bool marks_event(Mark mark, const replay::Event& event);

class MarkSet {
 public:
  // What the timeline showed before the marks were a choice: the segment splits.
  static MarkSet defaults() { return none().set(Mark::splits); }
  static MarkSet none() { return MarkSet(0); }
  static MarkSet all() { return MarkSet((1u << kMarkCount) - 1); }
  bool has(Mark m) const { return bits_ >> static_cast<unsigned>(m) & 1u; }
  MarkSet& set(Mark m, bool on = true) {
    const std::uint32_t bit = 1u << static_cast<unsigned>(m);
    bits_ = on ? bits_ | bit : bits_ & ~bit;
    return *this;
  }
  MarkSet& toggle(Mark m) { return set(m, !has(m)); }
  bool any_event_kind() const;
  std::uint32_t bits() const { return bits_; }
  friend bool operator==(const MarkSet&, const MarkSet&) = default;

 private:
  explicit MarkSet(std::uint32_t bits) : bits_(bits) {}
  std::uint32_t bits_;
};

// "splits, flips" (names in Mark order; "" for none), and back: nullopt and `bad` set to
// the word that is not a kind.
std::string format_marks(MarkSet marks);
std::optional<MarkSet> parse_marks(std::string_view text, std::string& bad);

}  // namespace meshstep::viewer
