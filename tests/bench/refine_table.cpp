// refine_table DIR [--inputs A,guitar,...] [--bounds 20,25,...,36] [--max-steiner N]
//                   [--triangle PATH] [--only-triangle]
//
// The comparison tables of docs/refinement.md, as Markdown on standard output: each Delaunay
// selection at each angle bound on each input (Steiner vertices, triangles, smallest angle,
// bound met, misses and how many of them lie away from small input angles, ms); the highest
// bound each selection reaches on each input; improvement + refinement against the plain
// run (25 to 33 degrees); and the area, aspect and combined algorithms. One run per cell (refinement is
// deterministic; the ms column is one measurement, for scale only).
//
// With --triangle PATH (a Triangle 1.6 binary, built beside this program and never part of
// meshstep), a first table sets every selection's Steiner count beside `triangle -pq<bound>`
// on the same input (with `a` where the .poly has regions: meshstep applies their areas),
// with the ratios' geometric means; --only-triangle prints that table alone.
//
// Exit status: 0 ok, 1 a run failed, 2 usage error or unreadable input.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "bench_args.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"

namespace {

using namespace meshstep;

constexpr const char* kUsage =
    "usage: refine_table DIR [--inputs A,guitar,la,face,earcut_water-huge] [--bounds 20,25,30,33,34,35,36]\n"
    "                    [--max-steiner N] [--triangle PATH] [--only-triangle]\n"
    "Prints docs/refinement.md's tables for DIR/NAME.poly of each input.\n";

int usage_error(const std::string& message) { return meshstep::bench::usage_error("refine_table", message, kUsage); }

using meshstep::bench::parse_whole;

struct Run {
  RefineReport report;
  AngleStats angles;
  std::size_t triangles = 0;
  double ms = 0.0;
};

Run run(const Pslg& in, const RefineOptions& options) {
  Run r;
  const auto start = std::chrono::steady_clock::now();
  const TriMesh m = refine(in, options, &r.report);
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  r.angles = angle_stats(m);
  r.triangles = m.triangles.size();
  return r;
}

std::vector<std::string> split(std::string_view text) {
  std::vector<std::string> out;
  std::stringstream ss{std::string(text)};
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

const char* met(const Run& r) { return r.report.stopped_by_cap ? "capped" : r.report.bounds_met ? "yes" : "no"; }
std::size_t far_misses(const Run& r) { return r.report.bad_triangles - r.report.bad_near_small_input_angle; }

double domain_area(const Pslg& in) {
  const TriMesh m = triangulate(in);
  double area = 0.0;
  for (const auto& t : m.triangles) {
    const Point &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return area;
}

RefineOptions named(std::string_view name, double min_angle, std::size_t max_steiner) {
  const AlgorithmInfo* algorithm = find_algorithm(name);
  if (!algorithm) throw std::logic_error("refine_table: no algorithm " + std::string(name));
  RefineOptions o = options_for(*algorithm);
  o.criteria.min_angle_deg = min_angle;
  o.criteria.max_steiner = max_steiner;
  return o;
}

struct Input {
  std::string name;
  Pslg pslg;
  std::string path;
};

// Triangle's Steiner vertices at `bound` (output vertices less input vertices), or nothing
// when it fails or takes more than a minute. It writes beside its input: a copy in a
// temporary folder.
std::optional<std::size_t> triangle_steiner(const std::string& triangle, const Input& in, double bound) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("refine_table_triangle_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path poly = dir / (in.name + ".poly");
  fs::copy_file(in.path, poly, fs::copy_options::overwrite_existing);
  char bound_text[32];
  std::snprintf(bound_text, sizeof bound_text, "%g", bound);
  // a: the regional areas, only where there are regions (Triangle then expects the section).
  const std::string command = "timeout 60 '" + triangle + "' -pq" + bound_text + (in.pslg.regions.empty() ? "" : "a") +
                              " -Q '" + poly.string() + "'";
  std::optional<std::size_t> steiner;
  if (std::system(command.c_str()) == 0) {
    try {
      const std::size_t out = io::read_node((dir / (in.name + ".1.node")).string()).points.size();
      if (out >= in.pslg.points.size()) steiner = out - in.pslg.points.size();
    } catch (const InputError&) {  // no output, or not one we read: no figure
    }
  }
  fs::remove_all(dir);
  return steiner;
}

// Steiner vertices of every Delaunay selection against Triangle's, with the ratios'
// geometric mean and largest per selection (over the cells where Triangle finished).
void triangle_table(const std::vector<Input>& inputs, const std::vector<double>& bounds, std::size_t cap,
                    const std::string& triangle) {
  static constexpr std::string_view kSelections[] = {"offcenter", "circumcenter", "lepp-centroid", "lepp-midpoint"};
  std::printf("| input | bound | Triangle 1.6 | offcenter (default) | circumcenter | lepp-centroid | lepp-midpoint |\n"
              "|---|--:|--:|--:|--:|--:|--:|\n");
  std::map<std::string_view, std::vector<double>> logs;
  for (const Input& in : inputs)
    for (const double bound : bounds) {
      const std::optional<std::size_t> theirs = triangle_steiner(triangle, in, bound);
      std::printf("| %s | %g | %s |", in.name.c_str(), bound, theirs ? std::to_string(*theirs).c_str() : "did not end");
      for (const std::string_view selection : kSelections) {
        const Run r = run(in.pslg, named(selection, bound, cap));
        const std::size_t ours = r.report.steiner_vertices;
        if (r.report.stopped_by_cap) {
          std::printf(" capped at %zu |", ours);
        } else if (theirs && *theirs > 0) {
          const double ratio = static_cast<double>(std::max<std::size_t>(ours, 1)) / static_cast<double>(*theirs);
          logs[selection].push_back(std::log(ratio));
          std::printf(" %zu (%.2f) |", ours, ratio);
        } else {
          std::printf(" %zu |", ours);
        }
      }
      std::printf("\n");
      std::fflush(stdout);
    }
  std::printf("\n| selection | cells | geometric mean of ours / Triangle's | largest |\n|---|--:|--:|--:|\n");
  for (const std::string_view selection : kSelections) {
    const std::vector<double>& l = logs[selection];
    if (l.empty()) continue;
    double sum = 0.0, largest = l.front();
    for (const double x : l) sum += x, largest = std::max(largest, x);
    std::printf("| %s | %zu | %.3f | %.3f |\n", std::string(selection).c_str(), l.size(), std::exp(sum / l.size()),
                std::exp(largest));
  }
  std::printf("\n");
}

void selection_table(const std::vector<Input>& inputs, const std::vector<double>& bounds, std::size_t cap) {
  static constexpr std::string_view kSelections[] = {"circumcenter", "offcenter", "lepp-midpoint", "lepp-centroid"};
  std::printf("| input | algorithm | bound | Steiner | triangles | min angle | met | missing | far from small angles | ms |\n"
              "|---|---|--:|--:|--:|--:|---|--:|--:|--:|\n");
  // Highest bound reached, per input and selection: everywhere, and away from small angles.
  std::vector<std::string> highest;
  for (const Input& in : inputs)
    for (const std::string_view selection : kSelections) {
      double everywhere = 0.0, away = 0.0;
      for (const double bound : bounds) {
        const Run r = run(in.pslg, named(selection, bound, cap));
        std::printf("| %s | %s | %g | %zu | %zu | %.2f | %s | %zu | %zu | %.1f |\n", in.name.c_str(),
                    std::string(selection).c_str(), bound, r.report.steiner_vertices, r.triangles,
                    r.angles.min_angle_deg, met(r), r.report.bad_triangles, far_misses(r), r.ms);
        std::fflush(stdout);
        if (r.report.bounds_met) everywhere = bound;
        if (!r.report.stopped_by_cap && far_misses(r) == 0) away = bound;
      }
      char line[256];
      std::snprintf(line, sizeof line, "| %s | %s | %s | %s |\n", in.name.c_str(), std::string(selection).c_str(),
                    everywhere > 0 ? (std::to_string(static_cast<int>(everywhere)) + "°").c_str() : "-",
                    away > 0 ? (std::to_string(static_cast<int>(away)) + "°").c_str() : "-");
      highest.push_back(line);
    }
  std::printf("\nHighest bound reached (of those tried):\n\n"
              "| input | algorithm | everywhere | away from small input angles |\n|---|---|--:|--:|\n");
  for (const std::string& line : highest) std::fputs(line.c_str(), stdout);
}

void improvement_table(const std::vector<Input>& inputs, const std::vector<double>& bounds, std::size_t cap) {
  // "removed": by the improvement pass, the plain run's own deletions near splits left out.
  std::printf("\n| input | selection | bound | Steiner plain | Steiner improved | removed | min angle plain | improved | "
              "met | ms |\n|---|---|--:|--:|--:|--:|--:|--:|---|--:|\n");
  for (const Input& in : inputs)
    for (const std::string_view selection : {"circumcenter", "offcenter", "lepp-centroid"})
      for (const double bound : bounds) {
        if (bound < 25.0 || bound > 33.0) continue;  // where every selection finishes
        const RefineOptions plain_options = named(selection, bound, cap);
        RefineOptions improved_options = plain_options;
        improved_options.improve = true;
        const Run plain = run(in.pslg, plain_options), improved = run(in.pslg, improved_options);
        std::printf("| %s | %s | %g | %zu | %zu | %zu | %.2f | %.2f | %s / %s | %.1f |\n", in.name.c_str(),
                    std::string(selection).c_str(), bound, plain.report.steiner_vertices,
                    improved.report.steiner_vertices, improved.report.removed_vertices - plain.report.removed_vertices,
                    plain.angles.min_angle_deg,
                    improved.angles.min_angle_deg, met(plain), met(improved), improved.ms);
        std::fflush(stdout);
      }
}

void other_algorithms_table(const std::vector<Input>& inputs, std::size_t cap) {
  std::printf("\n| input | algorithm | Steiner | triangles | min angle | met | missing | far from small angles | ms |\n"
              "|---|---|--:|--:|--:|---|--:|--:|--:|\n");
  for (const Input& in : inputs) {
    RefineOptions area = named("midpoint-area", 0.0, cap);
    area.criteria.max_area = domain_area(in.pslg) / 3000.0;
    RefineOptions aspect = named("lepp-aspect", 0.0, cap);
    aspect.criteria.max_aspect = kDefaultMaxAspect;
    RefineCriteria combined_criteria;
    combined_criteria.min_angle_deg = 30.0;
    combined_criteria.max_aspect = kDefaultMaxAspect;
    combined_criteria.max_steiner = cap;
    RefineOptions combined = named("combined", 0.0, cap);
    combined.phases = aspect_then_angle_phases(combined_criteria, *find_algorithm("combined"));
    const std::pair<const char*, RefineOptions> runs[] = {
        {"midpoint-area", area}, {"lepp-aspect", aspect}, {"combined", combined}};
    for (const auto& [name, options] : runs) {
      const Run r = run(in.pslg, options);
      std::printf("| %s | %s | %zu | %zu | %.2f | %s | %zu | %zu | %.1f |\n", in.name.c_str(), name,
                  r.report.steiner_vertices, r.triangles, r.angles.min_angle_deg, met(r), r.report.bad_triangles,
                  far_misses(r), r.ms);
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names = {"A", "guitar", "la", "face", "earcut_water-huge"};
  std::vector<double> bounds = {20, 25, 30, 33, 34, 35, 36};
  std::size_t cap = 1'000'000;  // runs past the highest bound stop here
  std::string dir, triangle;
  bool only_triangle = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (arg == "--inputs" && has_value) {
      names = split(argv[++i]);
    } else if (arg == "--bounds" && has_value) {
      bounds.clear();
      for (const std::string& b : split(argv[++i])) {
        double value = 0.0;
        if (!parse_whole(b, value) || !(value > 0.0 && value < 60.0))
          return usage_error("--bounds: '" + b + "' is not an angle in (0, 60)");
        bounds.push_back(value);
      }
    } else if (arg == "--triangle" && has_value) {
      triangle = argv[++i];
    } else if (arg == "--only-triangle") {
      only_triangle = true;
    } else if (arg == "--max-steiner" && has_value) {
      if (!parse_whole(argv[++i], cap))
        return usage_error(std::string("--max-steiner: '") + argv[i] + "' is not a count");
    } else if (dir.empty() && !arg.starts_with("-")) {
      dir = arg;
    } else {
      return usage_error(std::string("unexpected argument '") + argv[i] + "'");
    }
  }
  if (dir.empty()) return usage_error("no input directory");
  if (names.empty() || bounds.empty()) return usage_error("no inputs or no bounds");
  if (only_triangle && triangle.empty()) return usage_error("--only-triangle needs --triangle PATH");
  std::vector<Input> inputs;
  try {
    for (const std::string& name : names) {
      const std::string path = (std::filesystem::path(dir) / (name + ".poly")).string();
      inputs.push_back({name, io::read_pslg(path), path});
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "refine_table: error: %s\n", e.what());
    return 2;
  }
  try {
    if (!triangle.empty()) triangle_table(inputs, bounds, cap, triangle);
    if (only_triangle) return 0;
    selection_table(inputs, bounds, cap);
    improvement_table(inputs, bounds, cap);
    other_algorithms_table(inputs, cap);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "refine_table: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
