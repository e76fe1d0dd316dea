// bench_workbench: how fast the viewer's workbench (issue 27) shows the mesh of an edited
// input, measured in its scripted mode (meshstep-view --offscreen --script, --frame-log).
//
// The input: N vertices (default 1000), a closed wavy ring of N/5 of them round N - N/5
// points inside it (a fixed pseudo-random sequence), written as a .poly. The viewer opens
// it (triangulated, refined when --recipe gives options), then the script moves one inner
// vertex back and forth E times (default 41), each edit followed by two frames touching
// nothing. An edit's frame is the one in which the input is triangulated again, the recipe
// run again (recorded, as every run of the viewer is), its log opened and the new mesh
// drawn: its time, from the frame's start to its end, is the time from the edit to the
// mesh on screen. Printed: the median, 90th percentile and worst of those frames, and the
// median of the idle frames after them, with their allocations.
//
//   bench_workbench --view PATH [--vertices N] [--edits E] [--gl egl|osmesa]
//                   [--recipe "--algorithm lepp-centroid --min-angle 25"]
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_args.hpp"

namespace {

namespace fs = std::filesystem;
using meshstep::bench::parse_whole;
using meshstep::bench::usage_error;

constexpr const char* kUsage =
    "usage: bench_workbench --view PATH [--vertices N] [--edits E] [--gl egl|osmesa] [--recipe OPTIONS]\n";

struct Frame {
  double ms = 0;
  unsigned long long allocations = 0;
};

std::vector<Frame> read_frames(const fs::path& path) {
  std::vector<Frame> frames;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    unsigned long long index = 0;
    double end_ms = 0;
    Frame frame;
    f >> index >> end_ms >> frame.ms >> frame.allocations;
    frames.push_back(frame);
  }
  return frames;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

// A wavy ring of `ring` vertices (radius 1 +- 0.1) and `inner` points strictly inside it.
// Returns the first inner point's coordinates, the one the edits move.
std::pair<double, double> write_input(const fs::path& path, std::size_t ring, std::size_t inner) {
  std::ofstream out(path);
  out.precision(17);
  out << "# bench_workbench: a wavy ring of " << ring << " vertices round " << inner << " points\n";
  out << ring + inner << " 2 0 0\n";
  const double pi = std::acos(-1.0);
  for (std::size_t i = 0; i < ring; ++i) {
    const double a = 2 * pi * static_cast<double>(i) / static_cast<double>(ring);
    const double r = 1.0 + 0.1 * std::sin(7 * a);
    out << i << " " << r * std::cos(a) << " " << r * std::sin(a) << "\n";
  }
  std::uint64_t state = 12345;
  const auto next = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  std::pair<double, double> first{0, 0};
  for (std::size_t i = 0; i < inner; ++i) {
    // Uniform in the disc of radius 0.85 (inside the ring's smallest radius, 0.9).
    const double r = 0.85 * std::sqrt(next()), a = 2 * pi * next();
    const double x = r * std::cos(a), y = r * std::sin(a);
    if (i == 0) first = {x, y};
    out << ring + i << " " << x << " " << y << "\n";
  }
  out << ring << " 0\n";
  for (std::size_t i = 0; i < ring; ++i) out << i << " " << i << " " << (i + 1) % ring << "\n";
  out << "0\n0\n";
  return first;
}

}  // namespace

int main(int argc, char** argv) {
  std::string view, gl = "egl", recipe;
  std::size_t vertices = 1000, edits = 41;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--view" && has_value) view = argv[++i];
    else if (a == "--gl" && has_value) gl = argv[++i];
    else if (a == "--recipe" && has_value) recipe = argv[++i];
    else if (a == "--vertices" && has_value) {
      if (!parse_whole(argv[++i], vertices) || vertices < 10) return usage_error(argv[0], "--vertices: a whole number >= 10", kUsage);
    } else if (a == "--edits" && has_value) {
      if (!parse_whole(argv[++i], edits) || edits < 1) return usage_error(argv[0], "--edits: a whole number >= 1", kUsage);
    } else {
      return usage_error(argv[0], "unknown or incomplete argument '" + a + "'", kUsage);
    }
  }
  if (view.empty()) return usage_error(argv[0], "--view PATH is required", kUsage);
  const fs::path dir = fs::temp_directory_path() / ("bench_workbench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path input = dir / "ring.poly", script = dir / "script.txt", frames = dir / "frames.txt";
  const std::size_t ring = vertices / 5;
  const auto [x, y] = write_input(input, ring, vertices - ring);
  {
    std::ofstream s(script);
    s.precision(17);
    s << "frames 4\n";
    // Back and forth by a small step: the mesh changes near the vertex each time.
    for (std::size_t e = 0; e < edits; ++e) {
      const double from = e % 2 == 0 ? x : x + 0.01, to = e % 2 == 0 ? x + 0.01 : x;
      s << "edit move " << from << " " << y << " " << to << " " << y << "\nstate " << (dir / ("state" + std::to_string(e) + ".json")).string()
        << "\nframes 2\n";
    }
    s << "quit\n";
  }
  const std::string command = view + " " + input.string() + " " + recipe + " --offscreen --gl " + gl +
                              " -q --window 1280x800 --script " + script.string() + " --frame-log " +
                              frames.string();
  const int status = std::system(command.c_str());
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "bench_workbench: the viewer failed: %s\n", command.c_str());
    return 1;
  }
  const std::vector<Frame> all = read_frames(frames);
  if (all.size() < 3 * edits) {
    std::fprintf(stderr, "bench_workbench: %zu frames logged, expected at least %zu\n", all.size(), 3 * edits);
    return 1;
  }
  // The last 3E frames: an edit's frame, then two idle ones, E times.
  std::vector<double> edit_ms, idle_ms;
  unsigned long long idle_allocations = 0;
  const std::size_t first = all.size() - 3 * edits;
  for (std::size_t e = 0; e < edits; ++e) {
    edit_ms.push_back(all[first + 3 * e].ms);
    // The second frame after the edit (the first may still settle ImGui's layout).
    idle_ms.push_back(all[first + 3 * e + 2].ms);
    idle_allocations += all[first + 3 * e + 2].allocations;
  }
  // The workbench's own time for each edit (state's remesh_ms: the input written, triangulated,
  // the recipe run and recorded, the log opened), without the viewer's frame round it.
  std::vector<double> remesh_ms;
  for (std::size_t e = 0; e < edits; ++e) {
    std::ifstream in(dir / ("state" + std::to_string(e) + ".json"));
    for (std::string line; std::getline(in, line);)
      if (const auto at = line.find("\"remesh_ms\": "); at != std::string::npos)
        remesh_ms.push_back(std::atof(line.c_str() + at + 13));
  }
  std::printf("| input | recipe | edits | edit -> mesh drawn: median / p90 / worst | of which re-meshing (median) | idle frame median | idle allocations |\n");
  std::printf("|---|---|--:|--:|--:|--:|--:|\n");
  std::printf("| %zu vertices (%zu on a ring) | %s | %zu | %.1f / %.1f / %.1f ms | %.1f ms | %.2f ms | %llu |\n", vertices,
              ring, recipe.empty() ? "triangulate" : recipe.c_str(), edits, quantile(edit_ms, 0.5),
              quantile(edit_ms, 0.9), quantile(edit_ms, 1.0), quantile(remesh_ms, 0.5), quantile(idle_ms, 0.5),
              idle_allocations);
  std::error_code ec;
  fs::remove_all(dir, ec);
  return 0;
}
