// meshstep refine: Delaunay refinement of a .poly PSLG (or a .node point set) into a quality
// mesh, by one of the registered algorithms (refine/registry.hpp).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "refine_surface.hpp"
#include "console.hpp"
#include "file_roles.hpp"
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
#include "meshstep/refine/run_spec.hpp"
#include "memory_budget.hpp"
#include "output_prefix.hpp"
#include "operation_options.hpp"
#include "record_option.hpp"
#include "region_option.hpp"

namespace meshstep::app {
namespace {

struct RefineArgs {
  std::string input;
  std::string prefix;
  // The refinement's own options (algorithm, bounds, parts), from the registry's records.
  std::unique_ptr<OperationOptions> operation;
  std::string record;
  RegionArgs region;
  std::string stats;
  bool no_output = false;
  std::string max_memory;  // empty: default_memory_budget()
  bool write_partial = false;
  bool quiet = false;
  bool verbose = false;
};

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

// A 3D surface goes to longest-edge bisection in 3D; only its own options apply.
int refine_surface(const RefineArgs& args, const Operation& op) {
  if (args.region.given()) {
    print_error("--region and --region-poly limit a planar refinement: they do not apply to a 3D surface");
    return kExitUsage;
  }
  for (const std::string& name : args.operation->given()) {
    const ParameterInfo* p = find_parameter(std::string_view(name).substr(2));
    if (p && p->bound && name != "--size" && name != "--max-area") {
      print_error(name + " does not apply to a 3D surface: it takes --size L, --max-area A and --max-triangles N");
      return kExitUsage;
    }
  }
  SurfaceRefineArgs surface;
  surface.input = args.input;
  surface.output = args.prefix;
  surface.operation = op;
  if (op.size && !size_length(op)) {
    print_error("--size: a 3D surface takes a length, not '" + *op.size + "'");
    return kExitUsage;
  }
  surface.max_edge = size_length(op).value_or(0.0);
  surface.stats = args.stats;
  surface.no_output = args.no_output;
  surface.quiet = args.quiet;
  surface.record = args.record;
  return run_refine_surface(surface);
}

int run_refine(const RefineArgs& args) {
  const std::optional<Operation> given = args.operation->operation();
  if (!given) return kExitUsage;
  const Operation& op = *given;
  if (io::is_surface(args.input)) return refine_surface(args, op);
  if (op.flip_dihedral) {
    print_error("--flip-dihedral flips the edges of a 3D surface (.off, .obj, .ply, .stl), not of a planar mesh");
    return kExitUsage;
  }
  const Verbosity verbosity =
      args.quiet ? Verbosity::quiet : args.verbose ? Verbosity::verbose : Verbosity::normal;

  // An ESRI ASCII grid of sizes: the cell holding a triangle's centroid gives its longest
  // edge's bound (none outside the grid, on no-data cells and at values <= 0).
  const std::string size_text = op.size.value_or("");
  const double size = size_length(op).value_or(0.0);
  std::function<double(const Point&)> grid_size;
  if (op.size && !size_length(op)) {
    try {
      auto grid = std::make_shared<io::EsriGrid>(io::read_esri_grid(size_text));
      grid_size = [grid](const Point& p) { return grid->at(p, -1.0); };
    } catch (const InputError& e) {
      print_error(std::string("--size: ") + e.what());
      return kExitBadInput;
    }
  }
  RefineOptions options;
  try {
    options = refine_options(op, grid_size);
  } catch (const RunSpecError& e) {
    print_error(e.what());
    return kExitUsage;
  }
  const AlgorithmInfo* algorithm = find_algorithm(op.algorithm);  // (refine_options found it)
  int region_status = kExitOk;
  options.region = region_of(args.region, region_status);
  if (region_status != kExitOk) return region_status;
  RefineCriteria& criteria = options.criteria;
  // A mesh prefix (PREFIX.node + PREFIX.ele, and PREFIX.area if there) rather than an input
  // file: re-refinement, as Triangle's -r.
  bool re_refine = false, area_file = false;
  if (!io::is_planar_input(args.input)) {
    std::error_code ec;
    re_refine = std::filesystem::exists(args.input + ".node", ec) && std::filesystem::exists(args.input + ".ele", ec);
    area_file = re_refine && std::filesystem::exists(args.input + ".area", ec);
  }

  const bool any_bound = has_bound(op);
  // Without a bound on the command line, a re-refined mesh's PREFIX.area (as with Triangle's
  // -r -a) or a .poly's regional areas may still give one: the latter is known only once the
  // input is read.
  // The memory budget, as a triangle cap (unless the user's own cap is lower).
  std::uint64_t budget = default_memory_budget();
  if (!args.max_memory.empty()) {
    const std::optional<std::uint64_t> parsed = parse_memory(args.max_memory);
    if (!parsed) {
      print_error("--max-memory " + args.max_memory + ": expected a size such as 8G, 500M or 123456 (bytes), or none");
      return kExitUsage;
    }
    budget = *parsed;
  }
  const std::size_t budget_triangles = budget ? std::max<std::uint64_t>(budget / kBytesPerTriangle, 1000) : 0;
  const bool budget_caps = budget_triangles && (!criteria.max_triangles || criteria.max_triangles > budget_triangles);
  const std::string budget_words = "the memory budget (" + memory_text(budget) + ", about " +
                                   std::to_string(budget_triangles) + " triangles; --max-memory to change)";
  // Delaunay refinement is proven to end only to 20.7 degrees (Ruppert) or 28.6 (Shewchuk);
  // in practice each algorithm ends to its registry's known_to_end_deg (34 for off-centers,
  // as Triangle's documentation says of its own), judged with its own selection.
  const AlgorithmInfo* selected =
      op.selection ? find_algorithm(selection_info(*op.selection).name) : algorithm;
  const double known_to_end = (selected ? selected : algorithm)->known_to_end_deg;
  if (known_to_end > 0.0 && criteria.min_angle_deg > known_to_end && options.insertion != RefineInsertion::bisection)
    print_warning(verbosity, "--min-angle " + header_number(criteria.min_angle_deg) + " is above " +
                                 header_number(known_to_end) + " degrees, past which " +
                                 to_string(options.selection) + " refinement is not known to end" +
                                 (criteria.max_triangles || criteria.max_steiner ? ": it stops at your cap"
                                  : budget_caps                                  ? ": it stops at " + budget_words
                                                                                 : " (and no cap is set)"));

  const bool no_bound = criteria.min_angle_deg <= 0.0 && criteria.max_angle_deg >= 180.0 &&
                        criteria.max_aspect <= 0.0 && criteria.max_area <= 0.0 && !criteria.size && !area_file;
  const auto refuse_without_bound = [&] {
    print_error(std::string(algorithm->name) + " needs a bound: --max-area or --size" +
                (algorithm->insertion == RefineInsertion::bisection ? "" : " (or an angle or aspect bound)") +
                ", or a .poly with regional areas");
    return kExitUsage;
  };
  if (no_bound && (re_refine || ends_with(args.input, ".node"))) return refuse_without_bound();

  // (A mesh prefix has no extension to strip: box.1 becomes box.2, as with Triangle.)
  const std::string prefix =
      args.prefix.empty() ? default_output_prefix(re_refine ? args.input + ".node" : args.input) : args.prefix;
  FileRoles files;
  if (re_refine) files.reads_mesh(args.input);
  else files.reads_pslg(args.input);
  if (op.size && !size_length(op)) files.reads(*op.size);
  if (!args.region.poly.empty()) files.reads(args.region.poly);
  files.writes_mesh(args.prefix.empty() ? "" : "-o", args.no_output ? "" : prefix).writes_log("--record", args.record);
  if (const int refused = refuse_overwrites(files)) return refused;
  std::string bounds_text;
  const auto bound = [&bounds_text](const std::string& text) {
    bounds_text += (bounds_text.empty() ? "" : ", ") + text;
  };
  if (criteria.min_angle_deg > 0.0) bound("min angle " + header_number(criteria.min_angle_deg));
  if (!any_bound) bounds_text += " (no bound given: " + std::string(algorithm->name) + "'s default)";
  if (criteria.max_angle_deg < 180.0) bound("max angle " + header_number(criteria.max_angle_deg));
  if (criteria.max_aspect > 0.0) bound("max aspect " + header_number(criteria.max_aspect));
  if (criteria.max_area > 0.0) bound("max area " + header_number(criteria.max_area));
  if (criteria.size) bound("size " + (size > 0.0 ? header_number(size) : size_text));
  if (bounds_text.empty()) bounds_text = "no bounds";
  if (criteria.max_triangles) bound("at most " + std::to_string(criteria.max_triangles) + " triangles");
  if (criteria.max_steiner) bound("at most " + std::to_string(criteria.max_steiner) + " Steiner vertices");
  if (options.region) bound("only in " + (args.region.box.empty() ? "the polygon of " + args.region.poly : "the box " + args.region.box));

  Stopwatch clock;
  std::vector<std::string> warnings;
  Pslg input;
  TriMesh mesh;
  RefineReport report;
  double read_ms = 0, write_ms = 0;
  bool stopped_by_budget = false;
  std::size_t input_vertices = 0, input_segments = 0;
  try {
    TriMesh old;  // the mesh to re-refine
    if (re_refine) {
      note(verbosity, "reading the mesh " + args.input + ".node/.ele (re-refinement)");
      old = io::read_mesh(args.input, &warnings);
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
      note(verbosity, "reading " + args.input);
      input = io::read_pslg(args.input, &warnings);
      input_segments = input.segments.size();
    }
    read_ms = clock.lap_ms();
    for (const std::string& w : warnings) print_warning(verbosity, w);
    input_vertices = input.points.size();
    if (no_bound && !has_regional_area_bounds(input)) return refuse_without_bound();
    warn_of_small_input_angle(verbosity, args.input, input, criteria.min_angle_deg);
    if (const std::size_t cap = midpoint_shape_cap(options, input_vertices)) {
      criteria.max_steiner = cap;
      print_warning(verbosity, "longest-edge midpoints need not ever reach an angle or aspect bound (above about 20 "
                               "degrees they often do not); stopping at " + std::to_string(cap) +
                                   " Steiner vertices (--max-steiner to change)");
    }
    // After the cap above, which a user's cap (and so the budget's) would have turned off.
    if (budget_caps) criteria.max_triangles = budget_triangles;
    note(verbosity, "triangulating and refining " + std::to_string(input_vertices) + " vertices, " +
                        std::to_string(input_segments) + " segments: " + options.algorithm + " (selection " +
                        to_string(options.selection) + ", " + to_string(options.order) + " order, " +
                        (options.encroachment == Encroachment::lens ? "lens" : "circle") + " encroachment, " +
                        to_string(options.triangulate.data_structure) + ", " +
                        insertion_name(options) + "); " + bounds_text);
    if (verbosity != Verbosity::quiet) {
      options.progress = [](const RefineProgress& p) {
        std::fprintf(stderr, "meshstep: refining: %zu Steiner vertices, %zu triangles, %zu waiting (%.0f s)\n",
                     p.steiner_vertices, p.triangles, p.queued, p.seconds);
      };
    }
    std::unique_ptr<replay::LogWriter> log;
    if (!args.record.empty()) {
      log = open_log(args.record, re_refine ? args.input + ".node" : args.input, options.algorithm,
                     replay::refine_parameters(options, size_text, input_vertices, input.first_index) +
                         (options.region ? " region=" + options.region->text() : ""),
                     options.triangulate.data_structure, options.triangulate.insertion, &input);
      options.triangulate.record = log.get();
    }
    mesh = re_refine ? refine_mesh(old, options, &report) : refine(std::move(input), options, &report);
    clock.lap_ms();  // refine() times its own phases (report.triangulate_ms, refine_ms)
    for (const std::string& w : report.triangulation.warnings) print_warning(verbosity, args.input + ": " + w);
    stopped_by_budget = report.stopped_by_cap && budget_caps && mesh.triangles.size() >= budget_triangles;
    if (!args.no_output && (!stopped_by_budget || args.write_partial)) {
      print_progress(verbosity, "writing " + prefix + ".node/.ele/.poly");
      io::write_mesh(prefix, mesh);
      write_ms = clock.lap_ms();
    }
    // Last: the log writer's thread finishes its backlog while the mesh is written.
    if (log) {
      log->finish();
      print_progress(verbosity, record_summary(*log));
    }
  } catch (const InputError& e) {
    print_error(input_error_text(args.input, e));
    return kExitBadInput;
  }

  if (stopped_by_budget) {
    const std::string what = args.input + ": refinement stopped at " + budget_words + " with " +
                             std::to_string(report.bad_triangles) + " of its " + std::to_string(mesh.triangles.size()) +
                             " triangles still failing the bounds";
    if (!args.write_partial) {
      print_error(what + "; nothing written (--write-partial writes the mesh reached)");
      return kExitBadInput;
    }
    print_warning(verbosity, what + "; written as it is (--write-partial)");
  } else if (report.stopped_by_cap) {
    const bool triangle_cap = criteria.max_triangles && mesh.triangles.size() >= criteria.max_triangles;
    print_warning(verbosity, args.input + ": refinement stopped at the " +
                                 (triangle_cap ? "--max-triangles " + std::to_string(criteria.max_triangles)
                                               : "--max-steiner " + std::to_string(criteria.max_steiner)) +
                                 " cap before every triangle met the bounds");
  }
  if (options.region && report.region_triangles == 0)
    print_warning(verbosity, args.input + ": no triangle has its centroid in the region, so none was refined: the "
                                           "region lies inside triangles larger than it (refine the whole more coarsely first)");
  if (report.unsplittable_segments)
    print_warning(verbosity, args.input + ": " + std::to_string(report.unsplittable_segments) +
                                 " segment splits refused (subsegments too short to split in floating point)");
  if (report.points_out_of_range)
    print_warning(verbosity, args.input + ": " + std::to_string(report.points_out_of_range) +
                                 " bad triangles left as they are: their new point would have a coordinate below "
                                 "2^-140 of the largest, outside the range meshstep computes exactly in");

  const AngleStats angles = angle_stats(mesh);
  if (verbosity != Verbosity::quiet) {
    const std::string outcome =
        report.bounds_met ? std::string("bounds met")
                          : "bounds missed by " + std::to_string(report.bad_triangles) + " triangles (" +
                                std::to_string(report.bad_near_small_input_angle) + " near small input angles)";
    std::printf("%s: %zu vertices, %zu segments -> %zu triangles, %zu Steiner vertices (min angle %.2f, "
                "max angle %.2f); %s\n",
                args.input.c_str(), input_vertices, input_segments, mesh.triangles.size(), report.steiner_vertices,
                angles.min_angle_deg, angles.max_angle_deg, outcome.c_str());
    if (!args.no_output)
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
  if (args.stats == "json") {
    JsonLine ms;
    ms.field("read", read_ms)
        .field("triangulate", report.triangulate_ms)
        .field("refine", report.refine_ms)
        .field("write", write_ms);
    JsonLine phases;  // the refinement's phases: one, "refine", unless the algorithm has several
    for (const auto& [name, phase_ms] : report.phase_ms) phases.field(name, phase_ms);
    ms.object("phases", phases);
    JsonLine stats;
    stats.field("input", args.input)
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
  return kExitOk;
}

}  // namespace

Command add_refine_command(CLI::App& parent) {
  auto args = std::make_shared<RefineArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "refine",
      "Delaunay refinement: triangulate a .poly PSLG (or a .node point set), then insert Steiner\n"
      "vertices until every triangle meets the bounds (see 'meshstep list' for the algorithms).\n"
      "Without any bound (--min-angle, --max-angle, --max-aspect, --max-area, --size) the\n"
      "algorithm's default applies: a minimum angle of 20.7 degrees, an aspect ratio of 2.83\n"
      "for lepp-aspect; lepp-bisection and midpoint-area need --max-area or --size. INPUT may\n"
      "also be a mesh PREFIX (PREFIX.node + PREFIX.ele [+ PREFIX.area]) to refine again.");
  cmd->add_option("INPUT", args->input, "Input .poly or .node file (Triangle's formats), or a mesh PREFIX\n"
                  "(PREFIX.node + PREFIX.ele, optionally PREFIX.area) to refine again, as Triangle's -r;\n"
                  "or a 3D surface (.off, .obj, .ply, .stl): --algorithm lepp-bisection with --size L\n"
                  "and/or --max-area A, edges and areas in 3D; -o names the output surface file")->required();

  args->operation = std::make_unique<OperationOptions>(*cmd, OperationKind::refine);
  add_record_option(*cmd, args->record);
  add_region_options(*cmd, args->region);
  cmd->add_option("-o,--output", args->prefix,
                  "Output prefix: writes PREFIX.node, PREFIX.ele, PREFIX.poly\n"
                  "(default: INPUT without extension plus .1, as Triangle does)");
  cmd->add_option("--stats", args->stats,
                  "Print statistics; 'json': the last line of standard output is one JSON object\n"
                  "(vertices, triangles, steiner, segment_splits, bad_triangles, bounds_met,\n"
                  "stopped_by_cap, min_angle, max_angle, ms.read/triangulate/refine/write, ...)")
      ->check(CLI::IsMember({"json"}));
  cmd->add_flag("--no-output", args->no_output, "Refine but write no mesh files (for timing)");
  cmd->add_option("--max-memory", args->max_memory,
                  "Stop before the run takes more memory than SIZE (8G, 500M, ...; none: no\n"
                  "budget). Default: a quarter of this machine's memory. A run stopped there\n"
                  "writes nothing unless --write-partial (exit 1)")
      ->type_name("SIZE");
  cmd->add_flag("--write-partial", args->write_partial,
                "When the memory budget stops the run, write the mesh reached (valid, with\n"
                "triangles that fail the bounds left in it)");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors (and --stats)");
  cmd->add_flag("-v,--verbose", args->verbose, "Also print refinement counts, timings and the record summary");
  cmd->footer(
      "Example: meshstep refine assets/examples/plate.poly --algorithm offcenter --min-angle 30 -o plate_q\n"
      "Exit status: 0 done (even if some triangles miss the bounds; see the summary),\n"
      "1 bad input or bounds out of range, 2 usage error.");
  return {cmd, [args] { return run_refine(*args); }};
}

}  // namespace meshstep::app
