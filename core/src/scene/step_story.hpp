// What the current step did, read from the log: the events a picture explains, gathered
// once (the reader's event spans die at the next read) and kept as plain values. The
// overlays and the caption are both drawn from it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/replay/event.hpp"
#include "meshstep/replay/replay.hpp"

namespace meshstep::scene::detail {

using replay::FaceRecord;
using Triple = std::array<VertexId, 3>;

struct StepStory {
  // Where the cursor is.
  std::uint64_t position = 0;
  std::uint64_t step_count = 0;
  bool in_step = false;    // false: at the start, or in the preamble before the first step
  std::uint64_t step = 0;  // 0-based index of the step of the last applied event
  replay::StepKind kind = replay::StepKind::start;
  std::array<VertexId, 2> subject{kNone, kNone};
  // The events explained: [first_event, position). Usually from the step's step_begin; see
  // read_step for the Lepp path that opens the next step's explanation (next_triangle).
  std::uint64_t first_event = 0;
  bool next_triangle = false;

  struct Located {
    VertexId vertex = kNone;
    replay::LocateResult result = replay::LocateResult::in_face;
    FaceRecord face;           // the face found, as it was when found
    std::vector<Triple> walk;  // the faces visited, in order (empty in logs without it)
  };
  std::optional<Located> located;

  struct Selected {
    std::uint8_t strategy = 0;  // a meshstep::Selection
    Triple bad{};               // the bad triangle's vertices
    Point chosen;
    std::vector<Point> alternatives;
    bool chose_circumcenter = true;  // else the strategy's own point (off-center, Lepp point...)
  };
  std::optional<Selected> selected;

  struct Lepp {
    std::vector<Triple> path;       // from the bad triangle to a terminal triangle
    VertexId a = kNone, b = kNone;  // the terminal edge
    std::uint32_t terminal_triangles = 0;
  };
  std::optional<Lepp> lepp;

  struct Cavity {
    VertexId vertex = kNone;
    std::vector<FaceRecord> removed, fan;
  };
  std::vector<Cavity> cavities;

  struct Flip {
    std::array<VertexId, 4> v{};  // a, b: edge before; c, d: edge after
    replay::FlipReason reason = replay::FlipReason::delaunay;
  };
  std::vector<Flip> flips;

  struct Encroachment {
    VertexId a = kNone, b = kNone;  // the subsegment
    VertexId by = kNone;            // the encroaching vertex, or kNone for a rejected point
    Point point;                    // the encroaching point
    VertexId split = kNone;         // the vertex that split the subsegment, once it has
  };
  std::optional<Encroachment> encroached;

  struct Split {
    replay::SplitReason reason = replay::SplitReason::insert;
    VertexId vertex = kNone, a = kNone, b = kNone;
    std::vector<FaceRecord> made;  // the faces round the new vertex
  };
  std::vector<Split> splits;

  std::vector<VertexId> inserted;  // vertices the step put into the mesh, in order
  VertexId duplicate = kNone, duplicate_of = kNone;

  struct Removal {
    VertexId vertex = kNone;
    std::vector<FaceRecord> star;  // its faces when the step began
  };
  std::optional<Removal> removed;

  struct Criterion {
    std::uint8_t criterion = 0;  // a replay::Criterion
    Triple triangle{};
    double value = 0.0;
  };
  std::vector<Criterion> failed;  // passed tests are not kept

  std::size_t constrained = 0;                 // constrain events that set a segment
  std::array<std::size_t, 3> faces_removed{};  // by RemoveReason
  bool first_triangle = false;                 // init
  Triple init{};

  // The face slots the explained events wrote (sorted, unique).
  std::vector<FaceId> written;
};

// The story of the cursor's current step up to the cursor.
//
// A Lepp path is recorded when the refiner chooses the next bad triangle's point, which is
// before that triangle's step begins: at the tail of the step before. So a Lepp path that
// follows the mesh changes of its step opens the explanation of the next triangle (the
// step's finished work is no longer shown), and a step explained from its step_begin also
// shows the Lepp path its predecessor ended with.
StepStory read_step(const replay::Replay& cursor);

// What the chosen point is, in words: "circumcenter", "off-center", "terminal-edge
// midpoint"... A strategy that fell back on the circumcenter (the off-center farther than
// it, a Lepp point too close to a vertex) records no alternative: that is named too.
std::string chosen_point_name(const StepStory::Selected& selected, const std::optional<StepStory::Lepp>& lepp);

// The angle apb from which a point p encroached on a segment ab in the log's run: 90 for
// the diametral circle, the lens's angle otherwise (its `lens_angle` parameter; 120 in logs
// from before the lens followed the bound).
double encroachment_angle(const replay::LogReader& log);

// A failed criterion test as people read it: the measured value against the run's bound
// from the log's parameters ("22.4° < 30°", "area 0.71 > 0.5"); a bound that varies from
// place to place (regional, old mesh) is not among them and is named in words.
std::string criterion_text(const StepStory::Criterion& failed, const replay::LogReader& log);

}  // namespace meshstep::scene::detail
