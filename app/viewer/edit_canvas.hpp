// Edit mode on the canvas: the input drawn over the mesh (segments, vertices, hole and
// region points), the core's refusals and warnings next to the element they name, and the
// mouse as the editing tool (edit_canvas.cpp says which click does what).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/pslg/pslg_editor.hpp"
#include "meshstep/scene/camera.hpp"

namespace meshstep::viewer {

class WorkbenchHost;

// What a click on empty canvas makes; `box` is the region tool: a box dragged, or a lasso
// drawn, over the mesh, to refine it (the panel's form says how).
enum class EditTool { vertex, segment, hole, region, box };
const char* name(EditTool tool);

// The tool's state between frames (kept by the workbench host, so that it outlives the
// viewer each new run makes).
struct EditCanvasState {
  EditTool tool = EditTool::segment;
  // The polyline being drawn with the segment tool: its first and last vertex.
  std::optional<std::uint32_t> chain_first, chain_last;
  // An element being dragged: where it was when the drag began, where it is drawn now.
  std::optional<ElementRef> pressed_on;  // the point under the left button's press
  std::optional<ElementRef> dragging;
  Point drag_to{};
  // The element last clicked (Delete deletes it; a region point's values are in the form).
  std::optional<ElementRef> selected;
  std::optional<ElementRef> menu_for;  // the right-click menu's element
  bool grid = false;                   // clicks snap to a grid (its step from the zoom)
  // The box tool's box (world corners, low then high), once dragged.
  std::optional<std::pair<Point, Point>> box;
  // The region tool's shape: the lasso (press, drag round, release to close) or the box.
  bool lasso_shape = false;
  // The lasso: the path being drawn (world points, kLassoStepPixels apart), and the ring
  // last closed (simplified, simple; empty: none). A new one replaces the box, and a box
  // the lasso: the form refines the one shown.
  std::vector<Point> lasso_path, lasso;
  bool lasso_drawing = false;
  // The values a new region point gets (the form's).
  double region_attribute = 1.0, region_max_area = -1.0;
  // The pointer's world position, as the last frame saw it (the status line shows it).
  Point pointer{};
  bool pointer_in = false;
};

// Vertices within this many pixels of a click are snapped to.
inline constexpr double kSnapPixels = 8.0;

// The grid's step for a camera: a power of ten about a twentieth of the view's width.
double grid_step(const scene::Camera& camera);

// Draws the input and the notices over the canvas at (x, y), and, when `hovered`, takes the
// mouse's left and right buttons as edits. Draws and does nothing when the host is not
// editing. Allocates nothing on a frame where nothing is clicked.
void edit_canvas(WorkbenchHost& host, const scene::Camera& camera, float x, float y, bool hovered);

// Delete: the selected element goes (and the polyline being drawn ends).
void delete_selected(WorkbenchHost& host);

// B and Shift+B: the region tool, with the box or the lasso.
void choose_region_shape(WorkbenchHost& host, bool lasso);

}  // namespace meshstep::viewer
