// The event model of the step engine: what a recorded run is made of.
//
// An algorithm's run is a sequence of events. Events that change the mesh carry the mesh
// delta: for every face slot they touch, the triangle the slot held before and the one it
// holds after (SlotWrite), so a replay can apply an event forward or undo it exactly. The
// other events say what the algorithm looked at and decided (where a point was located,
// which point was selected and why, a Lepp path, an encroached segment, a criterion test).
//
// Events group into steps: a step_begin event opens a step, and the step runs until the
// next step_begin. One step is one top-level operation (one vertex inserted with all its
// flips, one segment recovered, one bisection with its propagation). Events before the
// first step_begin (a phase_begin, say) form a preamble that belongs to no step.
//
// Every event type has a fixed schema (eventSchema): how many ids it has and what they
// name, and which of the optional parts (point, value, list, points, mesh delta) it uses.
// The file codec and the text/JSON dumps are driven by the schema, so adding a type is one
// table row and one enumerator.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "meshstep/geometry/point.hpp"
#include "meshstep/mesh/handles.hpp"

namespace meshstep::replay {

enum class EventType : std::uint8_t {
  step_begin,      // code: StepKind; ids: subject vertices (or kNone)
  phase_begin,     // code: Phase
  phase_end,       // code: Phase
  locate,          // code: LocateResult; ids: vertex located, faces visited, face slot found;
                   // list: the walk's faces, 3 ids each (format 3; see Recorder::locate)
  vertex,          // a vertex enters the run; ids: vertex, its index in the input; point
  duplicate,       // a vertex at the same place as an earlier one; ids: vertex, earlier, input index
  init,            // the first triangle (and its ghost faces); ids: its three vertices
  split_face,      // a vertex inserted inside a face; ids: vertex
  split_edge,      // code: SplitReason; ids: vertex, edge endpoints
  flip,            // code: FlipReason; ids: a, b (edge before), c, d (edge after; c left of a->b)
  cavity,          // Bowyer-Watson: the faces in conflict replaced by a fan; ids: vertex
  constrain,       // code: 1 set, 0 cleared; ids: edge endpoints, segment marker
  remove_face,     // code: RemoveReason
  remove_vertex,   // a vertex of degree 3 removed: its three faces become one; ids: vertex
  point_selected,  // code: strategy; ids: the bad triangle; point: chosen; list/points: alternatives
  lepp_path,       // ids: terminal edge, number of terminal triangles; list: triangles (3 ids each)
  encroached,      // ids: segment endpoints, encroaching vertex (or kNone); point: encroaching point
  criterion_test,  // code: Criterion | kCriterionPassed; ids: triangle; value: what was measured
  elevation,       // a vertex's height (terrains, format 4); ids: vertex; value: the height
  count_
};
inline constexpr std::size_t kEventTypeCount = static_cast<std::size_t>(EventType::count_);

enum class StepKind : std::uint8_t {
  start,            // the first triangle
  insert_vertex,    // ids: vertex
  recover_segment,  // ids: segment endpoints
  carve,            // removal of holes, ghost faces and the outside
  refine,           // one refinement step (issue: refinement framework)
  split_segment,
  bisect,
  remove_vertex,
  flip_3d,          // terrains: an edge flipped for the 3D angles of its two triangles; ids: its ends
  count_
};

enum class Phase : std::uint8_t { insert_vertices, recover_segments, carve, refine, improve, count_ };
enum class LocateResult : std::uint8_t { in_face, on_edge, on_vertex, count_ };
enum class SplitReason : std::uint8_t { insert, crossing, encroached, bisection, count_ };
// vertex_removal: a flip that lowers a vertex's degree on the way to removing it.
// angles_3d: an edge of a terrain or a surface flipped to raise the smallest 3D angle of its
// two triangles. load: a surface put into the mesh structure (surface_loader.hpp) flips
// its scaffold to join two sides of a triangle at once.
enum class FlipReason : std::uint8_t { delaunay, segment_recovery, vertex_removal, angles_3d, load, count_ };
enum class RemoveReason : std::uint8_t { ghost, hole, outside, count_ };

// The bound a criterion_test weighed a triangle against, and what its value measured, in
// the units of the bound as the log's header gives it (coordinates as the log stores them).
enum class Criterion : std::uint8_t {
  min_angle,       // the smallest angle, in degrees (min_angle)
  max_angle,       // the largest angle, in degrees (max_angle)
  max_aspect,      // longest edge over shortest altitude (max_aspect)
  max_area,        // the area (max_area)
  local_max_area,  // the area, against the bound where the triangle lies: its region's
                   // (regional attributes) or the old mesh's triangle's (re-refinement)
  size,            // the longest edge, against the size function at the centroid (size)
  vertical_error,  // terrains: the largest vertical error of the samples the triangle covers,
                   // in height units (max_error; format 4)
  count_
};
// Set in a criterion_test's code when the triangle met the bound.
inline constexpr std::uint8_t kCriterionPassed = 0x80;
// How a criterion's measured value scales with lengths: 0 for angles and ratios, 1 for
// lengths, 2 for areas (the recorder unscales values with the coordinates).
constexpr int length_power(Criterion c) {
  switch (c) {
    case Criterion::max_area:
    case Criterion::local_max_area: return 2;
    case Criterion::size: return 1;
    default: return 0;
  }
}

// A terrain run's point_selected code: which grid sample goes in next. Codes from 16 on,
// apart from the refinement's (meshstep::Selection) that share the event.
enum class SampleChoice : std::uint8_t {
  worst_sample = 16,  // greedy: the sample of largest error (the bad triangle's worst)
  terminal_worst,     // Lepp-surface: the worst sample of a terminal triangle that misses the bound
  terminal_point,     // Lepp-surface: the sample nearest the terminal point (alternatives: the point)
  own_worst,          // Lepp-surface: the bad triangle's own worst, when the terminal point's
                      // sample was taken already, has no data or is on a tile's border
};
inline constexpr std::uint8_t kFirstSampleChoice = 16;
const char* name(SampleChoice choice);

// What one face slot holds: the triangle (counterclockwise, as the data structure stores
// it) and a constraint flag per edge (bit i: the edge from v[i] to v[(i+1)%3]). A dead slot
// holds no triangle.
struct FaceRecord {
  std::array<VertexId, 3> v{kNone, kNone, kNone};
  std::uint8_t constrained = 0;

