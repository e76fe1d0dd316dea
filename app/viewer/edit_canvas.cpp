// The mouse in edit mode:
//   left click on empty canvas    the tool's element there: a vertex; a segment from the
//                                 polyline's last vertex (a new vertex, or the vertex within
//                                 kSnapPixels); a hole point; a region point (the form's values)
//   left click on a vertex        segment tool: the polyline goes on to it (its first vertex
//                                 closes the polygon and ends the polyline); else selects it
//   left drag on a point          moves it (one edit, made when the button is released)
//   right click on an element     a menu: delete it
//   right click on empty canvas   ends the polyline
//   middle drag                   pans (the left button edits)
// The region tool (EditTool::box): a left drag draws a box; with the lasso shape, the
// pointer's path from press to release is the lasso, closed at the release and simplified
// (lasso_path.hpp). Either is kept for the panel's form, which refines it.
// With the grid on, a click's point rounds to the grid first.
#include "edit_canvas.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lasso_path.hpp"
#include "meshstep/error.hpp"
#include "meshstep/refine/region.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

const char* name(EditTool tool) {
  switch (tool) {
    case EditTool::vertex: return "vertex";
    case EditTool::segment: return "segment";
    case EditTool::hole: return "hole";
    case EditTool::region: return "region";
    case EditTool::box: return "box";
  }
  return "segment";
}

double grid_step(const scene::Camera& camera) {
  const double width = camera.width() / std::max(camera.pixels_per_unit(), 1e-300);
  return std::pow(10.0, std::floor(std::log10(std::max(width / 20.0, 1e-300))));
}

namespace {

constexpr ImU32 kSegment = IM_COL32(0, 70, 140, 255);
constexpr ImU32 kVertex = IM_COL32(0, 70, 140, 255);
constexpr ImU32 kHole = IM_COL32(200, 30, 30, 255);
constexpr ImU32 kRegion = IM_COL32(0, 140, 70, 255);
constexpr ImU32 kSelected = IM_COL32(213, 94, 0, 255);
// The draw list's vertices the input's markers may fill (of 65,536; see edit_canvas).
constexpr int kMarkerVertexBudget = 50000;
constexpr ImU32 kRefused = IM_COL32(220, 0, 0, 255);
constexpr ImU32 kWarned = IM_COL32(230, 140, 0, 255);

void run_edit(WorkbenchHost& host, const auto& edit) {
  try {
    edit(host.bench()->editor());
  } catch (const EditRefused& e) {
    host.say(e.what());
  }
}

}  // namespace

void delete_selected(WorkbenchHost& host) {
  EditCanvasState& st = host.tool;
  st.chain_first.reset();
  st.chain_last.reset();
  if (!host.bench() || !st.selected) return;
  const ElementRef at = *st.selected;
  st.selected.reset();
  run_edit(host, [&](PslgEditor& e) { e.erase(at); });
}

void choose_region_shape(WorkbenchHost& host, bool lasso) {
  EditCanvasState& st = host.tool;
  st.tool = EditTool::box;
  st.lasso_shape = lasso;
  st.chain_first.reset();
  st.chain_last.reset();
  st.lasso_drawing = false;
}

namespace {

// The lasso's press-drag-release: the path grows while the button is down; at the release
// it is simplified and checked, and kept when it makes a simple polygon. `step`: the world
// length of kLassoStepPixels.
void draw_lasso(WorkbenchHost& host, const Point& pointer, double step) {
  EditCanvasState& st = host.tool;
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    st.lasso_drawing = true;
    st.lasso_path.clear();
    st.lasso_path.push_back(pointer);
    return;
  }
  if (!st.lasso_drawing) return;
  const Point& last = st.lasso_path.back();
  // Every quarter step the pointer moves (a pixel): simplify_lasso keeps the path within a
  // quarter step of the ring.
  if (std::hypot(pointer.x - last.x, pointer.y - last.y) >= step / 4.0) st.lasso_path.push_back(pointer);
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
  st.lasso_drawing = false;
  std::vector<Point> ring = simplify_lasso(st.lasso_path, step);
  st.lasso_path.clear();
  if (ring.size() < 3) {
    host.say("lasso: too small to close (draw round the part to refine, then release)");
    return;
  }
  try {
    RefineRegion::polygon(ring);
  } catch (const InputError& e) {
    host.say("lasso: " + e.message() + "; draw it again without crossing its own path");
    return;
  }
  st.lasso = std::move(ring);
  st.box.reset();
  host.say("");
}

}  // namespace

