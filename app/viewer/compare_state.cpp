// The state's `runs` array (compare_view.hpp: runs_state_json).
#include <cstdio>
#include <string>

#include "compare_view.hpp"
#include "state_text.hpp"
#include "viewer.hpp"

namespace meshstep::viewer {

namespace {

std::string stats_json(const Stats& st) {
  return "{\"vertices\": " + std::to_string(st.vertices) + ", \"steiner\": " + std::to_string(st.steiner) +
         ", \"triangles\": " + std::to_string(st.triangles) + ", \"min_angle\": " + number(st.min_angle) +
         ", \"max_angle\": " + number(st.max_angle) + "}";
}

// One run: where its cursor stands (and the moment its canvas shows), its caption, its
// numbers at that moment and its steps per phase over the whole run.
std::string run_json(std::size_t index, Session& s, const std::string& caption, const Stats& stats,
                     std::uint64_t shown, bool leads, const std::vector<std::pair<std::string, std::uint64_t>>& phases,
                     const std::string& extra) {
  const CursorInfo c = s.cursor_info();
  std::string out = "{\"index\": " + std::to_string(index) + ", \"path\": " + quoted(s.title()) +
                    ", \"caption\": " + quoted(caption) + ", \"leads\": " + (leads ? "true" : "false") +
                    ", \"position\": " + std::to_string(c.position) + ", \"shown_position\": " +
                    (shown == UINT64_MAX ? std::string("null") : std::to_string(shown)) +
                    ", \"event_count\": " + std::to_string(c.event_count) + ", \"step\": " + std::to_string(c.step) +
                    ", \"completed\": " + std::to_string(c.completed) + ", \"step_count\": " +
                    std::to_string(c.step_count) + ", \"inserted_vertices\": " +
                    std::to_string(inserted_vertices(*s.log(), c.position)) + ", \"stats\": " + stats_json(stats) +
                    ", \"steps_per_phase\": {";
  for (std::size_t i = 0; i < phases.size(); ++i)
    out += (i ? ", " : "") + quoted(phases[i].first) + ": " + std::to_string(phases[i].second);
  return out + "}" + extra + "}";
}

}  // namespace

std::string runs_state_json(Viewer& v) {
  Session& s = v.session();
  if (!s.log()) return "[]";
  CompareView* compare = v.compare();
  if (!compare) {
    return "[\n    " + run_json(0, s, run_description(*s.log()), v.stats(), s.shown_position(), true,
                              steps_per_phase(*s.log()), "") +
           "\n  ],\n  \"sync\": null,\n  \"difference\": false";
  }
  std::string out = "[";
  for (std::size_t i = 0; i < compare->size(); ++i) {
    const CompareView::Pane& p = compare->pane(i);
    std::string extra = ", \"rect\": {\"x\": " + number(p.rect.x) + ", \"y\": " + number(p.rect.y) +
                        ", \"width\": " + number(p.rect.z) + ", \"height\": " + number(p.rect.w) + "}";
    if (compare->difference)
      extra += ", \"edges_not_in_run_" + std::to_string(compare->compared_with(i) + 1) +
               "\": " + std::to_string(p.different.size());
    out += (i ? ",\n    " : "\n    ") +
           run_json(i, *p.session, p.description, p.stats, p.shown_position, i == compare->leader(), p.phase_steps,
                    extra);
  }
  out += "\n  ],\n  \"sync\": \"" + std::string(name(compare->sync_mode())) + "\",\n  \"difference\": " +
         (compare->difference ? "true" : "false");
  return out;
}

}  // namespace meshstep::viewer
