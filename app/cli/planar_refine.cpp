// A planar refinement run from its operations (planar_refine.hpp): the first refines the
// input, each next one the mesh the one before left, as `refine PREFIX` re-refines.
#include "planar_refine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "console.hpp"
#include "refuse_overwrites.hpp"
#include "json_line.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/esri_grid.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/pslg/input_angles.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/run_header.hpp"
#include "memory_budget.hpp"
#include "mesh_output.hpp"
#include "common/output_prefix.hpp"
#include "record_option.hpp"

namespace meshstep::app {
namespace {

// Progress that is worth seeing on a normal run (refinement can take a while): on standard
// error, unless --quiet.
void note(Verbosity v, const std::string& message) {
  if (v != Verbosity::quiet) {
    std::fprintf(stderr, "meshstep: %s\n", message.c_str());
    std::fflush(stderr);
  }
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "30", "0.125", "1e-06": short and exact enough for messages and the log header.
std::string header_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  return buffer;
}

// Where two segments meet at less than the angle bound, every mesh that keeps them has a
// smaller angle there: said before the run (Triangle's users know the pitfall), and the
// run leaves those triangles as they are and counts them.
void warn_of_small_input_angle(Verbosity verbosity, const std::string& name, const Pslg& input, double min_angle) {
  if (min_angle <= 0.0) return;
  const std::optional<InputAngle> a = smallest_input_angle(input);
  if (!a || a->degrees >= min_angle) return;
  char degrees[32];
  std::snprintf(degrees, sizeof degrees, "%.3g", a->degrees);
  const auto number = [&](std::uint32_t i) { return std::to_string(i + input.first_index); };
  print_warning(verbosity, name + ": segments " + number(a->first) + " and " + number(a->second) + " meet at vertex " +
                               number(a->vertex) + " at " + degrees + " degrees, below --min-angle " +
                               header_number(min_angle) +
                               ": no mesh that keeps them reaches the bound there; the triangles in such corners are "
                               "left as they are, and counted at the end");
}

// Longest-edge midpoints split a bad triangle without removing its small angle: against an
// angle or aspect bound, midpoint-area went on without end on every corpus input at 30
// degrees (28M Steiner vertices when memory ran out). Without a cap of the user's, such a
// run gets one (0: no cap needed).
std::size_t midpoint_shape_cap(const RefineOptions& o, std::size_t input_vertices) {
  const RefineCriteria& c = o.criteria;
  const bool shape_bound = c.min_angle_deg > 0.0 || c.max_angle_deg < 180.0 || c.max_aspect > 0.0;
  if (o.selection != Selection::longest_edge_midpoint || o.insertion != RefineInsertion::delaunay || !shape_bound ||
      c.max_steiner || c.max_triangles)
    return 0;
  return 100'000 + 100 * input_vertices;
}


}  // namespace

namespace {

// One operation made ready to run: its options, and what its messages say of it.
struct PreparedStep {
  const Operation* op = nullptr;
  const AlgorithmInfo* algorithm = nullptr;
  RefineOptions options;
  std::string size_text;  // --size as given (a length or a grid's name; empty: none)
  std::string bounds_text;
  bool no_bound = false;
};


// Reads what an operation names (a size grid, a region polygon) and makes its options.
// Prints the error, prefixed by `origin`, and returns false when it cannot run.
bool prepare_step(const Operation& op, const std::string& origin, int refusal_status, PreparedStep& step,
                  int& status) {
  step.op = &op;
  step.size_text = op.size.value_or("");
  // An ESRI ASCII grid of sizes: the cell holding a triangle's centroid gives its longest
  // edge's bound (none outside the grid, on no-data cells and at values <= 0).
  std::function<double(const Point&)> grid_size;
  if (op.size && !size_length(op)) {
    try {
      auto grid = std::make_shared<io::EsriGrid>(io::read_esri_grid(step.size_text));
      grid_size = [grid](const Point& p) { return grid->at(p, -1.0); };
    } catch (const InputError& e) {
      print_error(origin + "--size: " + e.what());
      status = kExitBadInput;
      return false;
    }
  }
  try {
    step.options = refine_options(op, grid_size);
  } catch (const RunSpecError& e) {
    print_error(origin + e.what());
    status = refusal_status;
    return false;
  }
  // Out-of-range bounds are a usage error, refused before anything is read or printed.
  if (const std::string problem = criteria_problem(step.options.criteria); !problem.empty()) {
    print_error(origin + problem);
    status = refusal_status;
    return false;
  }
  step.algorithm = find_algorithm(op.algorithm);  // (refine_options found it)
  try {
    step.options.region = region_of(op);
  } catch (const InputError& e) {
    print_error(origin + "--region-poly: " + e.what());
    status = kExitBadInput;
    return false;
  }
  const RefineCriteria& criteria = step.options.criteria;
  step.no_bound = criteria.min_angle_deg <= 0.0 && criteria.max_angle_deg >= 180.0 && criteria.max_aspect <= 0.0 &&
                  criteria.max_area <= 0.0 && !criteria.size;
  std::string& text = step.bounds_text;
  const auto bound = [&text](const std::string& words) { text += (text.empty() ? "" : ", ") + words; };
  if (criteria.min_angle_deg > 0.0) bound("min angle " + header_number(criteria.min_angle_deg));
  if (!has_bound(op)) text += " (no bound given: " + std::string(step.algorithm->name) + "'s default)";
  if (criteria.max_angle_deg < 180.0) bound("max angle " + header_number(criteria.max_angle_deg));
  if (criteria.max_aspect > 0.0) bound("max aspect " + header_number(criteria.max_aspect));
  if (criteria.max_area > 0.0) bound("max area " + header_number(criteria.max_area));
  const double size = size_length(op).value_or(0.0);
  if (criteria.size) bound("size " + (size > 0.0 ? header_number(size) : step.size_text));
  if (text.empty()) text = "no bounds";
  if (criteria.max_triangles) bound("at most " + std::to_string(criteria.max_triangles) + " triangles");
  if (criteria.max_steiner) bound("at most " + std::to_string(criteria.max_steiner) + " Steiner vertices");
  if (step.options.region)
    bound("only in " + (op.region->box                ? "the box " + step.options.region->text().substr(4)
                        : !op.region->polygon.empty() ? "a polygon of " + std::to_string(op.region->polygon.size()) +
                                                            " vertices"
                                                      : "the polygon of " + op.region->polygon_file));
  return true;
}

}  // namespace

int run_planar_refine(const PlanarRefineJob& job) {
  const Verbosity verbosity = job.verbosity;
  const auto origin = [&job](std::size_t i) { return i < job.origins.size() ? job.origins[i] : std::string(); };
  std::vector<PreparedStep> steps(job.operations.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    int status = kExitOk;
    if (!prepare_step(job.operations[i], origin(i), job.refusal_status, steps[i], status)) return status;
  }
  // A mesh prefix (PREFIX.node + PREFIX.ele, and PREFIX.area if there) rather than an input
  // file: re-refinement, as Triangle's -r.
  bool re_refine = false, area_file = false;
  if (!io::is_planar_input(job.input)) {
    std::error_code ec;
    re_refine = io::is_mesh_prefix(job.input);
    area_file = re_refine && std::filesystem::exists(job.input + ".area", ec);
  }

  // The memory budget, as a triangle cap (unless the user's own cap is lower).
  std::uint64_t budget = default_memory_budget();
  if (!job.max_memory.empty()) {
    const std::optional<std::uint64_t> parsed = parse_memory(job.max_memory);
    if (!parsed) {
      print_error("--max-memory " + job.max_memory + ": expected a size such as 8G, 500M or 123456 (bytes), or none");
      return kExitUsage;
    }
    budget = *parsed;
  }
  const std::size_t budget_triangles = budget ? std::max<std::uint64_t>(budget / kBytesPerTriangle, 1000) : 0;
  const auto budget_caps = [&](const RefineCriteria& c) {
    return budget_triangles && (!c.max_triangles || c.max_triangles > budget_triangles);
  };
  const std::string budget_words = "the memory budget (" + memory_text(budget) + ", about " +
                                   std::to_string(budget_triangles) + " triangles; --max-memory to change)";
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const PreparedStep& step = steps[i];
    const RefineCriteria& criteria = step.options.criteria;
    // Delaunay refinement is proven to end only to 20.7 degrees (Ruppert) or 28.6 (Shewchuk);
    // in practice each algorithm ends to its registry's known_to_end_deg (34 for off-centers,
    // as Triangle's documentation says of its own), judged with its own selection.
    const AlgorithmInfo* selected =
        step.op->selection ? find_algorithm(selection_info(*step.op->selection).name) : step.algorithm;
    const double known_to_end = (selected ? selected : step.algorithm)->known_to_end_deg;
    if (known_to_end > 0.0 && criteria.min_angle_deg > known_to_end &&
        step.options.insertion != RefineInsertion::bisection)
      print_warning(verbosity, origin(i) + "--min-angle " + header_number(criteria.min_angle_deg) + " is above " +
                                   header_number(known_to_end) + " degrees, past which " +
                                   to_string(step.options.selection) + " refinement is not known to end" +
                                   (criteria.max_triangles || criteria.max_steiner ? ": it stops at your cap"
                                    : budget_caps(criteria)                        ? ": it stops at " + budget_words
                                                                                   : " (and no cap is set)"));
  }
  // Without a bound, a re-refined mesh's PREFIX.area (as with Triangle's -r -a) or a .poly's
  // regional areas may still give one: the latter is known only once the input is read.
  // The steps after the first refine a mesh of the run's own, which has neither.
  const auto refuse_without_bound = [&](std::size_t i) {
    const AlgorithmInfo* algorithm = steps[i].algorithm;
    print_error(origin(i) + std::string(algorithm->name) + " needs a bound: --max-area or --size" +
                (algorithm->insertion == RefineInsertion::bisection ? "" : " (or an angle or aspect bound)") +
                ", or a .poly with regional areas");
    return job.refusal_status;
  };
  const bool first_no_bound = steps[0].no_bound && !area_file;
  if (first_no_bound && (re_refine || ends_with(job.input, ".node"))) return refuse_without_bound(0);
  for (std::size_t i = 1; i < steps.size(); ++i)
    if (steps[i].no_bound) return refuse_without_bound(i);

