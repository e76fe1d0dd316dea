// meshstep triangulate: Delaunay triangulation of a .node, constrained Delaunay of a .poly.
#include <optional>
#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "refuse_overwrites.hpp"
#include "json_line.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/delaunay/voronoi.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "mesh_output.hpp"
#include "common/output_prefix.hpp"
#include "operation_options.hpp"
#include "record_option.hpp"
#include "meshstep/replay/run_header.hpp"

namespace meshstep::app {
namespace {

struct TriangulateArgs {
  std::string input;
  std::string prefix;
  // --ds, --insertion and --convex-hull, from the registry's records.
  std::unique_ptr<OperationOptions> operation;
  std::string stats;
  std::string record;
  bool no_output = false;
  bool edges = false;
  bool neighbors = false;
  bool voronoi = false;
  bool quiet = false;
  bool verbose = false;
};

int run_triangulate(const TriangulateArgs& args) {
  const Verbosity verbosity =
      args.quiet ? Verbosity::quiet : args.verbose ? Verbosity::verbose : Verbosity::normal;
  const std::optional<Operation> given = args.operation->operation();
  if (!given) return kExitUsage;
  const Operation& op = *given;
  TriangulateOptions options;
  options.data_structure = op.data_structure;
  options.insertion = op.insertion == PointInsertion::cavity ? Insertion::cavity : Insertion::flip;
  options.convex_hull = op.convex_hull;
  options.compute_neighbors = args.neighbors && !args.no_output;
  // Only what is printed is measured: at 1e6 points the angles cost a quarter of a run,
  // and converting a mesh nothing writes or measures a tenth.
  const bool prints_angles = verbosity == Verbosity::verbose || args.stats == "json";
  options.keep_mesh = !args.no_output || prints_angles;
  const std::string prefix = args.prefix.empty() ? default_output_prefix(args.input) : args.prefix;
  const MeshOutput output = MeshOutput::named(prefix);
  if (output.single_file() && (args.edges || args.neighbors)) {
    print_error(std::string(args.edges ? "-e/--edges" : "-n/--neighbors") +
                " writes a file of Triangle's beside PREFIX.node: it needs -o PREFIX, not the one file -o " + prefix);
    return kExitUsage;
  }
  FileRoles files;
  files.reads_pslg(args.input);
  if (!args.no_output) output.add_to(files, args.prefix.empty() ? "" : "-o");
  if (const int refused = refuse_overwrites(files.writes_log("--record", args.record))) return refused;

  Stopwatch clock;
  std::vector<std::string> warnings;
  Pslg input;
  TriMesh mesh;
  TriangulateReport report;
  double read_ms = 0, triangulate_ms = 0, write_ms = 0;
  std::size_t input_vertices = 0, input_segments = 0;
  try {
    print_progress(verbosity, "reading " + args.input);
    input = io::read_pslg(args.input, &warnings);
    read_ms = clock.lap_ms();
    for (const std::string& w : warnings) print_warning(verbosity, w);
    input_vertices = input.points.size();
    input_segments = input.segments.size();
    print_progress(verbosity, "triangulating " + std::to_string(input_vertices) + " vertices, " +
                                  std::to_string(input_segments) + " segments (" +
                                  to_string(options.data_structure) + ", " +
                                  to_string(options.insertion) + ")");
    std::unique_ptr<replay::LogWriter> log;
    if (!args.record.empty()) {
      log = open_log(args.record, args.input, "triangulate",
                     replay::triangulate_parameters(op.convex_hull, input_vertices, input.first_index),
                     options.data_structure, options.insertion, &input);
      options.record = log.get();
    }
    std::optional<Pslg> to_check;  // for the full check of a small output (mesh_output.hpp)
    if (!args.no_output && input.points.size() <= kFullCheckTriangles) to_check = input;
    mesh = triangulate(std::move(input), options, &report);
    triangulate_ms = clock.lap_ms();
    for (const std::string& w : report.warnings) print_warning(verbosity, args.input + ": " + w);
    if (!args.no_output) {
      check_before_writing(mesh, to_check ? &*to_check : nullptr, true);
      print_progress(verbosity, "writing " + output.files());
      output.write(mesh, {.edges = args.edges, .neighbors = args.neighbors});
      if (args.voronoi) {
        const std::string base = output.single_file() ? std::filesystem::path(prefix).replace_extension().string() : prefix;
        print_progress(verbosity, "writing " + base + ".v.node/.v.edge");
        write_voronoi(base, voronoi_of(mesh), mesh.first_index);
      }
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

  const AngleStats angles = prints_angles ? angle_stats(mesh) : AngleStats{};
  if (verbosity != Verbosity::quiet) {
    std::printf("%s: %zu vertices, %zu segments -> %zu triangles, %zu Steiner vertices%s\n",
                args.input.c_str(), input_vertices, input_segments, report.triangles,
                report.steiner_vertices,
                args.no_output ? " (not written)"
                : (", written to " + (output.single_file() ? prefix : prefix + ".*")).c_str());
  }
  if (verbosity == Verbosity::verbose) {
    std::printf("  angles: min %.4f, max %.4f degrees; %zu duplicates merged; %zu segment splits;"
                " %zu triangles removed (holes/outside)\n",
                angles.min_angle_deg, angles.max_angle_deg, report.duplicate_vertices,
                report.split_segments, report.removed_triangles);
    std::printf("  time: read %.1f ms, triangulate %.1f ms, write %.1f ms; mesh %.1f MiB\n", read_ms,
                triangulate_ms, write_ms, report.mesh_bytes / 1048576.0);
  }
  if (args.stats == "json") {
    JsonLine ms;
    ms.field("read", read_ms).field("triangulate", triangulate_ms).field("write", write_ms);
    JsonLine stats;
    stats.field("input", args.input)
        .field("vertices", report.vertices)
        .field("triangles", report.triangles)
        .field("segments", report.segments)
        .field("input_vertices", input_vertices)
        .field("input_segments", input_segments)
        .field("steiner", report.steiner_vertices)
        .field("duplicates", report.duplicate_vertices)
        .field("min_angle", angles.min_angle_deg)
        .field("max_angle", angles.max_angle_deg)
        .field("ds", std::string(to_string(options.data_structure)))
        .field("insertion", std::string(to_string(options.insertion)))
        .object("ms", ms);
    std::printf("%s\n", stats.str().c_str());
  }
  return kExitOk;
}

}  // namespace

Command add_triangulate_command(CLI::App& parent) {
  auto args = std::make_shared<TriangulateArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "triangulate",
      "Delaunay triangulation of a .node point set, or constrained Delaunay triangulation of a\n"
      ".poly PSLG (segments kept as edges; crossing segments split at their intersection;\n"
      "triangles in holes and, unless --convex-hull, outside the segments removed).");
  cmd->add_option("INPUT", args->input, "Input .node or .poly file (Triangle's formats), or .geojson or .wkt polygons")
      ->required();
  cmd->add_option("-o,--output", args->prefix,
                  "Output prefix: writes PREFIX.node, PREFIX.ele, PREFIX.poly\n"
                  "(default: INPUT without extension plus .1, as Triangle does);\n"
                  "or one file OUT.msh, .vtu, .obj, .off, .ply or .stl in that format (meshstep list)");
  args->operation = std::make_unique<OperationOptions>(*cmd, OperationKind::triangulate);
  cmd->add_option("--stats", args->stats,
                  "Print statistics; 'json': the last line of standard output is one JSON object\n"
                  "(vertices, triangles, input_vertices, steiner, min_angle, max_angle,\n"
                  "ms.read, ms.triangulate, ms.write)")
      ->check(CLI::IsMember({"json"}));
  add_record_option(*cmd, args->record);
  cmd->add_flag("--no-output", args->no_output, "Triangulate but write no files (for timing)");
  cmd->add_flag("-e,--edges", args->edges, "Also write PREFIX.edge");
  cmd->add_flag("-n,--neighbors", args->neighbors, "Also write PREFIX.neigh");
  // Triangle spells it -v, which is --verbose here (as in every meshstep command).
  cmd->add_flag("--voronoi", args->voronoi,
                "Also write the Voronoi diagram, as the mesh's dual, in Triangle's format: PREFIX.v.node\n"
                "(vertex k: the circumcenter of triangle k) and PREFIX.v.edge (an edge whose second end\n"
                "is -1 is a ray from a boundary edge's triangle, with its outward direction)");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors (and --stats)");
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress, timings and mesh statistics");
  cmd->footer("Example: meshstep triangulate assets/examples/plate.poly -o plate --stats json");
  return {cmd, [args] { return run_triangulate(*args); }};
}

}  // namespace meshstep::app
