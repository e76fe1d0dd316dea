// Which input segment every constrained edge of a run belongs to, and what happened to each
// input segment: the pieces constrained, the splits, the constraints cleared. Part of the
// element history's index (element_index.hpp), filled in its one pass over the log.
//
// The log has no segment ids: a `constrain` event names an edge, a `split_edge` event an
// edge and the vertex put on it. So the table follows the pieces as the run makes them:
//  - a piece constrained in a recover_segment step belongs to the step's subject, the input
//    segment being recovered (its pieces may bend off the straight line through rounded
//    crossing points, so geometry could not tell); a piece constrained in any other step is
//    an input segment of its own;
//  - a piece constrained in the step that cleared an older piece, and sharing an endpoint
//    with it, re-routes that older segment (segment recovery does this when a crossing
//    point rounds onto a vertex of the new segment);
//  - a split of an edge that was constrained (the faces' flags say so) gives both halves
//    the split piece's segment.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "index_rows.hpp"
#include "meshstep/mesh/handles.hpp"
#include "meshstep/replay/event.hpp"

namespace meshstep::viewer {

class SegmentTable {
 public:
  struct Input {
    VertexId a = kNone, b = kNone;  // the input segment's endpoints (the recovery step's subject)
    int marker = 0;
  };
  // One change to one of an input segment's pieces.
  struct Change {
    enum class Kind : std::uint8_t { constrained, cleared, split };
    std::uint32_t event = 0;
    Kind kind = Kind::constrained;
    replay::SplitReason reason = replay::SplitReason::insert;  // of a split
    VertexId a = kNone, b = kNone;  // the piece
    VertexId vertex = kNone;        // a split's new vertex
  };

  // Building: every event of the log in order, then finish().
  void add(const replay::Event& ev, std::uint32_t e);
  void finish();

  std::size_t size() const { return inputs_.size(); }
  // The input segment that the edge a-b was ever a piece of, or kNone.
  std::uint32_t segment_of(VertexId a, VertexId b) const;
  const Input& input(std::uint32_t s) const { return inputs_[s]; }
  // Its changes, in log order.
  std::span<const Change> changes(std::uint32_t s) const { return changes_.row(s); }
  // Its pieces after `position` events: a chain from input(s).a when they form one (pieces
  // that do not follow on are left at the end).
  std::vector<std::pair<VertexId, VertexId>> pieces_at(std::uint32_t s, std::uint64_t position) const;
  std::size_t bytes() const;

 private:
  std::uint32_t segment_for_new_piece(VertexId a, VertexId b, int marker);
  std::uint32_t input_segment(VertexId a, VertexId b, int marker);
  void record(std::uint32_t s, const Change& c) { pending_.emplace_back(s, c); }

  // While building.
  std::unordered_map<std::uint64_t, std::uint32_t> piece_segment_, by_ends_;
  replay::StepKind step_kind_ = replay::StepKind::start;
  VertexId subject_[2] = {kNone, kNone};
  struct Cleared {
    VertexId a, b;
    std::uint32_t segment;
  };
  std::vector<Cleared> cleared_in_step_;
  std::vector<std::pair<std::uint32_t, Change>> pending_;

  // Finished: every piece ever (its key, smaller id first) and its segment, sorted by key.
  std::vector<std::uint64_t> keys_;
  std::vector<std::uint32_t> key_segment_;
  std::vector<Input> inputs_;
  Rows<Change> changes_;
};

}  // namespace meshstep::viewer