  // (A mesh prefix has no extension to strip: box.1 becomes box.2, as with Triangle.)
  const std::string prefix =
      job.prefix.empty() ? default_output_prefix(re_refine ? job.input + ".node" : job.input) : job.prefix;
  FileRoles files;
  if (!job.recipe.empty()) files.reads(job.recipe);
  if (re_refine) files.reads_mesh(job.input);
  else files.reads_pslg(job.input);
  for (const Operation& op : job.operations) {
    if (op.size && !size_length(op)) files.reads(*op.size);
    if (op.region && !op.region->polygon_file.empty()) files.reads(op.region->polygon_file);
  }
  const MeshOutput output = MeshOutput::named(prefix);
  if (!job.no_output) output.add_to(files, job.prefix.empty() ? "" : "-o");
  files.writes_log("--record", job.record);
  if (const int refused = refuse_overwrites(files)) return refused;

  Stopwatch clock;
  std::vector<std::string> warnings;
  Pslg input;
  TriMesh mesh;
  RefineReport report;
  double read_ms = 0, write_ms = 0;
  bool stopped_by_budget = false;
  std::size_t input_vertices = 0, input_segments = 0;
  // The last step's criteria, as it ran (with the caps the run added).
  RefineCriteria criteria;
  try {
    TriMesh old;  // the mesh to re-refine
    if (re_refine) {
      note(verbosity, "reading the mesh " + job.input + ".node/.ele (re-refinement)");
      old = io::read_mesh(job.input, &warnings);
      input.points = old.points;
      input.first_index = old.first_index;
      // What the log's header keeps of the input (record_option.hpp: open_log).
      input.holes = old.holes;
      input.regions = old.regions;
      input.has_vertex_markers = !old.vertex_markers.empty();
      input.vertex_markers = old.vertex_markers;
      input.attributes_per_vertex = old.attributes_per_vertex;
      input.vertex_attributes = old.vertex_attributes;
      input.has_segment_markers = old.has_segment_markers;
      input_segments = old.segments.size();
    } else {
      note(verbosity, "reading " + job.input);
      input = io::read_pslg(job.input, &warnings);
      input_segments = input.segments.size();
    }
    read_ms = clock.lap_ms();
    for (const std::string& w : warnings) print_warning(verbosity, w);
    input_vertices = input.points.size();
    if (first_no_bound && !has_regional_area_bounds(input)) return refuse_without_bound(0);
    std::vector<RefineOptions> operations;
    std::vector<bool> budget_capped(steps.size(), false);
    for (std::size_t i = 0; i < steps.size(); ++i) {
      RefineOptions& options = steps[i].options;
      RefineCriteria& step_criteria = options.criteria;
      if (i == 0) warn_of_small_input_angle(verbosity, job.input, input, step_criteria.min_angle_deg);
      if (const std::size_t cap = midpoint_shape_cap(options, input_vertices)) {
        step_criteria.max_steiner = cap;
        print_warning(verbosity, origin(i) +
                                     "longest-edge midpoints need not ever reach an angle or aspect bound (above "
                                     "about 20 degrees they often do not); stopping at " +
                                     std::to_string(cap) + " Steiner vertices (--max-steiner to change)");
      }
      // After the cap above, which a user's cap (and so the budget's) would have turned off.
      budget_capped[i] = budget_caps(step_criteria);
      if (budget_capped[i]) step_criteria.max_triangles = budget_triangles;
      if (verbosity != Verbosity::quiet) {
        options.progress = [](const RefineProgress& p) {
          std::fprintf(stderr, "meshstep: refining: %zu Steiner vertices, %zu triangles, %zu waiting (%.0f s)\n",
                       p.steiner_vertices, p.triangles, p.queued, p.seconds);
        };
      }
      operations.push_back(options);
    }
    // One log for the whole run: the first operation's parameters, and a recipe's operations
    // in its header, each running its phases after the one before (run_header.hpp).
    std::unique_ptr<replay::LogWriter> log;
    if (!job.record.empty()) {
      std::string recipe_lines;
      if (steps.size() > 1)
        for (const Operation& op : job.operations) recipe_lines += print_operation(op) + "\n";
      log = open_log(job.record, re_refine ? job.input + ".node" : job.input, operations[0].algorithm,
                     replay::refine_parameters(operations[0], steps[0].size_text, input_vertices, input.first_index) +
                         (operations[0].region ? " region=" + operations[0].region->text() : ""),
                     operations[0].triangulate.data_structure, operations[0].triangulate.insertion, &input,
                     recipe_lines);
      operations[0].triangulate.record = log.get();
    }
    const auto announce = [&](std::size_t i) {
      const RefineOptions& options = operations[i];
      note(verbosity, std::string(i == 0 ? "triangulating and refining " + std::to_string(input_vertices) +
                                               " vertices, " + std::to_string(input_segments) + " segments: "
                                         : origin(i) + "refining the mesh so far: ") +
                          options.algorithm + " (selection " + to_string(options.selection) + ", " +
                          to_string(options.order) + " order, " +
                          (options.encroachment == Encroachment::lens ? "lens" : "circle") + " encroachment, " +
                          to_string(options.triangulate.data_structure) + ", " + insertion_name(options) + "); " +
                          steps[i].bounds_text);
    };
    // Every operation on the one mesh, in one run (refine.hpp: refine_chain).
    std::vector<RefineReport> reports(operations.size());
    // Kept for the full check of an output that can be small (mesh_output.hpp: a mesh of at
    // most kFullCheckTriangles has fewer vertices than that), when one is written.
    std::optional<Pslg> to_check;
    if (!job.no_output && !re_refine && input.points.size() <= kFullCheckTriangles) to_check = input;
    mesh = re_refine ? refine_mesh_chain(old, operations, reports, announce)
                     : refine_chain(std::move(input), operations, reports, announce);
    report = combined_report(reports);
    for (std::size_t i = 0; i < reports.size(); ++i)
      if (operations[i].region && reports[i].region_triangles == 0)
        print_warning(verbosity, origin(i) + job.input +
                                     ": no triangle has its centroid in the region, so none was refined: the region "
                                     "lies inside triangles larger than it (refine the whole more coarsely first)");
    criteria = operations.back().criteria;
    clock.lap_ms();  // refine_chain() times its own phases (report.triangulate_ms, refine_ms)
    for (const std::string& w : report.triangulation.warnings) print_warning(verbosity, job.input + ": " + w);
    for (std::size_t i = 0; i < reports.size(); ++i)
      stopped_by_budget |= reports[i].stopped_by_cap && budget_capped[i] && mesh.triangles.size() >= budget_triangles;
    if (!job.no_output && (!stopped_by_budget || job.write_partial)) {
      const bool delaunay = std::none_of(operations.begin(), operations.end(), [](const RefineOptions& o) {
        return o.insertion == RefineInsertion::bisection;
      });
      check_before_writing(mesh, to_check ? &*to_check : nullptr, delaunay);
      print_progress(verbosity, "writing " + output.files());
      output.write(mesh);
      write_ms = clock.lap_ms();
    }
    // Last: the log writer's thread finishes its backlog while the mesh is written.
    if (log) {
      log->finish();
      print_progress(verbosity, record_summary(*log));
    }
  } catch (const InputError& e) {
    print_error(input_error_text(job.input, e));
    return kExitBadInput;
  }
  const RefineOptions& options = steps.back().options;

