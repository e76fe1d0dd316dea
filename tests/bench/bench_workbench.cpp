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
//
// With --live, a big run instead (issue 27: "the window's frames stay under 50 ms while a
// 1M-triangle recipe runs live"): the viewer opens the input with the recipe (which should
// make a big mesh, e.g. --recipe "--max-area 3e-6" for about a million triangles), draws
// 10 frames after it has opened, moves the inner vertex once, which goes live (workbench.hpp: goes_live), and
// draws frames while the run goes (`watch`), then 30 idle ones. Printed: the frames drawn
// while the re-meshing ran live (median, 95th percentile, worst) against the idle frames
// after it, drawn in the same minutes.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "bench_args.hpp"

namespace {

namespace fs = std::filesystem;
using meshstep::bench::parse_whole;
using meshstep::bench::usage_error;

constexpr const char* kUsage =
    "usage: bench_workbench --view PATH [--vertices N] [--edits E] [--gl egl|osmesa] [--recipe OPTIONS] [--live]\n";

struct Frame {
  double ms = 0;
  unsigned long long allocations = 0;
  bool live = false;  // a live run went during the frame
  long long position = 0;  // the cursor's position in the run shown
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
    long long shown = 0;
    int live = 0;
    f >> index >> end_ms >> frame.ms >> frame.allocations >> frame.position >> shown >> live;
    frame.live = live == 1;
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

// The frames of the workbench's live run (the last stretch marked live: the first is the
// run the viewer opened with) against the idle frames after it.
int report_live(const std::vector<Frame>& all, std::size_t vertices, const std::string& recipe) {
  std::size_t end = all.size();
  while (end > 0 && !all[end - 1].live) --end;
  std::size_t begin = end;
  while (begin > 0 && all[begin - 1].live) --begin;
  // The new mesh's first frame: the first after the run whose cursor stands in another run
  // (the new run's end); the idle frames are those after it.
  std::size_t first = end;
  while (first < all.size() && all[first].position == all[begin].position) ++first;
  if (first == all.size()) {
    std::fprintf(stderr, "bench_workbench: the new mesh was never shown\n");
    return 1;
  }
  std::vector<double> live_ms, idle_ms, live_allocations;
  for (std::size_t i = begin; i < end; ++i) {
    live_ms.push_back(all[i].ms);
    live_allocations.push_back(static_cast<double>(all[i].allocations));
  }
  for (std::size_t i = first + 1; i < all.size(); ++i) idle_ms.push_back(all[i].ms);
  if (live_ms.size() < 3 || idle_ms.size() < 10) {
    std::fprintf(stderr, "bench_workbench: %zu frames while live, %zu idle after: did the edit go live?\n",
                 live_ms.size(), idle_ms.size());
    return 1;
  }
  // The frame after the run: its log opened, the new mesh's first picture asked for.
  // Allocations per live frame: the first (the edit's) and the last (the run's end) are
  // not the stretch's own; the median and worst of the rest.
  std::vector<double> between(live_allocations.begin() + 1, live_allocations.end() - 1);
  std::printf("| input | recipe | frames while live | live frame: median / p95 / worst | idle frame median (same run) | median ratio | the new mesh's first frame | allocations per live frame: median / worst |\n");
  std::printf("|---|---|--:|--:|--:|--:|--:|--:|\n");
  std::printf("| %zu vertices | %s | %zu | %.1f / %.1f / %.1f ms | %.1f ms | %.2f | %.1f ms | %.0f / %.0f |\n", vertices,
              recipe.c_str(), live_ms.size(), quantile(live_ms, 0.5), quantile(live_ms, 0.95), quantile(live_ms, 1.0),
              quantile(idle_ms, 0.5), quantile(live_ms, 0.5) / quantile(idle_ms, 0.5), all[first].ms,
              quantile(between, 0.5), quantile(between, 1.0));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string view, gl = "egl", recipe;
  std::size_t vertices = 1000, edits = 41;
  bool live = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--view" && has_value) view = argv[++i];
    else if (a == "--gl" && has_value) gl = argv[++i];
    else if (a == "--recipe" && has_value) recipe = argv[++i];
    else if (a == "--live") live = true;
    else if (a == "--vertices" && has_value) {
      if (!parse_whole(argv[++i], vertices) || vertices < 10) return usage_error(argv[0], "--vertices: a whole number >= 10", kUsage);
    } else if (a == "--edits" && has_value) {
      if (!parse_whole(argv[++i], edits) || edits < 1) return usage_error(argv[0], "--edits: a whole number >= 1", kUsage);
    } else {
      return usage_error(argv[0], "unknown or incomplete argument '" + a + "'", kUsage);
    }
  }
  if (view.empty()) return usage_error(argv[0], "--view PATH is required", kUsage);
  if (live && recipe.empty()) return usage_error(argv[0], "--live needs a --recipe that makes a big mesh", kUsage);
  const fs::path dir = fs::temp_directory_path() / ("bench_workbench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path input = dir / "ring.poly", script = dir / "script.txt", frames = dir / "frames.txt";
  const std::size_t ring = vertices / 5;
  const auto [x, y] = write_input(input, ring, vertices - ring);
  {
    std::ofstream s(script);
    s.precision(17);
    if (live) {
      // `state` waits for the run the viewer opened with, which then opens; the ten frames
      // after it are idle, so that the last frames marked live are the workbench's alone.
      s << "state " << (dir / "opened.json").string() << "\nframes 10\nedit move " << x << " " << y << " " << x + 0.01 << " " << y << "\nwatch\nframes 30\nstate "
        << (dir / "live.json").string() << "\nquit\n";
      edits = 0;
    }
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
  if (live) {
    // The new mesh's triangles and the live run's wall and processor time (state's fields).
    std::ifstream in(dir / "live.json");
    const std::string state((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto number = [&](const std::string& key) {
      const auto at = state.find("\"" + key + "\": ");
      return at == std::string::npos ? -1.0 : std::atof(state.c_str() + at + key.size() + 4);
    };
    std::printf("live re-meshing: %.0f triangles, %.0f ms (wall), %.0f ms (processor), live runs %.0f\n",
                number("mesh_triangles"), number("remesh_ms"), number("remesh_cpu_ms"), number("live_remeshes"));
    const int result = report_live(all, vertices, recipe);
    std::error_code ec;
    fs::remove_all(dir, ec);
    return result;
  }
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
