// The pseudo-code panel's model: the programs' texts, and which program and line each event
// of a recorded run of lesson.poly highlights, for every refinement algorithm; and of a
// recorded terrain run, for both terrain algorithms.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>

#include "golden_runs.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/scene/pseudocode.hpp"

namespace meshstep::scene {
namespace {

using replay::Event;
using replay::EventType;
using replay::FlipReason;
using replay::Phase;

constexpr const char* kOffcenter = "--algorithm offcenter --min-angle 30";
constexpr const char* kCircumcenter = "--algorithm circumcenter --min-angle 30";
constexpr const char* kOffcenterCavity = "--algorithm offcenter --min-angle 30 --insertion cavity";
constexpr const char* kLeppMidpoint = "--algorithm lepp-midpoint";
constexpr const char* kLeppCentroid = "--algorithm lepp-centroid";
constexpr const char* kLeppBisection = "--algorithm lepp-bisection --max-area 0.5";
constexpr const char* kMidpointArea = "--algorithm midpoint-area --max-area 0.5";
constexpr const char* kCombined = "--algorithm combined";
constexpr const char* kImprove = "--algorithm improve --min-angle 30 --max-area 1";  // removes a vertex on lesson.poly

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The text of the program `at` names, with that insertion.
const PseudoCode& program_text(const CodeAt& at, Insertion insertion) {
  return at.program == Program::delaunay_refinement ? pseudocode(at.selection, insertion)
                                                    : pseudocode(at.program, insertion);
}

// Whether the panel shows the Delaunay refinement program of `selection`.
bool runs(const CodeAt& at, Selection selection) {
  return at.program == Program::delaunay_refinement && at.selection == selection;
}

// The highlighted text (all its lines), or "" when nothing is highlighted.
std::string highlighted(const CodeAt& at) {
  std::string text;
  if (!at.code || at.line < 0) return text;
  for (int i = at.line; i < at.line + at.lines && i < static_cast<int>(at.code->lines.size()); ++i)
    text += at.code->lines[static_cast<std::size_t>(i)] + "\n";
  return text;
}

// The phase event e lies in.
std::optional<Phase> phase_of(const replay::LogReader& log, std::uint64_t e) {
  std::optional<Phase> phase;
  for (const replay::PhaseSpan& span : log.phases())
    if (span.begin <= e) phase = span.phase;
  return phase;
}

// The first event at or after `from` for which `match` holds, or event_count().
template <class Match>
std::uint64_t find_event(const replay::LogReader& log, Match match, std::uint64_t from = 0) {
  for (std::uint64_t e = from; e < log.event_count(); ++e)
    if (match(e, log.event(e))) return e;
  return log.event_count();
}

bool in_phase(const replay::LogReader& log, std::uint64_t e, Phase phase) { return phase_of(log, e) == phase; }

// The characters the viewer's font holds (host.cpp): printable Latin-1 and the arrows
// U+2190..2193. Decodes UTF-8; false on anything else (or on a broken sequence).
bool in_font(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::uint32_t code = 0;
    std::size_t length = 1;
    if (c < 0x80) {
      code = c;
    } else if ((c & 0xE0) == 0xC0) {
      code = c & 0x1Fu;
      length = 2;
    } else if ((c & 0xF0) == 0xE0) {
      code = c & 0x0Fu;
      length = 3;
    } else {
      return false;
    }
    if (i + length > text.size()) return false;
    for (std::size_t k = 1; k < length; ++k) {
      const auto d = static_cast<unsigned char>(text[i + k]);
      if ((d & 0xC0) != 0x80) return false;
      code = (code << 6) | (d & 0x3Fu);
    }
    const bool printable = (code >= 0x20 && code <= 0x7E) || (code >= 0xA0 && code <= 0xFF);
    if (!printable && !(code >= 0x2190 && code <= 0x2193)) return false;
    i += length;
  }
  return true;
}

// Characters, not bytes (UTF-8 continuation bytes do not count).
std::size_t columns(const std::string& text) {
  std::size_t n = 0;
  for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

TEST(PseudoCode, EveryProgramHasATitleAReferenceAndASlideOfCode) {
  const std::vector<const PseudoCode*> all = all_pseudocode();
  // Twelve programs, the five Delaunay refinement ones once per insertion.
  EXPECT_EQ(all.size(), 17u);
  for (const PseudoCode* code : all) {
    ASSERT_TRUE(code);
    SCOPED_TRACE(code->title);
    EXPECT_FALSE(code->title.empty());
    EXPECT_FALSE(code->reference.empty());
    EXPECT_GE(code->lines.size(), 6u);
    EXPECT_LE(code->lines.size(), 14u);
    EXPECT_TRUE(in_font(code->title));
    EXPECT_TRUE(in_font(code->reference));
    for (const std::string& line : code->lines) {
      EXPECT_FALSE(line.empty());
      EXPECT_TRUE(in_font(line)) << line;
      EXPECT_EQ(line.find('\t'), std::string::npos) << line;
      EXPECT_LE(columns(line), 80u) << line;
    }
  }
  // The papers they follow.
  EXPECT_TRUE(contains(pseudocode(Program::lawson).title, "Lawson 1977"));
  EXPECT_TRUE(contains(pseudocode(Program::bowyer_watson).title, "Bowyer 1981"));
  EXPECT_TRUE(contains(pseudocode(Program::bowyer_watson).title, "Watson 1981"));
  EXPECT_TRUE(contains(pseudocode(Program::segment_recovery).title, "Sloan 1993"));
  EXPECT_TRUE(contains(pseudocode(Selection::circumcenter).title, "Ruppert 1995"));
  EXPECT_TRUE(contains(pseudocode(Selection::circumcenter).title, "Chew"));
  EXPECT_TRUE(contains(pseudocode(Selection::circumcenter).reference, "Shewchuk"));
  EXPECT_TRUE(contains(pseudocode(Selection::offcenter).title, "Üngör"));
  EXPECT_TRUE(contains(pseudocode(Selection::offcenter).reference, "Off-centers"));
  for (const PseudoCode* code : {&pseudocode(Selection::lepp_midpoint), &pseudocode(Selection::lepp_centroid),
                                 &pseudocode(Program::lepp_bisection)})
    EXPECT_TRUE(contains(code->title, "Rivara")) << code->title;
  EXPECT_TRUE(contains(pseudocode(Selection::lepp_midpoint).reference, "Hitschfeld"));
  EXPECT_TRUE(contains(pseudocode(Program::lepp_bisection).reference, "New longest-edge algorithms"));
  EXPECT_TRUE(contains(pseudocode(Program::vertex_removal).title, "Coll"));
  EXPECT_TRUE(contains(pseudocode(Program::lepp_surface).title, "Coll, Guerrieri, Rivara, Sellarès 2008"));
  EXPECT_TRUE(contains(pseudocode(Program::lepp_surface).reference, "Meshing Roundtable"));
  EXPECT_TRUE(contains(pseudocode(Program::greedy_terrain).title, "Garland, Heckbert 1995"));
  EXPECT_TRUE(contains(pseudocode(Program::greedy_terrain).reference, "terrains and height fields"));
  // A refinement program says how its points go in; the others have one text.
  EXPECT_NE(&pseudocode(Selection::offcenter, Insertion::flips), &pseudocode(Selection::offcenter, Insertion::cavity));
  EXPECT_EQ(&pseudocode(Program::lawson, Insertion::flips), &pseudocode(Program::lawson, Insertion::cavity));
}

// A selection's program is written by its registry record: its title, its papers and the
// lines that choose the point, inside Ruppert's loop or Rivara's Lepp loop as the record
// says. Nothing else names a selection's program.
TEST(PseudoCode, EverySelectionsProgramIsItsRegistryRecords) {
  for (const SelectionInfo& s : selections()) {
    SCOPED_TRACE(s.name);
    ASSERT_FALSE(s.program.choose_point.empty());
    for (const Insertion insertion : {Insertion::flips, Insertion::cavity}) {
      const PseudoCode& code = pseudocode(s.selection, insertion);
      EXPECT_EQ(code.title, s.program.title);
      EXPECT_EQ(code.reference, s.program.reference);
      const auto first = std::find(code.lines.begin(), code.lines.end(), std::string(s.program.choose_point[0]));
      ASSERT_NE(first, code.lines.end());
      for (std::size_t k = 1; k < s.program.choose_point.size(); ++k)
        EXPECT_EQ(*(first + static_cast<std::ptrdiff_t>(k)), s.program.choose_point[k]);
      // Rivara's loop walks the Lepp before the point is chosen; Ruppert's does not.
      const bool walks_lepp = std::any_of(code.lines.begin(), first,
                                          [](const std::string& line) { return contains(line, "follow Lepp(t)"); });
      EXPECT_EQ(walks_lepp, s.program.lepp);
    }
    EXPECT_NE(&pseudocode(s.selection, Insertion::flips), &pseudocode(s.selection, Insertion::cavity));
  }
}

// The log's dumps name a chosen point's selection as its record does (and as the log's
// header and the command line spell it).
TEST(PseudoCode, TheLogNamesASelectionByItsRecord) {
  for (const SelectionInfo& s : selections())
    EXPECT_EQ(replay::code_name(EventType::point_selected, static_cast<std::uint8_t>(s.selection)), s.name);
  EXPECT_EQ(replay::code_name(EventType::point_selected, 15), "15");  // no selection has that code
}

// Walks every event of a run: every event but a phase's end highlights a line within its
// program, and the overload taking a cursor agrees.
void expect_every_event_mapped(const char* args) {
  SCOPED_TRACE(args);
  const replay::LogReader* log = golden::lesson_run(args);
  ASSERT_TRUE(log);
  replay::Replay cursor(*log);
  const CodeAt start = pseudocode_at(*log, cursor);
  ASSERT_TRUE(start.code);
  EXPECT_EQ(start.line, -1);
  std::set<EventType> seen;
  for (std::uint64_t e = 0; e < log->event_count(); ++e) {
    ASSERT_TRUE(cursor.next_event());
    const CodeAt at = pseudocode_at(*log, cursor);
    const CodeAt by_position = pseudocode_at(*log, e + 1);
    EXPECT_EQ(at.code, by_position.code);
    EXPECT_EQ(at.line, by_position.line);
    ASSERT_TRUE(at.code);
    const Event ev = log->event(e);
    seen.insert(ev.type);
    EXPECT_TRUE(at.code == &program_text(at, Insertion::flips) || at.code == &program_text(at, Insertion::cavity));
    if (ev.type == EventType::phase_end) {
      EXPECT_EQ(at.line, -1) << "event " << e;
      continue;
    }
    EXPECT_GE(at.line, 0) << "event " << e << ": " << replay::name(ev.type) << " "
                          << replay::code_name(ev.type, ev.code) << " in " << at.code->title;
    EXPECT_GE(at.lines, 1) << "event " << e;
    EXPECT_LE(at.line + at.lines, static_cast<int>(at.code->lines.size())) << "event " << e;
  }
  // The walk saw the kinds of event the runs hold.
  for (const EventType t : {EventType::locate, EventType::vertex, EventType::init, EventType::constrain,
                            EventType::remove_face, EventType::criterion_test})
    EXPECT_TRUE(seen.count(t)) << replay::name(t);
}

TEST(PseudoCode, EveryEventOfEveryAlgorithmHighlightsALine) {
  for (const char* args : {kOffcenter, kCircumcenter, kOffcenterCavity, kLeppMidpoint, kLeppCentroid, kLeppBisection,
                           kMidpointArea, kCombined, kImprove})
    expect_every_event_mapped(args);
}

TEST(PseudoCode, TriangulationPhasesShowTheInsertionAndRecoveryPrograms) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_TRUE(log);
  // Before any event: the first phase's program, nothing highlighted.
  const CodeAt start = pseudocode_at(*log, 0);
  EXPECT_EQ(start.program, Program::lawson);
  EXPECT_EQ(start.line, -1);

  const auto type_is = [](EventType t) { return [t](std::uint64_t, const Event& ev) { return ev.type == t; }; };
  // The first triangle.
  const std::uint64_t init = find_event(*log, type_is(EventType::init));
  ASSERT_LT(init, log->event_count());
  CodeAt at = pseudocode_at(*log, init + 1);
  EXPECT_EQ(at.program, Program::lawson);
  EXPECT_TRUE(contains(highlighted(at), "first triangle")) << highlighted(at);
  // A point located.
  const std::uint64_t locate = find_event(*log, type_is(EventType::locate));
  ASSERT_TRUE(in_phase(*log, locate, Phase::insert_vertices));
  at = pseudocode_at(*log, locate + 1);
  EXPECT_EQ(at.program, Program::lawson);
  EXPECT_TRUE(contains(highlighted(at), "locate the triangle containing p")) << highlighted(at);
  // Split.
  const std::uint64_t split = find_event(*log, type_is(EventType::split_face));
  at = pseudocode_at(*log, split + 1);
  EXPECT_TRUE(contains(highlighted(at), "split that triangle in 3")) << highlighted(at);

  // A step whose last event is a Delaunay flip, in the insertion phase: the flip line.
  bool found = false;
  for (std::uint64_t k = 0; k < log->step_count() && !found; ++k) {
    const std::uint64_t end = log->step_start(k + 1);
    const Event last = log->event(end - 1);
    if (last.type != EventType::flip || static_cast<FlipReason>(last.code) != FlipReason::delaunay) continue;
    if (!in_phase(*log, end - 1, Phase::insert_vertices)) continue;
    found = true;
    replay::Replay cursor(*log);
    cursor.seek_step(k + 1);
    ASSERT_EQ(cursor.position(), end);
    at = pseudocode_at(*log, cursor);
    EXPECT_EQ(at.program, Program::lawson);
    EXPECT_TRUE(contains(highlighted(at), "in-circle")) << highlighted(at);
    EXPECT_TRUE(contains(highlighted(at), "flip it")) << highlighted(at);
  }
  EXPECT_TRUE(found);

  // Segment recovery: its flips, the mark, and the carving.
  const std::uint64_t recovery_flip = find_event(*log, [](std::uint64_t, const Event& ev) {
    return ev.type == EventType::flip && static_cast<FlipReason>(ev.code) == FlipReason::segment_recovery;
  });
  ASSERT_LT(recovery_flip, log->event_count());
  at = pseudocode_at(*log, recovery_flip + 1);
  EXPECT_EQ(at.program, Program::segment_recovery);
  EXPECT_TRUE(contains(highlighted(at), "quadrilateral is convex: flip")) << highlighted(at);
  // The mark right after those flips: the segment is recovered.
  ASSERT_EQ(log->event(recovery_flip + 1).type, EventType::constrain);
  at = pseudocode_at(*log, recovery_flip + 2);
  EXPECT_EQ(highlighted(at), "    mark ab constrained\n");
  // A segment that was an edge already.
  const std::uint64_t first_mark = find_event(*log, type_is(EventType::constrain));
  ASSERT_LT(first_mark, recovery_flip);
  at = pseudocode_at(*log, first_mark + 1);
  EXPECT_EQ(at.program, Program::segment_recovery);
  EXPECT_TRUE(contains(highlighted(at), "an edge already")) << highlighted(at);
  // Carving.
  const std::uint64_t removed = find_event(*log, type_is(EventType::remove_face));
  at = pseudocode_at(*log, removed + 1);
  EXPECT_EQ(at.program, Program::segment_recovery);
  EXPECT_TRUE(contains(highlighted(at), "reachable from a hole")) << highlighted(at);
}

TEST(PseudoCode, OffcenterRefinementLines) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_TRUE(log);
  const auto in_refine = [&](EventType t) {
    return [&log, t](std::uint64_t e, const Event& ev) { return ev.type == t && in_phase(*log, e, Phase::refine); };
  };