  if (stopped_by_budget) {
    const std::string what = job.input + ": refinement stopped at " + budget_words + " with " +
                             std::to_string(report.bad_triangles) + " of its " + std::to_string(mesh.triangles.size()) +
                             " triangles still failing the bounds";
    if (!job.write_partial) {
      print_error(what + "; nothing written (--write-partial writes the mesh reached)");
      return kExitBadInput;
    }
    print_warning(verbosity, what + "; written as it is (--write-partial)");
  } else if (report.stopped_by_cap) {
    const bool triangle_cap = criteria.max_triangles && mesh.triangles.size() >= criteria.max_triangles;
    print_warning(verbosity, job.input + ": refinement stopped at the " +
                                 (triangle_cap ? "--max-triangles " + std::to_string(criteria.max_triangles)
                                               : "--max-steiner " + std::to_string(criteria.max_steiner)) +
                                 " cap before every triangle met the bounds");
  }
  if (report.unsplittable_segments)
    print_warning(verbosity, job.input + ": " + std::to_string(report.unsplittable_segments) +
                                 " segment splits refused (subsegments too short to split in floating point)");
  if (report.points_out_of_range)
    print_warning(verbosity, job.input + ": " + std::to_string(report.points_out_of_range) +
                                 " bad triangles left as they are: their new point would have a coordinate below "
                                 "2^-140 of the largest, outside the range meshstep computes exactly in");

