// Predict the next step (docs/tours.md, "The quiz"): the questions a run's log can ask about
// its next step, and the grading of an answer given as a point of the plane (a click).
//
//   point               where does the new point go? (a refinement step's selected point;
//                       right within a quarter of the bad triangle's shortest edge)
//   flip                which edge flips first? (a Delaunay flip of the step: Lawson)
//   terminal-edge       which edge is the terminal edge of the Lepp path? (a Lepp step)
//   encroached-segment  which segment is encroached? (a step that finds one)
//
// An edge is answered by clicking nearest it: the edge of the mesh (for a segment, the
// constrained edge) nearest the click is the answer. No GL: the viewer asks and draws, the
// tests grade here.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/mesh/handles.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"

namespace meshstep::teach {

enum class QuestionKind : std::uint8_t { point, flip, terminal_edge, encroached_segment, count_ };
const char* name(QuestionKind kind);
std::optional<QuestionKind> parse_question_kind(std::string_view text);
// What the viewer asks: "Where does the new point go? Click where you predict it."
const char* prompt(QuestionKind kind);

using Edge = std::array<VertexId, 2>;

struct Question {
  QuestionKind kind = QuestionKind::point;
  std::uint64_t step = 0;  // the step asked about; the question is asked at moment step - 1
  Point point;             // point: where the step puts its new point
  double tolerance = 0.0;  // point: an answer this near is right
  Edge edge{kNone, kNone}; // the others: the edge that is the answer
  // What the question shows, so that it can be answered: the bad triangle (point,
  // terminal-edge), or the point the step puts in (flip: the new vertex; encroached-segment:
  // the encroaching point).
  std::array<VertexId, 3> triangle{kNone, kNone, kNone};
  std::optional<Point> hint;
};

// The question step k (1..n) asks, of the kind wanted (none: the first that applies, in the
// order encroached-segment, terminal-edge, point, flip), or none when it asks nothing such.
std::optional<Question> question_at(const replay::LogReader& log, std::uint64_t k, std::optional<QuestionKind> wanted);
// The first question of a step after moment `moment` (steps moment + 1..n), or none.
std::optional<Question> next_question(const replay::LogReader& log, std::uint64_t moment,
                                      std::optional<QuestionKind> wanted);

struct Answer {
  Point at;                    // the click, in the plane
  bool right = false;
  double distance = 0.0;       // point: from the click to the true point; edges: to the chosen edge
  Edge chosen{kNone, kNone};   // edges: the edge nearest the click (kNone: there is none)
};

// Grades a click against the mesh of `before` (a cursor at the question's moment, step - 1).
Answer grade(const Question& question, const replay::Replay& before, Point click);

// The edge of the cursor's mesh nearest `p` (only constrained edges when `segments_only`),
// and its distance; {kNone, kNone} when the mesh has none.
std::pair<Edge, double> nearest_edge(const replay::Replay& at, Point p, bool segments_only);

// A running score, and its summary as JSON (one answer a line).
struct QuizRecord {
  Question question;
  Answer answer;
};
struct QuizScore {
  std::vector<QuizRecord> answers;
  std::size_t right() const;
  std::string summary_json(const replay::LogReader& log) const;
};

}  // namespace meshstep::teach
