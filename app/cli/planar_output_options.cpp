#include "planar_output_options.hpp"

#include "record_option.hpp"

namespace meshstep::app {

void add_planar_output_options(CLI::App& cmd, PlanarOutputOptions& options) {
  PlanarRefineJob& job = options.job;
  add_record_option(cmd, job.record);
  cmd.add_option("-o,--output", job.prefix,
                 "Output prefix: writes PREFIX.node, PREFIX.ele, PREFIX.poly\n"
                 "(default: INPUT without extension plus .1, as Triangle does);\n"
                 "or one file OUT.msh, .vtu, .obj, .off, .ply or .stl in that format (meshstep list)");
  cmd.add_option("--stats", job.stats,
                 "Print statistics; 'json': the last line of standard output is one JSON object\n"
                 "(vertices, triangles, steiner, segment_splits, bad_triangles, bounds_met,\n"
                 "stopped_by_cap, min_angle, max_angle, ms.read/triangulate/refine/write, ...)")
      ->check(CLI::IsMember({"json"}));
  cmd.add_flag("--no-output", job.no_output, "Refine but write no mesh files (for timing)");
  cmd.add_option("--max-memory", job.max_memory,
                 "Stop before the run takes more memory than SIZE (8G, 500M, ...; none: no\n"
                 "budget). Default: a quarter of this machine's memory. A run stopped there\n"
                 "writes nothing unless --write-partial (exit 1)")
      ->type_name("SIZE");
  cmd.add_flag("--write-partial", job.write_partial,
               "When the memory budget stops the run, write the mesh reached (valid, with\n"
               "triangles that fail the bounds left in it)");
  cmd.add_flag("-q,--quiet", options.quiet, "Print nothing but errors (and --stats)");
  cmd.add_flag("-v,--verbose", options.verbose, "Also print refinement counts, timings and the record summary");
}

}  // namespace meshstep::app