  // The bad triangle's test and the point selection: the off-center program.
  const std::uint64_t test = find_event(*log, in_refine(EventType::criterion_test));
  ASSERT_LT(test, log->event_count());
  CodeAt at = pseudocode_at(*log, test + 1);
  EXPECT_TRUE(runs(at, Selection::offcenter));
  EXPECT_TRUE(contains(at.code->title, "Off-center"));
  EXPECT_TRUE(contains(highlighted(at), "while a bad triangle t")) << highlighted(at);
  // The step's beginning highlights the same decision.
  ASSERT_EQ(log->event(test - 1).type, EventType::step_begin);
  EXPECT_EQ(pseudocode_at(*log, test).line, at.line);

  const std::uint64_t selected = find_event(*log, in_refine(EventType::point_selected));
  ASSERT_LT(selected, log->event_count());
  at = pseudocode_at(*log, selected + 1);
  EXPECT_TRUE(runs(at, Selection::offcenter));
  EXPECT_TRUE(contains(at.code->lines[static_cast<std::size_t>(at.line)], "off-center")) << highlighted(at);
  EXPECT_EQ(at.lines, 3);  // with the circumcenter's alternative

  // The point's location and insertion.
  const std::uint64_t locate = find_event(*log, in_refine(EventType::locate));
  at = pseudocode_at(*log, locate + 1);
  EXPECT_TRUE(contains(highlighted(at), "locate the triangle containing c")) << highlighted(at);
  const std::uint64_t inserted = find_event(*log, in_refine(EventType::split_face));
  at = pseudocode_at(*log, inserted + 1);
  EXPECT_TRUE(contains(highlighted(at), "split it in 3")) << highlighted(at);

