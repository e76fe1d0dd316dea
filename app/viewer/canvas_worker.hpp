// The canvas of a big run, drawn on a thread of its own, so that the window never waits for
// a seek, a scene or a picture of a million triangles.
//
// The UI asks for a picture (a position of the run, the drawing options, the camera) every
// frame; the worker draws the latest one asked for, skipping those that were overtaken, with
// its own reader of the log, its own replay cursor and its own off-screen GL context, and
// hands back the picture with the exact scene and words of that position. Meanwhile the
// canvas keeps showing the last picture finished, labelled with its own step.
//
// A new request for a big mesh (the cursor dragged along the timeline, a pan) is drawn first
// with the renderer's level of detail (render::Detail::approximate: the small triangles found
// on the CPU), marked "approximate while scrubbing" on the picture; if no newer request came
// meanwhile, the same request is drawn again exactly at once. So the picture at rest is
// always exact, and a request counts as drawn (wait_until_drawn, drawing) only then.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/image.hpp"
#include "draw_turns.hpp"
#include "mesh_stats.hpp"
#include "session.hpp"
#include "view_3d.hpp"

namespace meshstep::render {
class Renderer;
}

namespace meshstep::viewer {

struct CanvasRequest {
  std::uint64_t position = 0;
  scene::ColorBy color_by = scene::ColorBy::none;
  scene::Theme theme = scene::Theme::light;
  scene::LayerSet layers = scene::LayerSet::standard();
  float text_scale = 1.0f;  // Scene::text_scale
  Point center{0, 0};
  double pixels_per_unit = 1.0;
  int width = 0, height = 0;
  bool fit = false;              // the camera fitted to the picture's scene instead
  // A terrain's run in 3D: the moment lifted onto its heights, as the orbit sees it (the
  // camera is then in the orbit's screen plane).
  bool in_3d = false;
  Orbit orbit;
  std::uint32_t generation = 0;  // a new one asks again for the same (a log that grew)
  friend bool operator==(const CanvasRequest&, const CanvasRequest&) = default;

  scene::Camera camera() const { return scene::Camera(center, pixels_per_unit, width, height); }

  // The planar picture of the moment `position` with a session's look, through `camera`.
  static CanvasRequest planar(std::uint64_t position, const scene::SceneOptions& o, const scene::Camera& camera) {
    CanvasRequest r;
    r.position = position;
    r.color_by = o.color_by;
    r.theme = o.theme;
    r.layers = o.layers;
    r.text_scale = o.text_scale;
    r.center = camera.center();
    r.pixels_per_unit = camera.pixels_per_unit();
    r.width = camera.width();
    r.height = camera.height();
    return r;
  }
};

struct CanvasPicture {
  CanvasRequest request;
  Session::Moment moment;  // the scene and words of request.position (planar)
  scene::Scene lifted;     // request.in_3d: the scene drawn, moment.scene lifted (else stale)
  Stats stats;             // of the moment's mesh
  scene::Image image;      // rows top to bottom, request.width x request.height
  bool approximate = false;  // the mesh drawn with the level of detail (said so on the image)
};

// Meshes from this many triangles up get an approximate picture first.
inline constexpr std::size_t kApproximateFrom = 100000;
inline constexpr const char* kApproximateNote = "approximate while scrubbing";

class CanvasWorker {
 public:
  // fixed_log: the log is opened once. growing_log: a log still being written (a live
  // run's LOG.partial), opened again for every picture as the prefix written so far; while
  // it cannot be read yet, no picture is made (and no error reported).
  enum class Follow { fixed_log, growing_log };
  // Whose CPU comes first on a small machine. `normal`: the canvas's pictures are what the
  // user waits for (a single run scrubbed; runs side by side, which take turns instead:
  // below the window, nice 5, their pictures starved). `below_ui`: the window's frames
  // come first: a live run's preview (the run beside it needs the cores).
  enum class Priority { normal, below_ui };

  // Starts the thread; it opens LOG_PATH and an off-screen context of `backend` ("egl" or
  // "osmesa": the GL library the UI's context uses, whose functions are loaded already).
  // `approximate_from`: the meshes that get an approximate picture first, by their triangles.
  // `keep_writes_bytes`: the biggest log whose writes the worker's reader keeps decoded
  // (LogReader; runs side by side share one budget). A growing log's worker is always
  // below the UI. `turns`: shared with other workers, each picture is drawn in a turn of
  // its own (it must outlive the worker); none: drawn whenever asked.
  CanvasWorker(std::string log_path, std::string backend, Follow follow = Follow::fixed_log,
               std::size_t approximate_from = kApproximateFrom,
               std::uint64_t keep_writes_bytes = replay::LogReader::kKeepWritesBytes,
               Priority priority = Priority::normal, DrawTurns* turns = nullptr);
  ~CanvasWorker();
  CanvasWorker(const CanvasWorker&) = delete;
  CanvasWorker& operator=(const CanvasWorker&) = delete;

  // The picture wanted now (the last call wins). Allocates nothing.
  void request(const CanvasRequest& wanted);
  // The newest picture finished since the last take, swapped into `picture` (whose old
  // buffers go back to the worker, to be reused). False when there is none.
  bool take(CanvasPicture& picture);
  // True while the last request is not yet drawn and taken.
  bool drawing() const;
  // Waits until the last request is drawn (scripts, before they look).
  void wait_until_drawn();
  // Pictures drawn so far, approximate and exact.
  std::size_t pictures_drawn() const;
  // Pictures drawn with the level of detail so far (each followed by an exact one at rest).
  std::size_t approximate_pictures() const;
  // Why the worker stopped ("" while it works): the log or the context failed.
  std::string error() const;

 private:
  void run();
  // `may_approximate`: a new request, which a big mesh draws with the level of detail first.
  void draw(const CanvasRequest& wanted, Session& session, View3d& view, render::Renderer& renderer,
            bool may_approximate, CanvasPicture& out);

  const std::string log_path_, backend_;
  const Follow follow_;
  const std::size_t approximate_from_;
  const std::uint64_t keep_writes_bytes_;
  const Priority priority_;
  DrawTurns* const turns_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, drawn_;
  CanvasRequest wanted_;
  bool has_request_ = false;
  std::uint64_t asked_ = 0, finished_ = 0;  // requests counted as asked and as drawn
  CanvasPicture ready_;       // the newest finished picture
  bool ready_fresh_ = false;  // not taken yet
  bool stop_ = false;
  std::string error_;
  std::size_t approximate_pictures_ = 0, pictures_drawn_ = 0;
  Stats stats_;  // the worker's own: of the moment it drew last
  std::size_t stats_serial_ = SIZE_MAX;
  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace meshstep::viewer
