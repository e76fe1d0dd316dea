#include "quiz_mode.hpp"

#include <imgui.h>

#include <cstdio>

#include "meshstep/replay/step_numbers.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {
namespace {

// What gives the next step away at the moment before it: the last step's overlay, its
// highlighted faces, the labels and caption that name it.
constexpr scene::Layer kHidden[] = {scene::Layer::overlay, scene::Layer::highlight, scene::Layer::labels,
                                    scene::Layer::caption};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string edge_name(const replay::LogReader& log, const teach::Edge& e) {
  if (e[0] == kNone) return "none";
  return log.vertex_name(e[0]) + "-" + log.vertex_name(e[1]);
}

std::string escaped(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

bool QuizMode::start(Viewer& viewer, std::optional<teach::QuestionKind> kind, std::string& why) {
  if (!viewer.session().log()) {
    why = "the quiz asks about a recorded run: open a log, or an input to run";
    return false;
  }
  kind_ = kind;
  // From the cursor; a log opens at its end, so with nothing after it, from the start.
  const std::uint64_t here = viewer.session().cursor_info().completed;
  return ask(viewer, here, why) || (here > 0 && ask(viewer, 0, why));
}

bool QuizMode::ask(Viewer& viewer, std::uint64_t from_moment, std::string& why) {
  Session& session = viewer.session();
  const replay::LogReader& log = *session.log();
  std::optional<teach::Question> q = teach::next_question(log, from_moment, kind_);
  if (!q) {
    why = std::string("no ") + (kind_ ? std::string(teach::name(*kind_)) + " " : std::string()) +
          "question after step " + std::to_string(from_moment) + " (the run has " + std::to_string(log.step_count()) +
          " steps)";
    return false;
  }
  question_ = q;
  answered_ = false;
  if (session.playback().playing) session.toggle_play();
  session.go_to_step(static_cast<std::int64_t>(q->step - 1));
  hide(viewer);
  session.set_narration("Step " + std::to_string(q->step) + ": " + teach::prompt(q->kind));
  return true;
}

void QuizMode::hide(Viewer& viewer) {
  Session& session = viewer.session();
  if (!hidden_) saved_layers_ = session.options().layers;
  hidden_ = true;
  for (const scene::Layer l : kHidden) session.set_layer(l, false);
}

void QuizMode::show(Viewer& viewer) {
  if (!hidden_) return;
  for (const scene::Layer l : kHidden) viewer.session().set_layer(l, saved_layers_.has(l));
  hidden_ = false;
}

void QuizMode::stop(Viewer& viewer) {
  show(viewer);
  viewer.session().set_narration("");
  question_.reset();
}

bool QuizMode::answer(Viewer& viewer, Point world) {
  if (!asking()) return false;
  Session& session = viewer.session();
  const replay::LogReader& log = *session.log();
  // Graded against the mesh the question was asked on, wherever the person scrubbed since.
  session.go_to_step(static_cast<std::int64_t>(question_->step - 1));
  const teach::Answer a = teach::grade(*question_, *session.cursor(), world);
  score_.answers.push_back({*question_, a});
  answered_ = true;
  show(viewer);
  session.go_to_step(static_cast<std::int64_t>(question_->step));
  std::string verdict = a.right ? "Right: " : "Not quite: ";
  if (question_->kind == teach::QuestionKind::point) {
    verdict += "the point went " + number(a.distance) + " from your click (right within " +
               number(question_->tolerance) + ").";
  } else {
    verdict += "the answer is edge " + edge_name(log, question_->edge) + (a.right ? "." : ", you chose " + edge_name(log, a.chosen) + ".");
  }
  verdict += " Score: " + std::to_string(score_.right()) + " of " + std::to_string(score_.answers.size()) +
             ". N: the next question.";
  session.set_narration(verdict);
  return true;
}

bool QuizMode::next(Viewer& viewer, std::string& why) {
  const std::uint64_t from = question_ ? question_->step : viewer.session().cursor_info().completed;
  return ask(viewer, from, why);
}

void QuizMode::draw(Viewer& viewer, float x, float y, float width) {
  (void)width;
  if (!question_) return;
  const Session& session = viewer.session();
  const scene::Camera& camera = viewer.camera();
  const auto screen = [&](Point p) {
    const Point s = camera.to_screen(p);
    return ImVec2(x + static_cast<float>(s.x), y + static_cast<float>(s.y));
  };
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  const float k = viewer.ui_scale;
  if (!answered_) {
    // What the question is about: the bad triangle in orange, the point to go in in blue.
    if (session.cursor_info().position != replay::step_position(*session.log(), question_->step - 1)) return;
    const auto& v = session.log()->vertices();
    const auto& t = question_->triangle;
    if (t[0] < v.size() && t[1] < v.size() && t[2] < v.size())
      draw.AddTriangle(screen(v[t[0]].point), screen(v[t[1]].point), screen(v[t[2]].point), IM_COL32(230, 110, 0, 255),
                       4.0f * k);
    if (question_->hint) {
      draw.AddCircleFilled(screen(*question_->hint), 7.0f * k, IM_COL32(0, 90, 200, 255));
      draw.AddCircle(screen(*question_->hint), 7.0f * k, IM_COL32(255, 255, 255, 255), 0, 2.0f * k);
    }
    return;
  }
  if (score_.answers.empty()) return;
  if (session.cursor_info().position != replay::step_position(*session.log(), question_->step)) return;
  const teach::QuizRecord& r = score_.answers.back();
  const ImU32 right = IM_COL32(0, 150, 60, 255), chosen = r.answer.right ? right : IM_COL32(200, 30, 30, 255);
  const auto& v = session.log()->vertices();
  const auto edge_line = [&](const teach::Edge& e, ImU32 colour, float thickness) {
    if (e[0] >= v.size() || e[1] >= v.size()) return;
    draw.AddLine(screen(v[e[0]].point), screen(v[e[1]].point), colour, thickness * k);
  };
  if (r.question.kind == teach::QuestionKind::point) {
    const ImVec2 truth = screen(r.question.point), click = screen(r.answer.at);
    draw.AddLine(click, truth, IM_COL32(60, 60, 60, 200), 1.5f * k);
    draw.AddCircle(truth, 9.0f * k, right, 0, 3.0f * k);
  } else {
    if (!r.answer.right) edge_line(r.answer.chosen, chosen, 4.0f);
    edge_line(r.question.edge, right, 5.0f);
  }
  // The click: a cross, green when right.
  const ImVec2 c = screen(r.answer.at);
  const float arm = 7.0f * k;
  draw.AddLine(ImVec2(c.x - arm, c.y - arm), ImVec2(c.x + arm, c.y + arm), chosen, 3.0f * k);
  draw.AddLine(ImVec2(c.x - arm, c.y + arm), ImVec2(c.x + arm, c.y - arm), chosen, 3.0f * k);
}

std::string QuizMode::state_json(const Viewer& viewer) const {
  (void)viewer;
  std::string out = "{\"question\": ";
  out += question_ ? "\"" + std::string(teach::name(question_->kind)) + "\"" : std::string("null");
  out += ", \"step\": " + (question_ ? std::to_string(question_->step) : std::string("null"));
  out += ", \"answered\": " + std::string(answered_ ? "true" : "false");
  out += ", \"asked\": " + std::to_string(score_.answers.size()) + ", \"right\": " + std::to_string(score_.right());
  if (!score_.answers.empty()) {
    const teach::QuizRecord& r = score_.answers.back();
    out += ", \"last\": {\"right\": " + std::string(r.answer.right ? "true" : "false") +
           ", \"distance\": " + number(r.answer.distance) + "}";
  }
  out += ", \"prompt\": " + (question_ && !answered_ ? "\"" + escaped(teach::prompt(question_->kind)) + "\"" : std::string("null"));
  return out + "}";
}

}  // namespace meshstep::viewer