  // A Delaunay flip in the refinement: the refinement program's flip line.
  const std::uint64_t flip = find_event(*log, in_refine(EventType::flip));
  ASSERT_LT(flip, log->event_count());
  at = pseudocode_at(*log, flip + 1);
  EXPECT_TRUE(runs(at, Selection::offcenter));
  EXPECT_TRUE(contains(highlighted(at), "in-circle")) << highlighted(at);

  // Encroachment: by a vertex (Ruppert's first loop), or by the selected point (split instead).
  const std::uint64_t by_vertex = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::encroached && ev.ids[2] != kNone && in_phase(*log, e, Phase::refine);
  });
  ASSERT_LT(by_vertex, log->event_count());
  at = pseudocode_at(*log, by_vertex + 1);
  EXPECT_TRUE(contains(highlighted(at), "while a subsegment s is encroached")) << highlighted(at);
  const std::uint64_t split = find_event(*log, in_refine(EventType::split_edge), by_vertex);
  at = pseudocode_at(*log, split + 1);
  EXPECT_TRUE(contains(highlighted(at), "split s: midpoint")) << highlighted(at);
  EXPECT_TRUE(contains(highlighted(at), "corner: shell")) << highlighted(at);

  const std::uint64_t by_point = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::encroached && ev.ids[2] == kNone && in_phase(*log, e, Phase::refine);
  });
  ASSERT_LT(by_point, log->event_count());
  at = pseudocode_at(*log, by_point + 1);
  EXPECT_TRUE(contains(highlighted(at), "if c encroaches a subsegment s")) << highlighted(at);
  at = pseudocode_at(*log, by_point);  // the split step's beginning
  EXPECT_TRUE(contains(highlighted(at), "if c encroaches a subsegment s")) << highlighted(at);
  const std::uint64_t split_instead = find_event(*log, in_refine(EventType::split_edge), by_point);
  at = pseudocode_at(*log, split_instead + 1);
  EXPECT_TRUE(contains(highlighted(at), "split s instead")) << highlighted(at);

  // The refinement phase's beginning: the first line; its end: none.
  const std::uint64_t begin = find_event(*log, in_refine(EventType::phase_begin));
  at = pseudocode_at(*log, begin + 1);
  EXPECT_TRUE(runs(at, Selection::offcenter));
  EXPECT_EQ(at.line, 0);
  EXPECT_TRUE(contains(highlighted(at), "constrained Delaunay triangulation"));
  const std::uint64_t end = find_event(*log, in_refine(EventType::phase_end));
  EXPECT_EQ(pseudocode_at(*log, end + 1).line, -1);
}

