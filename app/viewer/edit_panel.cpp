#include "edit_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "edit_keys.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "viewer.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

namespace {

// The region tool's form (issue 27 item 3), from the registry's records: the shape (box or
// lasso), the algorithm, then each of its bounds with the registry's help and default;
// "Refine the box" (or "Refine the lasso") appends the operation, limited to the region, to
// the recipe, which runs again at once.
void draw_region_form(WorkbenchHost& host, Workbench& bench) {
  EditCanvasState& st = host.tool;
  static int algorithm = 0;
  static char values[16][32] = {};
  const std::span<const AlgorithmInfo> all = algorithms();
  int shape = st.lasso_shape ? 1 : 0;
  ImGui::TextUnformatted("region:");
  ImGui::SameLine();
  ImGui::RadioButton("box (B)", &shape, 0);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("drag a box over the mesh");
  ImGui::SameLine();
  ImGui::RadioButton("lasso (Shift+B)", &shape, 1);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("press, drag round the part to refine, release to close");
  if ((shape == 1) != st.lasso_shape) choose_region_shape(host, shape == 1);
  const bool lasso = !st.lasso.empty();
  if (lasso) {
    ImGui::Text("lasso of %zu vertices", st.lasso.size());
  } else if (st.box) {
    ImGui::Text("box %.4g, %.4g to %.4g, %.4g", st.box->first.x, st.box->first.y, st.box->second.x, st.box->second.y);
  } else if (st.lasso_shape) {
    ImGui::TextWrapped("Press on the mesh, drag round the part to refine and release: the lasso closes, and the "
                       "operation below refines the triangles whose centroid is in it.");
  } else {
    ImGui::TextWrapped("Drag a box over the mesh: the operation below refines the triangles whose centroid is in it.");
  }
  algorithm = std::clamp(algorithm, 0, static_cast<int>(all.size()) - 1);
  if (ImGui::BeginCombo("algorithm", all[static_cast<std::size_t>(algorithm)].name.data())) {
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (ImGui::Selectable(all[i].name.data(), static_cast<int>(i) == algorithm)) algorithm = static_cast<int>(i);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%.*s", static_cast<int>(all[i].description.size()), all[i].description.data());
    }
    ImGui::EndCombo();
  }
  std::size_t k = 0;
  for (const ParameterInfo& p : refine_parameters()) {
    if (!p.bound || k >= 16) continue;
    ImGui::SetNextItemWidth(120.0f);
    ImGui::InputTextWithHint(p.name.data(), p.default_text.empty() ? "(none)" : p.default_text.data(), values[k], sizeof values[k]);
    if (ImGui::IsItemHovered() && !p.help.empty()) ImGui::SetTooltip("%.*s", static_cast<int>(p.help.size()), p.help.data());
    ++k;
  }
  ImGui::BeginDisabled(!st.box && !lasso);
  if (ImGui::SmallButton(lasso || (!st.box && st.lasso_shape) ? "Refine the lasso" : "Refine the box")) {
    // The recipe line's words: what `refine-region` and a recipe file take.
    std::vector<std::string> words{"refine", "--algorithm", std::string(all[static_cast<std::size_t>(algorithm)].name)};
    k = 0;
    for (const ParameterInfo& p : refine_parameters()) {
      if (!p.bound || k >= 16) continue;
      if (values[k][0] != '\0') {
        words.push_back("--" + std::string(p.name));
        words.push_back(values[k]);
      }
      ++k;
    }
    if (lasso) {
      // Its vertices written out (--region-polygon): the recipe stays one file.
      std::string ring;
      for (const Point& p : st.lasso)
        ring += (ring.empty() ? "" : ",") + io::shortest_text(p.x) + "," + io::shortest_text(p.y);
      words.push_back("--region-polygon");
      words.push_back(std::move(ring));
    } else {
      char box[160];
      std::snprintf(box, sizeof box, "%.17g,%.17g,%.17g,%.17g", st.box->first.x, st.box->first.y, st.box->second.x,
                    st.box->second.y);
      words.push_back("--region");
      words.push_back(box);
    }
    try {
      bench.append_operation(parse_operation(words));
      host.say("");
    } catch (const RunSpecError& e) {
      host.say(std::string(lasso ? "Refine the lasso: " : "Refine the box: ") + e.what());
    }
  }
  ImGui::EndDisabled();
}

}  // namespace

