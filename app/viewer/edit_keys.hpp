// The workbench's keys (keys.cpp's table calls these): E, Ctrl+N, Ctrl+S, Ctrl+Z,
// Ctrl+Shift+Z and Ctrl+Y, Delete, and B and Shift+B (the region tool: box, lasso). Each does nothing but say why on the canvas when the
// viewer has no workbench (a viewer made by a test) or nothing is being edited.
#pragma once

namespace meshstep::viewer {

class Viewer;

enum class EditKey { toggle, new_input, save, undo, redo, erase, region_box, region_lasso };
void edit_key(Viewer& viewer, EditKey key);

}  // namespace meshstep::viewer
