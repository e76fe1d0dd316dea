// "Compare with...": the input of the run open, run again with another refinement (another
// algorithm, data structure, insertion or bound), live as any input runs, and then shown
// side by side with the run open (compare_view.hpp). No GL and no ImGui here but the panel.
#pragma once

#include <string>

#include "meshstep/replay/log_reader.hpp"
#include "open_input.hpp"

namespace meshstep::viewer {

class Viewer;

struct CompareWith {
  std::string base_log;  // the run open, shown first
  std::string input;     // its input, as its log's header names it
  RefineOptions refine;  // the other run's refinement
};

// The comparison the words ask for ("refine --algorithm circumcenter --min-angle 30", or
// without the leading "refine"). Throws RunSpecError for words that are no refinement, and
// InputError when the log names no input or its input is not there any more.
CompareWith compare_with(const replay::LogReader& log, const std::string& words);

// A first suggestion for the words: the run's own bounds with the other of the two
// classic algorithms (off-center for circumcenter, circumcenter for anything else).
std::string suggested_comparison(const replay::LogReader& log);

// The side panel's "Compare with..." section: the words, and the button that asks the
// run's loop for the run (Viewer::compare_words).
void draw_compare_with(Viewer& viewer, char* words, std::size_t size);

}  // namespace meshstep::viewer
