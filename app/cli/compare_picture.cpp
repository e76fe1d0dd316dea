// Runs side by side at one moment, or as an animation (compare_picture.hpp).
#include "compare_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "draw_options.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/scene/svg.hpp"
#include "moment_scene.hpp"
#include "video_pipe.hpp"
#include "render/painter.hpp"

namespace meshstep::app {
namespace {

// The open logs, a cursor on each, and the one camera every panel shares.
class Panels {
 public:
  explicit Panels(const SideBySide& p) : p_(p), draw_(parse_draw_args(DrawArgs{})) {
    for (const std::string& path : p.logs) {
      logs_.push_back(std::make_unique<replay::LogReader>(path));
      moments_.push_back(std::make_unique<LogScenes>(*logs_.back(), draw_.scene));
      const BBox box = run_bounds(*logs_.back());
      world_.add(box.lo);
      world_.add(box.hi);
    }
    // Tall enough for the box at the panel's width (less the fit's margins), plus the
    // caption band: a wide input gets no empty band above and below. Even, for video codecs.
    height_ = p.panel_height;
    if (height_ <= 0) {
      const double dx = world_.hi.x - world_.lo.x, dy = world_.hi.y - world_.lo.y;
      const double wanted = dx > 0.0 ? (p.panel_width - 48.0) * dy / dx + 48.0 + 36.0 : 560.0;
      height_ = static_cast<int>(std::clamp(std::ceil(wanted), 200.0, 1000.0));
    }
    height_ += height_ % 2;
  }

  std::size_t size() const { return logs_.size(); }
  const replay::LogReader& log(std::size_t i) const { return *logs_[i]; }
  int width() const { return p_.panel_width * static_cast<int>(size()); }
  int height() const { return height_; }
  int samples() const { return draw_.samples; }
  const std::string& gl() const { return draw_.gl; }

  // Every run's scene at its position; the camera is fitted on the first call (the panels
  // are alike, so one fit serves them all and every frame of an animation).
  std::vector<scene::Scene> scenes(const std::vector<std::uint64_t>& positions) {
    std::vector<scene::Scene> out;
    for (std::size_t i = 0; i < size(); ++i) {
      scene::Scene s = moments_[i]->at(positions[i]);
      // The run's description, then the scene's phase and step ("refine · step 30 of 59");
      // what the step did is left out, for two or more captions to fit their panels.
      const std::size_t first = s.caption.find(" \u00b7 ");
      const std::size_t second = first == std::string::npos ? first : s.caption.find(" \u00b7 ", first + 1);
      s.caption = p_.captions[i] + " \u00b7 " + s.caption.substr(0, second);
      s.bounds = world_;  // one world scale for every panel
      out.push_back(std::move(s));
    }
    if (!camera_) camera_ = scene::fit_scene(out.front(), p_.panel_width, height_);
    return out;
  }
  const scene::Camera& camera() const { return *camera_; }
  std::uint64_t completed_steps(std::size_t i) const { return moments_[i]->cursor().completed_steps(); }

  // The panels drawn by OpenGL into one picture, left to right.
  void paint(render::Painter& painter, const std::vector<scene::Scene>& scenes, scene::Image& whole) {
    whole.width = width();
    whole.height = height_;
    whole.rgba.assign(static_cast<std::size_t>(whole.width) * height_ * 4, 255);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      painter.paint(scenes[i], *camera_, draw_.samples, panel_);
      for (int y = 0; y < std::min(panel_.height, height_); ++y)
        std::copy(panel_.row(y), panel_.row(y) + static_cast<std::size_t>(std::min(panel_.width, p_.panel_width)) * 4,
                  whole.row(y) + i * static_cast<std::size_t>(p_.panel_width) * 4);
    }
  }