TEST(PseudoCode, TheParametersChooseTheRefinementProgram) {
  struct Case {
    const char* args;
    Selection program;      // whose Delaunay refinement program
    const char* selection;  // in the highlighted selection line
  };
  for (const Case& c : {Case{kCircumcenter, Selection::circumcenter, "circumcenter of t"},
                        Case{"--algorithm circumcenter --select offcenter --min-angle 30", Selection::offcenter,
                             "off-center of t"},
                        Case{kLeppMidpoint, Selection::lepp_midpoint, "midpoint of e"},
                        Case{kLeppCentroid, Selection::lepp_centroid, "centroid of the two terminal triangles"},
                        Case{kCombined, Selection::lepp_centroid, "centroid of the two terminal triangles"},
                        Case{kMidpointArea, Selection::longest_edge_midpoint, "midpoint of t's longest edge"}}) {
    SCOPED_TRACE(c.args);
    const replay::LogReader* log = golden::lesson_run(c.args);
    ASSERT_TRUE(log);
    const std::uint64_t selected =
        find_event(*log, [](std::uint64_t, const Event& ev) { return ev.type == EventType::point_selected; });
    ASSERT_LT(selected, log->event_count());
    const CodeAt at = pseudocode_at(*log, selected + 1);
    EXPECT_TRUE(runs(at, c.program));
    EXPECT_EQ(at.code, &pseudocode(c.program, Insertion::flips));
    EXPECT_TRUE(contains(highlighted(at), c.selection)) << highlighted(at);
  }
}

