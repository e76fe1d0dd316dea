#include "element_story.hpp"

#include <algorithm>

namespace meshstep::viewer {

namespace {

// Does the record hold the face with these vertices (sorted), in any rotation?
bool holds(const replay::FaceRecord& r, const std::array<VertexId, 3>& sorted) {
  if (r.dead()) return false;
  auto v = r.v;
  std::sort(v.begin(), v.end());
  return v == sorted;
}

}  // namespace

TriangleStory triangle_story(const replay::LogReader& log, const ElementIndex& index,
                             const std::array<VertexId, 3>& face, std::uint64_t position) {
  TriangleStory t;
  auto sorted = face;
  std::sort(sorted.begin(), sorted.end());
  // The write that made it names one of its corners (a flip its new edge, a split or a
  // cavity the new vertex, a vertex removal its link: element_index.hpp), so the latest
  // event before the position that wrote it is in one of its corners' rows.
  for (const VertexId corner : face) {
    const auto row = index.events_of_vertex(corner);
    for (auto it = std::lower_bound(row.begin(), row.end(), position); it != row.begin();) {
      const std::uint64_t e = *--it;
      if (t.created != kNoEvent && e <= t.created) break;
      const std::span<const replay::SlotWrite> writes = log.writes(e);
      const auto made = std::find_if(writes.begin(), writes.end(), [&](const replay::SlotWrite& w) {
        return holds(w.after, sorted) && !holds(w.before, sorted);
      });
      if (made == writes.end()) continue;
      t.created = e;
      t.slot = made->slot;
      break;
    }
  }
  if (t.created == kNoEvent) return t;
  // Then its slot's later writes: flags changed, until one writes another face there.
  const auto row = index.events_of_slot(t.slot);
  for (auto it = std::upper_bound(row.begin(), row.end(), t.created); it != row.end(); ++it) {
    if (it != row.begin() && *(it - 1) == *it) continue;
    const std::span<const replay::SlotWrite> writes = log.writes(*it);
    const auto last = std::find_if(writes.rbegin(), writes.rend(), [&](const replay::SlotWrite& w) { return w.slot == t.slot; });
    if (last == writes.rend()) continue;
    if (!holds(last->after, sorted)) {
      t.removed = *it;
      break;
    }
    t.reflagged.push_back(*it);
  }
  return t;
}

SegmentStory segment_story(const replay::LogReader& log, const ElementIndex& index, VertexId a, VertexId b,
                           std::uint64_t position) {
  SegmentStory s;
  const SegmentTable& table = index.segments();
  s.segment = table.segment_of(a, b);
  if (s.segment == kNone) return s;
  s.a = table.input(s.segment).a;
  s.b = table.input(s.segment).b;
  s.pieces = table.pieces_at(s.segment, position);
  const auto& vertices = log.vertices();
  const auto at = [&](VertexId v) { return v < vertices.size() ? vertices[v].point : Point{}; };
  for (const SegmentTable::Change& c : table.changes(s.segment)) {
    if (s.events.empty() || s.events.back() != c.event) s.events.push_back(c.event);
    if (c.kind != SegmentTable::Change::Kind::split) continue;
    const Point p = at(c.vertex), pa = at(c.a), pb = at(c.b);
    // The same test as the step's caption: the exact midpoint, or not.
    const bool midpoint = p == Point{0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)};
    s.splits.push_back({c.event, c.vertex, c.a, c.b, c.reason, midpoint});
  }
  return s;
}

const char* split_place(const SegmentStory::Split& split) {
  using replay::SplitReason;
  if (split.reason == SplitReason::crossing) return "crossing";
  if (split.reason == SplitReason::insert) return "insert";
  if (split.midpoint) return "midpoint";
  return split.reason == SplitReason::bisection ? "bisection" : "shell";
}

SelectionStory selection_story(const replay::LogReader& log, const ElementIndex& index, const Picked& picked,
                               const std::array<VertexId, 3>& face, std::uint64_t position) {
  SelectionStory story;
  if (!index.ready()) return story;
  switch (picked.kind) {
    case Picked::Kind::vertex: {
      const auto events = index.events_of_vertex(picked.index);
      story.events.assign(events.begin(), events.end());
      break;
    }
    case Picked::Kind::triangle:
      story.triangle = triangle_story(log, index, face, position);
      if (story.triangle.created != kNoEvent) story.events.push_back(story.triangle.created);
      story.events.insert(story.events.end(), story.triangle.reflagged.begin(), story.triangle.reflagged.end());
      if (story.triangle.removed != kNoEvent) story.events.push_back(story.triangle.removed);
      break;
    case Picked::Kind::segment:
      story.segment = segment_story(log, index, picked.index, picked.other, position);
      story.events = story.segment.events;
      break;
    case Picked::Kind::none: break;
  }
  for (const std::uint64_t e : story.events) {
    const std::uint64_t k = log.step_of_event(e);
    if (k < log.step_count() && (story.steps.empty() || story.steps.back() != k + 1)) story.steps.push_back(k + 1);
  }
  return story;
}

}  // namespace meshstep::viewer
