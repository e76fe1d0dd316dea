#include "session.hpp"

#include <algorithm>
#include <cmath>

namespace meshstep::viewer {

const char* name(Unit unit) {
  switch (unit) {
    case Unit::event: return "events";
    case Unit::step: return "steps";
    case Unit::phase: return "phases";
  }
  return "?";
}

std::unique_ptr<Session> Session::open_log(const std::string& path, std::uint64_t keep_writes_bytes) {
  std::unique_ptr<Session> s(new Session);
  s->title_ = path;
  s->log_ = std::make_unique<replay::LogReader>(path, keep_writes_bytes);
  s->cursor_ = std::make_unique<replay::Replay>(*s->log_);
  s->position_ = s->log_->event_count();  // the end of the run; replayed when first drawn
  return s;
}

std::unique_ptr<Session> Session::still(TriMesh mesh, std::string title) {
  std::unique_ptr<Session> s(new Session);
  s->title_ = std::move(title);
  s->mesh_ = std::move(mesh);
  return s;
}

std::unique_ptr<Session> Session::still(Pslg input, std::string title) {
  std::unique_ptr<Session> s(new Session);
  s->title_ = std::move(title);
  s->input_ = std::move(input);
  return s;
}

Session::~Session() = default;

CursorInfo Session::cursor_info() const {
  CursorInfo info;
  if (!log_) return info;
  info.position = position_;
  info.event_count = log_->event_count();
  const replay::StepAt at = replay::step_at(*log_, position_);
  info.step = at.step;
  info.within = at.within;
  info.completed = log_->completed_steps_at(position_);
  info.step_count = log_->step_count();
  // Phases nest: the last one begun before the cursor that has not ended is the innermost.
  for (const replay::PhaseSpan& p : log_->phases())
    if (p.begin < info.position && info.position <= p.end) info.phase = p.phase;
  return info;
}

void Session::moved() {
  scene_stale_ = explanation_stale_ = true;
}

void Session::seek(std::uint64_t position) {
  if (!log_) return;
  position = std::min(position, log_->event_count());
  if (position == position_) return;
  position_ = position;
  moved();
}

std::string Session::go_to_step(std::int64_t k, const std::string& what) {
  if (!log_) return "";
  std::string refused = replay::step_refusal(*log_, what, k, false);
  if (refused.empty()) seek_step(static_cast<std::uint64_t>(k));
  return refused;
}

void Session::seek_step(std::uint64_t steps) {
  if (log_) seek(log_->step_start(std::min(steps, log_->step_count())));
}

const replay::Replay* Session::cursor() {
  if (cursor_ && cursor_->position() != position_) cursor_->seek_event(position_);
  return cursor_.get();
}

void Session::to_end() {
  if (log_) seek(log_->event_count());
}

void Session::move(Unit unit, int direction) {
  if (!log_ || direction == 0) return;
  const std::uint64_t at = position_;
  switch (unit) {
    case Unit::event:
      if (direction > 0) seek(at + 1);
      else if (at > 0) seek(at - 1);
      return;
    case Unit::step:
      seek(direction > 0 ? log_->next_step_boundary(at) : log_->prev_step_boundary(at));
      return;
    case Unit::phase: {
      // To the next phase boundary (a begin or an end) past the cursor, or the one before it.
      std::uint64_t target = direction > 0 ? log_->event_count() : 0;
      for (const replay::PhaseSpan& p : log_->phases())
        for (const std::uint64_t b : {p.begin, std::min(p.end, log_->event_count())}) {
          if (direction > 0 && b > at) target = std::min(target, b);
          if (direction < 0 && b < at) target = std::max(target, b);
        }
      seek(target);
      return;
    }
  }
}

bool Session::find_step(replay::StepKind kind, int direction) {
  if (!log_) return false;
  const std::uint64_t steps = log_->step_count();
  const std::uint64_t done = log_->completed_steps_at(position_);
  // The cursor stands at the end of step done - 1 (or inside step done).
  if (direction > 0) {
    for (std::uint64_t k = done; k < steps; ++k)
      if (log_->step_kind(k) == kind && log_->step_start(k + 1) > position_) {
        seek(log_->step_start(k + 1));
        return true;
      }
  } else {
    for (std::uint64_t k = std::min(done, steps); k-- > 0;)
      if (log_->step_kind(k) == kind && log_->step_start(k + 1) < position_) {
        seek(log_->step_start(k + 1));
        return true;
      }
  }
  return false;
}

bool Session::find_event(const std::function<bool(const replay::Event&)>& wanted, int direction) {
  if (!log_) return false;
  const std::uint64_t at = position_, n = log_->event_count();
  if (direction > 0) {
    for (std::uint64_t e = at; e < n; ++e)
      if (wanted(log_->event(e))) {
        seek(e + 1);
        return true;
      }
  } else {
    // The event just applied is the one the cursor shows: look before it.
    for (std::uint64_t e = at >= 1 ? at - 1 : 0; e-- > 0;)
      if (wanted(log_->event(e))) {
        seek(e + 1);
        return true;
      }
  }
  return false;
}

bool is_rejected_point(const replay::Event& e) {
  return e.type == replay::EventType::encroached && e.ids[2] == kNone;
}

bool is_big_cavity(const replay::Event& e) {
  if (e.type != replay::EventType::cavity) return false;
  std::size_t removed = 0;
  for (const replay::SlotWrite& w : e.writes) removed += !w.before.dead();
  return removed > 10;
}

void Session::toggle_play() {
  if (!log_) return;
  // Play at the end starts again from the beginning, as a video player does.
  if (!playback_.playing && position_ == log_->event_count()) seek(0);
  playback_.playing = !playback_.playing;
  playback_.owed = 0.0;
}

void Session::advance(double seconds) {
  if (!log_ || !playback_.playing) return;
  playback_.owed += playback_.speed * seconds;
  // 30 frames of 1/30 s at 30 steps a second are 30 steps, not 29.999...: a hair of
  // rounding does not hold a step back.
  const double whole = std::floor(playback_.owed + 1e-9);
  playback_.owed = std::max(0.0, playback_.owed - whole);
  const auto units = static_cast<std::uint64_t>(whole);
  if (units == 0) return;
  if (playback_.unit == Unit::event) {
    seek(position_ + units);
  } else if (playback_.unit == Unit::step) {
    seek_step(log_->completed_steps_at(position_) + units);
  } else {
    for (std::uint64_t i = 0; i < units; ++i) move(Unit::phase, +1);
  }
  if (position_ == log_->event_count()) playback_.playing = false;
}

void Session::scale_speed(double factor) {
  playback_.speed = std::clamp(playback_.speed * factor, Playback::kMinSpeed, Playback::kMaxSpeed);
}

void Session::set_bookmark(int slot) {
  if (log_ && slot >= 1 && slot <= 9) bookmarks_[static_cast<std::size_t>(slot)] = position_;
}

bool Session::go_to_bookmark(int slot) {
  const auto at = bookmark(slot);
  if (!at) return false;
  seek(*at);
  return true;
}

std::optional<std::uint64_t> Session::bookmark(int slot) const {
  if (slot < 1 || slot > 9) return std::nullopt;
  return bookmarks_[static_cast<std::size_t>(slot)];
}

void Session::set_color_by(scene::ColorBy color_by) {
  if (options_.color_by == color_by) return;
  options_.color_by = color_by;
  scene_stale_ = true;
}

void Session::set_theme(scene::Theme theme) {
  if (options_.theme == theme) return;
  options_.theme = theme;
  scene_stale_ = true;
}

void Session::set_text_scale(float scale) {
  options_.text_scale = scale;
  scene_.text_scale = scale;  // a scale changed needs no new scene
}

void Session::set_layer(scene::Layer layer, bool on) {
  // The Voronoi layer's shapes are built only while it is on (scene/build.hpp); any other
  // layer switched needs no new scene.
  if (layer == scene::Layer::voronoi && options_.layers.has(layer) != on) scene_stale_ = true;
  options_.layers.set(layer, on);
  scene_.visible = options_.layers;
}

void Session::set_narration(std::string text) {
  if (narration_ == text) return;
  narration_ = std::move(text);
  scene_.narration = narration_;
  ++scene_builds_;  // the same mesh with other words: drawn again, not built again
}

const scene::Scene& Session::scene() {
  if (!scene_stale_ || pictures_deferred_) return scene_;
  if (log_) {
    cursor();  // brought to the position
    if (options_.color_by == scene::ColorBy::age) {
      ages_.update(*cursor_);
      scene_ = scene::build_scene(*cursor_, options_, &ages_);
    } else {
      scene_ = scene::build_scene(*cursor_, options_);
    }
  } else if (mesh_) {
    scene_ = scene::build_scene(*mesh_, options_);
  } else if (input_) {
    scene_ = scene::build_scene(*input_, options_);
  }
  scene_.narration = narration_;
  scene_stale_ = false;
  ++scene_builds_;
  return scene_;
}

const scene::Explanation& Session::explanation() {
  if (!explanation_stale_ || pictures_deferred_) return explanation_;
  if (log_) {
    explanation_ = scene::explain_step(*cursor());
  } else {
    explanation_ = {title_, {mesh_ ? "a mesh: " + std::to_string(mesh_->triangles.size()) + " triangles"
                                   : "an input: " + std::to_string(input_ ? input_->points.size() : 0) + " vertices"}};
  }
  explanation_stale_ = false;
  return explanation_;
}

void Session::defer_pictures(bool on) {
  pictures_deferred_ = on;
  scene_stale_ = explanation_stale_ = true;  // built here again when no longer deferred
  adopted_serial_ = SIZE_MAX;
}

void Session::adopt(Moment& moment) {
  if (moment.serial == adopted_serial_ && moment.position == shown_position_) return;
  adopted_serial_ = moment.serial;
  std::swap(scene_, moment.scene);
  std::swap(explanation_, moment.explanation);
  shown_position_ = moment.position;
  scene_.visible = options_.layers;
  scene_.text_scale = options_.text_scale;
  scene_.narration = narration_;
  ++scene_builds_;
}

void Session::build_moment(Moment& moment) {
  moment.position = position_;
  moment.scene = scene();
  moment.explanation = explanation();
  moment.serial = scene_builds_;
}

}  // namespace meshstep::viewer