TEST(PseudoCode, CavityRunsShowBowyerWatson) {
  const replay::LogReader* log = golden::lesson_run(kOffcenterCavity);
  ASSERT_TRUE(log);
  const auto cavity_in = [&](Phase phase) {
    return find_event(*log, [&](std::uint64_t e, const Event& ev) {
      return ev.type == EventType::cavity && in_phase(*log, e, phase);
    });
  };
  // Triangulation: the Bowyer-Watson program, the cavity lines.
  const std::uint64_t first = cavity_in(Phase::insert_vertices);
  ASSERT_LT(first, log->event_count());
  CodeAt at = pseudocode_at(*log, first + 1);
  EXPECT_EQ(at.program, Program::bowyer_watson);
  EXPECT_TRUE(contains(highlighted(at), "remove every triangle whose circumcircle contains p")) << highlighted(at);
  EXPECT_TRUE(contains(highlighted(at), "connect p to every edge of the cavity's boundary")) << highlighted(at);
  EXPECT_FALSE(contains(at.code->title, "Lawson"));
  // Refinement: the off-center program, ending in cavities.
  const std::uint64_t refine = cavity_in(Phase::refine);
  ASSERT_LT(refine, log->event_count());
  at = pseudocode_at(*log, refine + 1);
  EXPECT_TRUE(runs(at, Selection::offcenter));
  EXPECT_EQ(at.code, &pseudocode(Selection::offcenter, Insertion::cavity));
  EXPECT_TRUE(contains(highlighted(at), "circumcircle contains c")) << highlighted(at);
  // The flips after a segment split.
  const std::uint64_t flip = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::flip && in_phase(*log, e, Phase::refine);
  });
  ASSERT_LT(flip, log->event_count());
  at = pseudocode_at(*log, flip + 1);
  EXPECT_TRUE(contains(highlighted(at), "after a segment split")) << highlighted(at);
  EXPECT_TRUE(contains(highlighted(at), "in-circle")) << highlighted(at);
}

