// What the viewer shows and where it stands: a recorded run (a replay log and its cursor), or
// a still mesh or input; playback, bookmarks and the drawing options. No GL and no ImGui:
// the UI reads and drives it, and the tests drive it directly.
//
// The canvas always shows the exact mesh at a position of the run: scene() is rebuilt from
// the replay cursor whenever the position or the options change, never approximated. Moving
// only sets the position (the step and phase come from the log's index); the cursor replays
// to it when a picture or the words are asked for.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "meshstep/pslg/pslg.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/explain.hpp"

namespace meshstep::viewer {

// What one move or one played tick advances by.
enum class Unit { event, step, phase };
const char* name(Unit unit);

struct Playback {
  static constexpr double kMinSpeed = 0.25, kMaxSpeed = 1000.0;
  bool playing = false;
  double speed = 4.0;  // units per second
  Unit unit = Unit::step;
  double owed = 0.0;   // the part of a unit played but not yet moved
};

// Where the run is, in the numbers people read: steps count from 1 as the caption does.
struct CursorInfo {
  std::uint64_t position = 0, event_count = 0;
  // The step the cursor shows, numbered as every command numbers it (step_numbers.hpp):
  // K at the mesh after K steps, and K too while step K's events are being applied
  // (`within`); `completed` is the steps wholly done.
  std::uint64_t step = 0, step_count = 0, completed = 0;
  bool within = false;
  std::optional<replay::Phase> phase;      // the innermost phase the cursor is in
};

// Events worth jumping to: a point rejected because it encroached a segment; a
// Bowyer-Watson cavity of more than 10 faces.
bool is_rejected_point(const replay::Event& e);
bool is_big_cavity(const replay::Event& e);

class Session {
 public:
  // A recorded run; throws InputError for a file that is not a valid log. A session whose
  // pictures are made elsewhere (runs side by side) keeps none of the log's writes decoded
  // (keep_writes_bytes 0: LogReader): it never replays.
  static std::unique_ptr<Session> open_log(const std::string& path,
                                           std::uint64_t keep_writes_bytes = replay::LogReader::kKeepWritesBytes);
  // A mesh or an input, to look at (no timeline).
  static std::unique_ptr<Session> still(TriMesh mesh, std::string title);
  static std::unique_ptr<Session> still(Pslg input, std::string title);
  ~Session();

  const std::string& title() const { return title_; }
  void set_title(std::string title) { title_ = std::move(title); }
  const replay::LogReader* log() const { return log_.get(); }
  bool has_timeline() const { return log_ != nullptr; }
  CursorInfo cursor_info() const;
  // The replay cursor, brought to the position (a seek, replayed on this thread).
  const replay::Replay* cursor();

  // Moving. All clamp to the run and mark the scene stale when the position changes.
  void seek(std::uint64_t position);
  // Moves to the mesh after k steps, or, for a k outside 0..n, stays and returns the words
  // every command refuses it in (step_numbers.hpp); "" when it moved.
  // `what` names the number in the refusal ("step", "--step").
  std::string go_to_step(std::int64_t k, const std::string& what = "step");
  void seek_step(std::uint64_t steps);  // the mesh after `steps` steps
  void move(Unit unit, int direction);  // by one unit, forward (+1) or backward (-1)
  void to_start() { seek(0); }
  void to_end();
  // To the end of the next (previous) step of this kind; false when there is none.
  bool find_step(replay::StepKind kind, int direction);
  // To just after the next (previous) event that `wanted` accepts; false when there is none.
  // Scans the events one by one (a few million a second).
  bool find_event(const std::function<bool(const replay::Event&)>& wanted, int direction);

  Playback& playback() { return playback_; }
  const Playback& playback() const { return playback_; }
  void toggle_play();
  // Plays `seconds` of time: moves by speed x seconds units (whole ones; the rest is owed
  // to the next call). Stops at the end.
  void advance(double seconds);
  // Doubles (factor 2) or halves the speed, within the limits.
  void scale_speed(double factor);

  // Bookmarks 1-9: a position each.
  void set_bookmark(int slot);
  bool go_to_bookmark(int slot);
  std::optional<std::uint64_t> bookmark(int slot) const;

  const scene::SceneOptions& options() const { return options_; }
  void set_color_by(scene::ColorBy color_by);
  void set_theme(scene::Theme theme);
  // The canvas's words this many times their size (Scene::text_scale; the UI scale).
  void set_text_scale(float scale);
  void set_layer(scene::Layer layer, bool on);
  // A tour's caption on the canvas (Scene::narration), kept across moves; "" for none.
  void set_narration(std::string text);
  const std::string& narration() const { return narration_; }
  bool layer(scene::Layer layer) const { return options_.layers.has(layer); }

  // The picture at the cursor (rebuilt if stale), and the words for it.
  const scene::Scene& scene();
  const scene::Explanation& explanation();
  // Times the scene was built (or adopted): stays put while nothing changes (an idle viewer).
  std::size_t scene_builds() const { return scene_builds_; }

  // Pictures made on another thread (the canvas worker, for big runs): once deferred,
  // scene() and explanation() never build on this thread; they return the last moment
  // adopted, which shows shown_position() while the cursor may already stand elsewhere.
  struct Moment {
    std::uint64_t position = 0;
    std::size_t serial = 0;  // the builder's scene_builds(): the same for the same content
    scene::Scene scene;
    scene::Explanation explanation;
  };
  void defer_pictures(bool on);
  bool pictures_deferred() const { return pictures_deferred_; }
  // Takes the moment's scene and words (swapped, so that its buffers are reused), unless it
  // is the moment shown already (a picture of it from another camera).
  void adopt(Moment& moment);
  std::uint64_t shown_position() const { return pictures_deferred_ ? shown_position_ : position_; }
  // The worker's side: the moment at the position, built here.
  void build_moment(Moment& moment);

 private:
  Session() = default;
  void moved();

  std::string title_;
  std::unique_ptr<replay::LogReader> log_;
  std::unique_ptr<replay::Replay> cursor_;  // follows position_ when a picture is asked for
  std::uint64_t position_ = 0;
  std::optional<TriMesh> mesh_;
  std::optional<Pslg> input_;

  Playback playback_;
  std::array<std::optional<std::uint64_t>, 10> bookmarks_{};
  scene::SceneOptions options_;
  scene::FaceAges ages_;
  std::string narration_;

  scene::Scene scene_;
  scene::Explanation explanation_;
  bool scene_stale_ = true, explanation_stale_ = true;
  std::size_t scene_builds_ = 0;
  bool pictures_deferred_ = false;
  std::uint64_t shown_position_ = UINT64_MAX;  // none yet
  std::size_t adopted_serial_ = SIZE_MAX;
};

}  // namespace meshstep::viewer
