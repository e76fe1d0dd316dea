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

// A small window at the bottom saying why the last file could not be opened.
void draw_problem(const std::string& problem);

}  // namespace meshstep::viewer
