#include "meshstep/scene/pseudocode.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "meshstep/refine/registry.hpp"
#include "meshstep/replay/operations.hpp"

namespace meshstep::scene {

namespace {

using replay::Event;
using replay::EventType;
using replay::FlipReason;
using replay::Phase;
using replay::StepKind;

// The roles a line plays, named so that the texts and the event mapping below stay in step:
// a program marks the lines of the roles it has, and an event asks for a role.
enum class At : std::uint8_t {
  start,            // the first line: the mesh the program starts from
  each,             // the loop over the points, segments or vertices
  locate,           // locate the triangle containing the point
  duplicate,        // the point is a vertex already
  insert,           // split the triangle (or the edge's two) at the point
  cavity,           // Bowyer-Watson: remove the conflicting triangles, fan the hole
  legalize,         // while an edge fails the in-circle test: flip it
  present,          // segment recovery: the segment is an edge already
  split_at,         // segment recovery: a vertex on the segment or a crossing segment
  crossing_flip,    // segment recovery: flip an edge the segment crosses
  constrain,        // segment recovery: mark the recovered segment
  carve,            // remove holes, the outside and the ghost triangles
  encroached,       // refinement: a subsegment encroached by a vertex
  split,            // refinement: split it
  bad,              // refinement: a bad (or too large) triangle
  still_there,      // Lepp: the same triangle, still in the mesh
  lepp,             // Lepp: the path to the terminal edge
  select,           // the new point
  rejected,         // the new point encroaches a subsegment
  split_instead,    // which is split instead
  bisect,           // Lepp bisection: split the terminal edge
  removal_accept,   // vertex removal: the plan is accepted
  removal_flip,     // vertex removal: flip a spoke away
  removal_merge,    // vertex removal: the vertex of degree 3 goes
  terminal_worst,   // Lepp-surface: a terminal triangle's worst sample
  terminal_point,   // Lepp-surface: the sample nearest the terminal point
  height,           // terrain: the new vertex takes its sample's height
  flip_3d,          // terrain: an edge flipped for the smallest 3D angle
  count_
};

struct Span {
  int line = -1;
  int count = 0;
};

struct Entry {
  PseudoCode code;
  std::array<Span, static_cast<std::size_t>(At::count_)> spans{};

  Span span(At at) const { return spans[static_cast<std::size_t>(at)]; }
};

class Builder {
 public:
  Builder(std::string title, std::string reference) {
    entry_.code.title = std::move(title);
    entry_.code.reference = std::move(reference);
  }
  // Lines with no role.
  Builder& add(std::initializer_list<const char*> lines) {
    for (const char* l : lines) entry_.code.lines.emplace_back(l);
    return *this;
  }
  // Lines that carry out `at` (highlighted together).
  Builder& add(At at, std::initializer_list<const char*> lines) {
    entry_.spans[static_cast<std::size_t>(at)] = {static_cast<int>(entry_.code.lines.size()),
                                                  static_cast<int>(lines.size())};
    return add(lines);
  }
  Builder& add(At at, std::span<const std::string_view> lines) {
    entry_.spans[static_cast<std::size_t>(at)] = {static_cast<int>(entry_.code.lines.size()),
                                                  static_cast<int>(lines.size())};
    for (const std::string_view l : lines) entry_.code.lines.emplace_back(l);
    return *this;
  }
  // One more role for the last line added.
  Builder& also(At at) {
    entry_.spans[static_cast<std::size_t>(at)] = {static_cast<int>(entry_.code.lines.size()) - 1, 1};
    return *this;
  }
  Entry take() { return std::move(entry_); }

