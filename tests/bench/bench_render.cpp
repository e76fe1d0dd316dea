// bench_render: what pictures cost. Medians of repeated runs, printed as a table
// (docs/rendering.md):
//   frame   an off-screen frame of a Delaunay mesh of about 1M triangles at 1920x1080,
//           render plus read-back, on each off-screen backend (EGL, OSMesa), beside the
//           floor: the same triangles in flat colours by the plainest shader (plain_frame.hpp);
//   scene   building that mesh's scene (colour by smallest angle);
//   svg     the SVG of a 100k-triangle mesh, made and written to a file;
//   export  whole `meshstep export` processes on a recorded refinement (A.poly at 30
//           degrees unless --poly says otherwise), 1280x720, one frame per step: PNG frames
//           and an MP4 through ffmpeg, in frames per second (process start and log opening
//           included).
//
//   bench_render [--triangles N] [--repeat R] [--meshstep PATH --poly FILE] [--skip-export]
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/scene/svg.hpp"
#include "plain_frame.hpp"
#include "random_points.hpp"
#include "render/gl_context.hpp"
#include "render/mesh_raster.hpp"
#include "render/renderer.hpp"

namespace {

using namespace meshstep;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage =
    "usage: bench_render [--triangles N] [--repeat R] [--meshstep PATH --poly FILE] [--skip-export]\n";

struct Stats {
  double min = 0, median = 0, max = 0;
};

Stats stats_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v.front(), v[v.size() / 2], v.back()};
}

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

Stats time_ms(int repeat, const std::function<void()>& f) {
  std::vector<double> times;
  for (int i = 0; i < repeat; ++i) {
    const auto t0 = Clock::now();
    f();
    times.push_back(ms_since(t0));
  }
  return stats_of(times);
}

void row(const std::string& what, const Stats& s, const char* unit) {
  std::printf("| %-58s | %9.1f | %9.1f | %9.1f | %s |\n", what.c_str(), s.min, s.median, s.max, unit);
  std::fflush(stdout);
}

TriMesh delaunay_mesh(std::size_t triangles) {
  Pslg points;
  points.points = bench::uniform_points(triangles / 2 + 2);
  return triangulate(std::move(points));
}

void bench_frames(const TriMesh& mesh, int repeat) {
  scene::SceneOptions options;
  options.color_by = scene::ColorBy::angle;
  scene::Scene picture;
  row("scene of " + std::to_string(mesh.triangles.size()) + " triangles (colour by angle)",
      time_ms(repeat, [&] { picture = scene::build_scene(mesh, options); }), "ms");
  const scene::Camera camera = scene::fit_scene(picture, 1920, 1080);
  for (const char* backend : {"egl", "osmesa"}) {
    std::unique_ptr<render::GlContext> context;
    try {
      context = render::make_offscreen_context(backend);
    } catch (const render::GlUnavailable& e) {
      std::printf("| %-58s | %s |\n", (std::string(backend) + ": skipped").c_str(), e.what());
      continue;
    }
    {
      render::Renderer renderer;
      scene::Image image;
      const int samples = render::kDefaultSamples;
      renderer.render(picture, camera, samples);  // first frame: uploads
      renderer.read_pixels(image);
      // The renderer's frame and the plain floor alternate, so that the machine's drift
      // (tens of percent within minutes) falls on both alike.
      bench::PlainFrame plain(mesh, 1920, 1080);
      plain.draw_and_read();
      std::vector<double> ours, floor, approximate;
      scene::Image approximate_image;
      for (int i = 0; i < repeat; ++i) {
        auto t0 = Clock::now();
        renderer.render(picture, camera, samples);
        renderer.read_pixels(image);
        ours.push_back(ms_since(t0));
        t0 = Clock::now();
        plain.draw_and_read();
        floor.push_back(ms_since(t0));
        t0 = Clock::now();
        renderer.render(picture, camera, samples, render::Detail::approximate);
        renderer.read_pixels(approximate_image);
        approximate.push_back(ms_since(t0));
      }
      const Stats ours_stats = stats_of(ours), floor_stats = stats_of(floor);
      row(std::string(backend) + ": 1920x1080 frame, render + read-back (samples " + std::to_string(samples) + ")",
          ours_stats, "ms");
      row(std::string(backend) + ": floor: same triangles, flat colour only, no edges", floor_stats, "ms");
      std::printf("| %-58s | %9.2f | %9.2f | %9s | %s |\n", (std::string(backend) + ": frame over floor").c_str(),
                  ours_stats.min / floor_stats.min, ours_stats.median / floor_stats.median, "", "ratio");
      const Stats approximate_stats = stats_of(approximate);
      row(std::string(backend) + ": the same frame, level of detail (mesh_raster.hpp)", approximate_stats, "ms");
      std::printf("| %-58s | %9.2f | %9.2f | %9s | %s |\n", (std::string(backend) + ": level of detail over frame").c_str(),
                  approximate_stats.min / ours_stats.min, approximate_stats.median / ours_stats.median, "", "ratio");
      std::printf("|   (%zu of the triangles drawn on the CPU)\n", renderer.counters().raster_triangles);
      {
        // The CPU's part of the level of detail alone: the points snapped, the triangles found.
        render::MeshRaster raster;
        const render::WorldFrame frame = render::choose_frame(picture.bounds, camera, nullptr);
        const render::View view{1920, 1080, render::local_to_pixels(frame, camera)};
        std::vector<std::uint32_t> pixels(1920 * 1080), large;
        row(std::string(backend) + ": level of detail: its CPU raster alone",
            time_ms(repeat, [&] { raster.draw(picture.mesh, frame, view, true, pixels, large); }), "ms");
      }
      const scene::ImageDiff diff = scene::compare_images(image, approximate_image, 5);
      const std::size_t differing = diff.differing_pixels;
      std::printf("| %-58s | %9zu | %8.4f%% | %9s | %s |\n", (std::string(backend) + ": level of detail: pixels off by > 5").c_str(),
                  differing, 100.0 * static_cast<double>(differing) / (1920.0 * 1080.0), "", "pixels");
      row(std::string(backend) + ": same, with the mesh uploaded again", time_ms(repeat, [&] {
            renderer.invalidate();
            renderer.render(picture, camera, samples);
            renderer.read_pixels(image);
          }),
          "ms");
    }
  }
}

