#include "teach_script.hpp"

#include <cstdlib>

#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {
namespace {

bool is_count(const std::string& s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos; }

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

}  // namespace

std::string check_teaching_action(const ScriptAction& a) {
  const auto n = a.args.size();
  if (a.verb == "tour") {
    if (n == 1 && (a.args[0] == "next" || a.args[0] == "prev")) return "";
    if (n == 2 && a.args[0] == "stop" && is_count(a.args[1]) && a.args[1] != "0") return "";
    return "expected: tour next | tour prev | tour stop K (K from 1)";
  }
  if (n >= 1 && a.args[0] == "on") {
    if (n == 1 || (n == 2 && (a.args[1] == "any" || teach::parse_question_kind(a.args[1])))) return "";
    return "expected: quiz on [any|point|flip|terminal-edge|encroached-segment]";
  }
  if (n == 1 && (a.args[0] == "off" || a.args[0] == "next")) return "";
  if (n == 3 && a.args[0] == "answer" && is_number(a.args[1]) && is_number(a.args[2])) return "";
  if (n == 2 && a.args[0] == "save") return "";
  return "expected: quiz on [KIND] | quiz off | quiz next | quiz answer X Y | quiz save FILE";
}

void run_teaching_action(const ScriptAction& a, Viewer& viewer, const std::string& script_path) {
  const auto refuse = [&](const std::string& why) {
    throw InputError(script_path, static_cast<std::size_t>(a.line), a.verb + " " + a.args[0] + ": " + why);
  };
  if (a.verb == "tour") {
    TourGuide* tour = viewer.tour();
    if (!tour) refuse("no tour plays (meshstep view --tour FILE)");
    if (a.args[0] == "next") {
      if (!tour->next(viewer)) refuse("there is no stop after this one");
    } else if (a.args[0] == "prev") {
      if (!tour->previous(viewer)) refuse("there is no stop before this one");
    } else {
      const std::size_t k = std::strtoull(a.args[1].c_str(), nullptr, 10);
      if (!tour->go(viewer, k - 1)) refuse("the tour has " + std::to_string(tour->stop_count()) + " stops");
    }
    return;
  }
  std::string why;
  const std::string& what = a.args[0];
  if (what == "on") {
    std::optional<teach::QuestionKind> kind;
    if (a.args.size() == 2 && a.args[1] != "any") kind = teach::parse_question_kind(a.args[1]);
    if (!viewer.start_quiz(kind, why)) refuse(why);
  } else if (what == "off") {
    viewer.stop_quiz();
  } else if (!viewer.quiz()) {
    refuse("the quiz is off ('quiz on' first)");
  } else if (what == "next") {
    if (!viewer.quiz()->next(viewer, why)) refuse(why);
  } else if (what == "answer") {
    const Point p{std::strtod(a.args[1].c_str(), nullptr), std::strtod(a.args[2].c_str(), nullptr)};
    if (!viewer.quiz()->answer(viewer, p)) refuse("no open question (answered already: 'quiz next')");
  } else if (what == "save") {
    io::write_file_atomically(a.args[1], viewer.quiz()->score().summary_json(*viewer.session().log()));
  }
}

void next_key(Viewer& viewer) {
  std::string why;
  if (viewer.quiz()) {
    if (!viewer.quiz()->next(viewer, why)) viewer.notify("quiz: " + why);
  } else if (viewer.tour()) {
    if (!viewer.tour()->next(viewer)) viewer.notify("tour: this is the last stop");
  } else {
    viewer.notify("N: the next stop of a tour (meshstep view --tour FILE) or the quiz's next question (G)");
  }
}

void previous_key(Viewer& viewer) {
  if (viewer.tour()) {
    if (!viewer.tour()->previous(viewer)) viewer.notify("tour: this is the first stop");
  } else {
    viewer.notify("P: the previous stop of a tour (meshstep view --tour FILE)");
  }
}

void quiz_key(Viewer& viewer) {
  if (viewer.quiz()) {
    viewer.stop_quiz();
    return;
  }
  std::string why;
  if (!viewer.start_quiz(std::nullopt, why)) viewer.notify("quiz: " + why);
}

std::string tour_state_json(Viewer& viewer) {
  TourGuide* tour = viewer.tour();
  if (!tour) return "null";
  if (!viewer.quiz()) tour->update(viewer);  // as the next frame will: the cursor may have moved
  std::string steps = "[";
  for (const std::uint64_t k : tour->steps()) steps += (steps.size() > 1 ? ", " : "") + std::to_string(k);
  return "{\"stop\": " + std::to_string(tour->current() + 1) + ", \"stops\": " + std::to_string(tour->stop_count()) +
         ", \"at_stop\": " + (tour->at_stop() ? "true" : "false") + ", \"steps\": " + steps + "]" +
         ", \"caption\": " + quoted(tour->at_stop() ? tour->tour().stops[tour->current()].caption : "") +
         ", \"narration\": " + quoted(viewer.session().narration()) + "}";
}

std::string quiz_state_json(const Viewer& viewer) {
  const QuizMode* quiz = viewer.quiz();
  return quiz ? quiz->state_json(viewer) : "null";
}

}  // namespace meshstep::viewer
