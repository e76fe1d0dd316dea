#include "state_json.hpp"

#include <algorithm>
#include <cstdio>

#include "compare_view.hpp"
#include "meshstep/scene/pseudocode.hpp"
#include "state_text.hpp"
#include "ui_look.hpp"
#include "teach_script.hpp"
#include "viewer.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

namespace {

// An event as {"step": K, "event": E}, its step counted from 1 as the caption does.
std::string event_json(std::uint64_t e, const replay::LogReader& log) {
  if (e == kNoEvent) return "null";
  return std::string("{\"step\": ").append(std::to_string(log.step_of_event(e) + 1)).append(", \"event\": ").append(std::to_string(e)).append("}");
}

// The selection's story on one line: a triangle's making and replacement, a segment's input
// segment, pieces and splits (null for a vertex, whose history is selection_history).
std::string story_json(const SelectionStory& story, const replay::LogReader* log) {
  if (!log) return "null";
  if (story.triangle.created != kNoEvent) {
    std::string out = std::string("{\"created\": ").append(event_json(story.triangle.created, *log));
    out.append(", \"removed\": ").append(event_json(story.triangle.removed, *log));
    return out.append(", \"slot\": ").append(std::to_string(story.triangle.slot)).append("}");
  }
  const SegmentStory& g = story.segment;
  if (g.segment == kNone) return "null";
  std::string out = std::string("{\"input\": [").append(std::to_string(g.a)).append(", ").append(std::to_string(g.b));
  out.append("], \"pieces\": [");
  for (std::size_t i = 0; i < g.pieces.size(); ++i)
    out.append(i ? ", [" : "[").append(std::to_string(g.pieces[i].first)).append(", ").append(std::to_string(g.pieces[i].second)).append("]");
  out.append("], \"splits\": [");
  for (std::size_t i = 0; i < g.splits.size(); ++i) {
    const SegmentStory::Split& x = g.splits[i];
    out.append(i ? ", " : "").append("{\"step\": ").append(std::to_string(log->step_of_event(x.event) + 1));
    out.append(", \"event\": ").append(std::to_string(x.event)).append(", \"vertex\": ").append(std::to_string(x.vertex));
    out.append(", \"piece\": [").append(std::to_string(x.a)).append(", ").append(std::to_string(x.b)).append("]");
    out.append(", \"at\": ").append(quoted(split_place(x))).append("}");
  }
  return out.append("]}");
}

}  // namespace

