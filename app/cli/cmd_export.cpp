// meshstep export: a run's animation, as numbered PNG frames or as a video through ffmpeg.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "draw_options.hpp"
#include "refuse_overwrites.hpp"
#include "frame_moments.hpp"
#include "meshstep/error.hpp"
#include "meshstep/scene/layout.hpp"
#include "moment_scene.hpp"
#include "orbit_options.hpp"
#include "png_frame_writer.hpp"
#include "common/scene_source.hpp"
#include "frame_sink.hpp"
#include "tour_export.hpp"
#include "video_pipe.hpp"
#include "render/painter.hpp"

namespace meshstep::app {
namespace {

struct ExportArgs {
  std::string log;
  std::string tour;  // a guided tour instead of a log (tour_export.hpp)
  std::string frames;
  std::string video;
  std::string every = "step";
  std::int64_t from = 0;
  std::int64_t to = -1;
  double fps = 10.0;
  double duration = 0.0;
  DrawArgs draw;
  OrbitArgs orbit;
  double spin = 0.0;  // degrees the azimuth turns over the animation (3D)
  bool quiet = false;
};

// Progress on a terminal, about twice a second; nothing when standard error is a file.
class ExportProgress {
 public:
  ExportProgress(bool show, std::size_t total) : show_(show && ::isatty(2)), total_(total) {}
  void frame(std::size_t done) {
    if (!show_) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total_ && now - last_ < std::chrono::milliseconds(500)) return;
    last_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "\rmeshstep: export: frame %zu of %zu (%.0f frames/s)   ", done, total_,
                 seconds > 0 ? done / seconds : 0.0);
    if (done == total_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }

 private:
  bool show_;
  std::size_t total_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
};

void check_args(const ExportArgs& args) {
  if (args.frames.empty() == args.video.empty())
    throw UsageError("give --frames DIR or --video OUT.mp4|OUT.webm|OUT.gif (one of them)");
  if (!(args.fps > 0.0) || args.fps > 240.0) throw UsageError("--fps: expected a rate above 0 and at most 240");
  if (args.duration < 0.0 || !std::isfinite(args.duration) || args.duration > 3600.0)
    throw UsageError("--duration: expected seconds from 0 (one frame per moment) to 3600");
  if (args.duration > 0.0 && args.video.empty()) throw UsageError("--duration applies to --video only");
  if (!std::isfinite(args.spin) || std::abs(args.spin) > 3600.0)
    throw UsageError("--spin: expected degrees from -3600 to 3600");
  if (args.spin != 0.0 && args.orbit.orbit.empty() && args.orbit.z_scale.empty())
    throw UsageError("--spin turns the 3D camera: give --orbit AZ,EL (or --z-scale) too");
}

// The frames already in DIR that a run would write over (frame_NNNNNN.png): only a file
// that exists can be the log.
std::vector<std::string> existing_frames(const std::string& dir) {
  std::vector<std::string> frames;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.starts_with("frame_") && name.ends_with(".png")) frames.push_back(it->path().string());
  }
  return frames;
}

// The video or the frames folder may not replace what the export reads (a log, a tour).
int refuse_export_overwrites(const ExportArgs& args, const std::string& input) {
  return refuse_overwrites(FileRoles()
                               .reads(input)
                               .writes("--video", args.video, "video")
                               .writes("--frames", args.frames, "frames folder")
                               .writes_existing("--frames", args.frames, existing_frames(args.frames), "frames folder"));
}

// A tour names its own run and its own moments: none of a log's options goes with it.
int run_tour_export(const ExportArgs& args, const CLI::App& cmd) {
  if (const int refused = refuse_export_overwrites(args, args.tour)) return refused;
  return with_picture_errors("", [&] {
    if (!args.log.empty()) throw UsageError("--tour names its own run: give no LOG (" + args.log + ") with it");
    for (const char* option : {"--every", "--from", "--to", "--duration", "--spin", "--orbit", "--z-scale"})
      if (cmd.count(option)) throw UsageError(std::string(option) + " is for a log's animation: a tour's stops say what it shows");
    check_args(args);
    TourExportArgs tour;
    tour.tour = args.tour;
    tour.frames = args.frames;
    tour.video = args.video;
    tour.fps = args.fps;
    tour.draw = parse_draw_args(args.draw);
    tour.quiet = args.quiet;
    return export_tour(tour);
  });
}

