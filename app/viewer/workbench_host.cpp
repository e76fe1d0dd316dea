#include "workbench_host.hpp"

#include <chrono>
#include <cstdio>
#include <thread>
#include <filesystem>

#include "meshstep/error.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/replay/run_header.hpp"
#include "sibling_program.hpp"
#include "state_text.hpp"

namespace meshstep::viewer {

std::string workbench_state_fields(const WorkbenchHost& host) {
  const Workbench* bench = host.bench();
  std::string out;
  const auto field = [&](const char* key, const std::string& value) {
    out += std::string("  \"") + key + "\": " + value + ",\n";
  };
  field("editing", host.editing ? "true" : "false");
  if (!bench) return out;
  const Pslg& in = bench->editor().input();
  field("input", "{\"vertices\": " + std::to_string(in.points.size()) + ", \"segments\": " +
                     std::to_string(in.segments.size()) + ", \"holes\": " + std::to_string(in.holes.size()) +
                     ", \"regions\": " + std::to_string(in.regions.size()) + "}");
  std::string recipe = "[";
  for (const Operation& op : bench->recipe()) recipe += (recipe.size() > 1 ? ", " : "") + quoted(print_operation(op));
  field("recipe", recipe + "]");
  field("refusal", bench->refused() ? quoted(bench->notices().front().text) : "null");
  std::string notices = "[";
  for (const InputNotice& n : bench->notices())
    notices += std::string(notices.size() > 1 ? ", " : "") + "{\"element\": " + quoted(to_string(n.element.kind)) +
               ", \"index\": " + std::to_string(n.element.index + in.first_index) +
               ", \"refused\": " + (n.refused ? "true" : "false") + ", \"text\": " + quoted(n.text) + "}";
  field("input_notices", notices + "]");
  field("mesh_triangles", std::to_string(bench->mesh_triangles()));
  char ms[32];
  std::snprintf(ms, sizeof ms, "%.3f", bench->remesh_ms());
  field("remesh_ms", ms);
  std::snprintf(ms, sizeof ms, "%.3f", bench->last_cpu_ms());
  field("remesh_cpu_ms", ms);
  field("remesh_live", host.remeshing_live() ? "true" : "false");
  field("live_remeshes", std::to_string(bench->live_runs()));
  field("live_cancelled", std::to_string(host.live_cancelled()));
  field("undo_depth", std::to_string(bench->editor().undo_depth()));
  field("edit_message", quoted(host.message));
  // The region tool: its tool and shape, and the region drawn for the form (the lasso's
  // vertices, simplified, or the box's corners).
  std::string drawn = "null";
  if (!host.tool.lasso.empty()) {
    drawn = "{\"lasso\": [";
    for (std::size_t i = 0; i < host.tool.lasso.size(); ++i)
      drawn += std::string(i ? ", " : "") + "[" + io::shortest_text(host.tool.lasso[i].x) + ", " +
               io::shortest_text(host.tool.lasso[i].y) + "]";
    drawn += "]}";
  } else if (host.tool.box) {
    drawn = "{\"box\": [" + io::shortest_text(host.tool.box->first.x) + ", " + io::shortest_text(host.tool.box->first.y) + ", " +
            io::shortest_text(host.tool.box->second.x) + ", " + io::shortest_text(host.tool.box->second.y) + "]}";
  }
  field("edit_tool", quoted(std::string(name(host.tool.tool)) +
                            (host.tool.tool == EditTool::box ? (host.tool.lasso_shape ? " lasso" : " box") : "")));
  field("drawn_region", drawn);
  field("input_file", quoted(bench->file()));
  return out;
}

void WorkbenchHost::start_new() {
  std::vector<Operation> recipe = bench_ ? bench_->recipe() : std::vector<Operation>{};
  if (opening_) abandoned_.push_back(std::move(opening_));
  live_.reset();
  bench_ = std::make_unique<Workbench>(Pslg{}, std::move(recipe), "");
  tool = {};
  editing = true;
}

std::string WorkbenchHost::start_from(const Session& session, const std::optional<std::vector<Operation>>& known) {
  const replay::LogReader* log = session.log();
  // The input file: the log's (as recorded), or the file shown when it is an input.
  const std::string input = log ? log->header().input : session.title();
  std::error_code ec;
  if (!io::is_planar_input(input) || !std::filesystem::exists(input, ec))
    return input + ": only a run of a .poly or .node input that is still there can be edited (or start a new "
                   "input: Ctrl+N)";
  try {
    Pslg pslg = io::read_pslg(input);
    std::vector<Operation> recipe = known                                       ? *known
                                    : !known_input_.empty() && input == known_input_ ? known_recipe_
                                    : log                                            ? replay::recorded_recipe(log->header(), log->run())
                                                                                     : std::vector<Operation>{};
    // Saved as a .poly: a .node input is saved beside itself with the new extension.
    std::string file = input;
    if (!file.ends_with(".poly")) file = file.substr(0, file.find_last_of('.')) + ".poly";
    if (opening_) abandoned_.push_back(std::move(opening_));
    live_.reset();
    bench_ = std::make_unique<Workbench>(std::move(pslg), std::move(recipe), file);
    if (log) bench_->expect_vertices(log->vertices().size());
    tool = {};
  } catch (const InputError& e) {
    return e.what();
  }
  editing = true;
  return "";
}

std::string WorkbenchHost::toggle(const Session* session) {
  if (editing) {
    editing = false;
    return "";
  }
  if (bench_) {
    editing = true;
    return "";
  }
  if (!session) {
    start_new();
    return "";
  }
  return start_from(*session);
}

std::string WorkbenchHost::save(const std::string& path) {
  if (!bench_) return message = "nothing to save: no input is being edited (E, or Ctrl+N)";
  const std::string file = path.empty() ? bench_->file() : path;
  if (file.empty()) return message = "a new input: type its name under Save as (in the Edit panel)";
  try {
    bench_->save(file);
    message = "saved " + file;
  } catch (const InputError& e) {
    message = e.what();
  }
  return message;
}

void WorkbenchHost::undo() {
  tool.chain_first.reset();
  tool.chain_last.reset();
  tool.selected.reset();
  if (bench_ && !bench_->editor().undo()) message = "nothing to undo";
}

void WorkbenchHost::redo() {
  tool.chain_first.reset();
  tool.chain_last.reset();
  tool.selected.reset();
  if (bench_ && !bench_->editor().redo()) message = "nothing to redo";
}

bool WorkbenchHost::in_view(const scene::Camera& camera) const {
  if (!bench_) return false;
  const Pslg& in = bench_->editor().input();
  if (in.points.empty()) return false;  // nothing to frame
  const BBox view = camera.visible();
  const auto inside = [&](Point p) { return p.x >= view.lo.x && p.x <= view.hi.x && p.y >= view.lo.y && p.y <= view.hi.y; };
  for (const Point& p : in.points)
    if (!inside(p)) return false;
  for (const Point& p : in.holes)
    if (!inside(p)) return false;
  for (const Region& r : in.regions)
    if (!inside(r.point)) return false;
  return true;
}

void WorkbenchHost::reap_abandoned() {
  std::erase_if(abandoned_, [](const std::unique_ptr<LogOpening>& o) { return o->ready(); });
}

void WorkbenchHost::start_opening() {
  if (opening_ || !live_ || live_->running() || !live_->succeeded()) return;
  opening_ = std::make_unique<LogOpening>(live_->log(), bench_->title());
}

std::unique_ptr<Session> WorkbenchHost::take_session(bool take_ended_live) {
  if (!abandoned_.empty()) reap_abandoned();
  if (!bench_) return nullptr;
  if (bench_->stale()) {
    if (live_) {  // a newer edit: the run of the older one is of no use
      live_->cancel();
      if (opening_) abandoned_.push_back(std::move(opening_));
      live_.reset();
      ++live_cancelled_;
    }
    if (!bench_->goes_live()) return bench_->remesh();
    Workbench::LiveCommand c = bench_->live_command(sibling_program("meshstep"));
    try {
      live_ = std::make_unique<LiveRun>(std::move(c.args), bench_->title(), c.log, "");
    } catch (const InputError&) {
      return bench_->remesh();  // no program to run it: in this process, as small runs are
    }
    return nullptr;
  }
  if (!live_ || live_->running()) return nullptr;
  // Its log is opened on a thread of its own (log_opening.hpp), as soon as the run has
  // ended; the session is taken on a later frame, once it is open.
  start_opening();
  if (!take_ended_live || (opening_ && !opening_->ready())) return nullptr;
  std::unique_ptr<Session> opened;
  std::string open_error;
  if (opening_) {
    opened = opening_->take();
    open_error = opening_->error();
  }
  std::unique_ptr<Session> s =
      bench_->finish_live(live_->log(), live_->succeeded(), live_->messages(), live_->output(), live_->cpu_seconds(),
                          1e3 * live_->seconds(), std::move(opened), open_error);
  opening_.reset();
  live_.reset();
  return s;
}

void WorkbenchHost::wait_live() {
  while (live_ && live_->running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  start_opening();
  while (opening_ && !opening_->ready()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

}  // namespace meshstep::viewer