std::string state_json(Viewer& v) {
  Session& s = v.session();
  const CursorInfo c = s.cursor_info();
  const Playback& p = s.playback();
  std::string out = "{\n";
  const auto field = [&](const char* key, const std::string& value) {
    out += std::string("  \"") + key + "\": " + value + ",\n";
  };
  field("title", quoted(s.title()));
  field("window_title", quoted(v.window_title));
  field("position", std::to_string(c.position));
  field("event_count", std::to_string(c.event_count));
  field("step", std::to_string(c.step));
  field("in_step", c.within ? "true" : "false");
  field("step_count", std::to_string(c.step_count));
  field("phase", c.phase ? quoted(replay::name(*c.phase)) : "null");
  field("playing", p.playing ? "true" : "false");
  field("speed", number(p.speed));
  field("unit", quoted(name(p.unit)));
  field("color_by", quoted(scene::name(s.options().color_by)));
  field("theme", quoted(theme_name(s.options().theme)));
  std::string layers = "[";
  for (std::size_t i = 0; i < scene::kLayerCount; ++i)
    if (s.layer(static_cast<scene::Layer>(i)))
      layers += std::string(layers.size() > 1 ? ", " : "") + quoted(scene::name(static_cast<scene::Layer>(i)));
  field("layers", layers + "]");
  field("help_open", v.help_open ? "true" : "false");
  field("follow", v.follow ? "true" : "false");
  std::string marks = "{";
  for (int slot = 1; slot <= 9; ++slot)
    if (const auto at = s.bookmark(slot))
      marks += std::string(marks.size() > 1 ? ", " : "") + "\"" + std::to_string(slot) + "\": " + std::to_string(*at);
  field("bookmarks", marks + "}");
  const scene::Camera& cam = v.camera();
  field("camera", "{\"x\": " + number(cam.center().x) + ", \"y\": " + number(cam.center().y) +
                      ", \"pixels_per_unit\": " + number(cam.pixels_per_unit()) + "}");
  // The view: 2D, or 3D (a terrain's run) from the orbit; in 3D the camera is in the orbit's
  // screen plane. The notice: why the last key did nothing, while the canvas shows it.
  field("view", v.view_3d() ? "\"3d\"" : "\"2d\"");
  field("view_3d_available", v.can_view_3d() ? "true" : "false");
  field("orbit", "{\"azimuth\": " + number(v.orbit().azimuth_deg) + ", \"elevation\": " +
                     number(v.orbit().elevation_deg) + ", \"z_scale\": " + number(v.orbit().z_scale) + "}");
  field("notice", v.notice_shown() ? quoted(v.notice()) : "null");
  // Who drew the canvas, and which moment it shows (the cursor's, once settled).
  field("canvas", v.canvas_on_worker() ? "\"worker\"" : "\"main\"");
  field("shown_position", std::to_string(s.shown_position()));
  field("caption", quoted(v.shown_scene().caption));
  const scene::Explanation& e = s.explanation();
  field("explain_heading", quoted(e.heading));
  std::string lines = "[";
  for (const std::string& line : e.lines) lines += std::string(lines.size() > 1 ? ",\n    " : "\n    ") + quoted(line);
  field("explain", lines + "\n  ]");
  if (const replay::LogReader* log = s.log()) {
    const scene::CodeAt code = scene::pseudocode_at(*log, s.shown_position());
    field("code_title", code.code ? quoted(code.code->title) : "null");
    std::string current;
    for (int i = code.line; code.code && i >= 0 && i < code.line + std::max(1, code.lines) &&
                            i < static_cast<int>(code.code->lines.size());
         ++i)
      current += (current.empty() ? "" : " / ") + code.code->lines[static_cast<std::size_t>(i)];
    field("code_line", code.line >= 0 ? quoted(current) : "null");
  }
  const Stats& st = v.stats();
  field("stats", "{\"vertices\": " + std::to_string(st.vertices) + ", \"steiner\": " + std::to_string(st.steiner) +
                     ", \"triangles\": " + std::to_string(st.triangles) + ", \"min_angle\": " + number(st.min_angle) +
                     ", \"max_angle\": " + number(st.max_angle) + "}");
  const auto& invariants = v.invariants().report();
  field("invariants", invariants ? quoted(describe(*invariants))
                                 : v.invariants().error().empty() ? "null" : quoted(v.invariants().error()));
  const SelectionStory& story = v.selection_story();
  std::string steps = "[";
  for (const std::uint64_t k : story.steps) steps += (steps.size() > 1 ? ", " : "") + std::to_string(k);
  field("selection_history", steps + "]");
  field("selection_story", story_json(story, s.log()));
  const ElementIndex& index = v.history();
  std::string built = "null";
  if (index.ready()) {
    built = std::string("{\"seconds\": ").append(number(index.build_seconds()));
    built.append(", \"bytes\": ").append(std::to_string(index.bytes()));
    built.append(", \"vertex_bytes\": ").append(std::to_string(index.vertex_bytes()));
    built.append(", \"slot_bytes\": ").append(std::to_string(index.slot_bytes()));
    built.append(", \"segment_bytes\": ").append(std::to_string(index.segment_bytes())).append("}");
  }
  field("history_index", built);
  const std::string selected = v.selection_text();
  field("selection", selected.empty() ? "null" : quoted(selected));
  if (v.plots().ready() && !v.plots().triangles().empty()) {
    const std::size_t k = std::min<std::size_t>(c.completed, v.plots().triangles().size() - 1);
    field("plots_at_cursor", "{\"triangles\": " + number(v.plots().triangles()[k]) +
                                 ", \"smallest_angle\": " + number(v.plots().smallest_angle()[k]) +
                                 ", \"bad\": " + number(v.plots().bad()[k]) + ", \"steps\": " +
                                 std::to_string(v.plots().triangles().size()) + "}");
  }
  if (s.log()) {
    // The kinds the timeline marks, each with how many the last frame counted (null when it
    // has not counted that kind yet).
    std::string marks_shown = "{";
    for (std::size_t m = 0; m < kMarkCount; ++m) {
      const auto mark = static_cast<Mark>(m);
      if (!v.timeline_marks.has(mark)) continue;
      marks_shown.append(marks_shown.size() > 1 ? ", \"" : "\"").append(name(mark)).append("\": ");
      marks_shown.append(v.timeline().counted(mark) ? std::to_string(v.timeline().total_marks[m]) : "null");
    }
    field("timeline_marks", marks_shown + "}");
  }
  // Presentation: the UI scale, the font atlas it was rasterised into (its texture's
  // height grows with the scale), the panels hidden or not, full screen, the window and the
  // canvas's rectangle. Last: tests of older fields find the camera's by its first "x".
  // A tour's stop and a quiz's score (teach_script.hpp), null when none is on.
  field("tour", tour_state_json(v));
  field("quiz", quiz_state_json(v));
  field("ui_scale", format_ui_scale(v.ui_scale));
  field("font_pixels", number(ImGui::GetIO().Fonts->Fonts.empty() ? 0.0 : ImGui::GetIO().Fonts->Fonts[0]->FontSize));
  field("font_atlas", "{\"width\": " + std::to_string(ImGui::GetIO().Fonts->TexWidth) +
                          ", \"height\": " + std::to_string(ImGui::GetIO().Fonts->TexHeight) + "}");
  field("panels_hidden", v.panels_hidden ? "true" : "false");
  field("full_screen", v.full_screen ? "true" : "false");
  field("window", "{\"width\": " + std::to_string(v.window_width()) + ", \"height\": " +
                      std::to_string(v.window_height()) + "}");
  const ImVec4 r = v.canvas_rect();
  field("canvas_rect", "{\"x\": " + number(r.x) + ", \"y\": " + number(r.y) + ", \"width\": " + number(r.z) +
                           ", \"height\": " + number(r.w) + "}");
  if (v.workbench) out += workbench_state_fields(*v.workbench);  // the workbench's, one a line
  field("scene_builds", std::to_string(s.scene_builds()));
  field("canvas_renders", std::to_string(v.canvas_renders()));
  // Last, so that older tests' first match of a key stays the top-level one.
  out += "  \"runs\": " + runs_state_json(v) + "\n}\n";
  return out;
}

}  // namespace meshstep::viewer
