// The start page (`meshstep view` with no INPUT): the bundled examples, each with its line
// and buttons to watch its triangulation or an off-center refinement, the recent files, and
// a field to open any log, mesh or input by name. A file dropped on the window opens too.
#pragma once

#include <string>

#include "open_input.hpp"
#include "settings.hpp"

namespace meshstep::viewer {

// Draws the page over the whole window; sets `picked` (and its refinement) when a file is
// chosen. `settings` may be null (no recent files).
void draw_start_page(int width, int height, const Settings* settings, std::string& picked, RefineOptions& refine);
// Whether the page's New input button was clicked since the last call (then false again).
bool start_page_wants_new();

// A small window saying why the last file could not be opened (or why the run shown
// stopped short): at the bottom, or at the top when a run is shown, clear of its timeline.
// Closing it clears `problem`.
void draw_problem(std::string& problem, const char* title, bool at_top);

}  // namespace meshstep::viewer
