// The workbench's scripted actions (script.hpp lists every action):
//
//   new                          an empty input (the workbench's recipe kept), in edit mode
//   edit add-vertex X Y
//   edit add-segment X0 Y0 X1 Y1 each end snaps to a vertex there or makes one
//   edit move X Y X2 Y2          the vertex (else hole, else region point) at X Y goes to X2 Y2
//   edit delete X Y              the vertex (with its segments), hole, region point or segment at X Y
//   edit hole X Y
//   edit region X Y ATTRIBUTE [MAX_AREA]
//   undo | redo
//   save FILE.poly               the input, written atomically
//   refine-region X0 Y0 X1 Y1 OPTIONS...
//                                a refine operation (OPTIONS as on a recipe line) limited to
//                                the box, appended to the recipe, which runs again
//   refine-lasso X0 Y0 X1 Y1 X2 Y2 ... [-- OPTIONS...]
//                                the same, limited to the polygon through the points in
//                                order (a lasso; at least 3, simple, taken as given: a
//                                script's points are not simplified as a drawn lasso's are)
//   recipe remove|off|on|up|down N
//                                the recipe's operation N (from 1): removed, switched off or
//                                on, moved up or down
//   save-recipe FILE             the recipe file `meshstep run` reads, written atomically
//
// "At X Y" is within 1e-9 of the input's extent (exactly there when it has one point): a
// script names the coordinates it gave. An `edit` with no workbench open starts one from
// the run shown, as E does. An edit that makes no sense (nothing at X Y, a segment there
// already) stops the script, as FILE:LINE: what is wrong; input the core refuses does not:
// the refusal is shown (and in `state`), as it is to a person.
#pragma once

#include <string>

#include "script.hpp"

namespace meshstep::viewer {

class Session;
class WorkbenchHost;

// Whether the verb is one of these actions.
bool is_edit_action(const std::string& verb);
// What is wrong with the action's words, or "".
std::string check_edit_action(const ScriptAction& a);
// Runs it. Throws InputError(script, line, why) for an edit refused, and InputError for a
// file that cannot be written. `session`: the run shown (null on the start page).
void run_edit_action(const ScriptAction& a, WorkbenchHost& host, const Session* session, const std::string& script);

}  // namespace meshstep::viewer