void edit_canvas(WorkbenchHost& host, const scene::Camera& camera, float x, float y, bool hovered) {
  Workbench* bench = host.bench();
  if (!bench || !host.editing) return;
  EditCanvasState& st = host.tool;
  PslgEditor& editor = bench->editor();
  const Pslg& in = editor.input();
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  const auto screen = [&](Point p) {
    const Point s = camera.to_screen(p);
    return ImVec2(static_cast<float>(s.x) + x, static_cast<float>(s.y) + y);
  };
  const ImGuiIO& io = ImGui::GetIO();
  const Point pointer_world = camera.to_world({io.MousePos.x - x, io.MousePos.y - y});
  st.pointer = pointer_world;
  st.pointer_in = hovered;
  const double tolerance = kSnapPixels / camera.pixels_per_unit();
  // Where an element is drawn: the pointer's place while it is dragged.
  const auto where = [&](ElementRef e) {
    return st.dragging && *st.dragging == e ? st.drag_to : editor.position(e);
  };

  // --- The input over the mesh. A window's draw list holds 65,536 vertices (ImGui's 16-bit
  // indices; more is an assertion): a big input's markers (a 21,000-vertex input has 84,000
  // corners) are drawn while there is room, leaving some for what follows.
  const auto room = [&draw] { return draw.VtxBuffer.Size < kMarkerVertexBudget; };
  for (std::uint32_t s = 0; s < in.segments.size() && room(); ++s) {
    const Segment& seg = in.segments[s];
    const bool selected = st.selected && *st.selected == ElementRef{InputElement::segment, s};
    draw.AddLine(screen(where({InputElement::vertex, seg.a})), screen(where({InputElement::vertex, seg.b})),
                 selected ? kSelected : kSegment, selected ? 4.0f : 2.0f);
  }
  for (std::uint32_t v = 0; v < in.points.size() && room(); ++v) {
    const ImVec2 c = screen(where({InputElement::vertex, v}));
    const bool selected = st.selected && *st.selected == ElementRef{InputElement::vertex, v};
    draw.AddRectFilled(ImVec2(c.x - 3.5f, c.y - 3.5f), ImVec2(c.x + 3.5f, c.y + 3.5f), selected ? kSelected : kVertex);
  }
  for (std::uint32_t h = 0; h < in.holes.size() && room(); ++h) {
    const ImVec2 c = screen(where({InputElement::hole, h}));
    draw.AddCircle(c, 7.0f, kHole, 0, 2.0f);
    draw.AddLine(ImVec2(c.x - 5, c.y - 5), ImVec2(c.x + 5, c.y + 5), kHole, 2.0f);
    draw.AddLine(ImVec2(c.x - 5, c.y + 5), ImVec2(c.x + 5, c.y - 5), kHole, 2.0f);
  }
  char label[64];
  for (std::uint32_t r = 0; r < in.regions.size() && room(); ++r) {
    const ImVec2 c = screen(where({InputElement::region, r}));
    const bool selected = st.selected && *st.selected == ElementRef{InputElement::region, r};
    const ImU32 colour = selected ? kSelected : kRegion;
    draw.AddQuadFilled(ImVec2(c.x, c.y - 7), ImVec2(c.x + 7, c.y), ImVec2(c.x, c.y + 7), ImVec2(c.x - 7, c.y), colour);
    std::snprintf(label, sizeof label, "%g", in.regions[r].attribute);
    draw.AddText(ImVec2(c.x + 9, c.y - 8), colour, label);
  }
  // The region to refine: the box or the lasso being drawn, else the last one drawn.
  constexpr ImU32 kBox = IM_COL32(130, 40, 160, 255);
  const auto draw_ring = [&](const std::vector<Point>& ring, bool closed) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) draw.AddLine(screen(ring[i]), screen(ring[i + 1]), kBox, 2.0f);
    if (closed && ring.size() > 2) draw.AddLine(screen(ring.back()), screen(ring.front()), kBox, 2.0f);
  };
  if (st.tool == EditTool::box && !st.lasso_shape && hovered && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 4.0f)) {
    const ImVec2 press = io.MouseClickedPos[0];
    draw.AddRect(ImVec2(std::min(press.x, io.MousePos.x), std::min(press.y, io.MousePos.y)),
                 ImVec2(std::max(press.x, io.MousePos.x), std::max(press.y, io.MousePos.y)), kBox, 0.0f, 0, 2.0f);
  } else if (st.lasso_drawing && !st.lasso_path.empty()) {
    draw_ring(st.lasso_path, false);
    draw.AddLine(screen(st.lasso_path.back()), io.MousePos, kBox, 2.0f);
    draw.AddLine(io.MousePos, screen(st.lasso_path.front()), kBox, 1.0f);  // where the release closes it
  } else if (!st.lasso.empty()) {
    draw_ring(st.lasso, true);
  } else if (st.box) {
    const ImVec2 a = screen(st.box->first), b = screen(st.box->second);
    draw.AddRect(ImVec2(a.x, b.y), ImVec2(b.x, a.y), kBox, 0.0f, 0, 2.0f);
  }
  if (st.chain_last && *st.chain_last < in.points.size() && hovered)
    draw.AddLine(screen(in.points[*st.chain_last]), io.MousePos, kSegment, 1.0f);
  // The notices: the element ringed, the core's words beside it.
  for (const InputNotice& n : bench->notices()) {
    const ImU32 colour = n.refused ? kRefused : kWarned;
    ImVec2 at(x + 12.0f, y + 40.0f);
    if (n.element.kind != InputElement::none) {
      at = screen(editor.position(n.element));
      draw.AddCircle(at, 12.0f, colour, 0, 3.0f);
      at = ImVec2(at.x + 16.0f, at.y - 6.0f);
    }
    const char* text = n.text.c_str();
    const ImVec2 size = ImGui::CalcTextSize(text, text + n.text.size(), false, 420.0f);
    // An element out of view: its words stay on the canvas, at the nearest edge.
    const ImVec2 canvas_max(x + static_cast<float>(camera.width()), y + static_cast<float>(camera.height()));
    at.x = std::clamp(at.x, x + 4.0f, std::max(x + 4.0f, canvas_max.x - size.x - 8.0f));
    at.y = std::clamp(at.y, y + 30.0f, std::max(y + 30.0f, canvas_max.y - size.y - 8.0f));
    draw.AddRectFilled(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2), IM_COL32(255, 255, 255, 235));
    draw.AddRect(ImVec2(at.x - 3, at.y - 2), ImVec2(at.x + size.x + 3, at.y + size.y + 2), colour);
    draw.AddText(nullptr, 0.0f, at, colour, text, text + n.text.size(), 420.0f);
  }

  // --- The mouse.
  // The right-click menu (opened below), drawn while it is open whatever the pointer is
  // over: once open, the popup, not the canvas, is under the pointer (the canvas is no
  // longer hovered), and a menu drawn only on a hovered canvas closed before it was seen.
  if (ImGui::BeginPopup("##edit_menu")) {
    if (st.menu_for) {
      std::snprintf(label, sizeof label, "Delete %s %u", to_string(st.menu_for->kind),
                    st.menu_for->index + static_cast<unsigned>(in.first_index));
      if (ImGui::MenuItem(label)) {
        st.selected = st.menu_for;
        delete_selected(host);
        st.menu_for.reset();
      }
    }
    ImGui::EndPopup();
  }
  if (st.dragging) {
    st.drag_to = pointer_world;
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      const ElementRef e = *st.dragging;
      st.dragging.reset();
      const Point from = editor.position(e);
      if (from.x != st.drag_to.x || from.y != st.drag_to.y) run_edit(host, [&](PslgEditor& ed) { ed.move(e, st.drag_to); });
    }
    return;
  }
  // The lasso: drawn from its press to its release, wherever the pointer goes meanwhile.
  if (st.tool == EditTool::box && st.lasso_shape && (hovered || st.lasso_drawing)) {
    draw_lasso(host, pointer_world, kLassoStepPixels / camera.pixels_per_unit());
    return;
  }
  if (!hovered) return;
  // The box tool: a drag draws the box (kept for the panel's form), not a move.
  if (st.tool == EditTool::box) {
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && io.MouseDragMaxDistanceSqr[0] >= 16.0f) {
      const ImVec2 press = io.MouseClickedPos[0];
      const Point a = camera.to_world({press.x - x, press.y - y});
      st.box = std::pair{Point{std::min(a.x, pointer_world.x), std::min(a.y, pointer_world.y)},
                         Point{std::max(a.x, pointer_world.x), std::max(a.y, pointer_world.y)}};
      st.lasso.clear();
    }
    return;
  }
  const ElementRef under = editor.element_near(pointer_world, tolerance);
  // Pressed on a point, then moved more than a few pixels: that point is dragged.
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Left))
    st.pressed_on = under.kind == InputElement::none || under.kind == InputElement::segment
                        ? std::nullopt
                        : std::optional<ElementRef>(under);
  if (st.pressed_on && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 4.0f)) {
    st.dragging = st.pressed_on;
    st.pressed_on.reset();
    st.drag_to = pointer_world;
    return;
  }
  if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
    if (under.kind == InputElement::none) {
      st.chain_first.reset();
      st.chain_last.reset();
    } else {
      st.menu_for = under;
      ImGui::OpenPopup("##edit_menu");
    }
  }
  if (!ImGui::IsMouseReleased(ImGuiMouseButton_Left) || io.MouseDragMaxDistanceSqr[0] >= 9.0f) return;
  // A click.
  Point p = pointer_world;
  if (st.grid) {
    const double step = grid_step(camera);
    p = {std::round(p.x / step) * step, std::round(p.y / step) * step};
  }
  switch (st.tool) {
    case EditTool::segment: {
      std::optional<std::uint32_t> v = editor.vertex_near(pointer_world, tolerance);
      if (!st.chain_last) {
        if (!v) run_edit(host, [&](PslgEditor& e) { v = e.add_vertex(p); });
        st.chain_first = st.chain_last = v;
        st.selected = v ? std::optional<ElementRef>({InputElement::vertex, *v}) : std::nullopt;
        return;
      }
      const std::uint32_t from = *st.chain_last;
      // One edit, the new end and the segment together (one undo).
      run_edit(host, [&](PslgEditor& e) {
        if (v && *v != from) {
          e.add_segment(from, *v);
        } else if (!v) {
          const std::uint32_t s = e.add_segment(e.input().points[from], p, tolerance);
          v = e.input().segments[s].b;
        }
      });
      if (v && st.chain_first && *v == *st.chain_first) {
        st.chain_first.reset();  // closed: the polygon is done
        st.chain_last.reset();
      } else {
        st.chain_last = v;
      }
      return;
    }
    case EditTool::vertex:
      if (under.kind != InputElement::none) st.selected = under;
      else run_edit(host, [&](PslgEditor& e) { st.selected = ElementRef{InputElement::vertex, e.add_vertex(p)}; });
      return;
    case EditTool::hole:
      if (under.kind != InputElement::none) st.selected = under;
      else run_edit(host, [&](PslgEditor& e) { e.add_hole(p); });
      return;
    case EditTool::box: return;  // (handled above)
    case EditTool::region:
      if (under.kind != InputElement::none) st.selected = under;
      else
        run_edit(host, [&](PslgEditor& e) {
          st.selected = ElementRef{InputElement::region, e.add_region({p, st.region_attribute, st.region_max_area})};
        });
      return;
  }
}

}  // namespace meshstep::viewer