  const AngleStats angles = angle_stats(mesh);
  if (verbosity != Verbosity::quiet) {
    std::string outcome =
        report.bounds_met ? std::string("bounds met")
                          : "bounds missed by " + std::to_string(report.bad_triangles) + " triangles (" +
                                std::to_string(report.bad_near_small_input_angle) + " near small input angles)";
    // Kept segments are a reason of their own for bounds missed: the count says how often.
    if (options.segment_splits != SegmentSplits::all)
      outcome += "; " + std::string(options.segment_splits == SegmentSplits::none ? "no" : "no boundary") +
                 " segment split, " + std::to_string(report.kept_segment_refusals) +
                 " bad triangles set aside by kept segments";
    std::printf("%s: %zu vertices, %zu segments -> %zu triangles, %zu Steiner vertices (min angle %.2f, "
                "max angle %.2f); %s\n",
                job.input.c_str(), input_vertices, input_segments, mesh.triangles.size(), report.steiner_vertices,
                angles.min_angle_deg, angles.max_angle_deg, outcome.c_str());
    if (!job.no_output && output.single_file())
      std::printf("  written to %s\n", prefix.c_str());
    else if (!job.no_output)
      std::printf("  written to %s.node, .ele, .poly%s\n", prefix.c_str(), mesh.triangle_max_area.empty() ? "" : ", .area");
  }
  if (verbosity == Verbosity::verbose) {
    std::printf("  refinement: %zu segment splits, %zu triangles split, %zu points rejected (encroaching),"
                " %zu bad triangles left at small input angles, %zu unsplittable segments,"
                " %zu Steiner vertices removed\n",
                report.segment_splits, report.triangles_split, report.rejected_points, report.skipped_small_angle,
                report.unsplittable_segments, report.removed_vertices);
    std::printf("  after: %zu triangles below the minimum angle, %zu missing a bound\n", report.below_min_angle,
                report.bad_triangles);
    // (report.triangulation.steiner_vertices is the run's total after refine(), not the
    // crossings alone, so it is not shown here.)
    std::printf("  triangulation: %zu duplicates merged, %zu triangles removed (holes/outside);"
                " mesh %.1f MiB\n",
                report.triangulation.duplicate_vertices, report.triangulation.removed_triangles,
                report.triangulation.mesh_bytes / 1048576.0);
    std::printf("  time: read %.1f ms, triangulate %.1f ms, refine %.1f ms, write %.1f ms\n", read_ms,
                report.triangulate_ms, report.refine_ms, write_ms);
    if (report.phase_ms.size() > 1) {
      std::printf("  phases:");
      for (const auto& [name, phase_ms] : report.phase_ms) std::printf(" %s %.1f ms", name.c_str(), phase_ms);
      std::printf("\n");
    }
  }
  if (job.stats == "json") {
    JsonLine ms;
    ms.field("read", read_ms)
        .field("triangulate", report.triangulate_ms)
        .field("refine", report.refine_ms)
        .field("write", write_ms);
    JsonLine phases;  // the refinement's phases: one, "refine", unless the algorithm has several
    for (const auto& [name, phase_ms] : report.phase_ms) phases.field(name, phase_ms);
    ms.object("phases", phases);
    JsonLine stats;
    stats.field("input", job.input)
        .field("algorithm", options.algorithm)
        .field("selection", std::string(to_string(options.selection)))
        .field("order", std::string(to_string(options.order)))
        .field("encroachment", std::string(options.encroachment == Encroachment::lens ? "lens" : "circle"))
        .field("min_angle_bound", criteria.min_angle_deg)
        .field("vertices", mesh.points.size())
        .field("triangles", mesh.triangles.size())
        .field("segments", mesh.segments.size())
        .field("input_vertices", input_vertices)
        .field("input_segments", input_segments)
        .field("steiner", report.steiner_vertices)
        .field("removed_vertices", report.removed_vertices)
        .field("segment_splits", report.segment_splits)
        .field("triangles_split", report.triangles_split)
        .field("rejected_points", report.rejected_points)
        .field("skipped_small_angle", report.skipped_small_angle)
        .field("unsplittable_segments", report.unsplittable_segments)
        .field("split_segments", std::string(to_string(options.segment_splits)))
        .field("kept_segment_refusals", report.kept_segment_refusals)
        .field("below_min_angle", report.below_min_angle)
        .field("bad_triangles", report.bad_triangles)
        .field("bad_near_small_input_angle", report.bad_near_small_input_angle)
        .field("bounds_met", report.bounds_met)
        .field("stopped_by_cap", report.stopped_by_cap)
        .field("min_angle", angles.min_angle_deg)
        .field("max_angle", angles.max_angle_deg)
        .field("ds", std::string(to_string(options.triangulate.data_structure)))
        .field("insertion", insertion_name(options))
        .object("ms", ms);
    std::printf("%s\n", stats.str().c_str());
  }
  if (job.result) {
    job.result->mesh = std::move(mesh);
    job.result->report = std::move(report);
    job.result->angles = angles;
    job.result->input_vertices = input_vertices;
    job.result->input_segments = input_segments;
    job.result->read_ms = read_ms;
  }
  return kExitOk;
}


}  // namespace meshstep::app
