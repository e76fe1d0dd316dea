// The teaching actions of keys and scripts: a tour's stops (N, P; `tour next|prev|stop K`)
// and the quiz (G, N; `quiz on [KIND]|off|next|answer X Y|save FILE`), in one place so that a
// key and a script's line do the same thing.
#pragma once

#include <string>

#include "script.hpp"

namespace meshstep::viewer {

class Viewer;

// What is wrong with a `tour` or `quiz` action's words, or "" when nothing is.
std::string check_teaching_action(const ScriptAction& action);
// Runs it; throws InputError("SCRIPT:LINE: ...") when it cannot be done (no tour, no
// question left, no open question to answer).
void run_teaching_action(const ScriptAction& action, Viewer& viewer, const std::string& script_path);

// Keys. N: the quiz's next question while it is on, else the tour's next stop. P: the
// tour's previous stop. G: the quiz on (any question) or off. The canvas says why when
// there is nothing to do.
void next_key(Viewer& viewer);
void previous_key(Viewer& viewer);
void quiz_key(Viewer& viewer);

// The viewer's state's "tour" and "quiz" fields (null when none plays).
std::string tour_state_json(Viewer& viewer);
std::string quiz_state_json(const Viewer& viewer);

}  // namespace meshstep::viewer
