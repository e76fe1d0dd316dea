// The viewer's predict-the-next-step mode (teach/quiz.hpp): the cursor goes to the moment
// before a step that asks something, what would give the answer away (the overlay, the
// highlight, the labels and the caption) is hidden, and the student clicks. The viewer then
// shows the step, the click and the right answer (the true point, the right edge), and the
// running score. `G` switches it on and off, N asks the next question; scripts say
// `quiz on [KIND]`, `quiz answer X Y`, `quiz next`, `quiz save FILE`, `quiz off`.
#pragma once

#include <optional>
#include <string>

#include "meshstep/scene/scene.hpp"
#include "meshstep/teach/quiz.hpp"

namespace meshstep::viewer {

class Viewer;

class QuizMode {
 public:
  // Starts asking questions of this kind (none: any) from the cursor; false, with the
  // reason in `why`, when the run has no such question after the cursor.
  bool start(Viewer& viewer, std::optional<teach::QuestionKind> kind, std::string& why);
  // Puts the layers back as they were.
  void stop(Viewer& viewer);
  bool asking() const { return question_ && !answered_; }
  // Grades a click (world point) and shows the step; false when no question is open.
  bool answer(Viewer& viewer, Point world);
  // The next question after the one answered (or skipped); false at the run's end.
  bool next(Viewer& viewer, std::string& why);

  const teach::QuizScore& score() const { return score_; }
  const std::optional<teach::Question>& question() const { return question_; }
  bool answered() const { return answered_; }
  std::optional<teach::QuestionKind> kind() const { return kind_; }

  // The question, or the verdict and the score, over the canvas; the click and the answer
  // drawn on it (camera: world to canvas pixels, the canvas at x, y).
  void draw(Viewer& viewer, float x, float y, float width);
  // {"on": ..., "question": ..., "asked": N, "right": N, ...} for the viewer's state.
  std::string state_json(const Viewer& viewer) const;

 private:
  bool ask(Viewer& viewer, std::uint64_t from_moment, std::string& why);
  void hide(Viewer& viewer);
  void show(Viewer& viewer);

  std::optional<teach::QuestionKind> kind_;
  std::optional<teach::Question> question_;
  bool answered_ = false;
  teach::QuizScore score_;
  scene::LayerSet saved_layers_ = scene::LayerSet::all();
  bool hidden_ = false;
};

}  // namespace meshstep::viewer
