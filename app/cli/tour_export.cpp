// Exporting a tour (tour_export.hpp).
#include "tour_export.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "common/tour_run.hpp"
#include "console.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/teach/tour.hpp"
#include "moment_scene.hpp"
#include "render/painter.hpp"
#include "png_frame_writer.hpp"
#include "frame_sink.hpp"
#include "video_pipe.hpp"

namespace meshstep::app {
namespace {

// This program, to record the tour's run as `meshstep refine|triangulate|run` would.
std::string tour_own_program() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("meshstep") : self.string();
}

}  // namespace

int export_tour(const TourExportArgs& args) {
  const Verbosity verbosity = args.quiet ? Verbosity::quiet : Verbosity::normal;
  const teach::Tour tour = teach::read_tour(args.tour);
  const ScratchFolder scratch;
  const std::string log_path = record_tour_run(tour, tour_own_program(), scratch);
  const replay::LogReader log(log_path);
  const std::vector<std::uint64_t> steps = teach::resolve_stops(tour, log);

  // Every stop's frame count first: a video's length is known before ffmpeg starts.
  std::vector<std::size_t> holds;
  std::size_t total = 0;
  for (const teach::TourStop& stop : tour.stops) {
    holds.push_back(std::max<std::size_t>(1, std::llround(stop.hold_seconds.value_or(tour.hold_seconds) * args.fps)));
    total += holds.back();
  }

  render::Painter painter(args.draw.gl);
  FrameSink sink(args.frames, args.video, args.draw.width, args.draw.height, args.fps);
  const BBox whole = run_bounds(log);
  scene::Image image;
  std::size_t index = 0;
  for (std::size_t i = 0; i < tour.stops.size(); ++i) {
    const teach::TourStop& stop = tour.stops[i];
    // The stop's look over the tour's over the command line's (--color-by, --layers...).
    scene::SceneOptions options = args.draw.scene;
    if (tour.layers) options.layers = tour.layers->apply(options.layers);
    if (stop.layers) options.layers = stop.layers->apply(options.layers);
    if (const auto c = stop.color_by ? stop.color_by : tour.color_by) options.color_by = *c;
    LogScenes scenes(log, options);
    scene::Scene picture = scenes.at(replay::step_position(log, steps[i]));
    picture.narration = stop.caption;
    // The stop's box, or the whole run's (a picture that holds still from stop to stop),
    // in what the caption, the narration and the legend leave free.
    BBox box = whole;
    if (stop.camera) {
      box = BBox{};
      box.add({stop.camera->x0, stop.camera->y0});
      box.add({stop.camera->x1, stop.camera->y1});
    }
    const scene::Camera camera = scene::Camera::fit(box, args.draw.width, args.draw.height,
                                                    scene::layout(picture, args.draw.width, args.draw.height).margins);
    painter.paint(picture, camera, args.draw.samples, image);
    for (std::size_t h = 0; h < holds[i]; ++h, ++index) {
      sink.add(index, image);
    }
  }
  sink.finish();
  if (verbosity != Verbosity::quiet) {
    const std::string where = sink.writes_frames() ? args.frames + "/frame_000000.png .. " + PngFrameWriter::frame_name(total - 1) : args.video;
    std::printf("%s: %zu frames of %dx%d (%s), %zu stops of the tour %s (its run: %llu steps)\n", where.c_str(), total,
                args.draw.width, args.draw.height, painter.description().c_str(), tour.stops.size(), args.tour.c_str(),
                static_cast<unsigned long long>(log.step_count()));
  }
  return 0;
}

}  // namespace meshstep::app
