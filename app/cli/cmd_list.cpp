// meshstep list: the registered refinement algorithms and the parts they are made of
// (refine/registry.hpp), as text in sections or as one JSON object.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "command.hpp"
#include "json_line.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/terrain/tin.hpp"

namespace meshstep::app {
namespace {

struct ListArgs {
  bool json = false;
};

struct Row {
  std::string name, description;
};

struct Section {
  const char* key;    // the JSON key
  const char* title;  // the text heading
  std::vector<Row> rows;
};

std::string short_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

template <class Part>
std::vector<Row> rows_of(std::span<const Part> parts) {
  std::vector<Row> rows;
  for (const Part& p : parts) rows.push_back({std::string(p.name), std::string(p.description)});
  return rows;
}

// ".poly  pslg, RW: Triangle's PSLG: ...": the format table (io/formats.hpp), with what a 2D
// mesh written by `-o OUT.EXT` keeps ("2D mesh: ...") where the format has that writer.
std::vector<Row> format_rows() {
  std::vector<Row> rows;
  for (const io::FileFormat& f : io::file_formats())
    rows.push_back({std::string(f.extension),
                    std::string(io::to_string(f.kind)) + ", " + (f.read ? "R" : "") + (f.write ? "W" : "") + ": " +
                        std::string(f.description) +
                        (f.write_mesh ? "; 2D mesh (-o OUT" + std::string(f.extension) + "): " + std::string(f.carries)
                                      : std::string())});
  return rows;
}

// The bounds and caps among the refinement's parameter records: "--min-angle DEG: Every
// angle at least DEG (below 60; ...".
std::vector<Row> criteria_rows() {
  std::vector<Row> rows;
  for (const ParameterInfo& p : refine_parameters()) {
    if (!p.bound && p.kind != ParameterKind::count) continue;
    std::string help(p.help);
    std::replace(help.begin(), help.end(), '\n', ' ');
    rows.push_back({std::string(p.name), "--" + std::string(p.name) + " " + std::string(p.type_name) + ": " + help});
  }
  return rows;
}

std::vector<Section> sections() {
  std::vector<Row> algorithm_rows;
  for (const AlgorithmInfo& a : algorithms())
    algorithm_rows.push_back({std::string(a.name), std::string(a.description) + " (selection " +
                                                       to_string(a.selection) + "; default --min-angle " +
                                                       short_number(a.default_min_angle_deg) +
                                                       (a.known_to_end_deg > 0.0 ? "; ends in practice to " +
                                                                                       short_number(a.known_to_end_deg) + " degrees"
                                                                                 : std::string()) +
                                                       ")"});
  std::vector<Row> terrain_rows;
  for (const terrain::TerrainAlgorithmInfo& a : terrain::terrain_algorithms())
    terrain_rows.push_back({std::string(a.name), std::string(a.description)});
  return {
      {"algorithms", "Algorithms (refine --algorithm NAME)", std::move(algorithm_rows)},
      {"terrain_algorithms", "Terrain algorithms (terrain --algorithm NAME)", std::move(terrain_rows)},
      {"terrain_tiles", "Terrain in tiles: grids bigger than memory (docs/terrain.md, \"Tiles\")",
       {{"terrain --tile N", "streams the grid and approximates it in tiles of N x N samples, each "
                             "independent (--tile-index R,C for one), writing OUT.rR-cC.EXT; neighbours "
                             "share their border vertices exactly"},
        {"terrain-join", "welds the tile files into one surface and checks it for cracks"}}},
      {"selections", "Selections (refine --select S): where a bad triangle's new vertex goes",
       rows_of(meshstep::selections())},
      {"insertions", "Insertions (--insertion): how a vertex goes in", rows_of(meshstep::insertions())},
      {"criteria", "Criteria (refine): a triangle is bad when it fails any bound given", criteria_rows()},
      {"segment_splits", "Segment splits (refine --split-segments): which segments refinement may split",
       rows_of(meshstep::segment_splits_modes())},
      {"data_structures", "Data structures (--ds)", rows_of(meshstep::data_structures())},
      {"file_formats", "File formats (R: meshstep reads it, W: writes it)", format_rows()},
  };
}

int run_list(const ListArgs& args) {
  const std::vector<Section> all = sections();
  if (args.json) {
    // {"algorithms":[{"name":..,"description":..,...}],"selections":[...],...}
    std::string out = "{";
    for (const Section& s : all) {
      if (out.size() > 1) out += ',';
      out += '"' + std::string(s.key) + "\":[";
      bool first = true;
      for (const Row& r : s.rows) {
        JsonLine item;
        item.field("name", r.name).field("description", r.description);
        if (std::string(s.key) == "algorithms") {
          const AlgorithmInfo* a = find_algorithm(r.name);
          item.field("selection", std::string(to_string(a->selection)))
              .field("default_min_angle", a->default_min_angle_deg);
        }
        if (!first) out += ',';
        out += item.str();
        first = false;
      }
      out += ']';
    }
    out += '}';
    std::printf("%s\n", out.c_str());
    return kExitOk;
  }
  // The algorithms' rows carry their own description; the others are "name  description".
  bool first = true;
  for (const Section& s : all) {
    std::printf("%s%s:\n", first ? "" : "\n", s.title);
    first = false;
    std::size_t width = 0;
    for (const Row& r : s.rows) width = std::max(width, r.name.size());
    for (const Row& r : s.rows)
      std::printf("  %-*s  %s\n", static_cast<int>(width), r.name.c_str(), r.description.c_str());
  }
  return kExitOk;
}

}  // namespace

Command add_list_command(CLI::App& parent) {
  auto args = std::make_shared<ListArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "list",
      "List the registered refinement algorithms, selections, insertions, criteria, data\n"
      "structures and file formats, with a line of description each.");
  cmd->add_flag("--json", args->json, "Print one JSON object: {\"algorithms\":[{\"name\",\"description\",...}],...}");
  cmd->footer("Example: meshstep list --json");
  return {cmd, [args] { return run_list(*args); }};
}

}  // namespace meshstep::app