 private:
  const SideBySide& p_;
  DrawSettings draw_;
  std::vector<std::unique_ptr<replay::LogReader>> logs_;
  std::vector<std::unique_ptr<LogScenes>> moments_;
  BBox world_;
  int height_ = 0;
  std::optional<scene::Camera> camera_;
  scene::Image panel_;
};

// The position of the moment asked for in one run.
std::uint64_t moment_of(const SideBySide& p, const replay::LogReader& log) {
  const std::uint64_t steps = log.step_count();
  if (p.fraction) {
    const auto k = static_cast<std::uint64_t>(std::llround(*p.fraction * static_cast<double>(steps)));
    return log.step_start(std::min(k, steps));
  }
  if (p.step && *p.step >= 0) return log.step_start(std::min(static_cast<std::uint64_t>(*p.step), steps));
  return log.event_count();
}

// One SVG document made a part of another: its XML declaration dropped, placed at x, and its
// ids (and the references to them) made unique with a prefix.
std::string nested_svg(std::string doc, int x, const std::string& prefix) {
  if (doc.rfind("<?xml", 0) == 0) doc.erase(0, doc.find('\n') + 1);
  const auto replace_all = [&doc](const std::string& from, const std::string& to) {
    for (std::size_t at = doc.find(from); at != std::string::npos; at = doc.find(from, at + to.size()))
      doc.replace(at, from.size(), to);
  };
  replace_all(" id=\"", " id=\"" + prefix);
  replace_all("url(#", "url(#" + prefix);
  replace_all("href=\"#", "href=\"#" + prefix);
  const std::size_t open = doc.find("<svg");
  if (open != std::string::npos) doc.insert(open + 4, " x=\"" + std::to_string(x) + "\" y=\"0\"");
  return doc;
}

}  // namespace

std::vector<unsigned long long> write_side_by_side(const SideBySide& p, const std::string& out) {
  if (p.fraction && !(*p.fraction >= 0.0 && *p.fraction <= 1.0))
    throw UsageError("--fraction " + std::to_string(*p.fraction) + ": expected a number from 0 to 1");
  if (p.step && *p.step < -1) throw UsageError("--step " + std::to_string(*p.step) + ": expected 0 or more, or -1 for the end");
  Panels panels(p);
  std::vector<std::uint64_t> positions;
  for (std::size_t i = 0; i < panels.size(); ++i) positions.push_back(moment_of(p, panels.log(i)));
  const std::vector<scene::Scene> scenes = panels.scenes(positions);
  std::vector<unsigned long long> shown;
  for (std::size_t i = 0; i < panels.size(); ++i) shown.push_back(panels.completed_steps(i));

  const int w = p.panel_width, h = panels.height(), total = panels.width();
  if (out.ends_with(".svg")) {
    std::string doc = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      std::to_string(total) + "\" height=\"" + std::to_string(h) + "\" viewBox=\"0 0 " +
                      std::to_string(total) + " " + std::to_string(h) + "\">\n";
    for (std::size_t i = 0; i < scenes.size(); ++i)
      doc += nested_svg(scene::to_svg(scenes[i], panels.camera()), static_cast<int>(i) * w,
                        "run" + std::to_string(i + 1) + "-");
    // A thin rule between panels.
    for (std::size_t i = 1; i < scenes.size(); ++i)
      doc += "<line x1=\"" + std::to_string(i * w) + "\" y1=\"0\" x2=\"" + std::to_string(i * w) + "\" y2=\"" +
             std::to_string(h) + "\" stroke=\"#888\" stroke-width=\"1\"/>\n";
    io::write_file_atomically(out, doc + "</svg>\n");
    return shown;
  }
  render::Painter painter(panels.gl());
  scene::Image whole;
  panels.paint(painter, scenes, whole);
  scene::write_png(out, whole);
  return shown;
}

std::size_t write_side_by_side_video(const SideBySide& p, const std::string& out, double fps) {
  if (!(fps > 0.0) || fps > 240.0) throw UsageError("--fps: expected a rate above 0 and at most 240");
  Panels panels(p);
  std::uint64_t longest = 0;
  for (std::size_t i = 0; i < panels.size(); ++i) longest = std::max(longest, panels.log(i).step_count());
  render::Painter painter(panels.gl());
  VideoPipe video(out, panels.width(), panels.height(), fps);
  scene::Image frame;
  // Frame k: every run after k steps (a shorter run stays at its end), k = 1 .. longest.
  for (std::uint64_t k = 1; k <= std::max<std::uint64_t>(longest, 1); ++k) {
    std::vector<std::uint64_t> positions;
    for (std::size_t i = 0; i < panels.size(); ++i)
      positions.push_back(panels.log(i).step_start(std::min(k, panels.log(i).step_count())));
    panels.paint(painter, panels.scenes(positions), frame);
    video.add(frame);
  }
  video.finish();
  return static_cast<std::size_t>(std::max<std::uint64_t>(longest, 1));
}

}  // namespace meshstep::app