TEST(PseudoCode, LeppDelaunayFollowsThePathAndComesBackToItsTriangle) {
  const replay::LogReader* log = golden::lesson_run(kLeppMidpoint);
  ASSERT_TRUE(log);
  const std::uint64_t lepp =
      find_event(*log, [](std::uint64_t, const Event& ev) { return ev.type == EventType::lepp_path; });
  ASSERT_LT(lepp, log->event_count());
  CodeAt at = pseudocode_at(*log, lepp + 1);
  EXPECT_TRUE(runs(at, Selection::lepp_midpoint));
  EXPECT_TRUE(contains(highlighted(at), "follow Lepp(t)")) << highlighted(at);
  EXPECT_TRUE(contains(highlighted(at), "terminal edge")) << highlighted(at);

  // Two refinement steps in a row on one triangle: its first test is the outer loop's, the
  // second the inner "still in the mesh" loop's.
  int outer = 0, inner = 0;
  std::optional<Event> previous_test;
  for (std::uint64_t k = 0; k < log->step_count(); ++k) {
    if (log->step_kind(k) != replay::StepKind::refine) continue;
    const std::uint64_t e = log->step_start(k) + 1;
    const Event test = log->event(e);
    ASSERT_EQ(test.type, EventType::criterion_test);
    const bool same = previous_test && previous_test->ids == test.ids;
    const CodeAt t = pseudocode_at(*log, e + 1);
    if (same) {
      ++inner;
      EXPECT_TRUE(contains(highlighted(t), "while t is still in the mesh")) << highlighted(t);
    } else {
      ++outer;
      EXPECT_TRUE(contains(highlighted(t), "while a bad triangle t")) << highlighted(t);
    }
    previous_test = test;
  }
  EXPECT_GT(outer, 0);
  EXPECT_GT(inner, 0);
}

TEST(PseudoCode, LeppBisectionNamesRivaraAndBisectsTheTerminalEdge) {
  const replay::LogReader* log = golden::lesson_run(kLeppBisection);
  ASSERT_TRUE(log);
  const std::uint64_t bisection = find_event(*log, [](std::uint64_t, const Event& ev) {
    return ev.type == EventType::split_edge && static_cast<replay::SplitReason>(ev.code) == replay::SplitReason::bisection;
  });
  ASSERT_LT(bisection, log->event_count());
  CodeAt at = pseudocode_at(*log, bisection + 1);
  EXPECT_EQ(at.program, Program::lepp_bisection);
  EXPECT_TRUE(contains(at.code->title, "Rivara"));
  EXPECT_TRUE(contains(highlighted(at), "bisect the terminal edge")) << highlighted(at);
  // Its new vertex, its path and its target.
  ASSERT_EQ(log->event(bisection - 1).type, EventType::vertex);
  EXPECT_EQ(pseudocode_at(*log, bisection).line, at.line);
  ASSERT_EQ(log->event(bisection - 2).type, EventType::lepp_path);
  at = pseudocode_at(*log, bisection - 1);
  EXPECT_TRUE(contains(highlighted(at), "follow Lepp(t)")) << highlighted(at);
  ASSERT_EQ(log->event(bisection - 3).type, EventType::criterion_test);
  at = pseudocode_at(*log, bisection - 2);
  EXPECT_TRUE(contains(highlighted(at), "too large")) << highlighted(at);
  // No Delaunay flip in this program.
  for (const std::string& line : at.code->lines) EXPECT_FALSE(contains(line, "in-circle")) << line;
}

