// triangle_compare [--meshstep PATH] [--make-points PATH] [--triangle PATH | --triangle-source DIR]
//                  [--poly FILE] [--min-angle DEG] [--max-area A] [--points N] [--repeat R] [--work DIR]
//
// docs/benchmarks.md's comparison with Jonathan Shewchuk's Triangle 1.6, whole processes, as
// Markdown on standard output:
//   refine       meshstep refine FILE --min-angle DEG --max-area A --no-output -q
//                triangle -pqDEGaA -NEPQ FILE      (A.poly, 30 degrees, 7.7e-8: 1.3M triangles)
//   triangulate  meshstep triangulate P.node --no-output -q
//                triangle -NEPQ P.node             (N uniform random points from make_points)
// Neither writes its mesh (N, E, P: no .node, .ele, .poly). Each pair runs both programs one
// after the other, which goes first alternating from pair to pair, after one warm-up run of
// each; reported: the medians of wall time, CPU time and peak memory (wait4's ru_maxrss), and
// the median, smallest and largest of the pairs' own ratios meshstep / Triangle (a ratio taken
// within a pair cancels most of a shared machine's drift).
//
// Triangle is built on first use into triangle/ beside this program, from triangle.c in
// --triangle-source (the shared peers folder; read in place, never copied), with
// `gcc -O3 -DLINUX -o triangle triangle.c -lm`. When that folder is absent the comparison is
// skipped with a message (exit 0). Never copy or imitate Triangle's code (peers/README.md).
//
// Exit status: 0 ok or skipped, 1 a run failed, 2 usage error.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "whole_process.hpp"

#ifndef MESHSTEP_TRIANGLE_SOURCE
#define MESHSTEP_TRIANGLE_SOURCE "../shared/peers/triangle"
#endif
#ifndef MESHSTEP_DEFAULT_POLY
#define MESHSTEP_DEFAULT_POLY "../shared/data/pslg/A.poly"
#endif

