// cgal_mesher FILE.poly [--min-angle DEG] [--max-area A] [--repeat N] [--meshstep-max-area A]
//
// Meshes a PSLG with CGAL's 2D Delaunay mesher N times (see cgal_mesher.hpp) and prints,
// per run and then the median of each column: triangles in the domain, vertices, smallest
// angle, construction and refinement wall seconds, and triangles per second of refinement.
// With --meshstep-max-area, each CGAL run is followed by meshstep's own refinement of the
// same input (circumcenter, same angle, that area bound), and the ratio of the two
// throughputs (output triangles per second of construction plus refinement) is printed: the
// peer comparison in one process, runs interleaved so that machine noise hits both.
//
// Exit status: 0 ok, 1 a run failed, 2 usage error or unreadable input.
#include <CGAL/version.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "bench_args.hpp"
#include "cgal_mesher.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"

namespace {

constexpr const char* kUsage =
    "usage: cgal_mesher FILE.poly [--min-angle DEG] [--max-area A] [--repeat N] [--meshstep-max-area A]\n";

constexpr const char* kHelp =
    "Meshes a Triangle .poly (or .node) file with CGAL's 2D Delaunay mesher, N times,\n"
    "and prints each run and the medians: triangles in the domain, vertices, smallest\n"
    "angle, construction and refinement wall seconds, triangles per refinement second.\n"
    "\n"
    "  --min-angle DEG  smallest angle to reach, 0 <= DEG < 60 (default 20; 0: no shape\n"
    "                   criterion). CGAL's termination guarantee ends near 20.7.\n"
    "  --max-area A     triangle area bound, as Triangle's -a (default none); CGAL takes\n"
    "                   it as the edge bound sqrt(4A/sqrt(3)), the equilateral of area A\n"
    "  --repeat N       number of runs (default 3)\n"
    "  --meshstep-max-area A\n"
    "                   also refine with meshstep (circumcenter, same angle, area bound A)\n"
    "                   after each CGAL run, and print both throughputs and their ratio\n"
    "  -h, --help       this text\n"
    "\n"
    "Hole points are CGAL seeds of regions not to mesh. Exit status: 0 ok, 1 a run\n"
    "failed, 2 usage error or unreadable input.\n";

int usage_error(const std::string& message) { return meshstep::bench::usage_error("cgal_mesher", message, kUsage); }

using meshstep::bench::parse_whole;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t m = values.size() / 2;
  return values.size() % 2 == 1 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

void print_row(const char* label, double triangles, double vertices, double angle,
               double construct, double refine) {
  std::printf("%-8s %11.0f %11.0f %9.3f %12.6f %11.6f %14.0f\n", label, triangles, vertices,
              angle, construct, refine, refine > 0 ? triangles / refine : 0.0);
}

struct OurRun {
  double triangles, seconds, min_angle_deg;
};

// meshstep's refinement of the same input: triangulation and refinement, timed together.
OurRun run_meshstep(const meshstep::Pslg& input, double min_angle, double max_area) {
  meshstep::RefineOptions o;
  o.criteria.min_angle_deg = min_angle;
  o.criteria.max_area = max_area;
  const auto start = std::chrono::steady_clock::now();
  const meshstep::TriMesh m = meshstep::refine(input, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {static_cast<double>(m.triangles.size()), seconds, meshstep::angle_stats(m).min_angle_deg};
}

}  // namespace

int main(int argc, char** argv) {
  std::string path;
  double min_angle = 20.0;
  double max_area = 0.0;
  double meshstep_max_area = 0.0;
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::printf("%s\n%s", kUsage, kHelp);
      return 0;
    }
    if (arg == "--min-angle" || arg == "--max-area" || arg == "--repeat" || arg == "--meshstep-max-area") {
      if (i + 1 >= argc) return usage_error(std::string(arg) + " needs a value");
      const std::string_view value = argv[++i];
      if (arg == "--min-angle") {
        if (!parse_whole(value, min_angle) || !(min_angle >= 0 && min_angle < 60)) {
          return usage_error("--min-angle must be a number in [0, 60)");
        }
      } else if (arg == "--max-area" || arg == "--meshstep-max-area") {
        double& area = arg == "--max-area" ? max_area : meshstep_max_area;
        if (!parse_whole(value, area) || !(area > 0)) {
          return usage_error(std::string(arg) + " must be a positive number");
        }
      } else if (!parse_whole(value, repeat) || repeat < 1) {
        return usage_error("--repeat must be a positive integer");
      }
    } else if (arg.starts_with("-") && arg.size() > 1) {
      return usage_error("unknown option " + std::string(arg));
    } else if (path.empty()) {
      path = arg;
    } else {
      return usage_error("more than one input file");
    }
  }
  if (path.empty()) return usage_error("no input file");

  meshstep::Pslg input;
  try {
    std::vector<std::string> warnings;
    input = meshstep::io::read_pslg(path, &warnings);
    for (const auto& w : warnings) std::fprintf(stderr, "cgal_mesher: warning: %s\n", w.c_str());
  } catch (const meshstep::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }

  std::printf("CGAL %s Delaunay mesher: %s (%zu points, %zu segments, %zu holes)\n",
              CGAL_VERSION_STR, path.c_str(), input.points.size(), input.segments.size(),
              input.holes.size());
  std::printf("min angle %g degrees, ", min_angle);
  if (max_area > 0) {
    std::printf("max area %g\n", max_area);
  } else {
    std::printf("no area bound\n");
  }
  std::printf("%-8s %11s %11s %9s %12s %11s %14s\n", "run", "triangles", "vertices", "min angle",
              "construct s", "refine s", "triangles/s");

  std::vector<double> triangles, vertices, angles, construct, refine;
  std::vector<double> ours_rate, cgal_rate, ratio;  // with --meshstep-max-area
  double area = 0.0;
  try {
    for (int run = 1; run <= repeat; ++run) {
      const meshstep::bench::CgalMeshResult r =
          meshstep::bench::cgal_refine(input, min_angle, max_area);
      triangles.push_back(static_cast<double>(r.triangles));
      vertices.push_back(static_cast<double>(r.vertices));
      angles.push_back(r.min_angle_deg);
      construct.push_back(r.construct_seconds);
      refine.push_back(r.refine_seconds);
      area = r.domain_area;
      print_row(std::to_string(run).c_str(), triangles.back(), vertices.back(), angles.back(),
                construct.back(), refine.back());
      if (meshstep_max_area > 0) {
        const OurRun ours = run_meshstep(input, min_angle, meshstep_max_area);
        cgal_rate.push_back(triangles.back() / (construct.back() + refine.back()));
        ours_rate.push_back(ours.triangles / ours.seconds);
        ratio.push_back(ours_rate.back() / cgal_rate.back());
        std::printf("  meshstep %11.0f triangles, min angle %.3f, %.6f s, %.0f triangles/s: %.2fx CGAL's %.0f\n",
                    ours.triangles, ours.min_angle_deg, ours.seconds, ours_rate.back(), ratio.back(),
                    cgal_rate.back());
      }
      std::fflush(stdout);  // long runs: show progress as it comes
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cgal_mesher: error: %s\n", e.what());
    return 1;
  }
  // Medians per column: the row need not be one actual run.
  print_row("median", median(triangles), median(vertices), median(angles), median(construct),
            median(refine));
  std::printf("domain area %.10g\n", area);
  if (!ratio.empty()) {
    std::printf("median triangles/s (construction + refinement): meshstep %.0f, CGAL %.0f; median ratio %.2fx\n",
                median(ours_rate), median(cgal_rate), median(ratio));
  }
  return 0;
}
