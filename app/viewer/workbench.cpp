#include "workbench.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "common/file_roles.hpp"
#include "common/run_log.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/io/write_pslg.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/run_header.hpp"

namespace meshstep::viewer {

namespace fs = std::filesystem;

ElementRef element_named(const std::string& message, int first_index) {
  // The core names elements as "vertex 3", "hole point 1", "region point 2", "segment 5";
  // the first it names is the one drawn (a range message names the smaller coordinate's
  // element first, which is the odd one out).
  static constexpr std::pair<const char*, InputElement> kNames[] = {
      {"hole point ", InputElement::hole},
      {"region point ", InputElement::region},
      {"vertex ", InputElement::vertex},
      {"segment ", InputElement::segment},
  };
  std::size_t best_at = std::string::npos;
  ElementRef found;
  for (const auto& [word, kind] : kNames) {
    for (std::size_t at = message.find(word); at != std::string::npos; at = message.find(word, at + 1)) {
      const std::size_t digits = at + std::char_traits<char>::length(word);
      if (digits >= message.size() || message[digits] < '0' || message[digits] > '9') continue;
      // "point " inside "hole point " must not be read as another word: the longer names
      // are tried first and an earlier match wins.
      if (at < best_at) {
        const long number = std::strtol(message.c_str() + digits, nullptr, 10);
        if (number >= first_index) {
          best_at = at;
          found = {kind, static_cast<std::uint32_t>(number - first_index)};
        }
      }
      break;
    }
  }
  return found;
}

std::string recipe_label(const std::string& line) {
  static constexpr std::string_view kOption = "--region-polygon ";
  std::string out;
  std::size_t from = 0;
  for (std::size_t at = line.find(kOption); at != std::string::npos; at = line.find(kOption, from)) {
    const std::size_t value = at + kOption.size();
    const std::size_t end = std::min(line.find(' ', value), line.size());
    const std::size_t commas = static_cast<std::size_t>(std::count(line.begin() + static_cast<std::ptrdiff_t>(value),
                                                                   line.begin() + static_cast<std::ptrdiff_t>(end), ','));
    out.append(line, from, value - from);
    out += "(lasso of " + std::to_string((commas + 1) / 2) + " points)";
    from = end;
  }
  out.append(line, from, std::string::npos);
  return out;
}

Workbench::Workbench(Pslg input, std::vector<Operation> recipe, std::string file)
    : editor_(std::move(input)), recipe_(std::move(recipe)), file_(std::move(file)) {
  for (const Operation& op : recipe_) recipe_lines_.push_back(print_operation(op));
  for (const std::string& line : recipe_lines_) recipe_labels_.push_back(recipe_label(line));
  enabled_.assign(recipe_.size(), true);
  static std::atomic<int> count{0};
  folder_ = (fs::temp_directory_path() /
             ("meshstep-workbench-" + std::to_string(::getpid()) + "-" + std::to_string(count++)))
                .string();
  std::error_code ec;
  fs::remove_all(folder_, ec);
  fs::create_directories(folder_, ec);
  if (ec) throw InputError(folder_, 0, "cannot make the workbench's temporary folder: " + ec.message());
}

Workbench::~Workbench() {
  std::error_code ec;
  fs::remove_all(folder_, ec);
}

std::string Workbench::temporary(const std::string& name) const { return (fs::path(folder_) / name).string(); }

void Workbench::recipe_changed() {
  recipe_lines_.clear();
  recipe_labels_.clear();
  for (const Operation& op : recipe_) recipe_lines_.push_back(print_operation(op));
  for (const std::string& line : recipe_lines_) recipe_labels_.push_back(recipe_label(line));
  ++recipe_revision_;
}

void Workbench::append_operation(Operation op) {
  recipe_.push_back(std::move(op));
  enabled_.push_back(true);
  recipe_changed();
}

void Workbench::remove_operation(std::size_t i) {
  if (i >= recipe_.size()) return;
  recipe_.erase(recipe_.begin() + static_cast<std::ptrdiff_t>(i));
  enabled_.erase(enabled_.begin() + static_cast<std::ptrdiff_t>(i));
  recipe_changed();
}

void Workbench::replace_operation(std::size_t i, Operation op) {
  if (i >= recipe_.size()) return;
  recipe_[i] = std::move(op);
  recipe_changed();
}

void Workbench::move_operation(std::size_t i, int direction) {
  const std::size_t j = direction < 0 ? i - 1 : i + 1;
  if (i >= recipe_.size() || j >= recipe_.size()) return;
  std::swap(recipe_[i], recipe_[j]);
  const bool on = enabled_[i];
  enabled_[i] = enabled_[j];
  enabled_[j] = on;
  recipe_changed();
}

void Workbench::switch_operation(std::size_t i, bool on) {
  if (i >= recipe_.size() || enabled_[i] == on) return;
  enabled_[i] = on;
  recipe_changed();
}

std::string Workbench::recipe_text() const {
  std::string text = "# made in meshstep view's workbench: meshstep run RECIPE INPUT\n";
  for (std::size_t i = 0; i < recipe_.size(); ++i)
    text += (enabled_[i] ? "" : "# switched off: ") + recipe_lines_[i] + "\n";
  return text;
}

void Workbench::save_recipe(const std::string& path) const {
  // The input edited is the user's file: a recipe saved over it would lose it.
  if (const std::optional<std::string> clash =
          app::FileRoles().reads_pslg(file_).writes("save-recipe", path, "recipe file").clash())
    throw InputError(path, 0, *clash);
  io::write_file_atomically(path, recipe_text());
}

std::string Workbench::title() const { return file_.empty() ? std::string("new input") : file_; }

void Workbench::save(const std::string& path) {
  io::write_pslg(path, editor_.input());
  file_ = path;
}

// A hole point that removes no triangle does nothing; the triangulator says nothing of it.
// Found by triangulating without it: the same count of triangles means it removed none
// (it lies outside every domain the segments close, or in another hole).
void Workbench::find_idle_holes(const Pslg& input) {
  // A person's few holes on an input drawn by hand: each costs a triangulation more per edit,
  // which a file's thousands of holes, or a big input, would not afford.
  if (input.holes.empty() || input.holes.size() > 16 || input.points.size() > 20000) return;
  TriangulateOptions plain;
  const std::size_t with_all = triangulate(input, plain).triangles.size();
  for (std::size_t h = 0; h < input.holes.size(); ++h) {
    Pslg without = input;
    without.holes.erase(without.holes.begin() + static_cast<std::ptrdiff_t>(h));
    if (triangulate(std::move(without), plain).triangles.size() == with_all)
      notices_.push_back({{InputElement::hole, static_cast<std::uint32_t>(h)},
                          "hole point " + std::to_string(h + input.first_index) +
                              " removes nothing: it lies outside every domain the segments close (or in another hole)",
                          false});
  }
}

namespace {

double thread_cpu_ms() {
  timespec t{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

}  // namespace

std::unique_ptr<Session> Workbench::shown(const std::string& log) {
  std::unique_ptr<Session> session = Session::open_log(log);
  session->to_end();  // the mesh made, at the end of its run
  return shown(std::move(session), log);
}

std::unique_ptr<Session> Workbench::shown(std::unique_ptr<Session> session, const std::string& log) {
  session->set_title(title());
  has_mesh_ = true;
  std::error_code ec;
  if (!shown_log_.empty() && shown_log_ != log) fs::remove(shown_log_, ec);  // open still if a session holds it
  shown_log_ = log;
  return session;
}

std::unique_ptr<Session> Workbench::remesh() {
  const auto started = std::chrono::steady_clock::now();
  const double cpu_started = thread_cpu_ms();
  made_revision_ = editor_.revision() + recipe_revision_;
  ++remeshes_;
  notices_.clear();
  const Pslg& input = editor_.input();
  const std::string poly = temporary("input.poly");
  const std::string log = temporary("run-" + std::to_string(remeshes_) + ".mslog");
  std::unique_ptr<Session> session;
  if (input.points.empty()) {
    // Nothing to mesh yet (New): not a refusal to draw in red, just the empty canvas.
    remesh_ms_ = 0.0;
    mesh_triangles_ = 0;
    has_mesh_ = false;
    return Session::still(input, title());
  }
  try {
    // The input as a file, as `meshstep run` reads it: the log's header names it and keeps
    // its checksum.
    io::write_pslg(poly, input);
    const std::uint64_t n = input.points.size();
    RefineReport first;
    // The operations switched on, in order.
    std::vector<Operation> run;
    for (std::size_t i = 0; i < recipe_.size(); ++i)
      if (enabled_[i]) run.push_back(recipe_[i]);
    if (run.empty()) {
      TriangulateOptions options;
      std::unique_ptr<replay::LogWriter> writer =
          app::open_log(log, poly, "triangulate", replay::triangulate_parameters(false, n, input.first_index),
                        options.data_structure, options.insertion, &input);
      options.record = writer.get();
      TriangulateReport report;
      const TriMesh mesh = triangulate(input, options, &report);
      writer->finish();
      mesh_triangles_ = mesh.triangles.size();
      last_vertices_ = mesh.points.size();
      first.triangulation = std::move(report);
    } else {
      std::vector<RefineOptions> operations;
      for (const Operation& op : run) {
        RefineOptions o = refine_options(op);
        o.region = region_of(op);
        operations.push_back(std::move(o));
      }
      std::string recipe_lines;
      if (run.size() > 1)
        for (const Operation& op : run) recipe_lines += print_operation(op) + "\n";
      const std::string size_text = run[0].size.value_or("");
      std::unique_ptr<replay::LogWriter> writer =
          app::open_log(log, poly, operations[0].algorithm,
                        replay::refine_parameters(operations[0], size_text, n, input.first_index) +
                            (operations[0].region ? " region=" + operations[0].region->text() : ""),
                        operations[0].triangulate.data_structure, operations[0].triangulate.insertion, &input,
                        recipe_lines);
      operations[0].triangulate.record = writer.get();
      std::vector<RefineReport> reports(operations.size());
      const TriMesh mesh = refine_chain(input, operations, reports);
      writer->finish();
      mesh_triangles_ = mesh.triangles.size();
      last_vertices_ = mesh.points.size();
      first = std::move(reports[0]);
    }
    session = shown(log);
    for (const std::string& w : first.triangulation.warnings)
      notices_.push_back({element_named(w, input.first_index), w, false});
    find_idle_holes(input);
  } catch (const InputError& e) {
    notices_.insert(notices_.begin(), {element_named(e.message(), input.first_index), e.message(), true});
  } catch (const RunSpecError& e) {
    notices_.insert(notices_.begin(), {ElementRef{}, e.what(), true});
  }
  std::error_code ec;
  if (!session) {
    fs::remove(log, ec);
    fs::remove(log + ".partial", ec);
    // Until there is a good mesh, and after New, the input alone is shown (its points and
    // segments).
    if (!has_mesh_ || input.points.empty()) session = Session::still(input, title());
  }
  cpu_ms_ = thread_cpu_ms() - cpu_started;
  remesh_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  return session;
}

}  // namespace meshstep::viewer