 private:
  Entry entry_;
};

// --- The texts ------------------------------------------------------------------------------

constexpr const char* kFirstTriangle = "T ← a first triangle of three points, closed by ghost triangles";
constexpr const char* kEachPoint = "for each other point p (in a spatially coherent order):";
constexpr const char* kLocatePoint = "    locate the triangle containing p, walking from the last one";
constexpr const char* kDuplicate = "    if p is a vertex already: skip it (a duplicate)";

Entry lawson() {
  return Builder("Delaunay insertion by flips (Lawson 1977)",
                 "C. L. Lawson, \"Software for C¹ surface interpolation\", Mathematical Software III, "
                 "Academic Press, 1977")
      .add(At::start, {kFirstTriangle})
      .add(At::each, {kEachPoint})
      .add(At::locate, {kLocatePoint})
      .add(At::duplicate, {kDuplicate})
      .add(At::insert, {"    split that triangle in 3 (p on an edge: its two triangles in 4)"})
      .add({"    suspect ← the edges opposite p"})
      .add(At::legalize, {"    while a suspect edge fails the in-circle test: flip it"})
      .add({"        the two edges beyond the flipped one become suspect"})
      .take();
}

Entry bowyer_watson() {
  return Builder("Delaunay insertion by cavities (Bowyer 1981, Watson 1981)",
                 "A. Bowyer, \"Computing Dirichlet tessellations\"; D. F. Watson, \"Computing the "
                 "n-dimensional Delaunay tessellation...\"; The Computer Journal 24(2), 1981")
      .add(At::start, {kFirstTriangle})
      .add(At::each, {kEachPoint})
      .add(At::locate, {kLocatePoint})
      .add(At::duplicate, {kDuplicate})
      .add(At::cavity, {"    remove every triangle whose circumcircle contains p",
                        "        (the cavity, grown from the located triangle edge by edge)",
                        "    connect p to every edge of the cavity's boundary"})
      .add({"    // the cavity is star-shaped from p: the new triangles are Delaunay"})
      .take();
}

Entry segment_recovery() {
  return Builder("Constrained Delaunay: segment recovery by flips (Sloan 1993)",
                 "S. W. Sloan, \"A fast algorithm for generating constrained Delaunay triangulations\", "
                 "Computers & Structures 47(3), 1993")
      .add(At::each, {"for each segment ab of the input:"})
      .also(At::start)
      .add(At::present, {"    if ab is an edge already: mark it constrained, next segment"})
      .add({"    walk from a to b, listing the edges that ab crosses"})
      .add(At::split_at, {"    a vertex on ab, or a segment crossing it: split ab there"})
      .add({"    while an edge e still crosses ab:"})
      .add(At::crossing_flip, {"        if e's quadrilateral is convex: flip e (else come back to it)"})
      .add({"        if the new edge crosses ab too: list it again"})
      .add(At::constrain, {"    mark ab constrained"})
      .add(At::legalize, {"    while a new edge fails the in-circle test: flip it (not a segment)"})
      .add(At::carve, {"remove the triangles reachable from a hole, or from outside,",
                       "    without crossing a segment, and the ghost triangles"})
      .take();
}

constexpr const char* kCdt = "T ← constrained Delaunay triangulation of the input, holes carved";

// The head of every Delaunay refinement program: the mesh, and Ruppert's first loop.
void refinement_head(Builder& b) {
  b.add(At::start, {kCdt})
      .add(At::encroached, {"while a subsegment s is encroached (a vertex in its diametral lens or circle):"})
      .add(At::split, {"    split s: midpoint, deleting free vertices in its circle; corner: shell"});
}

// The tail: the new point (c, or p in a Lepp program's inner loop) rejected or inserted, by
// flips or by a cavity.
void refinement_tail(Builder& b, Insertion insertion, bool lepp) {
  if (lepp) {
    b.add(At::rejected, {"        if p encroaches a subsegment s, or a segment blocks the walk to p:"})
        .add(At::split_instead, {"            split s instead (as above); t stays in the queue"})
        .add(At::locate, {"        else: locate the triangle containing p, walking from e"});
    if (insertion == Insertion::flips) {
      b.add(At::insert, {"            split it in 3 (p on an edge: its two triangles in 4)"})
          .add(At::legalize, {"        after each new vertex: while an edge fails the in-circle test: flip it"});
    } else {
      b.add(At::cavity, {"            remove every triangle whose circumcircle contains p",
                         "            connect p to every edge of the cavity's boundary"})
          .add(At::legalize, {"        after a segment split: while an edge fails the in-circle test: flip it"});
    }
    return;
  }
  b.add(At::rejected, {"    if c encroaches a subsegment s, or a segment blocks the walk to c:"})
      .add(At::split_instead, {"        split s instead (as above); t stays in the queue"})
      .add(At::locate, {"    else: locate the triangle containing c, walking from t"});
  if (insertion == Insertion::flips) {
    b.add(At::insert, {"        split it in 3 (c on an edge: its two triangles in 4)"})
        .add(At::legalize, {"    after each new vertex: while an edge fails the in-circle test: flip it"});
  } else {
    b.add(At::cavity, {"        remove every triangle whose circumcircle contains c",
                       "        connect c to every edge of the cavity's boundary"})
        .add(At::legalize, {"    after a segment split: while an edge fails the in-circle test: flip it"});
  }
}

constexpr const char* kBadLoop = "while a bad triangle t remains (a bound fails; shortest edge first):";

void lepp_head(Builder& b, const char* loop, const char* stop) {
  b.add(At::bad, {loop})
      .add(At::still_there, {"    while t is still in the mesh:"})
      .add(At::lepp, {"        follow Lepp(t): step across longest edges while they grow,", stop});
}

// A point selection's program: its record gives the title, the papers and the lines that
// choose the point; the loop round them is Ruppert's, or Rivara's Lepp loop.
Entry delaunay_refinement(const SelectionProgram& program, Insertion insertion) {
  Builder b(std::string(program.title), std::string(program.reference));
  refinement_head(b);
  if (program.lepp)
    lepp_head(b, kBadLoop, "            to the terminal edge e (longest of both its triangles, or a segment)");
  else
    b.add(At::bad, {kBadLoop});
  b.add(At::select, program.choose_point);
  refinement_tail(b, insertion, program.lepp);
  return b.take();
}

Entry lepp_bisection() {
  Builder b("Lepp longest-edge bisection (Rivara 1997)",
            "M.-C. Rivara, \"New longest-edge algorithms for the refinement and/or improvement of "
            "unstructured triangulations\", IJNME 40(18), 1997");
  b.add(At::start, {kCdt});
  lepp_head(b, "while a triangle t is too large (it fails the area or the size bound):",
            "            to the terminal edge e (longest of both its triangles, or boundary)");
  b.add(At::bisect, {"        bisect the terminal edge e: join its midpoint to the opposite",
                     "            vertex of each terminal triangle (two inside, one on the boundary)"})
      .add({"// no flips: T stays conforming but not Delaunay; segments split like edges;",
            "// no angle ever falls below half the smallest angle of the first T"});
  return b.take();
}

Entry vertex_removal() {
  return Builder("Improvement: removing Steiner vertices (Coll et al. 2008)",
                 "N. Coll et al., improvement + refinement, 2008; Delaunay deletion: O. Devillers, \"On "
                 "deletion in Delaunay triangulations\", IJCGA 12(3), 2002")
      .add(At::each, {"for each free Steiner vertex v (not on a segment), worst star first:"})
      .also(At::start)
      .add({"    P ← the polygon of v's neighbours",
            "    plan: fill P by clipping ears whose circumcircle holds no other vertex of P"})
      .add(At::removal_accept, {"    if the plan raises the smallest angle round v and keeps every bound:"})
      .add(At::removal_flip, {"        for each planned triangle but one: flip the spoke from v to its tip"})
      .add(At::removal_merge, {"        v now has degree 3: remove it, its three triangles become one"})
      .add({"        v's neighbours are candidates again"})
      .take();
}

// The terrains' programs share their start, their insertion and their improvement. A grid
// sample has no choice of place: where a Delaunay program would locate a point, these
// locate a sample, and where it is inserted the triangles round it are measured again.
constexpr const char* kGridCorners = "T ← the grid's four corners: two Delaunay triangles, at their heights";
constexpr const char* kWorstLoop = "while the worst triangle t misses the bound (its vertical error > E):";

void terrain_insertion(Builder& b) {
  b.add(At::insert, {"    locate s; split its triangle in 3 (s on an edge: its two in 4)"})
      .also(At::locate)
      .add(At::legalize, {"    while an edge fails the in-circle test: flip it"})
      .add(At::height, {"    s takes its height; the new triangles' worst samples are measured"});
}

void terrain_improvement(Builder& b, const char* when) {
  b.add(At::each, {when})
      .add(At::removal_accept, {"    if removing v keeps errors within E, not lowering its least 3D angle:"})
      .add(At::removal_flip, {"        flip v's spokes away to degree 3, then remove v: 3 triangles → 1"})
      .also(At::removal_merge)
      .add(At::flip_3d, {"then, with --flips: flip edges that raise the smallest 3D angle, within E"});
}

Entry lepp_surface() {
  Builder b("Lepp-surface terrain approximation (Coll, Guerrieri, Rivara, Sellarès 2008)",
            "N. Coll, M. Guerrieri, M.-C. Rivara, J. A. Sellarès, 17th International Meshing Roundtable (IMR), "
            "2008; here triangles are ranked by their exact vertical error, and a terminal triangle that misses "
            "the bound gives its worst sample (docs/terrain.md)");
  b.add(At::start, {kGridCorners})
      .add(At::bad, {kWorstLoop})
      .add(At::lepp, {"    follow Lepp(t): across longest edges (3D lengths) to the terminal edge e"})
      .add(At::terminal_worst, {"    if a terminal triangle misses the bound: s ← its worst sample"})
      .add(At::terminal_point, {"    else: s ← the sample nearest the terminal point, the terminal",
                                "        triangles' centroid (or e's midpoint, if the run asked for it);",
                                "        s a vertex already or without data: s ← t's own worst sample"});
  terrain_insertion(b);
  terrain_improvement(b, "improve: for each vertex v off the border, in up to three rounds:");
  return b.take();
}

Entry greedy_terrain() {
  Builder b("Greedy insertion (Garland, Heckbert 1995)",
            "M. Garland, P. S. Heckbert, \"Fast polygonal approximation of terrains and height fields\", "
            "CMU-CS-95-181, Carnegie Mellon University, 1995");
  b.add(At::start, {kGridCorners})
      .add(At::bad, {kWorstLoop})
      .add(At::select, {"    s ← t's worst sample: of all samples, the one of largest error"});
  terrain_insertion(b);
  terrain_improvement(b, "with --improve: for each vertex v off the border, in up to three rounds:");
  return b.take();
}

constexpr std::size_t kProgramCount = static_cast<std::size_t>(Program::count_);

// Every text of a fixed program, built once: [program][insertion] (delaunay_refinement's
// slot is unused: those come from the selections' records, below).
const std::array<std::array<Entry, 2>, kProgramCount>& entries() {
  static const std::array<std::array<Entry, 2>, kProgramCount> table = [] {
    std::array<std::array<Entry, 2>, kProgramCount> t;
    const auto one = [&](Program p, const Entry& e) { t[static_cast<std::size_t>(p)] = {e, e}; };
    one(Program::lawson, lawson());
    one(Program::bowyer_watson, bowyer_watson());
    one(Program::segment_recovery, segment_recovery());
    one(Program::lepp_bisection, lepp_bisection());
    one(Program::vertex_removal, vertex_removal());
    one(Program::lepp_surface, lepp_surface());
    one(Program::greedy_terrain, greedy_terrain());
    return t;
  }();
  return table;
}

// Every selection's Delaunay refinement program, built once from its record, in the
// registry's order: [selection][insertion].
const std::vector<std::array<Entry, 2>>& refinement_entries() {
  static const std::vector<std::array<Entry, 2>> table = [] {
    std::vector<std::array<Entry, 2>> t;
    for (const SelectionInfo& s : selections())
      t.push_back({delaunay_refinement(s.program, Insertion::flips), delaunay_refinement(s.program, Insertion::cavity)});
    return t;
  }();
  return table;
}

const Entry& entry(Selection selection, Insertion insertion) {
  const std::span<const SelectionInfo> all = selections();
  std::size_t i = 0;
  while (i < all.size() && all[i].selection != selection) ++i;
  if (i == all.size()) i = 0;  // a selection without a record: the first (registry.cpp holds them together)
  return refinement_entries()[i][insertion == Insertion::cavity ? 1 : 0];
}

const Entry& entry(Program p, Selection selection, Insertion insertion) {
  if (p == Program::delaunay_refinement) return entry(selection, insertion);
  return entries()[static_cast<std::size_t>(p)][0];
}

// --- Which program ----------------------------------------------------------------------------

Insertion triangulation_insertion(const replay::LogReader& log) {
  return log.header().insertion == "cavity" ? Insertion::cavity : Insertion::flips;
}

Insertion refinement_insertion(const replay::LogReader& log) {
  return log.run().insertion == "cavity" ? Insertion::cavity : Insertion::flips;
}

// The refinement program: by the point selection the header names (an algorithm's own or
// --select's), the bisection insertion first; by the algorithm's registered selection when
// the header does not say.
// In a recipe's log, by the operation that recorded the phase.
struct Choice {
  Program program;
  Insertion insertion;
  Selection selection = Selection::circumcenter;
};

Choice refinement_choice(const replay::LogReader& log, const replay::PhaseSpan* span) {
  const Operation* op = span ? replay::operation_of(log, *span) : nullptr;
  const AlgorithmInfo* algorithm = find_algorithm(op ? op->algorithm : log.header().algorithm);
  const bool bisection = op ? op->insertion == PointInsertion::bisection : log.run().insertion == "bisection";
  if (bisection || (algorithm && algorithm->insertion == RefineInsertion::bisection))
    return {Program::lepp_bisection, Insertion::flips};
  const std::optional<Selection> named = op ? op->selection : log.run().selection;
  const std::optional<Selection> selection =
      named ? named : algorithm ? std::optional(algorithm->selection) : std::nullopt;
  return {Program::delaunay_refinement, refinement_insertion(log), selection.value_or(Selection::circumcenter)};
}

// The phase span event e lies in: the last one begun at or before it.
const replay::PhaseSpan* phase_of(const replay::LogReader& log, std::uint64_t e) {
  const replay::PhaseSpan* found = nullptr;
  for (const replay::PhaseSpan& span : log.phases()) {
    if (span.begin > e) break;
    found = &span;
  }
  return found;
}

// A terrain's program, by the algorithm the header names; nullopt for any other run.
std::optional<Program> terrain_program(const replay::LogReader& log) {
  if (!log.has_elevation()) return std::nullopt;
  if (log.header().algorithm == "lepp-surface") return Program::lepp_surface;
  if (log.header().algorithm == "greedy") return Program::greedy_terrain;
  return std::nullopt;
}

Choice program_for(const replay::LogReader& log, const replay::PhaseSpan* span) {
  if (const std::optional<Program> terrain = terrain_program(log)) return {*terrain, Insertion::flips};
  const Phase phase = span ? span->phase : Phase::insert_vertices;
  switch (phase) {
    case Phase::recover_segments:
    case Phase::carve: return {Program::segment_recovery, Insertion::flips};
    case Phase::refine: return refinement_choice(log, span);
    case Phase::improve: return {Program::vertex_removal, Insertion::flips};
    default: {
      const Insertion insertion = triangulation_insertion(log);
      return {insertion == Insertion::cavity ? Program::bowyer_watson : Program::lawson, insertion};
    }
  }
}

// --- Which line -------------------------------------------------------------------------------

constexpr std::optional<At> kNoLine = std::nullopt;

bool is_flip(const Event& ev, FlipReason reason) {
  return ev.type == EventType::flip && static_cast<FlipReason>(ev.code) == reason;
}

// The step event e belongs to, and its kind (none for the preamble).
std::optional<StepKind> step_kind_of(const replay::LogReader& log, std::uint64_t e, std::uint64_t& step) {
  step = log.step_of_event(e);
  if (step >= log.step_count()) return std::nullopt;
  return log.step_kind(step);
}

std::optional<At> insertion_line(const Event& ev, std::optional<StepKind> kind) {
  switch (ev.type) {
    case EventType::phase_begin:
    case EventType::init: return At::start;
    case EventType::step_begin: return kind == StepKind::start ? At::start : At::each;
    case EventType::vertex: return kind == StepKind::start ? At::start : At::insert;
    case EventType::locate: return At::locate;
    case EventType::duplicate: return At::duplicate;
    case EventType::split_face:
    case EventType::split_edge: return At::insert;
    case EventType::cavity: return At::cavity;
    case EventType::flip: return is_flip(ev, FlipReason::delaunay) ? std::optional<At>(At::legalize) : kNoLine;
    default: return kNoLine;
  }
}

std::optional<At> recovery_line(const replay::LogReader& log, std::uint64_t e, const Event& ev) {
  switch (ev.type) {
    case EventType::phase_begin:
      return static_cast<Phase>(ev.code) == Phase::carve ? At::carve : At::each;
    case EventType::step_begin: return static_cast<StepKind>(ev.code) == StepKind::carve ? At::carve : At::each;
    case EventType::remove_face: return At::carve;
    case EventType::locate:
    case EventType::vertex:
    case EventType::split_face:
    case EventType::split_edge: return At::split_at;
    case EventType::flip:
      if (is_flip(ev, FlipReason::segment_recovery)) return At::crossing_flip;
      if (is_flip(ev, FlipReason::delaunay)) return At::legalize;
      return kNoLine;
    case EventType::constrain: {
      if (ev.code == 0) return At::split_at;  // a crossed segment's mark cleared to split it
      // What came before this run of marks: the flips that recovered the segment, a split
      // (the halves keep the split segment's mark), or neither (the segment was an edge).
      for (std::uint64_t q = e; q-- > 0;) {
        const Event before = log.event(q);
        if (before.type == EventType::constrain) continue;
        if (is_flip(before, FlipReason::segment_recovery)) return At::constrain;
        if (before.type == EventType::split_edge || before.type == EventType::vertex) return At::split_at;
        return At::present;
      }
      return At::present;
    }
    default: return kNoLine;
  }
}

// Of a split_segment step: did a vertex encroach (Ruppert's first loop), or a point that was
// then rejected (the split instead)?
bool split_by_vertex(const replay::LogReader& log, std::uint64_t step) {
  const std::uint64_t first = log.step_start(step) + 1;
  if (first >= log.step_start(step + 1)) return true;
  const Event ev = log.event(first);
  return ev.type != EventType::encroached || ev.ids[2] != kNone;
}

// Is the bad triangle of the test at event e the one the previous refinement step tested
// (in the same phase): still in the mesh after that step?
bool tested_before(const replay::LogReader& log, std::uint64_t e, const Event& test,
                   const replay::PhaseSpan* span) {
  constexpr std::uint64_t kStepsBack = 64;  // split steps between two of a triangle's turns: a few
  const std::uint64_t step = log.step_of_event(e);
  if (step >= log.step_count()) return false;
  const std::array<std::uint32_t, 3> triangle{test.ids[0], test.ids[1], test.ids[2]};
  for (std::uint64_t k = step; k-- > 0 && step - k <= kStepsBack;) {
    const std::uint64_t begin = log.step_start(k);
    if (span && begin < span->begin) return false;
    const StepKind kind = log.step_kind(k);
    if (kind != StepKind::refine && kind != StepKind::bisect) continue;
    if (begin + 1 >= log.step_start(k + 1)) return false;
    const Event previous = log.event(begin + 1);
    if (previous.type != EventType::criterion_test) return false;
    return std::array<std::uint32_t, 3>{previous.ids[0], previous.ids[1], previous.ids[2]} == triangle;
  }
  return false;
}

std::optional<At> refinement_line(const replay::LogReader& log, std::uint64_t e, const Event& ev,
                                  const replay::PhaseSpan* span) {
  std::uint64_t step = 0;
  const std::optional<StepKind> kind = step_kind_of(log, e, step);
  const bool in_split = kind == StepKind::split_segment;
  const bool by_vertex = in_split && split_by_vertex(log, step);
  switch (ev.type) {
    case EventType::phase_begin: return At::start;
    case EventType::step_begin:
      switch (static_cast<StepKind>(ev.code)) {
        case StepKind::split_segment: return split_by_vertex(log, step) ? At::encroached : At::rejected;
        case StepKind::refine:
        case StepKind::bisect:
          // The decision is the triangle's test, the next event.
          if (e + 1 < log.event_count()) {
            const Event next = log.event(e + 1);
            if (next.type == EventType::criterion_test)
              return tested_before(log, e + 1, next, span) ? At::still_there : At::bad;
          }
          return At::bad;
        default: return kNoLine;
      }
    case EventType::encroached: return ev.ids[2] != kNone ? At::encroached : At::rejected;
    case EventType::criterion_test: return tested_before(log, e, ev, span) ? At::still_there : At::bad;
    case EventType::point_selected: return At::select;
    case EventType::lepp_path: return At::lepp;
    case EventType::locate: return in_split ? kNoLine : std::optional<At>(At::locate);
    case EventType::vertex:
    case EventType::split_face:
    case EventType::split_edge:
    case EventType::cavity:
    case EventType::constrain:
      if (in_split) return by_vertex ? At::split : At::split_instead;
      if (kind == StepKind::bisect) return At::bisect;
      if (ev.type == EventType::constrain) return kNoLine;
      return ev.type == EventType::cavity ? At::cavity : At::insert;
    case EventType::flip:
      if (is_flip(ev, FlipReason::delaunay)) return At::legalize;
      // The free vertices deleted near a split go with it.
      return in_split && is_flip(ev, FlipReason::vertex_removal) ? std::optional<At>(At::split) : kNoLine;
    case EventType::remove_vertex: return in_split ? std::optional<At>(At::split) : kNoLine;
    default: return kNoLine;
  }
}

std::optional<At> removal_line(const Event& ev) {
  switch (ev.type) {
    case EventType::phase_begin: return At::start;
    case EventType::step_begin:
      return static_cast<StepKind>(ev.code) == StepKind::remove_vertex ? std::optional<At>(At::removal_accept)
                                                                        : kNoLine;
    case EventType::flip:
      return is_flip(ev, FlipReason::vertex_removal) ? std::optional<At>(At::removal_flip) : kNoLine;
    case EventType::remove_vertex: return At::removal_merge;
    default: return kNoLine;
  }
}

// A terrain's run: the four corners (the first two steps) are the start; each refinement
// step opens with its worst triangle, its Lepp path and its sample; the improvement's
// removals and the 3D flips are steps of their own.
std::optional<At> terrain_line(const replay::LogReader& log, std::uint64_t e, const Event& ev) {
  std::uint64_t step = 0;
  const std::optional<StepKind> kind = step_kind_of(log, e, step);
  const bool corners = !kind || kind == StepKind::start || kind == StepKind::insert_vertex;
  switch (ev.type) {
    case EventType::phase_begin:
      if (static_cast<Phase>(ev.code) == Phase::refine) return At::bad;
      // The improvement's phase, or that of the 3D flips after it (their steps follow).
      if (e + 1 < log.event_count()) {
        const Event next = log.event(e + 1);
        if (next.type == EventType::step_begin && static_cast<StepKind>(next.code) == StepKind::flip_3d)
          return At::flip_3d;
      }
      return At::each;
    case EventType::step_begin:
      switch (static_cast<StepKind>(ev.code)) {
        case StepKind::start:
        case StepKind::insert_vertex: return At::start;
        case StepKind::refine: return At::bad;
        case StepKind::remove_vertex: return At::removal_accept;
        case StepKind::flip_3d: return At::flip_3d;
        default: return kNoLine;
      }
    case EventType::criterion_test: return At::bad;
    case EventType::lepp_path: return At::lepp;
    case EventType::point_selected:
      switch (static_cast<replay::SampleChoice>(ev.code)) {
        case replay::SampleChoice::worst_sample: return At::select;
        case replay::SampleChoice::terminal_worst: return At::terminal_worst;
        case replay::SampleChoice::terminal_point:
        case replay::SampleChoice::own_worst: return At::terminal_point;
      }
      return kNoLine;
    case EventType::init:
    case EventType::vertex:
    case EventType::locate:
    case EventType::split_face:
    case EventType::split_edge:
      if (corners) return At::start;
      return ev.type == EventType::locate ? At::locate : At::insert;
    case EventType::elevation: return corners ? At::start : At::height;
    case EventType::flip:
      switch (static_cast<FlipReason>(ev.code)) {
        case FlipReason::delaunay: return corners ? At::start : At::legalize;
        case FlipReason::vertex_removal: return At::removal_flip;
        case FlipReason::angles_3d: return At::flip_3d;
        default: return kNoLine;
      }
    case EventType::remove_vertex: return At::removal_merge;
    default: return kNoLine;
  }
}

}  // namespace

const PseudoCode& pseudocode(Program program, Insertion insertion) {
  if (program >= Program::count_) program = Program::lawson;
  return entry(program, Selection::circumcenter, insertion).code;
}

const PseudoCode& pseudocode(Selection selection, Insertion insertion) { return entry(selection, insertion).code; }

std::vector<const PseudoCode*> all_pseudocode() {
  std::vector<const PseudoCode*> out;
  for (std::size_t p = 0; p < kProgramCount; ++p)
    if (static_cast<Program>(p) != Program::delaunay_refinement) out.push_back(&entries()[p][0].code);
  for (const std::array<Entry, 2>& variants : refinement_entries())
    for (const Entry& e : variants) out.push_back(&e.code);
  return out;
}

CodeAt pseudocode_at(const replay::LogReader& log, std::uint64_t position) {
  position = std::min(position, log.event_count());
  if (position == 0) {
    const Choice choice = program_for(log, log.phases().empty() ? nullptr : &log.phases().front());
    return {&entry(choice.program, choice.selection, choice.insertion).code, -1, 0, choice.program, choice.selection};
  }
  const std::uint64_t e = position - 1;
  const replay::PhaseSpan* span = phase_of(log, e);
  const Choice choice = program_for(log, span);
  const Entry& program = entry(choice.program, choice.selection, choice.insertion);
  CodeAt at{&program.code, -1, 0, choice.program, choice.selection};

  const Event ev = log.event(e);
  std::optional<At> role;
  switch (choice.program) {
    case Program::lawson:
    case Program::bowyer_watson: {
      std::uint64_t step = 0;
      role = insertion_line(ev, step_kind_of(log, e, step));
      break;
    }
    case Program::segment_recovery: role = recovery_line(log, e, ev); break;
    case Program::vertex_removal: role = removal_line(ev); break;
    case Program::lepp_surface:
    case Program::greedy_terrain: role = terrain_line(log, e, ev); break;
    default: role = refinement_line(log, e, ev, span); break;
  }
  if (!role) return at;
  Span s = program.span(*role);
  // A point goes in by the program's own insertion, whichever event the log has for it.
  if (s.line < 0 && *role == At::insert) s = program.span(At::cavity);
  if (s.line < 0 && *role == At::cavity) s = program.span(At::insert);
  // A triangle tested again, in a program with one loop over bad triangles.
  if (s.line < 0 && *role == At::still_there) s = program.span(At::bad);
  if (s.line < 0) return at;
  at.line = s.line;
  at.lines = s.count;
  return at;
}

CodeAt pseudocode_at(const replay::LogReader& log, const replay::Replay& cursor) {
  return pseudocode_at(log, cursor.position());
}

}  // namespace meshstep::scene
