// bench_viewer: how the viewer responds, measured in its scripted mode (meshstep-view
// --offscreen --script, with --frame-log: each frame's time and allocations). For each size
// N, the log of a recorded triangulation of N uniform random points:
//   open    from the program's start to the end of its first frame (the log opened and
//           its timeline shown), 1280x800;
//   picture from the start to the first frame that shows the mesh at the end of the run
//           (the same frame as `open` when the canvas is drawn on the main thread; with
//           the canvas's worker thread, for runs of more than 20,000 vertices, later);
//   scrub   61 seeks spread over the whole run, one frame each, as a drag along the
//           timeline does: the frames' median, 95th percentile and worst time, the frames
//           per second over the drag (61 frames over the time from the first's start to the
//           last's end), and how many new pictures of the mesh the canvas showed per
//           second meanwhile (every frame's, when the main thread draws);
//   idle    30 frames with nothing changing: their median time and their allocations;
//   live    the viewer opened on the N points themselves: it runs the triangulation live
//           (the meshstep program beside it, recording) and draws frames until it ends
//           (`watch`): the run's time, the frames drawn meanwhile, their median, 99th
//           percentile and worst time.
// Repeated R times (alternating sizes); medians over the repetitions.
// --side-by-side K (2 to 4): the scrub's script on K runs of the same points at once (tds
// and dcel, flips and cavities: one Delaunay triangulation made K ways), as `meshstep view A
// B C D` shows them (issue 28: under 1 GB and above 30 frames a second with four runs of
// 1e5 points); the table gains the viewer's peak resident memory. --no-live: no live runs.
//
//   bench_viewer --view PATH --meshstep PATH --make-points PATH [--sizes 1e5,1e6] [--repeat R]
//                [--side-by-side K] [--no-live]
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
    "usage: bench_viewer --view PATH --meshstep PATH --make-points PATH [--sizes 1e5,1e6] [--repeat R]\n"
    "                    [--side-by-side K] [--no-live]\n";

struct Frame {
  double end_ms = 0, ms = 0;
  unsigned long long allocations = 0, position = 0;
  long long shown = -1;  // the position the canvas shows
};

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

