#include "refine_surface.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "refuse_overwrites.hpp"
#include "json_line.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/surface/surface_flips.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/replay/run_header.hpp"
#include "meshstep/surface/surface_refine.hpp"
#include "record_option.hpp"

namespace meshstep::app {

namespace {

// INPUT.off -> INPUT.1.off, as Triangle numbers its outputs.
std::string default_output(const std::string& input) {
  const std::filesystem::path p(input);
  return (p.parent_path() / (p.stem().string() + ".1" + p.extension().string())).string();
}

// "bounds missed by N triangles (E over --size, A over --max-area)", as refine says it in
// the plane.
std::string bounds_missed_words(std::size_t over_bounds, const surface::BisectionReport& report) {
  std::string words = "bounds missed by " + std::to_string(over_bounds) + " of " + std::to_string(report.triangles) +
                      " triangles (";
  if (report.over_max_edge > 0) words += std::to_string(report.over_max_edge) + " over --size";
  if (report.over_max_edge > 0 && report.over_max_area > 0) words += ", ";
  if (report.over_max_area > 0) words += std::to_string(report.over_max_area) + " over --max-area";
  words += ")";
  if (report.too_fine_to_cut > 0)
    words += "; " + std::to_string(report.too_fine_to_cut) +
             " cut(s) refused: the doubles cannot cut those edges at these coordinates' magnitudes";
  return words;
}

}  // namespace

int run_refine_surface(const SurfaceRefineArgs& args) {
  const Verbosity verbosity = args.quiet ? Verbosity::quiet : Verbosity::normal;
  const Operation& op = args.operation;
  const double max_area = op.max_area.value_or(0.0);
  const double flip_dihedral = op.flip_dihedral.value_or(-1.0);
  if (op.algorithm != "lepp-bisection") {
    print_error(args.input + ": a 3D surface is refined by --algorithm lepp-bisection (longest-edge bisection "
                             "keeps it on the surface); '" + op.algorithm + "' works in the plane");
    return kExitUsage;
  }
  if (args.max_edge <= 0.0 && max_area <= 0.0 && flip_dihedral < 0.0) {
    print_error("refining a surface needs --size L (longest edge), --max-area A or --flip-dihedral DEG");
    return kExitUsage;
  }
  const std::string output = args.output.empty() ? default_output(args.input) : args.output;
  if (const int refused = refuse_overwrites(FileRoles()
                                                .reads(args.input)
                                                .writes(args.output.empty() ? "" : "-o", args.no_output ? "" : output,
                                                        "output surface")
                                                .writes_log("--record", args.record)))
    return refused;
  const auto format = io::surface_format_for(output);
  if (!args.no_output && !format) {
    print_error(output + ": not a surface file name (.off, .obj, .ply, .stl)");
    return kExitUsage;
  }
  try {
    const io::Surface in = io::read_surface(args.input);
    surface::BisectionOptions options;
    options.max_edge = args.max_edge;
    options.max_area = max_area;
    options.max_triangles = op.max_triangles;
    options.data_structure = op.data_structure;
    std::unique_ptr<replay::LogWriter> log;
    if (!args.record.empty()) {
      log = open_log(args.record, args.input, "lepp-bisection",
                     replay::surface_parameters(args.max_edge, max_area, in.vertices.size(), op.max_triangles,
                                                flip_dihedral),
                     options.data_structure, Insertion::flip, nullptr);
      options.record = log.get();
    }
    // The bisection, then the flips, in one mesh (and one log).
    options.flip_dihedral_deg = flip_dihedral;
    surface::BisectionReport report;
    Stopwatch clock;
    io::Surface out = surface::bisect_surface(in, options, &report);
    const double refine_ms = clock.lap_ms();
    if (!args.no_output) io::write_surface(output, out, *format);
    if (log) {
      log->finish();
      print_progress(verbosity, record_summary(*log));
    }
    const bool has_bounds = args.max_edge > 0.0 || max_area > 0.0;
    const std::size_t over_bounds = report.over_bounds;
    const std::string cap_words = "stopped at --max-triangles " + std::to_string(op.max_triangles);
    if (over_bounds > 0)
      print_warning(verbosity, args.input + ": " + (report.capped ? cap_words + ": " : "") +
                                   bounds_missed_words(over_bounds, report));
    else if (report.capped)
      print_warning(verbosity, cap_words + "; the flips met every bound all the same");
    if (verbosity != Verbosity::quiet)
      std::printf("%s: %zu triangles -> %zu (%zu bisections%s); smallest angle %.2f -> %.2f degrees; area %.17g%s%s\n",
                  args.input.c_str(), in.triangles.size(), report.triangles, report.bisections,
                  flip_dihedral < 0.0 ? "" : (", " + std::to_string(report.flips) + " flips").c_str(),
                  report.smallest_angle_before_deg, report.smallest_angle_after_deg, report.area_after,
                  !has_bounds ? "" : over_bounds == 0 ? "; bounds met" : ("; " + bounds_missed_words(over_bounds, report)).c_str(),
                  args.no_output ? " (not written)" : (", written to " + output).c_str());
    if (args.stats == "json") {
      JsonLine stats;
      stats.field("input", args.input)
          .field("triangles_before", in.triangles.size())
          .field("triangles", report.triangles)
          .field("vertices", out.vertices.size())
          .field("bisections", report.bisections)
          .field("flips", report.flips)
          .field("largest_dihedral_flipped", report.largest_dihedral_flipped_deg)
          .field("min_angle_before", report.smallest_angle_before_deg)
          .field("min_angle", report.smallest_angle_after_deg)
          .field("area_before", report.area_before)
          .field("area", report.area_after)
          .field("capped", report.capped)
          .field("too_fine_to_cut", report.too_fine_to_cut)
          .field("bounds_met", over_bounds == 0)
          .field("over_bounds", over_bounds)
          .field("over_size", report.over_max_edge)
          .field("over_max_area", report.over_max_area)
          .field("ms", refine_ms);
      std::printf("%s\n", stats.str().c_str());
    }
  } catch (const InputError& e) {
    print_error(input_error_text(args.input, e));
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace meshstep::app
