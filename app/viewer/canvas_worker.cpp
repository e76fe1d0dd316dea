#include "canvas_worker.hpp"

#include <sys/resource.h>
#include <cerrno>
#include <algorithm>
#include <unistd.h>

#include <memory>
#include <optional>
#include <utility>

#include "render/gl_context.hpp"
#include "render/renderer.hpp"
#include "meshstep/scene/layout.hpp"

namespace meshstep::viewer {

namespace {
constexpr int kPreviewNice = 5;
}  // namespace

CanvasWorker::CanvasWorker(std::string log_path, std::string backend, Follow follow, std::size_t approximate_from,
                           std::uint64_t keep_writes_bytes, Priority priority, DrawTurns* turns)
    : log_path_(std::move(log_path)),
      backend_(std::move(backend)),
      follow_(follow),
      approximate_from_(approximate_from),
      keep_writes_bytes_(keep_writes_bytes),
      priority_(follow == Follow::growing_log ? Priority::below_ui : priority),
      turns_(turns),
      thread_([this] { run(); }) {}

CanvasWorker::~CanvasWorker() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void CanvasWorker::request(const CanvasRequest& wanted) {
  {
    const std::lock_guard lock(mutex_);
    if (has_request_ && wanted == wanted_) return;
    wanted_ = wanted;
    has_request_ = true;
    ++asked_;
  }
  wake_.notify_one();
}

bool CanvasWorker::take(CanvasPicture& picture) {
  const std::lock_guard lock(mutex_);
  if (!ready_fresh_) return false;
  std::swap(picture, ready_);
  ready_fresh_ = false;
  return true;
}

bool CanvasWorker::drawing() const {
  const std::lock_guard lock(mutex_);
  return error_.empty() && (finished_ != asked_ || ready_fresh_);
}

void CanvasWorker::wait_until_drawn() {
  std::unique_lock lock(mutex_);
  drawn_.wait(lock, [&] { return finished_ == asked_ || !error_.empty(); });
}

std::size_t CanvasWorker::pictures_drawn() const {
  const std::lock_guard lock(mutex_);
  return pictures_drawn_;
}

std::size_t CanvasWorker::approximate_pictures() const {
  const std::lock_guard lock(mutex_);
  return approximate_pictures_;
}

std::string CanvasWorker::error() const {
  const std::lock_guard lock(mutex_);
  return error_;
}

void CanvasWorker::draw(const CanvasRequest& wanted, Session& session, View3d& view, render::Renderer& renderer,
                        bool may_approximate, CanvasPicture& out) {
  session.seek(wanted.position);
  session.set_color_by(wanted.color_by);
  session.set_theme(wanted.theme);
  session.set_layer(scene::Layer::voronoi, wanted.layers.has(scene::Layer::voronoi));  // built only when shown
  // Copied into the buffers the picture had before (their capacity is reused).
  session.build_moment(out.moment);
  if (out.moment.serial != stats_serial_) {  // measured once per moment, not per pan
    stats_ = measure(out.moment.scene.mesh, session.log());
    stats_serial_ = out.moment.serial;
  }
  out.stats = stats_;
  out.moment.scene.visible = wanted.layers;
  out.moment.scene.text_scale = wanted.text_scale;
  out.request = wanted;
  // In 3D the picture is the lifted scene, handed back with the planar moment (whose words
  // and mesh the inspector reads). The lift is kept while only the camera changes; the copy
  // into the picture (its buffers reused) costs little beside the drawing.
  const bool in_3d = wanted.in_3d && view.available();
  if (in_3d) {
    view.set_orbit(wanted.orbit);
    out.lifted = view.lifted(out.moment.scene, out.moment.serial, max_vertex_markers_for(wanted.width, wanted.height));
    out.lifted.visible = wanted.layers;
    out.lifted.text_scale = wanted.text_scale;
  }
  const scene::Scene& drawn = in_3d ? out.lifted : out.moment.scene;
  const scene::Camera camera =
      wanted.fit ? scene::Camera::fit(drawn.bounds, wanted.width, wanted.height,
                                      scene::layout(drawn, wanted.width, wanted.height).margins)
                 : wanted.camera();
  out.approximate = may_approximate && drawn.mesh.triangles.size() >= approximate_from_ &&
                    render::Renderer::can_approximate(drawn, render::kDefaultSamples);
  if (out.approximate)
    renderer.render(drawn, camera, render::kDefaultSamples, render::Detail::approximate, kApproximateNote);
  else
    renderer.render(drawn, camera, render::kDefaultSamples);
  renderer.read_pixels(out.image);
}

void CanvasWorker::run() {
  // Below the UI thread (Priority): a live run's preview, where the machine is busy with the
  // run beside it (on two cores: the run, this thread and its log reader's helper). Linux
  // gives each thread its own nice value, inherited by the threads it starts (set before
  // the GL context, whose rasterizer thread may start here); failing to lower it only costs
  // responsiveness. A single run scrubbed, and runs side by side (in turns), keep the
  // normal priority: there the pictures are what the user waits for.
  if (priority_ == Priority::below_ui) {
    // Below the thread that started it, whatever its own nice value (a viewer started with
    // `nice -n 10` keeps its workers below it too).
    const auto tid = static_cast<id_t>(gettid());
    errno = 0;
    const int base = getpriority(PRIO_PROCESS, tid);
    if (errno == 0) (void)setpriority(PRIO_PROCESS, tid, std::min(base + kPreviewNice, 19));
  }
  std::unique_ptr<render::GlContext> context;
  std::unique_ptr<render::Renderer> renderer;
  std::unique_ptr<Session> session;
  std::unique_ptr<View3d> view;  // of the session's log
  const auto fail = [&](const char* what, const std::exception& e) {
    {
      const std::lock_guard lock(mutex_);
      error_ = std::string(what).append(e.what());
    }
    drawn_.notify_all();
  };
  try {
    context = backend_ == "osmesa" ? render::make_osmesa_context() : render::make_egl_worker_context();
    context->make_current_with_loaded_functions();
    renderer = std::make_unique<render::Renderer>();
    if (follow_ == Follow::fixed_log) {
      session = Session::open_log(log_path_, keep_writes_bytes_);
      view = std::make_unique<View3d>(session->log());
    }
  } catch (const std::exception& e) {
    fail("the canvas's worker could not start: ", e);
    return;
  }

  CanvasPicture out;
  std::uint64_t drawn_approximately = 0;  // the request number last drawn with the level of detail
  for (;;) {
    CanvasRequest wanted;
    std::uint64_t number = 0;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || (has_request_ && finished_ != asked_); });
      if (stop_) break;
    }
    // With turns, the request is read once the turn comes: what was asked while this worker
    // waited for it replaces what woke it, so a wait never costs a stale picture. The turn
    // ends with the drawing, before the picture is handed over.
    std::optional<DrawTurns::Seat> seat(std::in_place, turns_);
    {
      const std::lock_guard lock(mutex_);
      if (stop_) break;
      wanted = wanted_;
      number = asked_;
    }
    bool drawn = true;
    try {
      if (follow_ == Follow::growing_log) {
        // What the run has written so far; not yet readable (no header, no whole block)
        // or gone (renamed when the run ended): no picture this time.
        try {
          session = Session::open_log(log_path_, keep_writes_bytes_);
          view = std::make_unique<View3d>(session->log());
        } catch (const std::exception&) {
          drawn = false;
        }
      }
      // A request already drawn approximately is drawn exactly now; a new one may be
      // approximate (a live run's preview stays exact: it is drawn a few times a second).
      const bool may_approximate = number != drawn_approximately && follow_ == Follow::fixed_log;
      if (drawn) draw(wanted, *session, *view, *renderer, may_approximate, out);
    } catch (const std::exception& e) {
      fail("the canvas could not be drawn: ", e);
      break;
    }
    seat.reset();
    {
      const std::lock_guard lock(mutex_);
      const bool approximate = drawn && out.approximate;
      if (drawn) {
        std::swap(out, ready_);
        ready_fresh_ = true;
      }
      // An approximate picture leaves the request pending: the loop takes it again (drawn
      // exactly) unless a newer one came meanwhile.
      if (drawn) ++pictures_drawn_;
      if (approximate) {
        drawn_approximately = number;
        ++approximate_pictures_;
      } else {
        finished_ = number;
      }
    }
    drawn_.notify_all();
  }
  renderer.reset();  // while its context is current
}

}  // namespace meshstep::viewer