void bench_svg(int repeat) {
  const TriMesh mesh = delaunay_mesh(100000);
  scene::SceneOptions options;
  options.color_by = scene::ColorBy::angle;
  const scene::Scene picture = scene::build_scene(mesh, options);
  const scene::Camera camera = scene::fit_scene(picture, 1920, 1080);
  const std::string path = (std::filesystem::temp_directory_path() / "bench_render.svg").string();
  std::size_t bytes = 0;
  row("svg of " + std::to_string(mesh.triangles.size()) + " triangles, made and written", time_ms(repeat, [&] {
        const std::string svg = scene::to_svg(picture, camera);
        bytes = svg.size();
        io::write_file_atomically(path, svg);
      }),
      "ms");
  std::printf("|   (%.1f MB)\n", bytes / 1e6);
  std::filesystem::remove(path);
}

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

// Frames per second of whole `meshstep export` processes.
void bench_export(const std::string& meshstep, const std::string& poly, int repeat) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "bench_render_export";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string log = (dir / "run.mslog").string();
  if (run(meshstep + " refine " + poly + " --min-angle 30 --record " + log + " --no-output -q") != 0) {
    std::printf("| export: recording %s failed |\n", poly.c_str());
    return;
  }
  // One frame per step: the PNG run counts them, the video has as many.
  std::size_t frame_count = 0;
  for (const char* kind : {"frames", "video"}) {
    const bool frames = std::string(kind) == "frames";
    std::vector<double> fps;
    for (int i = 0; i < repeat; ++i) {
      fs::remove_all(dir / "frames");
      const std::string target = frames ? "--frames " + (dir / "frames").string() : "--video " + (dir / "run.mp4").string();
      const auto t0 = Clock::now();
      if (run(meshstep + " export " + log + " " + target + " --size 1280x720 --every step -q") != 0) {
        std::printf("| export %s failed |\n", kind);
        return;
      }
      const double seconds = ms_since(t0) / 1000.0;
      if (frames) {
        frame_count = 0;
        for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir / "frames")) ++frame_count;
      }
      fps.push_back(static_cast<double>(frame_count) / seconds);
    }
    row(std::string("export ") + poly.substr(poly.find_last_of('/') + 1) + " at 30 deg, 1280x720, " +
            (frames ? "PNG frames (" : "MP4 (") + std::to_string(frame_count) + " frames)",
        stats_of(fps), "frames/s");
  }
  fs::remove_all(dir);
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t triangles = 1000000;
  int repeat = 7;
  std::string meshstep, poly;
  bool skip_export = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--triangles" && has_value) {
      double n = 0;
      if (!bench::parse_whole(argv[++i], n) || n < 2 || n > 1e8)
        return bench::usage_error("bench_render", "--triangles: expected a count from 2 to 1e8", kUsage);
      triangles = static_cast<std::size_t>(n);
    } else if (arg == "--repeat" && has_value) {
      if (!bench::parse_whole(argv[++i], repeat) || repeat < 1)
        return bench::usage_error("bench_render", "--repeat: expected a count >= 1", kUsage);
    } else if (arg == "--meshstep" && has_value) {
      meshstep = argv[++i];
    } else if (arg == "--poly" && has_value) {
      poly = argv[++i];
    } else if (arg == "--skip-export") {
      skip_export = true;
    } else {
      return bench::usage_error("bench_render", "unknown argument " + arg, kUsage);
    }
  }
  std::printf("| what | min | median | max | unit |\n|---|--:|--:|--:|---|\n");
  bench_frames(delaunay_mesh(triangles), repeat);
  bench_svg(std::max(3, repeat / 2));
  if (!skip_export && !meshstep.empty() && !poly.empty()) bench_export(meshstep, poly, std::max(3, repeat / 2));
  return 0;
}
