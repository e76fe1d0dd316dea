// The questions of the predict-the-next-step quiz, and their grading (teach/quiz.hpp).
#include "meshstep/teach/quiz.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "meshstep/replay/event.hpp"

namespace meshstep::teach {
namespace {

constexpr std::array<const char*, 4> kKindWords = {"point", "flip", "terminal-edge", "encroached-segment"};
constexpr std::array<const char*, 4> kPrompts = {
    "Where does the new point go for the bad triangle outlined in orange? Click where you predict it.",
    "The blue point goes in next. Which edge flips first? Click on it.",
    "Follow the Lepp path from the bad triangle outlined in orange. Which edge is its terminal edge? Click on it.",
    "Which segment does the blue point encroach? Click on it.",
};

double distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

bool same_edge(const Edge& e, VertexId a, VertexId b) { return (e[0] == a && e[1] == b) || (e[0] == b && e[1] == a); }

// The candidates of step k, by kind (the first event of each kind in the step).
std::array<std::optional<Question>, 4> candidates(const replay::LogReader& log, std::uint64_t k) {
  using replay::EventType;
  std::array<std::optional<Question>, 4> found;
  const auto slot = [&](QuestionKind q) -> std::optional<Question>& { return found[static_cast<std::size_t>(q)]; };
  const std::uint64_t begin = log.step_start(k - 1), end = log.step_start(k);
  std::optional<Point> inserted;  // the step's new vertex, once it is in
  for (std::uint64_t e = begin; e < end; ++e) {
    const replay::Event ev = log.event(e);
    if ((ev.type == EventType::split_face || ev.type == EventType::split_edge || ev.type == EventType::cavity) &&
        !inserted && ev.ids[0] < log.vertices().size())
      inserted = log.vertices()[ev.ids[0]].point;
    Question q;
    q.step = k;
    if (ev.type == EventType::point_selected && !slot(QuestionKind::point) && ev.ids[0] != kNone &&
        ev.code < replay::kFirstSampleChoice) {
      q.kind = QuestionKind::point;
      q.point = ev.point;
      // A quarter of the bad triangle's shortest edge: near enough to be the same choice,
      // far from every other vertex of the triangle.
      const auto& v = log.vertices();
      double shortest = INFINITY;
      for (int i = 0; i < 3; ++i) {
        const VertexId a = ev.ids[i], b = ev.ids[(i + 1) % 3];
        if (a < v.size() && b < v.size())
          shortest = std::min(shortest, std::hypot(v[a].point.x - v[b].point.x, v[a].point.y - v[b].point.y));
      }
      if (!std::isfinite(shortest)) continue;
      q.tolerance = 0.25 * shortest;
      q.triangle = {ev.ids[0], ev.ids[1], ev.ids[2]};
      slot(QuestionKind::point) = q;
    } else if (ev.type == EventType::flip && ev.code == static_cast<std::uint8_t>(replay::FlipReason::delaunay) &&
               !slot(QuestionKind::flip)) {
      // Lawson flips after an insertion: the new vertex is the hint (none: not asked).
      if (!inserted) continue;
      q.kind = QuestionKind::flip;
      q.edge = {ev.ids[0], ev.ids[1]};
      q.hint = inserted;
      slot(QuestionKind::flip) = q;
    } else if (ev.type == EventType::lepp_path && !slot(QuestionKind::terminal_edge)) {
      if (ev.list.size() < 3) continue;
      q.kind = QuestionKind::terminal_edge;
      q.edge = {ev.ids[0], ev.ids[1]};
      q.triangle = {ev.list[0], ev.list[1], ev.list[2]};  // the path starts at the bad triangle
      slot(QuestionKind::terminal_edge) = q;
    } else if (ev.type == EventType::encroached && !slot(QuestionKind::encroached_segment)) {
      q.kind = QuestionKind::encroached_segment;
      q.edge = {ev.ids[0], ev.ids[1]};
      q.hint = ev.point;
      slot(QuestionKind::encroached_segment) = q;
    }
  }
  return found;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

const char* name(QuestionKind kind) { return kKindWords[static_cast<std::size_t>(kind)]; }
const char* prompt(QuestionKind kind) { return kPrompts[static_cast<std::size_t>(kind)]; }

std::optional<QuestionKind> parse_question_kind(std::string_view text) {
  for (std::size_t i = 0; i < kKindWords.size(); ++i)
    if (text == kKindWords[i]) return static_cast<QuestionKind>(i);
  return std::nullopt;
}

std::optional<Question> question_at(const replay::LogReader& log, std::uint64_t k, std::optional<QuestionKind> wanted) {
  if (k < 1 || k > log.step_count()) return std::nullopt;
  const auto found = candidates(log, k);
  if (wanted) return found[static_cast<std::size_t>(*wanted)];
  for (const QuestionKind q : {QuestionKind::encroached_segment, QuestionKind::terminal_edge, QuestionKind::point,
                               QuestionKind::flip})
    if (found[static_cast<std::size_t>(q)]) return found[static_cast<std::size_t>(q)];
  return std::nullopt;
}

std::optional<Question> next_question(const replay::LogReader& log, std::uint64_t moment,
                                      std::optional<QuestionKind> wanted) {
  for (std::uint64_t k = moment + 1; k <= log.step_count(); ++k)
    if (auto q = question_at(log, k, wanted)) return q;
  return std::nullopt;
}

std::pair<Edge, double> nearest_edge(const replay::Replay& at, Point p, bool segments_only) {
  const auto& v = at.log().vertices();
  Edge best{kNone, kNone};
  double best_d = INFINITY;
  for (const replay::FaceRecord& f : at.slots()) {
    if (f.dead() || f.ghost()) continue;
    for (int i = 0; i < 3; ++i) {
      if (segments_only && !(f.constrained >> i & 1u)) continue;
      const VertexId a = f.v[i], b = f.v[(i + 1) % 3];
      if (a >= v.size() || b >= v.size()) continue;
      const double d = distance_to_segment(p, v[a].point, v[b].point);
      // Ties (an edge seen from both its faces) keep the first: the same edge anyway.
      if (d < best_d) {
        best_d = d;
        best = {std::min(a, b), std::max(a, b)};
      }
    }
  }
  return {best, best_d};
}

Answer grade(const Question& question, const replay::Replay& before, Point click) {
  Answer a;
  a.at = click;
  if (question.kind == QuestionKind::point) {
    a.distance = std::hypot(click.x - question.point.x, click.y - question.point.y);
    a.right = a.distance <= question.tolerance;
    return a;
  }
  const auto [edge, d] = nearest_edge(before, click, question.kind == QuestionKind::encroached_segment);
  a.chosen = edge;
  a.distance = d;
  a.right = edge[0] != kNone && same_edge(question.edge, edge[0], edge[1]);
  return a;
}

std::size_t QuizScore::right() const {
  return static_cast<std::size_t>(std::count_if(answers.begin(), answers.end(), [](const QuizRecord& r) { return r.answer.right; }));
}

std::string QuizScore::summary_json(const replay::LogReader& log) const {
  const auto edge_text = [&](const Edge& e) {
    if (e[0] == kNone) return std::string("null");
    return "\"" + log.vertex_name(e[0]) + "-" + log.vertex_name(e[1]) + "\"";
  };
  std::string out = "{\n  \"asked\": " + std::to_string(answers.size()) + ",\n  \"right\": " + std::to_string(right()) +
                    ",\n  \"answers\": [";
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const QuizRecord& r = answers[i];
    out += i ? ",\n    " : "\n    ";
    out += "{\"step\": " + std::to_string(r.question.step) + ", \"question\": \"" + name(r.question.kind) +
           "\", \"clicked\": [" + number(r.answer.at.x) + ", " + number(r.answer.at.y) + "], \"right\": " +
           (r.answer.right ? "true" : "false") + ", \"distance\": " + number(r.answer.distance);
    if (r.question.kind == QuestionKind::point) {
      out += ", \"true_point\": [" + number(r.question.point.x) + ", " + number(r.question.point.y) +
             "], \"tolerance\": " + number(r.question.tolerance);
    } else {
      out += ", \"true_edge\": " + edge_text(r.question.edge) + ", \"chosen_edge\": " + edge_text(r.answer.chosen);
    }
    out += "}";
  }
  out += answers.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

}  // namespace meshstep::teach