// A free vertex deleted near a split segment (the default, Chew's rule) lights the split's
// own line in the refinement program, not the improvement's.
TEST(PseudoCode, FreeVerticesDeletedNearASplitShowTheirLine) {
  const replay::LogReader* log = golden::lesson_run(kCircumcenter);
  ASSERT_TRUE(log);
  const std::uint64_t removal = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::remove_vertex && in_phase(*log, e, Phase::refine);
  });
  ASSERT_LT(removal, log->event_count()) << "the run deletes no vertex near a split any more: pick another";
  const CodeAt at = pseudocode_at(*log, removal + 1);
  EXPECT_TRUE(runs(at, Selection::circumcenter));
  EXPECT_TRUE(contains(highlighted(at), "deleting free vertices in its circle")) << highlighted(at);
}

TEST(PseudoCode, ImprovementShowsVertexRemoval) {
  const replay::LogReader* log = golden::lesson_run(kImprove);
  ASSERT_TRUE(log);
  // The improvement's removals (the refinement before it deletes free vertices near splits too).
  const std::uint64_t removal = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::remove_vertex && in_phase(*log, e, Phase::improve);
  });
  ASSERT_LT(removal, log->event_count()) << "the run removes no vertex any more: pick another";
  CodeAt at = pseudocode_at(*log, removal + 1);
  EXPECT_EQ(at.program, Program::vertex_removal);
  EXPECT_TRUE(contains(highlighted(at), "remove it")) << highlighted(at);
  const std::uint64_t flip = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::flip && static_cast<FlipReason>(ev.code) == FlipReason::vertex_removal &&
           in_phase(*log, e, Phase::improve);
  });
  ASSERT_LT(flip, removal);
  at = pseudocode_at(*log, flip + 1);
  EXPECT_TRUE(contains(highlighted(at), "flip the spoke")) << highlighted(at);
  // Before the improvement phase: the refinement's own program.
  const std::uint64_t selected =
      find_event(*log, [](std::uint64_t, const Event& ev) { return ev.type == EventType::point_selected; });
  EXPECT_TRUE(runs(pseudocode_at(*log, selected + 1), Selection::circumcenter));
}

// --- Terrains ---------------------------------------------------------------------------

constexpr const char* kLeppSurface = "--max-error 1 --flips";  // with the improvement (its default)
constexpr const char* kGreedy = "--algorithm greedy --max-error 1 --improve --flips";

// Walks every event of a terrain run: each one but a phase's end highlights a line of the
// run's one program; together they reach every line of it. Returns the lines' text by
// event type and code, for the tests below to look at.
void expect_every_terrain_line_reached(const char* args, Program program) {
  SCOPED_TRACE(args);
  const replay::LogReader* log = golden::terrain_run(args);
  ASSERT_TRUE(log);
  ASSERT_TRUE(log->has_elevation());
  const PseudoCode& code = pseudocode(program);
  std::set<int> reached;
  replay::Replay cursor(*log);
  EXPECT_EQ(pseudocode_at(*log, cursor).program, program) << "before the first event";
  for (std::uint64_t e = 0; e < log->event_count(); ++e) {
    ASSERT_TRUE(cursor.next_event());
    const CodeAt at = pseudocode_at(*log, cursor);
    ASSERT_EQ(at.program, program) << "event " << e;
    ASSERT_EQ(at.code, &code);
    const Event ev = log->event(e);
    if (ev.type == EventType::phase_end) {
      EXPECT_EQ(at.line, -1) << "event " << e;
      continue;
    }
    ASSERT_GE(at.line, 0) << "event " << e << ": " << replay::name(ev.type) << " " << replay::code_name(ev.type, ev.code);
    ASSERT_LE(at.line + at.lines, static_cast<int>(code.lines.size())) << "event " << e;
    for (int i = at.line; i < at.line + at.lines; ++i) reached.insert(i);
  }
  for (int i = 0; i < static_cast<int>(code.lines.size()); ++i)
    EXPECT_TRUE(reached.count(i)) << "no event reaches line " << i << ": " << code.lines[static_cast<std::size_t>(i)];
}

TEST(PseudoCode, EveryLineOfTheTerrainProgramsIsReachedByARecordedRun) {
  expect_every_terrain_line_reached(kLeppSurface, Program::lepp_surface);
  expect_every_terrain_line_reached(kGreedy, Program::greedy_terrain);
}

// The first event of this type (and code, unless any) and the text it highlights.
std::string line_of_first(const replay::LogReader& log, EventType type, int code = -1) {
  const std::uint64_t e = find_event(log, [&](std::uint64_t, const Event& ev) {
    return ev.type == type && (code < 0 || ev.code == code);
  });
  if (e >= log.event_count()) return "(no such event)";
  return highlighted(pseudocode_at(log, e + 1));
}