  bool dead() const { return v[0] == kNone; }
  bool ghost() const { return v[0] == kInfiniteVertex || v[1] == kInfiniteVertex || v[2] == kInfiniteVertex; }
  friend bool operator==(const FaceRecord&, const FaceRecord&) = default;
};

struct SlotWrite {
  FaceId slot;
  FaceRecord before, after;
};

// One event, as the reader decodes it. The spans point into the reader's decoded block and
// stay valid while the block is cached (copy what you keep).
struct Event {
  EventType type = EventType::phase_begin;
  std::uint8_t code = 0;
  std::array<std::uint32_t, 4> ids{kNone, kNone, kNone, kNone};
  Point point{0.0, 0.0};
  double value = 0.0;
  std::span<const std::uint32_t> list;
  std::span<const Point> points;
  std::span<const SlotWrite> writes;
};

// How each id of an event is encoded and shown.
enum class IdKind : std::uint8_t {
  vertex,  // a vertex id (kInfiniteVertex and kNone allowed)
  count,   // a plain unsigned number
  slot,    // a face slot
  input,   // an index in the input file's numbering
  marker,  // a segment marker: a signed number stored as unsigned (two's complement)
};

struct EventSchema {
  const char* name;
  std::uint8_t id_count;
  std::array<IdKind, 4> id_kinds;
  std::array<const char*, 4> id_names;
  bool has_point, has_value, has_list, has_points, has_writes;
  bool changes_mesh() const { return has_writes; }
};

namespace detail {
using K = IdKind;
inline constexpr K V = K::vertex;

// name, ids, id kinds, id names, point, value, list, points, writes
inline constexpr EventSchema kSchemas[kEventTypeCount] = {
    {"step_begin", 2, {V, V}, {"subject", "subject2"}, false, false, false, false, false},
    {"phase_begin", 0, {}, {}, false, false, false, false, false},
    {"phase_end", 0, {}, {}, false, false, false, false, false},
    {"locate", 3, {V, K::count, K::slot}, {"vertex", "visited", "face"}, false, false, true, false, false},
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
    {"elevation", 1, {V}, {"vertex"}, false, true, false, false, false},
};

}  // namespace detail

// The schema of a valid event type (decoders check the type first): inline, since the
// codec asks for every event.
inline const EventSchema& schema(EventType type) { return detail::kSchemas[static_cast<std::size_t>(type)]; }
const char* name(EventType type);
const char* name(StepKind kind);
const char* name(Phase phase);
const char* name(Criterion criterion);
// The name of an event's code for its type (a step kind, a phase, a reason...), or its number.
std::string code_name(EventType type, std::uint8_t code);

}  // namespace meshstep::replay