namespace {

namespace fs = std::filesystem;
using meshstep::bench::parse_whole;
using meshstep::bench::Process;
using meshstep::bench::program_dir;
using meshstep::bench::run_process;

constexpr const char* kUsage =
    "usage: triangle_compare [--meshstep PATH] [--make-points PATH] [--triangle PATH | --triangle-source DIR]\n"
    "                        [--poly FILE] [--min-angle DEG] [--max-area A] [--points N] [--repeat R] [--work DIR]\n"
    "Times meshstep against Triangle 1.6, whole processes in alternating pairs: refining FILE (default\n"
    "A.poly of the shared data) at DEG degrees (30) under area A (7.7e-8), and triangulating N uniform\n"
    "random points (1000000); R pairs each (9). Markdown on standard output.\n";

// Triangle's switches take a plain decimal (it reads digits and a point, no exponent).
std::string plain_decimal(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15f", x);
  std::string s = buf;
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::optional<fs::path> find_beside(const std::string& given, const std::vector<fs::path>& candidates) {
  if (!given.empty()) return fs::exists(given) ? std::optional<fs::path>(fs::absolute(given)) : std::nullopt;
  for (const fs::path& p : candidates)
    if (fs::exists(p)) return fs::weakly_canonical(p);
  return std::nullopt;
}

// Triangle's binary: the one given, else triangle/triangle beside this program, compiled there
// on first use. nullopt (with the reason on stderr) skips the comparison.
std::optional<fs::path> find_or_build_triangle(const std::string& given, const fs::path& source) {
  if (!given.empty()) return fs::exists(given) ? std::optional<fs::path>(fs::absolute(given)) : std::nullopt;
  if (!fs::exists(source / "triangle.c")) {
    std::fprintf(stderr, "triangle_compare: Triangle skipped: %s is absent\n", (source / "triangle.c").c_str());
    return std::nullopt;
  }
  const fs::path dest = program_dir() / "triangle", binary = dest / "triangle";
  if (fs::exists(binary)) return binary;
  fs::create_directories(dest);
  const fs::path log = dest / "build.log";
  std::fprintf(stderr, "triangle_compare: building Triangle from %s into %s\n", source.c_str(), dest.c_str());
  const std::string command = "gcc -O3 -DLINUX -o '" + binary.string() + "' '" + (source / "triangle.c").string() +
                              "' -lm > '" + log.string() + "' 2>&1";
  if (std::system(command.c_str()) != 0 || !fs::exists(binary)) {
    std::fprintf(stderr, "triangle_compare: Triangle skipped: its build failed (see %s)\n", log.c_str());
    return std::nullopt;
  }
  return binary;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

struct Comparison {
  std::string name;
  std::vector<std::string> meshstep, triangle;
};

struct Figures {
  std::vector<Process> meshstep, triangle;
  std::vector<double> ratio;  // wall, pair by pair
};

// One warm-up run of each, then `repeat` pairs, alternating which goes first. False when a
// run fails (its stderr is left in the work folder).
bool measure(const Comparison& c, int repeat, const fs::path& work, Figures& f) {
  const fs::path out = work / (c.name + ".out"), err = work / (c.name + ".err");
  for (int pair = -1; pair < repeat; ++pair) {
    Process runs[2];
    for (int k = 0; k < 2; ++k) {
      const int who = (pair + k + 2) % 2;  // 0 meshstep, 1 Triangle
      runs[who] = run_process(who == 0 ? c.meshstep : c.triangle, out, err);
      if (runs[who].exit_status != 0) {
        std::fprintf(stderr, "triangle_compare: %s failed (exit %d): %s; see %s\n", c.name.c_str(),
                     runs[who].exit_status, (who == 0 ? c.meshstep : c.triangle)[0].c_str(), err.c_str());
        return false;
      }
    }
    if (pair < 0) continue;  // the warm-up
    f.meshstep.push_back(runs[0]);
    f.triangle.push_back(runs[1]);
    f.ratio.push_back(runs[0].ms / runs[1].ms);
  }
  return true;
}

double median_of(const std::vector<Process>& runs, double Process::*field) {
  std::vector<double> v;
  for (const Process& p : runs) v.push_back(p.*field);
  return median(v);
}

}  // namespace

int main(int argc, char** argv) {
  std::string meshstep_path, make_points_path, triangle_path, triangle_source = MESHSTEP_TRIANGLE_SOURCE;
  std::string poly = MESHSTEP_DEFAULT_POLY;
  double min_angle = 30, max_area = 7.7e-8;
  long points = 1000000;
  int repeat = 9;
  fs::path work = fs::temp_directory_path() / "meshstep_triangle_compare";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (i + 1 >= argc) return meshstep::bench::usage_error("triangle_compare", "missing value after " + a, kUsage);
    const std::string v = argv[++i];
    bool ok = true;
    if (a == "--meshstep") meshstep_path = v;
    else if (a == "--make-points") make_points_path = v;
    else if (a == "--triangle") triangle_path = v;
    else if (a == "--triangle-source") triangle_source = v;
    else if (a == "--poly") poly = v;
    else if (a == "--work") work = v;
    else if (a == "--min-angle") ok = parse_whole(v, min_angle) && min_angle > 0 && min_angle < 60;
    else if (a == "--max-area") ok = parse_whole(v, max_area) && max_area > 0;
    else if (a == "--points") ok = parse_whole(v, points) && points >= 3;
    else if (a == "--repeat") ok = parse_whole(v, repeat) && repeat >= 1 && repeat <= 100;
    else return meshstep::bench::usage_error("triangle_compare", "unknown option " + a, kUsage);
    if (!ok) return meshstep::bench::usage_error("triangle_compare", "bad value for " + a + ": " + v, kUsage);
  }

  const std::optional<fs::path> triangle = find_or_build_triangle(triangle_path, triangle_source);
  if (!triangle) {
    std::printf("Triangle is not available: the comparison is skipped.\n");
    return 0;
  }
  const auto meshstep =
      find_beside(meshstep_path, {program_dir() / "meshstep", program_dir() / ".." / ".." / "app" / "meshstep"});
  const auto make_points = find_beside(make_points_path, {program_dir() / "make_points"});
  if (!meshstep || !make_points)
    return meshstep::bench::usage_error("triangle_compare", "give --meshstep and --make-points (programs)", kUsage);
  if (!fs::exists(poly)) return meshstep::bench::usage_error("triangle_compare", poly + " does not exist", kUsage);

  fs::create_directories(work);
  const fs::path node = work / ("points_" + std::to_string(points) + ".node");
  if (!fs::exists(node) &&
      run_process({make_points->string(), std::to_string(points), node.string()}, work / "make_points.out",
                  work / "make_points.err")
              .exit_status != 0) {
    std::fprintf(stderr, "triangle_compare: make_points failed\n");
    return 1;
  }

  const std::string angle = plain_decimal(min_angle), area = plain_decimal(max_area);
  char area_text[32];
  std::snprintf(area_text, sizeof area_text, "%.17g", max_area);
  const std::vector<Comparison> comparisons = {
      {"refine",
       {meshstep->string(), "refine", poly, "--min-angle", angle, "--max-area", area_text, "--no-output", "-q"},
       {triangle->string(), "-pq" + angle + "a" + area + "NEPQ", poly}},
      {"triangulate",
       {meshstep->string(), "triangulate", node.string(), "--no-output", "-q"},
       {triangle->string(), "-NEPQ", node.string()}},
  };

  std::printf("meshstep: %s\nTriangle: %s\nload average before: %s; %d pairs per row after a warm-up, "
              "alternating which goes first\n\n",
              meshstep->c_str(), triangle->c_str(), meshstep::bench::load_average().c_str(), repeat);
  std::printf("| run | meshstep command | Triangle switches | meshstep wall (s) | Triangle wall (s) "
              "| meshstep / Triangle, wall: median (min–max) | CPU: meshstep / Triangle (s) "
              "| peak MiB: meshstep / Triangle |\n|---|---|---|--:|--:|--:|--:|--:|\n");
  int status = 0;
  for (const Comparison& c : comparisons) {
    Figures f;
    if (!measure(c, repeat, work, f)) {
      status = 1;
      continue;
    }
    std::string command = c.meshstep[1];
    for (std::size_t i = 2; i < c.meshstep.size(); ++i)
      command += " " + (i == 2 ? fs::path(c.meshstep[i]).filename().string() : c.meshstep[i]);
    const std::string input = fs::path(c.triangle.back()).filename().string();
    std::printf("| %s | `%s` | `%s %s` | %.3f | %.3f | **%.3f** (%.3f–%.3f) | %.3f / %.3f | %.1f / %.1f |\n",
                c.name.c_str(), command.c_str(), c.triangle[1].c_str(), input.c_str(),
                median_of(f.meshstep, &Process::ms) / 1e3, median_of(f.triangle, &Process::ms) / 1e3, median(f.ratio),
                *std::min_element(f.ratio.begin(), f.ratio.end()), *std::max_element(f.ratio.begin(), f.ratio.end()),
                median_of(f.meshstep, &Process::cpu_ms) / 1e3, median_of(f.triangle, &Process::cpu_ms) / 1e3,
                median_of(f.meshstep, &Process::peak_mb), median_of(f.triangle, &Process::peak_mb));
    std::fflush(stdout);
  }
  std::printf("\nload average after: %s\n", meshstep::bench::load_average().c_str());
  return status;
}