TEST(PseudoCode, LeppSurfaceLinesSayWhyTheSampleWentWhereItDid) {
  const replay::LogReader* log = golden::terrain_run(kLeppSurface);
  ASSERT_TRUE(log);
  using replay::SampleChoice;
  const auto code = [](auto c) { return static_cast<int>(c); };
  // The four corners, then each step's worst triangle, Lepp path and sample.
  EXPECT_TRUE(contains(line_of_first(*log, EventType::init), "four corners"));
  EXPECT_TRUE(contains(line_of_first(*log, EventType::criterion_test), "worst triangle t misses the bound"));
  EXPECT_TRUE(contains(line_of_first(*log, EventType::lepp_path), "follow Lepp(t)"));
  EXPECT_TRUE(contains(line_of_first(*log, EventType::lepp_path), "3D lengths"));
  EXPECT_TRUE(contains(line_of_first(*log, EventType::point_selected, code(SampleChoice::terminal_worst)),
                       "if a terminal triangle misses the bound: s ← its worst sample"));
  const std::string nearest = line_of_first(*log, EventType::point_selected, code(SampleChoice::terminal_point));
  EXPECT_TRUE(contains(nearest, "nearest the terminal point")) << nearest;
  EXPECT_TRUE(contains(nearest, "centroid")) << nearest;
  // The fourth corner goes in as the first line says; a sample by the insertion's lines:
  // Delaunay by flips, then the sample's height.
  EXPECT_TRUE(contains(line_of_first(*log, EventType::split_face), "four corners"));
  const std::uint64_t split = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::split_face && in_phase(*log, e, Phase::refine);
  });
  ASSERT_LT(split, log->event_count());
  EXPECT_TRUE(contains(highlighted(pseudocode_at(*log, split + 1)), "split its triangle in 3"));
  const std::uint64_t refine = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::flip && in_phase(*log, e, Phase::refine);
  });
  ASSERT_LT(refine, log->event_count());
  EXPECT_TRUE(contains(highlighted(pseudocode_at(*log, refine + 1)), "in-circle"));
  const std::uint64_t height = find_event(*log, [&](std::uint64_t e, const Event& ev) {
    return ev.type == EventType::elevation && in_phase(*log, e, Phase::refine);
  });
  ASSERT_LT(height, log->event_count());
  EXPECT_TRUE(contains(highlighted(pseudocode_at(*log, height + 1)), "s takes its height"));
  // The improvement and the 3D flips.
  EXPECT_TRUE(contains(line_of_first(*log, EventType::remove_vertex), "then remove v"));
  EXPECT_TRUE(contains(line_of_first(*log, EventType::flip, code(FlipReason::vertex_removal)), "flip v's spokes"));
  EXPECT_TRUE(contains(line_of_first(*log, EventType::flip, code(FlipReason::angles_3d)), "smallest 3D angle"));
  // A step's beginning highlights what the step decides.
  const std::uint64_t removal = find_event(*log, [&](std::uint64_t, const Event& ev) {
    return ev.type == EventType::step_begin && static_cast<replay::StepKind>(ev.code) == replay::StepKind::remove_vertex;
  });
  EXPECT_TRUE(contains(highlighted(pseudocode_at(*log, removal + 1)), "if removing v keeps errors within E"));
  // No line of a planar program shows in a terrain run.
  for (std::uint64_t e = 0; e < log->event_count(); e += 97)
    EXPECT_EQ(pseudocode_at(*log, e + 1).program, Program::lepp_surface) << "event " << e;
}

TEST(PseudoCode, GreedyInsertsTheSampleOfLargestError) {
  const replay::LogReader* log = golden::terrain_run(kGreedy);
  ASSERT_TRUE(log);
  const std::string selected = line_of_first(*log, EventType::point_selected);
  EXPECT_TRUE(contains(selected, "s ← t's worst sample")) << selected;
  EXPECT_TRUE(contains(selected, "largest error")) << selected;
  for (const std::string& line : pseudocode(Program::greedy_terrain).lines)
    EXPECT_FALSE(contains(line, "Lepp")) << line;
  // The improvement is asked of greedy here: the program says it is optional.
  EXPECT_TRUE(contains(line_of_first(*log, EventType::phase_begin, static_cast<int>(Phase::improve)),
                       "with --improve"));
}

TEST(PseudoCode, PositionsPastTheEndAreTheLastEvent) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_TRUE(log);
  const CodeAt last = pseudocode_at(*log, log->event_count());
  const CodeAt past = pseudocode_at(*log, log->event_count() + 5);
  EXPECT_EQ(last.code, past.code);
  EXPECT_EQ(last.line, past.line);
}

}  // namespace
}  // namespace meshstep::scene
