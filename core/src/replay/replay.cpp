// Moving through a replay log (see replay.hpp).
#include "meshstep/replay/replay.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <numeric>

#include "meshstep/error.hpp"
#include "meshstep/replay/mesh_hash.hpp"
#include "replay/output_order.hpp"

namespace meshstep::replay {
namespace {

// Restoring a keyframe copies every slot; applying an event writes about three. Costs
// in units of one event applied.
double keyframe_cost(const KeyframeInfo& k) { return static_cast<double>(k.slot_count) / 8.0; }

std::string describe(const FaceRecord& r) {
  if (r.dead()) return "nothing";
  const auto id = [](VertexId v) { return v == kInfiniteVertex ? std::string("inf") : std::to_string(v); };
  return "(" + id(r.v[0]) + " " + id(r.v[1]) + " " + id(r.v[2]) + ")";
}

}  // namespace

std::uint64_t Replay::completed_steps() const { return log_->completed_steps_at(position_); }

void Replay::write(const SlotWrite& w, bool forward, std::uint64_t event) {
  const FaceRecord& expected = forward ? w.before : w.after;
  const FaceRecord& next = forward ? w.after : w.before;
  if (w.slot >= slots_.size()) slots_.resize(std::size_t{w.slot} + 1);
  FaceRecord& slot = slots_[w.slot];
  if (slot != expected)
    throw InputError(log_->path(), 0,
                     "event " + std::to_string(event) + " expects face slot " + std::to_string(w.slot) +
                         " to hold " + describe(expected) + " but it holds " + describe(slot) +
                         " (the log is inconsistent)");
  if (track_hash_) hash_ += face_hash(next) - face_hash(slot);
  slot = next;
}

void Replay::forward_to(std::uint64_t target) {
  for (; position_ < target; ++position_)
    for (const SlotWrite& w : log_->writes(position_)) write(w, true, position_);
}

void Replay::backward_to(std::uint64_t target) {
  for (; position_ > target; --position_) {
    const auto writes = log_->writes(position_ - 1);
    for (auto it = writes.rbegin(); it != writes.rend(); ++it) write(*it, false, position_ - 1);
  }
}

void Replay::restore(const std::vector<FaceRecord>& keyframe, std::uint64_t event) {
  slots_ = keyframe;
  if (track_hash_) hash_ = mesh_hash(slots_);
  position_ = event;
}

std::uint64_t Replay::hash() const { return track_hash_ ? hash_ : mesh_hash(slots_); }

std::size_t Replay::live_faces() const {
  return static_cast<std::size_t>(
      std::count_if(slots_.begin(), slots_.end(), [](const FaceRecord& r) { return !r.dead(); }));
}

void Replay::seek_event(std::uint64_t target) {
  target = std::min(target, log_->event_count());
  const auto distance = [](std::uint64_t a, std::uint64_t b) {
    return static_cast<double>(a > b ? a - b : b - a);
  };
  // Candidates: stay, start over from the empty mesh, or the keyframes on either side.
  double best = distance(position_, target);
  int choice = 0;  // 0 current, 1 empty mesh, 2 keyframe `pick`
  std::size_t pick = 0;
  if (static_cast<double>(target) < best) {
    best = static_cast<double>(target);
    choice = 1;
  }
  const auto& keyframes = log_->keyframes();
  const auto after = std::lower_bound(keyframes.begin(), keyframes.end(), target,
                                      [](const KeyframeInfo& k, std::uint64_t e) { return k.event < e; });
  for (auto it : {after, after == keyframes.begin() ? keyframes.end() : after - 1}) {
    if (it == keyframes.end()) continue;
    const double cost = keyframe_cost(*it) + distance(it->event, target);
    if (cost < best) {
      best = cost;
      choice = 2;
      pick = static_cast<std::size_t>(it - keyframes.begin());
    }
  }
  if (choice == 1) {
    slots_.clear();
    hash_ = 0;
    position_ = 0;
  } else if (choice == 2) {
    restore(log_->keyframe(pick), keyframes[pick].event);
  }
  if (target > position_) forward_to(target);
  else backward_to(target);
}

void Replay::walk_to(std::uint64_t target) {
  target = std::min(target, log_->event_count());
  if (target > position_) forward_to(target);
  else backward_to(target);
}

void Replay::seek_step(std::uint64_t steps) {
  seek_event(log_->step_start(std::min(steps, log_->step_count())));
}

bool Replay::next_event() {
  if (position_ >= log_->event_count()) return false;
  forward_to(position_ + 1);
  return true;
}

bool Replay::prev_event() {
  if (position_ == 0) return false;
  backward_to(position_ - 1);
  return true;
}

bool Replay::next_step() {
  if (position_ >= log_->event_count()) return false;
  seek_event(log_->next_step_boundary(position_));
  return true;
}

bool Replay::prev_step() {
  if (position_ == 0) return false;
  seek_event(log_->prev_step_boundary(position_));
  return true;
}

std::optional<Event> Replay::last_event() const {
  if (position_ == 0) return std::nullopt;
  return log_->event(position_ - 1);
}

TriMesh Replay::mesh() const { return build_mesh(nullptr, nullptr); }

TriMesh Replay::build_mesh(std::vector<std::uint32_t>* output_index, std::vector<std::uint8_t>* constrained_bits) const {
  const std::vector<VertexInfo>& vertices = log_->vertices();
  const std::vector<VertexId> present = detail::output_order(vertices, position_);
  std::vector<std::uint32_t> index(vertices.size(), kNoIndex);
  TriMesh out;
  // The header's parameters say how many vertices the input had and how it numbers them.
  const std::uint64_t input_count = log_->run().input_vertices;
  out.first_index = log_->run().first_index;
  for (const VertexId v : present) {
    index[v] = static_cast<std::uint32_t>(out.points.size());
    out.points.push_back(vertices[v].point);
    if (vertices[v].input_index < input_count) ++out.input_vertex_count;
  }
  const auto map = [&](VertexId v) {
    if (v >= index.size() || index[v] == kNoIndex)
      throw InputError(log_->path(), 0, "a face names vertex " + std::to_string(v) +
                                            " before the log introduces it (the log is inconsistent)");
    return index[v];
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, bool> constrained;
  for (const FaceRecord& r : slots_) {
    if (r.dead() || r.ghost()) continue;
    out.triangles.push_back({map(r.v[0]), map(r.v[1]), map(r.v[2])});
    if (constrained_bits) constrained_bits->push_back(r.constrained);
    for (int i = 0; i < 3; ++i)
      if (r.constrained >> i & 1) {
        const std::uint32_t a = out.triangles.back()[i], b = out.triangles.back()[(i + 1) % 3];
        constrained[{std::min(a, b), std::max(a, b)}] = true;
      }
  }
  for (const auto& [edge, on] : constrained) out.segments.push_back({edge.first, edge.second, 1});
  if (output_index) *output_index = std::move(index);
  return out;
}

}  // namespace meshstep::replay
