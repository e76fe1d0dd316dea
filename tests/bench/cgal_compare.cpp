// cgal_compare [N] [REPETITIONS] [--seed S] [--no-memory]
//
// Times meshstep::triangulate against CGAL's Delaunay_triangulation_2 (with the
// Exact_predicates_inexact_constructions_kernel, range insertion, which sorts the points
// along a Hilbert curve internally) on the same N uniform random points (default 1e6),
// REPETITIONS times (default 5), in this one process.
//
// Every meshstep configuration (the default options, then each data structure x
// insertion strategy) is paired with a CGAL run; the order inside a pair alternates from
// one repetition and configuration to the next (A B, B A, ...) so that slow drift of the
// machine (frequency, other load) falls on both sides alike. Printed per configuration:
// the median meshstep time, the median time of the CGAL runs it was paired with, their
// ratio, and the triangle counts, which must agree (CGAL's finite faces = meshstep's
// triangles; exit status 1 when they do not).
//
// Timed on both sides: building the triangulation from a vector of points that already
// exists (meshstep: triangulate(Pslg&&) on a copy made untimed; CGAL: dt.insert(first,
// last) into an empty triangulation). Not timed: generating the points, freeing results.
//
// Memory: unless --no-memory, each configuration and CGAL first run once in a forked
// child of this (still small) process, and the child's peak resident set size (wait4's
// ru_maxrss) is printed: input points + triangulation + result, per point. The peak RSS
// of this process after all timing runs (getrusage) is printed at the end.
//
// Exit status: 0 ok, 1 triangle counts disagree or a run failed, 2 usage error.
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "bench_args.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "random_points.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<Kernel>;
using CgalPoint = Kernel::Point_2;
using Clock = std::chrono::steady_clock;

struct Configuration {
  std::string name;
  meshstep::TriangulateOptions options;
};

std::vector<Configuration> configurations() {
  std::vector<Configuration> list;
  list.push_back({"default", meshstep::TriangulateOptions{}});
  for (auto ds : {meshstep::DataStructure::tds, meshstep::DataStructure::dcel}) {
    for (auto insertion : {meshstep::Insertion::flip, meshstep::Insertion::cavity}) {
      meshstep::TriangulateOptions options;
      options.data_structure = ds;
      options.insertion = insertion;
      list.push_back({std::string(meshstep::to_string(ds)) + "/" + meshstep::to_string(insertion),
                      options});
    }
  }
  return list;
}

std::vector<CgalPoint> to_cgal(const std::vector<meshstep::Point>& points) {
  std::vector<CgalPoint> out;
  out.reserve(points.size());
  for (const auto& p : points) out.emplace_back(p.x, p.y);
  return out;
}

// Both clocks: wall time is what a user waits for; the process CPU time is what the
// numbers are compared on, because it does not count the time this single-threaded
// program spends waiting while other work has the cores.
struct Stopwatch {
  Clock::time_point wall = Clock::now();
  timespec cpu = now_cpu();

  static timespec now_cpu() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t;
  }
  double wall_seconds() const { return std::chrono::duration<double>(Clock::now() - wall).count(); }
  double cpu_seconds() const {
    const timespec t = now_cpu();
    return static_cast<double>(t.tv_sec - cpu.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec - cpu.tv_nsec);
  }
};

struct Run {
  double cpu = 0.0;
  double wall = 0.0;
  std::size_t triangles = 0;
};

Run run_meshstep(const std::vector<meshstep::Point>& points,
                 const meshstep::TriangulateOptions& options) {
  meshstep::Pslg input;
  input.points = points;
  const Stopwatch watch;
  meshstep::TriMesh mesh = meshstep::triangulate(std::move(input), options);
  const double cpu = watch.cpu_seconds();
  const double wall = watch.wall_seconds();
  return {cpu, wall, mesh.triangles.size()};
}

