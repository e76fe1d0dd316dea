// The side panel's Edit section: in edit mode the tools, the grid,
// the input's counts, the recipe, the core's refusal, the selected region point's form,
// Undo / Redo, Save and Save as.
#pragma once

namespace meshstep::viewer {

class Viewer;

void draw_edit_panel(Viewer& viewer);
// The Edit button (E), on the panel's first line beside Open...: Done while editing.
void edit_button(Viewer& viewer);

}  // namespace meshstep::viewer