int run_export(const ExportArgs& args) {
  const Verbosity verbosity = args.quiet ? Verbosity::quiet : Verbosity::normal;
  if (const int refused = refuse_export_overwrites(args, args.log)) return refused;
  return with_picture_errors("", [&] {
    check_args(args);
    const DrawSettings draw = parse_draw_args(args.draw);
    const MomentSpec spec = parse_every(args.every, args.from, args.to);
    if (!std::filesystem::is_regular_file(args.log) || !is_replay_log(args.log)) {
      if (!std::filesystem::exists(args.log)) throw InputError(args.log, 0, "no such file");
      throw InputError(args.log, 0, "not a replay log (write one with triangulate or refine --record LOG)");
    }
    const replay::LogReader log(args.log);
    if (!log.complete()) print_warning(verbosity, args.log + ": " + log.incomplete_reason());
    std::vector<std::uint64_t> moments = frame_moments(log, spec);
    if (args.duration > 0.0)
      moments = resample(moments, std::max<std::size_t>(1, std::llround(args.duration * args.fps)));

    // A terrain's run in 3D: one view per frame, the azimuth turning by --spin over them.
    const bool in_3d = args.orbit.given();
    if (in_3d && !log.has_elevation())
      throw UsageError(args.orbit.name() + " draws a terrain's run in 3D, and " + args.log +
                       " has no heights (record one with meshstep terrain --record LOG)");
    std::vector<scene::SurfaceView> views;
    if (in_3d) {
      scene::SurfaceView view = surface_view_of(args.orbit);
      view.pivot = run_pivot(log);
      for (std::size_t i = 0; i < moments.size(); ++i) {
        views.push_back(view);
        if (moments.size() > 1) views.back().azimuth_deg += args.spin * static_cast<double>(i) / (moments.size() - 1);
      }
    }
    scene::SceneOptions scene_options = draw.scene;
    // A surface seen at a slant packs its vertices closer: a quarter as many markers.
    if (in_3d) scene_options.max_vertex_markers /= 4;
    LogScenes scenes(log, scene_options);
    const auto scene_at = [&](std::size_t i) { return in_3d ? scenes.at(moments[i], views[i]) : scenes.at(moments[i]); };

    // One camera for every frame: the animation holds still while the mesh grows (and turns).
    scene::Scene first = scene_at(0);
    first.bounds = in_3d ? run_bounds_3d(log, views) : run_bounds(log);
    const scene::Camera camera =
        draw.view ? draw.camera(first.bounds) : scene::fit_scene(first, draw.width, draw.height);

    render::Painter painter(draw.gl);
    FrameSink sink(args.frames, args.video, draw.width, draw.height, args.fps);
    ExportProgress progress(verbosity != Verbosity::quiet, moments.size());
    const int samples = draw.samples;
    std::uint64_t last_position = UINT64_MAX;
    scene::Image image;
    for (std::size_t i = 0; i < moments.size(); ++i) {
      // A repeated moment (a video stretched to its duration) reuses the picture.
      if (moments[i] != last_position || args.spin != 0.0) {
        // The same image each time: no 3.7 MB allocation, zeroing and page faults per frame.
        painter.paint(i == 0 ? first : scene_at(i), camera, samples, image);
        last_position = moments[i];
      }
      sink.add(i, image);
      progress.frame(i + 1);
    }
    sink.finish();
    if (verbosity != Verbosity::quiet) {
      const std::string where = sink.writes_frames() ? args.frames + "/frame_000000.png .. " + PngFrameWriter::frame_name(moments.size() - 1)
                                       : args.video;
      std::printf("%s: %zu frames of %dx%d (%s) from %s, %llu steps\n", where.c_str(), moments.size(), draw.width,
                  draw.height, painter.description().c_str(), args.log.c_str(),
                  static_cast<unsigned long long>(log.step_count()));
    }
    return kExitOk;
  });
}

}  // namespace

Command add_export_command(CLI::App& parent) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = parent.add_subcommand(
      "export",
      "Export a recorded run's animation: numbered PNG frames (--frames DIR: frame_000000.png,\n"
      "...) or a video through ffmpeg (--video OUT.mp4|OUT.webm|OUT.gif). Each frame is the mesh\n"
      "at one moment with the overlays that explain the step just taken, drawn off screen.");
  cmd->add_option("LOG", args->log, "Replay log (written with --record); none with --tour");
  cmd->add_option("--tour", args->tour,
                  "A guided tour (docs/tours.md) instead of a log: its run is recorded, then each stop is\n"
                  "drawn with its caption and held for its seconds (4 unless the tour says)");
  cmd->add_option("--frames", args->frames, "Folder for the PNG frames (made if missing)");
  cmd->add_option("--video", args->video, "Video file: .mp4 (H.264), .webm (VP9) or .gif (needs ffmpeg)");
  cmd->add_option("--every", args->every,
                  "One frame per event, per step, per phase, or every N steps")
      ->default_str("step");
  cmd->add_option("--from", args->from, "First step (event with --every event, phase with --every phase)");
  cmd->add_option("--to", args->to, "Last step, included (-1: the last)");
  cmd->add_option("--fps", args->fps, "Video frames per second (a frame's time is its index over this)")
      ->default_str("10");
  cmd->add_option("--duration", args->duration,
                  "Video length in seconds: the moments are spread over fps x duration frames");
  add_draw_options(cmd, args->draw);
  add_orbit_options(*cmd, args->orbit, "A terrain's log (meshstep terrain --record), in 3D");
  cmd->add_option("--spin", args->spin,
                  "With --orbit: the camera's azimuth turns this many degrees over the animation\n"
                  "(360: once round)");
  cmd->add_flag("-q,--quiet", args->quiet, "Print only errors");
  cmd->footer(
      "Examples:\n"
      "  meshstep refine assets/examples/lesson.poly --algorithm offcenter --min-angle 30 --record l.mslog\n"
      "  meshstep export l.mslog --frames frames/ --every event --to 400\n"
      "  meshstep export l.mslog --video lesson.mp4 --fps 4\n"
      "  meshstep export l.mslog --video lesson.gif --duration 10 --size 640x360 --color-by quality\n"
      "  meshstep export --tour assets/tours/ruppert.tour --video ruppert.mp4");
  return {cmd, [args, cmd] {
            if (!args->tour.empty()) return run_tour_export(*args, *cmd);
            if (args->log.empty()) {
              print_error("export: give a LOG (or --tour FILE)");
              return kExitUsage;
            }
            return run_export(*args);
          }};
}

}  // namespace meshstep::app
