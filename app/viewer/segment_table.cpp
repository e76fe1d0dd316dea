#include "segment_table.hpp"

#include <algorithm>
#include <numeric>

namespace meshstep::viewer {

namespace {

std::uint64_t edge_key(VertexId a, VertexId b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

// Was the edge a-b constrained before this event? Its faces' flags say (bit i: the edge
// from v[i] to v[i + 1]); a face the event rewrites held it before if it had the edge.
bool was_constrained(std::span<const replay::SlotWrite> writes, VertexId a, VertexId b) {
  for (const replay::SlotWrite& w : writes) {
    const auto& v = w.before.v;
    if (w.before.dead()) continue;
    for (int i = 0; i < 3; ++i)
      if (edge_key(v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>((i + 1) % 3)]) == edge_key(a, b) &&
          (w.before.constrained >> i & 1))
        return true;
  }
  return false;
}

}  // namespace

std::uint32_t SegmentTable::input_segment(VertexId a, VertexId b, int marker) {
  const auto [it, fresh] = by_ends_.try_emplace(edge_key(a, b), static_cast<std::uint32_t>(inputs_.size()));
  if (fresh) inputs_.push_back({a, b, marker});
  return it->second;
}

std::uint32_t SegmentTable::segment_for_new_piece(VertexId a, VertexId b, int marker) {
  for (const Cleared& c : cleared_in_step_)
    if (a == c.a || a == c.b || b == c.a || b == c.b) return c.segment;
  if (step_kind_ == replay::StepKind::recover_segment && subject_[0] != kNone && subject_[1] != kNone)
    return input_segment(subject_[0], subject_[1], marker);
  return input_segment(a, b, marker);
}

void SegmentTable::add(const replay::Event& ev, std::uint32_t e) {
  using replay::EventType;
  switch (ev.type) {
    case EventType::step_begin:
      step_kind_ = static_cast<replay::StepKind>(ev.code);
      subject_[0] = ev.ids[0];
      subject_[1] = ev.ids[1];
      cleared_in_step_.clear();
      break;
    case EventType::constrain: {
      const VertexId a = ev.ids[0], b = ev.ids[1];
      const auto found = piece_segment_.find(edge_key(a, b));
      if (ev.code == 0) {
        if (found == piece_segment_.end()) break;
        cleared_in_step_.push_back({a, b, found->second});
        record(found->second, {e, Change::Kind::cleared, {}, a, b, kNone});
        break;
      }
      const std::uint32_t s = found != piece_segment_.end()
                                  ? found->second
                                  : segment_for_new_piece(a, b, static_cast<int>(ev.ids[2]));
      piece_segment_[edge_key(a, b)] = s;
      record(s, {e, Change::Kind::constrained, {}, a, b, kNone});
      break;
    }
    case EventType::split_edge: {
      const VertexId v = ev.ids[0], a = ev.ids[1], b = ev.ids[2];
      const auto found = piece_segment_.find(edge_key(a, b));
      if (found == piece_segment_.end() || !was_constrained(ev.writes, a, b)) break;
      const std::uint32_t s = found->second;
      record(s, {e, Change::Kind::split, static_cast<replay::SplitReason>(ev.code), a, b, v});
      piece_segment_[edge_key(a, v)] = s;
      piece_segment_[edge_key(v, b)] = s;
      break;
    }
    default: break;
  }
}

void SegmentTable::finish() {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> pieces(piece_segment_.begin(), piece_segment_.end());
  std::sort(pieces.begin(), pieces.end());
  keys_.resize(pieces.size());
  key_segment_.resize(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) std::tie(keys_[i], key_segment_[i]) = pieces[i];
  changes_ = Rows<Change>::from_pairs(pending_, inputs_.size());
  piece_segment_ = {};
  by_ends_ = {};
  pending_ = {};
  cleared_in_step_ = {};
}

std::uint32_t SegmentTable::segment_of(VertexId a, VertexId b) const {
  const std::uint64_t key = edge_key(a, b);
  const auto it = std::lower_bound(keys_.begin(), keys_.end(), key);
  return it != keys_.end() && *it == key ? key_segment_[static_cast<std::size_t>(it - keys_.begin())] : kNone;
}

std::vector<std::pair<VertexId, VertexId>> SegmentTable::pieces_at(std::uint32_t s, std::uint64_t position) const {
  std::vector<std::pair<VertexId, VertexId>> chain;
  if (s >= inputs_.size()) return chain;
  // The pieces by key: a segment split thousands of times stays linear.
  std::unordered_map<std::uint64_t, std::pair<VertexId, VertexId>> pieces;
  for (const Change& c : changes(s)) {
    if (c.event >= position) break;
    pieces.erase(edge_key(c.a, c.b));
    if (c.kind == Change::Kind::constrained) pieces[edge_key(c.a, c.b)] = {c.a, c.b};
    if (c.kind == Change::Kind::split) {
      pieces[edge_key(c.a, c.vertex)] = {c.a, c.vertex};
      pieces[edge_key(c.vertex, c.b)] = {c.vertex, c.b};
    }
  }
  // Chained from the input segment's first endpoint, each piece turned to follow on.
  std::unordered_multimap<VertexId, std::uint64_t> at_vertex;
  for (const auto& [key, p] : pieces) {
    at_vertex.emplace(p.first, key);
    at_vertex.emplace(p.second, key);
  }
  for (VertexId at = inputs_[s].a;;) {
    auto [first, last] = at_vertex.equal_range(at);
    while (first != last && !pieces.contains(first->second)) ++first;
    if (first == last) break;
    const auto p = pieces.extract(first->second).mapped();
    chain.emplace_back(at, p.first == at ? p.second : p.first);
    at = chain.back().second;
  }
  // Pieces that do not follow on (none in a run the table followed right), in key order.
  std::vector<std::pair<std::uint64_t, std::pair<VertexId, VertexId>>> rest(pieces.begin(), pieces.end());
  std::sort(rest.begin(), rest.end());
  for (const auto& r : rest) chain.push_back(r.second);
  return chain;
}

std::size_t SegmentTable::bytes() const {
  return keys_.size() * (sizeof(std::uint64_t) + sizeof(std::uint32_t)) + inputs_.size() * sizeof(Input) +
         changes_.bytes();
}

}  // namespace meshstep::viewer