void edit_button(Viewer& v) {
  if (!v.workbench) return;
  ImGui::SameLine();
  if (ImGui::SmallButton(v.workbench->editing ? "Done" : "Edit")) edit_key(v, EditKey::toggle);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("E: edit the input, re-meshed at each edit");
}

void draw_edit_panel(Viewer& v) {
  WorkbenchHost* host = v.workbench;
  if (!host) return;
  if (!host->editing) return;  // (the Edit button is beside Open..., edit_button())
  Workbench& bench = *host->bench();
  const PslgEditor& e = bench.editor();
  const Pslg& in = e.input();
  if (!ImGui::CollapsingHeader("Edit the input", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ImGui::SmallButton("Stop editing (E)")) edit_key(v, EditKey::toggle);
  ImGui::SameLine();
  if (ImGui::SmallButton("New")) edit_key(v, EditKey::new_input);
  ImGui::SameLine();
  ImGui::BeginDisabled(!e.can_undo());
  if (ImGui::SmallButton("Undo")) host->undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!e.can_redo());
  if (ImGui::SmallButton("Redo")) host->redo();
  ImGui::EndDisabled();

  EditCanvasState& st = host->tool;
  int tool = static_cast<int>(st.tool);
  ImGui::TextUnformatted("A click on empty canvas makes a:");
  for (int t = 0; t <= static_cast<int>(EditTool::box); ++t) {
    if (t > 0 && t != static_cast<int>(EditTool::box)) ImGui::SameLine();
    const bool box = t == static_cast<int>(EditTool::box);
    if (ImGui::RadioButton(box ? "region: refine a box or a lasso of the mesh" : name(static_cast<EditTool>(t)), &tool,
                           t)) {
      st.chain_first.reset();
      st.chain_last.reset();
    }
  }
  st.tool = static_cast<EditTool>(tool);
  ImGui::Checkbox("snap to grid", &st.grid);
  if (st.tool == EditTool::box) draw_region_form(*host, bench);
  ImGui::TextDisabled("drag: move; right click: delete; middle drag: pan");
  // Counts in words that agree with them ("1 hole"), formatted by ImGui: no allocation.
  const auto plural = [](std::size_t n) { return n == 1 ? "" : "s"; };
  ImGui::Text("%zu %s, %zu segment%s, %zu hole%s, %zu region%s", in.points.size(),
              in.points.size() == 1 ? "vertex" : "vertices", in.segments.size(), plural(in.segments.size()),
              in.holes.size(), plural(in.holes.size()), in.regions.size(), plural(in.regions.size()));
  // The recipe (issue 27 item 4): each operation switched on or off, moved, removed; the
  // run is made again at once.
  if (bench.recipe().empty()) ImGui::TextUnformatted("recipe: the triangulation alone");
  else ImGui::TextUnformatted("recipe (run in this order):");
  // What a button asked for, done after the list is drawn (it changes the list).
  enum class Change { none, on, off, up, down, remove } change = Change::none;
  std::size_t changed_at = 0;
  // The operation whose line is being edited (SIZE_MAX: none), and the line.
  static std::size_t editing = SIZE_MAX;
  static char line[2048] = "";
  static bool focus_line = false;  // the field takes the keys once, when the edit starts
  for (std::size_t i = 0; i < bench.recipe().size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    bool on = bench.operation_on(i);
    if (ImGui::Checkbox("##on", &on)) change = on ? Change::on : Change::off, changed_at = i;
    ImGui::SameLine();
    if (ImGui::SmallButton("^")) change = Change::up, changed_at = i;
    ImGui::SameLine();
    if (ImGui::SmallButton("v")) change = Change::down, changed_at = i;
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) change = Change::remove, changed_at = i;
    ImGui::SameLine();
    if (ImGui::SmallButton("e")) {
      editing = i;
      focus_line = true;
      std::snprintf(line, sizeof line, "%s", bench.recipe_lines()[i].c_str());
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("edit this operation's line");
    ImGui::SameLine();
    ImGui::TextWrapped("%zu. %s", i + 1, bench.recipe_labels()[i].c_str());
    ImGui::PopID();
  }
  if (editing < bench.recipe().size()) {
    // The line in the recipe's words (refine --algorithm ... --min-angle ...): Enter runs it.
    ImGui::Text("operation %zu (Enter: run it, Esc: leave it):", editing + 1);
    ImGui::SetNextItemWidth(-1.0f);
    if (std::exchange(focus_line, false)) ImGui::SetKeyboardFocusHere();
    const bool entered = ImGui::InputText("##operation", line, sizeof line, ImGuiInputTextFlags_EnterReturnsTrue);
    if (entered) {
      try {
        bench.replace_operation(editing, parse_operation(std::string_view(line)));
        editing = SIZE_MAX;
      } catch (const RunSpecError& e) {
        host->say(std::string("operation ") + std::to_string(editing + 1) + ": " + e.what());
      }
    } else if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
      editing = SIZE_MAX;
    }
  } else {
    editing = SIZE_MAX;
  }
  switch (change) {
    case Change::none: break;
    case Change::on:
    case Change::off: bench.switch_operation(changed_at, change == Change::on); break;
    case Change::up:
    case Change::down: bench.move_operation(changed_at, change == Change::up ? -1 : +1); break;
    case Change::remove: bench.remove_operation(changed_at); break;
  }
  ImGui::Text("mesh: %zu triangles, made in %.1f ms", bench.mesh_triangles(), bench.remesh_ms());
  for (const InputNotice& n : bench.notices()) {
    ImGui::PushStyleColor(ImGuiCol_Text, n.refused ? ImVec4(0.85f, 0.0f, 0.0f, 1.0f) : ImVec4(0.8f, 0.45f, 0.0f, 1.0f));
    ImGui::TextWrapped("%s%s", n.refused ? "refused (the last good mesh stays): " : "", n.text.c_str());
    ImGui::PopStyleColor();
  }
  if (!host->message.empty()) ImGui::TextWrapped("%s", host->message.c_str());

  // The region point's form: the selected one's values, else the next one's.
  const bool region_selected = st.selected && st.selected->kind == InputElement::region &&
                               st.selected->index < in.regions.size();
  double attribute = region_selected ? in.regions[st.selected->index].attribute : st.region_attribute;
  // Shown as 0 when there is no bound: the input keeps Triangle's -1 for that, which the
  // label's "(0: none)" contradicted.
  double max_area = std::max(0.0, region_selected ? in.regions[st.selected->index].max_area : st.region_max_area);
  ImGui::TextUnformatted(region_selected ? "Selected region point:" : "Next region point:");
  // The fields as wide as the panel leaves beside the longer label: at ImGui's default
  // width (two thirds of the panel) "max area (0: none)" was cut at 1280x720.
  const float field_width = std::max(
      60.0f, ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("max area (0: none)").x -
                 ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::SetNextItemWidth(field_width);
  bool changed = ImGui::InputDouble("attribute", &attribute, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SetNextItemWidth(field_width);
  changed |= ImGui::InputDouble("max area (0: none)", &max_area, 0.0, 0.0, "%.6g",
                                ImGuiInputTextFlags_EnterReturnsTrue);
  if (changed) {
    if (!(max_area > 0.0)) max_area = -1.0;  // none, as a .poly writes it
    if (region_selected) {
      Region r = in.regions[st.selected->index];
      r.attribute = attribute;
      r.max_area = max_area;
      try {
        bench.editor().set_region(st.selected->index, r);
      } catch (const EditRefused& x) {
        host->say(x.what());
      }
    } else {
      st.region_attribute = attribute;
      st.region_max_area = max_area;
    }
  }

  if (ImGui::SmallButton("Save (Ctrl+S)")) edit_key(v, EditKey::save);
  static char save_as[512] = "";
  ImGui::SetNextItemWidth(-80.0f);
  const bool entered = ImGui::InputText("##saveas", save_as, sizeof save_as, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::SmallButton("Save as") || entered) && save_as[0] != '\0') {
    const std::size_t n = std::strlen(save_as);
    if (n < 5 || std::strcmp(save_as + n - 5, ".poly") != 0) host->say("Save as: the name must end in .poly");
    else v.notify(host->save(save_as));
  }
  // The recipe beside the input (INPUT.recipe), for `meshstep run INPUT.recipe INPUT.poly`.
  if (ImGui::SmallButton("Save recipe")) {
    if (bench.file().empty()) {
      host->say("Save recipe: save the input first (it is written beside it)");
    } else {
      const std::string& file = bench.file();
      const std::size_t dot = file.find_last_of('.');
      const std::string path = (dot == std::string::npos ? file : file.substr(0, dot)) + ".recipe";
      try {
        bench.save_recipe(path);
        host->say("saved " + path);
      } catch (const InputError& e) {
        host->say(e.what());
      }
    }
  }
  ImGui::Separator();
}

}  // namespace meshstep::viewer