// The same, the command's own peak resident memory (MiB) in *peak_mib: the shell execs it,
// so that wait4's usage is the command's.
int run_measured(const std::string& command, double* peak_mib) {
  const pid_t pid = fork();
  if (pid < 0) return 1;
  if (pid == 0) {
    const std::string exec_command = "exec " + command;
    execl("/bin/sh", "sh", "-c", exec_command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return 1;
  *peak_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

std::vector<Frame> read_frames(const fs::path& path) {
  std::vector<Frame> frames;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    unsigned long long index = 0;
    Frame fr;
    f >> index >> fr.end_ms >> fr.ms >> fr.allocations >> fr.position >> fr.shown;
    frames.push_back(fr);
  }
  return frames;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Live {
  double seconds = 0, median_ms = 0, p99_ms = 0, max_ms = 0;
  std::size_t frames = 0;
};

struct Run {
  double open_ms = 0, picture_ms = 0, scrub_median_ms = 0, scrub_p95_ms = 0, scrub_max_ms = 0, scrub_rate = 0,
         pictures_per_s = 0, idle_ms = 0, peak_mib = 0;
  unsigned long long idle_allocations = 0;
};

}  // namespace

int main(int argc, char** argv) {
  std::string view, meshstep, make_points;
  std::vector<std::size_t> sizes = {100000, 1000000};
  int repeat = 3, side_by_side = 1;
  bool live_runs = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--view" && has_value) view = argv[++i];
    else if (arg == "--meshstep" && has_value) meshstep = argv[++i];
    else if (arg == "--make-points" && has_value) make_points = argv[++i];
    else if (arg == "--repeat" && has_value) {
      if (!parse_whole(argv[++i], repeat) || repeat < 1) return usage_error("bench_viewer", "--repeat: expected >= 1", kUsage);
    } else if (arg == "--side-by-side" && has_value) {
      if (!parse_whole(argv[++i], side_by_side) || side_by_side < 2 || side_by_side > 4)
        return usage_error("bench_viewer", "--side-by-side: 2 to 4 runs", kUsage);
    } else if (arg == "--no-live") {
      live_runs = false;
    } else if (arg == "--sizes" && has_value) {
      sizes.clear();
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');) {
        const double n = std::atof(item.c_str());
        if (n < 10 || n > 1e8) return usage_error("bench_viewer", "--sizes: counts from 10 to 1e8", kUsage);
        sizes.push_back(static_cast<std::size_t>(n));
      }
    } else {
      return usage_error("bench_viewer", "unknown argument " + arg, kUsage);
    }
  }
  if (view.empty() || meshstep.empty() || make_points.empty())
    return usage_error("bench_viewer", "--view, --meshstep and --make-points are needed", kUsage);

  const fs::path dir = fs::temp_directory_path() / "bench_viewer";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // logs[s]: the viewer's arguments for size s, one log or side_by_side of them.
  std::vector<std::string> logs, nodes;
  static constexpr const char* kWays[] = {"--ds tds --insertion flip", "--ds dcel --insertion flip",
                                          "--ds tds --insertion cavity", "--ds dcel --insertion cavity"};
  for (const std::size_t n : sizes) {
    const std::string node = (dir / ("p" + std::to_string(n) + ".node")).string();
    if (run(make_points + " " + std::to_string(n) + " " + node + " 11") != 0) {
      std::fprintf(stderr, "bench_viewer: making %zu points failed\n", n);
      return 1;
    }
    std::string arguments;
    for (int k = 0; k < side_by_side; ++k) {
      const std::string log = (dir / ("p" + std::to_string(n) + "_" + std::to_string(k) + ".mslog")).string();
      if (run(meshstep + " triangulate " + node + " " + kWays[k] + " --record " + log + " --no-output -q") != 0) {
        std::fprintf(stderr, "bench_viewer: recording %zu points failed\n", n);
        return 1;
      }
      arguments += (k ? " " : "") + log;
    }
    nodes.push_back(node);
    logs.push_back(arguments);
  }

  // The script: seeks spread over the run (event numbers beyond the end are clamped), one
  // frame each, then idle frames.
  const fs::path script = dir / "scrub.txt";
  std::vector<std::vector<Run>> runs(sizes.size());
  for (int r = 0; r < repeat; ++r) {
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      {
        std::ofstream out(script);
        // `settle` holds the script until the canvas shows the cursor (no frame passes).
        out << "frames 1\nsettle\nframes 1\n";
        const unsigned long long approx_events = 7ULL * sizes[s];
        for (int k = 0; k <= 60; ++k) out << "seek event " << approx_events * static_cast<unsigned long long>(k) / 60 << "\nframes 1\n";
        out << "wait\nframes 30\nquit\n";  // the canvas and the background work done
      }
      const fs::path frames_file = dir / "frames.txt";
      double peak_mib = 0;
      if (run_measured(view + " " + logs[s] + " --offscreen --window 1280x800 -q --script " + script.string() +
                           " --frame-log " + frames_file.string(),
                       &peak_mib) != 0) {
        std::fprintf(stderr, "bench_viewer: the viewer failed on %s\n", logs[s].c_str());
        return 1;
      }
      const std::vector<Frame> f = read_frames(frames_file);
      if (f.size() < 93) {
        std::fprintf(stderr, "bench_viewer: %zu frames logged, expected 93\n", f.size());
        return 1;
      }
      Run result;
      result.peak_mib = peak_mib;
      result.open_ms = f[0].end_ms;
      const auto shows_cursor = [](const Frame& fr) { return fr.shown == static_cast<long long>(fr.position); };
      result.picture_ms = shows_cursor(f[0]) ? f[0].end_ms : f[1].end_ms;
      std::vector<double> scrub, idle;
      std::size_t pictures = 0;
      for (std::size_t i = 2; i <= 62; ++i) {
        scrub.push_back(f[i].ms);
        pictures += f[i].shown != f[i - 1].shown;
      }
      const double drag_ms = std::max(1e-3, f[62].end_ms - f[1].end_ms);  // the 61 scrub frames, end to end
      result.pictures_per_s = 1000.0 * static_cast<double>(pictures) / drag_ms;
      result.scrub_rate = 1000.0 * 61.0 / drag_ms;
      for (std::size_t i = 63; i < f.size(); ++i) {
        idle.push_back(f[i].ms);
        if (i > 64) result.idle_allocations += f[i].allocations;  // after 2 warm-up frames
      }
      result.scrub_median_ms = median(scrub);
      {
        std::vector<double> sorted = scrub;
        std::sort(sorted.begin(), sorted.end());
        result.scrub_p95_ms = sorted[sorted.size() * 95 / 100];
      }
      result.scrub_max_ms = *std::max_element(scrub.begin(), scrub.end());
      result.idle_ms = median(idle);
      runs[s].push_back(result);
    }
  }

  // Live runs: the viewer on the points, drawing while the run goes.
  std::vector<std::vector<Live>> lives(sizes.size());
  for (int r = 0; r < repeat && live_runs; ++r) {
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      std::ofstream(script) << "watch\nquit\n";
      const fs::path frames_file = dir / "live_frames.txt";
      if (run(view + " " + nodes[s] + " --offscreen --window 1280x800 -q --script " + script.string() + " --frame-log " +
              frames_file.string()) != 0) {
        std::fprintf(stderr, "bench_viewer: the live run of %s failed\n", nodes[s].c_str());
        return 1;
      }
      const std::vector<Frame> f = read_frames(frames_file);
      if (f.size() < 2) continue;
      std::vector<double> ms;
      for (std::size_t i = 1; i < f.size(); ++i) ms.push_back(f[i].ms);  // the first frame starts the run
      std::sort(ms.begin(), ms.end());
      Live l;
      l.seconds = f.back().end_ms / 1000.0;
      l.frames = f.size();
      l.median_ms = ms[ms.size() / 2];
      l.p99_ms = ms[std::min(ms.size() - 1, ms.size() * 99 / 100)];
      l.max_ms = ms.back();
      lives[s].push_back(l);
    }
  }

  if (side_by_side > 1) std::printf("%d runs side by side, each a log of the same N points\n\n", side_by_side);
  std::printf("| log of N points | open: timeline shown (ms) | mesh shown (ms) | scrub frame median / p95 / worst (ms) | scrub frames/s (61 frames over the drag's time) | new pictures/s while scrubbing | idle frame (ms) | idle allocations | peak resident (MiB) |\n");
  std::printf("|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    std::vector<double> open, picture, med, p95, worst, rate, pictures, idle, peak;
    unsigned long long allocations = 0;
    for (const Run& r : runs[s]) {
      peak.push_back(r.peak_mib);
      open.push_back(r.open_ms);
      picture.push_back(r.picture_ms);
      pictures.push_back(r.pictures_per_s);
      med.push_back(r.scrub_median_ms);
      p95.push_back(r.scrub_p95_ms);
      worst.push_back(r.scrub_max_ms);
      rate.push_back(r.scrub_rate);
      idle.push_back(r.idle_ms);
      allocations += r.idle_allocations;
    }
    std::printf("| %zu | %.0f | %.0f | %.1f / %.0f / %.0f | %.1f | %.1f | %.1f | %llu | %.0f (worst %.0f) |\n", sizes[s],
                median(open), median(picture), median(med), median(p95), median(worst), median(rate), median(pictures),
                median(idle), allocations, median(peak), *std::max_element(peak.begin(), peak.end()));
  }
  if (!live_runs) {
    fs::remove_all(dir);
    return 0;
  }
  std::printf("\n| N points, run live | run (s) | frames drawn meanwhile | frame median / p99 / worst (ms) |\n");
  std::printf("|--:|--:|--:|--:|\n");
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    std::vector<double> seconds, med, p99, worst, frames;
    for (const Live& l : lives[s]) {
      seconds.push_back(l.seconds);
      med.push_back(l.median_ms);
      p99.push_back(l.p99_ms);
      worst.push_back(l.max_ms);
      frames.push_back(static_cast<double>(l.frames));
    }
    std::printf("| %zu | %.2f | %.0f | %.1f / %.1f / %.0f |\n", sizes[s], median(seconds), median(frames), median(med),
                median(p99), median(worst));
  }
  fs::remove_all(dir);
  return 0;
}