Run run_cgal(const std::vector<CgalPoint>& points) {
  CgalDelaunay dt;
  const Stopwatch watch;
  dt.insert(points.begin(), points.end());
  const double cpu = watch.cpu_seconds();
  const double wall = watch.wall_seconds();
  return {cpu, wall, dt.number_of_faces()};
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t m = values.size() / 2;
  return values.size() % 2 == 1 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

// Peak RSS (bytes) of a child that generates the points and runs `work` on them once;
// 0 when the child failed.
template <class Work>
long long child_peak_rss(Work work) {
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) return 0;
  if (pid == 0) {
    int code = 0;
    try {
      work();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cgal_compare: error in child: %s\n", e.what());
      code = 1;
    }
    std::fflush(nullptr);
    _exit(code);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return 0;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 0;
  return static_cast<long long>(usage.ru_maxrss) * 1024;  // Linux reports KiB
}

int usage_error(const char* message) {
  std::fprintf(stderr,
               "cgal_compare: error: %s\n"
               "usage: cgal_compare [N] [REPETITIONS] [--seed S] [--no-memory]\n",
               message);
  return 2;
}

using meshstep::bench::parse_whole;

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 1000000;
  int repetitions = 5;
  std::uint64_t seed = meshstep::bench::kDefaultSeed;
  bool measure_memory = true;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--no-memory") {
      measure_memory = false;
    } else if (arg == "--seed") {
      if (i + 1 >= argc || !parse_whole(argv[++i], seed)) return usage_error("bad --seed");
    } else if (arg == "-h" || arg == "--help") {
      std::printf("usage: cgal_compare [N] [REPETITIONS] [--seed S] [--no-memory]\n");
      return 0;
    } else if (positional == 0) {
      double value = 0;  // accepts 1000000 as well as 1e6
      if (!parse_whole(arg, value) || value < 3 || value > 4e9) return usage_error("bad N");
      n = static_cast<std::size_t>(value);
      ++positional;
    } else if (positional == 1) {
      if (!parse_whole(arg, repetitions) || repetitions < 1) {
        return usage_error("bad REPETITIONS");
      }
      ++positional;
    } else {
      return usage_error("too many arguments");
    }
  }

  const std::vector<Configuration> configs = configurations();
  std::printf("meshstep %s vs CGAL %s: %zu uniform random points in [0,1)^2 (seed %llu), "
              "%d repetition%s\n",
              MESHSTEP_VERSION, CGAL_VERSION_STR, n, static_cast<unsigned long long>(seed),
              repetitions, repetitions == 1 ? "" : "s");

  bool failed = false;
  if (measure_memory) {
    std::printf("\npeak RSS of a fresh process triangulating once (input points included)\n");
    std::printf("%-16s %12s %12s\n", "configuration", "peak MiB", "bytes/point");
    auto print_rss = [&](const std::string& name, long long bytes) {
      if (bytes == 0) {
        std::printf("%-16s %12s %12s\n", name.c_str(), "failed", "-");
        failed = true;
      } else {
        std::printf("%-16s %12.1f %12.1f\n", name.c_str(), static_cast<double>(bytes) / 1048576.0,
                    static_cast<double>(bytes) / static_cast<double>(n));
      }
    };
    for (const auto& config : configs) {
      const long long bytes = child_peak_rss([&] {
        meshstep::Pslg input;
        input.points = meshstep::bench::uniform_points(n, seed);
        const meshstep::TriMesh mesh = meshstep::triangulate(std::move(input), config.options);
        if (mesh.triangles.empty()) throw std::runtime_error("no triangles");
      });
      print_rss(config.name, bytes);
    }
    const long long cgal_bytes = child_peak_rss([&] {
      const std::vector<CgalPoint> points = to_cgal(meshstep::bench::uniform_points(n, seed));
      CgalDelaunay dt;
      dt.insert(points.begin(), points.end());
      if (dt.number_of_faces() == 0) throw std::runtime_error("no faces");
    });
    print_rss("CGAL", cgal_bytes);
  }

  const std::vector<meshstep::Point> points = meshstep::bench::uniform_points(n, seed);
  const std::vector<CgalPoint> cgal_points = to_cgal(points);

  struct Times {
    std::vector<double> meshstep, cgal, meshstep_wall, cgal_wall;
    std::size_t triangles = 0, faces = 0;
    bool counts_agree = true;
  };
  std::vector<Times> times(configs.size());
  bool completed = false;
  try {
    for (int rep = 0; rep < repetitions; ++rep) {
      for (std::size_t c = 0; c < configs.size(); ++c) {
        Times& t = times[c];
        const bool meshstep_first = (rep + static_cast<int>(c)) % 2 == 0;
        Run a, b;
        if (meshstep_first) {
          a = run_meshstep(points, configs[c].options);
          b = run_cgal(cgal_points);
        } else {
          b = run_cgal(cgal_points);
          a = run_meshstep(points, configs[c].options);
        }
        t.meshstep.push_back(a.cpu);
        t.cgal.push_back(b.cpu);
        t.meshstep_wall.push_back(a.wall);
        t.cgal_wall.push_back(b.wall);
        if (rep > 0 && (a.triangles != t.triangles || b.triangles != t.faces)) {
          t.counts_agree = false;  // not even deterministic
        }
        t.triangles = a.triangles;
        t.faces = b.triangles;
        if (a.triangles != b.triangles) t.counts_agree = false;
      }
    }
    completed = true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cgal_compare: error: %s\n", e.what());
    failed = true;
  }

  if (completed) {
    std::printf("\nmedians over %d repetition%s, CPU seconds (wall seconds in the last two"
                " columns); each meshstep run paired with a CGAL run\n",
                repetitions, repetitions == 1 ? "" : "s");
    std::printf("%-16s %11s %9s %14s %10s %10s %10s %11s %9s\n", "configuration", "meshstep s",
                "CGAL s", "meshstep/CGAL", "Mpoints/s", "triangles", "CGAL faces", "meshstep s",
                "CGAL s");
    std::vector<double> all_cgal, all_cgal_wall;
    for (std::size_t c = 0; c < configs.size(); ++c) {
      const Times& t = times[c];
      const double ms = median(t.meshstep);
      const double cg = median(t.cgal);
      all_cgal.insert(all_cgal.end(), t.cgal.begin(), t.cgal.end());
      all_cgal_wall.insert(all_cgal_wall.end(), t.cgal_wall.begin(), t.cgal_wall.end());
      std::printf("%-16s %11.3f %9.3f %14.2f %10.2f %10zu %10zu %11.3f %9.3f%s\n",
                  configs[c].name.c_str(), ms, cg, ms / cg, static_cast<double>(n) / ms / 1e6,
                  t.triangles, t.faces, median(t.meshstep_wall), median(t.cgal_wall),
                  t.counts_agree ? "" : "  MISMATCH");
      if (!t.counts_agree) failed = true;
    }
    std::printf("%-16s %11s %9.3f %14s %10.2f %10s %10s %11s %9.3f\n", "CGAL (all runs)", "",
                median(all_cgal), "", static_cast<double>(n) / median(all_cgal) / 1e6, "", "", "",
                median(all_cgal_wall));
    const double tds_flip = median(times[1].meshstep);
    const double dcel_flip = median(times[3].meshstep);
    const double tds_cavity = median(times[2].meshstep);
    const double dcel_cavity = median(times[4].meshstep);
    std::printf("dcel/tds time ratio: flip %.2f, cavity %.2f\n", dcel_flip / tds_flip,
                dcel_cavity / tds_cavity);
  }

  rusage self{};
  getrusage(RUSAGE_SELF, &self);
  std::printf("peak RSS of this process (all runs, both point copies): %.1f MiB\n",
              static_cast<double>(self.ru_maxrss) / 1024.0);
  if (failed) {
    std::fprintf(stderr, "cgal_compare: error: triangle counts disagree or a run failed\n");
    return 1;
  }
  return 0;
}
