// Scripted mode: a list of actions run with a fixed frame time, for tests and for
// reproducible teaching material. One action per line; `#` starts a comment.
//
//   seek step 45 | seek event 300 | seek start | seek end
//   frames N            draw N frames, touching nothing
//   play N              play for N frames, then pause
//   key CHORD           press a key for one frame: Space, Shift+Right, Ctrl+3, F2, ?
//   type TEXT           type the rest of the line into the ImGui field that has the keyboard
//                       (the file dialog's path, say), in one frame
//   toggle LAYER        switch a layer (fill, edges, highlight, overlay, segments, ...)
//   color-by NAME       none, angle, quality, area, region, age
//   speed X             steps (or events, phases) per second, 0.25 to 1000
//   unit event|step|phase
//   toggle-marks KIND   mark a kind on the timeline, or stop: splits, rejected, cavities,
//                       flips, refine, triangulate (timeline_marks.hpp)
//   view 2d|3d          the canvas in 2D, or in 3D (a terrain's run: a log with heights; for
//                       any other the script stops, saying why)
//   orbit AZ EL         the 3D view's azimuth and elevation, in degrees (elevation -90..90)
//   z-scale K           the 3D view's heights multiplied by K (> 0)
//   ui-scale S          every font and panel scaled by S (0.75 to 3, in steps of 0.25), as
//                       Ctrl+= / Ctrl+- do; takes a frame (the fonts are rasterised again)
//   theme NAME          light, dark or high-contrast (Shift+T: high contrast / light)
//   panels show|hide    the side panel and the timeline (Tab); hidden, the canvas is the window
//   full-screen on|off  as F11 (off screen there is no window: the notice says so)
//   mouse X Y           move the pointer to pixel X, Y of the window
//   click               press and release the left button where the pointer is
//   select X Y          select what is at world point X, Y, as a click there does (in 3D too,
//                       X, Y are a point of the plane)
//   drag DX DY          drag with the left button by DX, DY pixels (over 4 frames): pans in
//                       2D, turns the orbit in 3D
//   drag-path DX1 DY1 DX2 DY2 ...
//                       press the left button, move by each DX, DY pixels in turn (one frame
//                       each), release: a lasso drawn by hand
//   wait-until FILE SECONDS
//                       frames go on, the script touching neither mouse nor keys, so that
//                       the window's real events (xdotool's, a person's) are the viewer's,
//                       until FILE exists; after SECONDS without it the script stops, saying so
//   wait-input SECONDS  the same for SECONDS of wall-clock time
//   wheel N             turn the wheel N notches (positive: zoom in)
//   screenshot FILE     the window with its UI, as PNG
//   canvas FILE         the canvas alone (the renderer's picture), PNG or SVG
//   state FILE          the viewer's state as JSON (cursor, playback, options, panel text)
//   check               check every step boundary (valid, Delaunay) and wait for it
//   wait                wait for the background work of an opened log (the elements' history
//                       index, the plots over the whole run)
//   open FILE           open a log, mesh or input as a dropped file would (an input is
//                       triangulated); without INPUT the script starts on the start page
//   sync step|vertices|fraction   runs side by side: how the others follow the timeline's run
//   difference on|off   runs side by side: the difference overlay (D)
//   compare-with OPTIONS  run the open run's input again with these refine options, live,
//                       then show both side by side ("Compare with...")
//   tour next|prev      the tour's next (previous) stop; tour stop K: its K-th (from 1)
//   quiz on [KIND]      predict the next step: questions of KIND (point, flip, terminal-edge,
//                       encroached-segment; any when none); quiz answer X Y: a click at world
//                       point X, Y; quiz next; quiz save FILE (the summary, JSON); quiz off
//   quit
//   new | edit WHAT ... | undo | redo | save FILE.poly | refine-region ... | refine-lasso ...
//                       the workbench: an input edited and re-meshed at once (edit_script.hpp)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace meshstep::viewer {

struct ScriptAction {
  std::string verb;
  std::vector<std::string> args;
  int line = 0;
};

// Reads and checks a script; throws InputError("FILE:LINE: what is wrong").
std::vector<ScriptAction> read_script(const std::string& path);

}  // namespace meshstep::viewer
