#include "state_json.hpp"

#include <algorithm>
#include <cstdio>

#include "pseudocode.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + '"';
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
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
  field("position", std::to_string(c.position));
  field("event_count", std::to_string(c.event_count));
  field("step", std::to_string(c.step));
  field("step_count", std::to_string(c.step_count));
  field("phase", c.phase ? quoted(replay::name(*c.phase)) : "null");
  field("playing", p.playing ? "true" : "false");
  field("speed", number(p.speed));
  field("unit", quoted(name(p.unit)));
  field("color_by", quoted(scene::name(s.options().color_by)));
  field("theme", quoted(s.options().theme == scene::Theme::dark ? "dark" : "light"));
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
  field("caption", quoted(s.scene().caption));
  const scene::Explanation& e = s.explanation();
  field("explain_heading", quoted(e.heading));
  std::string lines = "[";
  for (const std::string& line : e.lines) lines += std::string(lines.size() > 1 ? ",\n    " : "\n    ") + quoted(line);
  field("explain", lines + "\n  ]");
  if (const replay::LogReader* log = s.log()) {
    const CodeAt code = pseudocode_at(*log, *s.cursor());
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
  std::string steps = "[";
  for (const std::uint64_t k : v.selected_vertex_steps()) steps += (steps.size() > 1 ? ", " : "") + std::to_string(k);
  field("selection_history", steps + "]");
  field("history_index", v.history().ready() ? "{\"seconds\": " + number(v.history().build_seconds()) +
                                                  ", \"bytes\": " + std::to_string(v.history().bytes()) + "}"
                                            : "null");
  const std::string selected = v.selection_text();
  field("selection", selected.empty() ? "null" : quoted(selected));
  if (v.plots().ready() && !v.plots().triangles().empty()) {
    const std::size_t k = std::min<std::size_t>(c.step, v.plots().triangles().size() - 1);
    field("plots_at_cursor", "{\"triangles\": " + number(v.plots().triangles()[k]) +
                                 ", \"smallest_angle\": " + number(v.plots().smallest_angle()[k]) +
                                 ", \"bad\": " + number(v.plots().bad()[k]) + ", \"steps\": " +
                                 std::to_string(v.plots().triangles().size()) + "}");
  }
  field("scene_builds", std::to_string(s.scene_builds()));
  out += "  \"canvas_renders\": " + std::to_string(v.canvas_renders()) + "\n}\n";
  return out;
}

}  // namespace meshstep::viewer
