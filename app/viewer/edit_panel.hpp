// The side panel's Edit section: the Edit button (E), and in edit mode the tools, the grid,
// the input's counts, the recipe, the core's refusal, the selected region point's form,
// Undo / Redo, Save and Save as.
#pragma once

namespace meshstep::viewer {

class Viewer;

void draw_edit_panel(Viewer& viewer);

}  // namespace meshstep::viewer
