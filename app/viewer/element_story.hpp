// What the element history's index says about one selected element at a position of the
// run (after `position` events), without GL or ImGui: the inspector's panel, its ticks on
// the timeline and the state a script reads all come from here.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "element_index.hpp"
#include "inspector.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::viewer {

inline constexpr std::uint64_t kNoEvent = UINT64_MAX;

// A triangle's life: the event that wrote this face (these three vertices) into its slot,
// the events that only changed its constraint flags, and the event that replaced it.
struct TriangleStory {
  std::uint64_t created = kNoEvent;
  std::vector<std::uint64_t> reflagged;
  std::uint64_t removed = kNoEvent;  // none: it lasts to the end of the run
  FaceId slot = kNone;
};
// `face` is in the mesh after `position` events. kNoEvent for created when the index does not
// know the face (not ready, or a log that does not describe it).
TriangleStory triangle_story(const replay::LogReader& log, const ElementIndex& index,
                             const std::array<VertexId, 3>& face, std::uint64_t position);

// An input segment: its endpoints, its pieces at the position, and every split of the run.
struct SegmentStory {
  std::uint32_t segment = kNone;  // kNone: the edge is no input segment's piece the index knows
  VertexId a = kNone, b = kNone;  // the input segment's endpoints
  std::vector<std::pair<VertexId, VertexId>> pieces;  // at the position, from a to b
  struct Split {
    std::uint64_t event = 0;
    VertexId vertex = kNone, a = kNone, b = kNone;  // the vertex put on the piece a-b
    replay::SplitReason reason = replay::SplitReason::insert;
    bool midpoint = false;  // exactly at the piece's midpoint (else, encroached: on a concentric shell)
  };
  std::vector<Split> splits;  // of the whole run: those at or after the position are to come
  std::vector<std::uint64_t> events;  // every change to its pieces (constrained, split, cleared)
};
SegmentStory segment_story(const replay::LogReader& log, const ElementIndex& index, VertexId a, VertexId b,
                           std::uint64_t position);
// "midpoint", "shell" (an encroached piece split off its midpoint: on a concentric shell
// round its input endpoint), "crossing" (another segment crossed it), "insert" (a vertex
// inserted on it), "bisection".
const char* split_place(const SegmentStory::Split& split);

// The selection's story: one of the above, or a vertex's events; the events are its ticks
// on the timeline, the steps (1-based, as the caption counts, each once) its buttons.
struct SelectionStory {
  TriangleStory triangle;
  SegmentStory segment;
  std::vector<std::uint64_t> events, steps;
};
SelectionStory selection_story(const replay::LogReader& log, const ElementIndex& index, const Picked& picked,
                               const std::array<VertexId, 3>& face, std::uint64_t position);

}  // namespace meshstep::viewer
