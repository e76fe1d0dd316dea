// A cursor over a replay log: the mesh at any moment of the run, reachable forward and
// backward.
//
// The position is the number of events applied. Moving forward applies each event's face
// writes; moving backward undoes them (each write holds what the slot held before), and
// both check that the slot holds what the log says it held, so a log that does not
// describe one consistent run is reported, not replayed into a wrong mesh. A seek starts
// from whichever is cheapest: the current position, the empty mesh, or the nearest
// keyframe before or after the target.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/replay/event.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay {

class Replay {
 public:
  // track_hash: keep the mesh hash current as events apply (about a third of the cost of
  // moving); otherwise hash() computes it when asked.
  explicit Replay(const LogReader& log, bool track_hash = false) : log_(&log), track_hash_(track_hash) {}

  const LogReader& log() const { return *log_; }
  std::uint64_t position() const { return position_; }
  // Steps completed at this position: those whose every event has been applied.
  std::uint64_t completed_steps() const;

  // All throw InputError when the log turns out to be inconsistent.
  void seek_event(std::uint64_t position);      // clamped to [0, event_count]
  void seek_step(std::uint64_t steps);          // the mesh after `steps` steps (clamped)
  // Moves by applying or undoing every event on the way, never jumping to a keyframe (for
  // verification: every write gets checked).
  void walk_to(std::uint64_t position);
  bool next_event();                            // false at the end
  bool prev_event();                            // false at the start
  bool next_step();                             // to the next step boundary
  bool prev_step();                             // to the previous step boundary

  // The event applied last (the one at position() - 1), if any. Its spans stay valid until
  // the next call on the cursor or the reader.
  std::optional<Event> last_event() const;

  // Every face slot as the run left it at this position (dead slots included; slots past
  // the end are dead).
  const std::vector<FaceRecord>& slots() const { return slots_; }
  std::uint64_t hash() const;
  std::size_t live_faces() const;

  // The mesh at this position as plain arrays: the vertices introduced so far (in the
  // input's order, then Steiner vertices), the live faces that are not ghost faces, and
  // the constrained edges as segments.
  TriMesh mesh() const;

  // The mesh at this position as the run's own output writes it: mesh(), plus what the
  // output carries beyond the faces. The segments keep their markers (the log's constrain
  // events, passed on to the pieces of a split), and the edges that bound one triangle
  // without being constrained are segments with marker 1. The triangles get their
  // regional attributes and area bounds (the regions' flood), and the vertices the input's
  // markers and attributes (a Steiner vertex takes the marker of the first segment, in
  // output order, that ends at it). At the end of a run: the run's own files.
  // Decodes every event before the position: for writing a moment, not for every step.
  TriMesh output_mesh() const;

 private:
  // mesh(), and optionally each vertex's index in it (kNoIndex: absent) and each
  // triangle's constrained bits (FaceRecord::constrained).
  TriMesh build_mesh(std::vector<std::uint32_t>* output_index, std::vector<std::uint8_t>* constrained_bits) const;
  void restore(const std::vector<FaceRecord>& keyframe, std::uint64_t event);
  void forward_to(std::uint64_t target);
  void backward_to(std::uint64_t target);
  void write(const SlotWrite& w, bool forward, std::uint64_t event);

  const LogReader* log_;
  std::uint64_t position_ = 0;
  std::vector<FaceRecord> slots_;
  bool track_hash_;
  std::uint64_t hash_ = 0;  // current when track_hash_
};

}  // namespace meshstep::replay
