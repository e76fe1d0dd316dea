// Runs side by side at one moment (compare_picture.hpp).
#include "compare_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "draw_options.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/scene/svg.hpp"
#include "moment_scene.hpp"
#include "painter.hpp"

namespace meshstep::app {
namespace {

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
std::string nested_svg(std::string doc, double x, const std::string& prefix) {
  if (doc.rfind("<?xml", 0) == 0) doc.erase(0, doc.find('\n') + 1);
  const auto replace_all = [&doc](const std::string& from, const std::string& to) {
    for (std::size_t at = doc.find(from); at != std::string::npos; at = doc.find(from, at + to.size()))
      doc.replace(at, from.size(), to);
  };
  replace_all(" id=\"", " id=\"" + prefix);
  replace_all("url(#", "url(#" + prefix);
  replace_all("href=\"#", "href=\"#" + prefix);
  const std::size_t open = doc.find("<svg");
  if (open != std::string::npos) doc.insert(open + 4, " x=\"" + std::to_string(static_cast<long long>(x)) + "\" y=\"0\"");
  return doc;
}

}  // namespace

std::vector<unsigned long long> write_side_by_side(const SideBySide& p, const std::string& out) {
  if (p.fraction && !(*p.fraction >= 0.0 && *p.fraction <= 1.0))
    throw UsageError("--fraction " + std::to_string(*p.fraction) + ": expected a number from 0 to 1");
  if (p.step && *p.step < -1) throw UsageError("--step " + std::to_string(*p.step) + ": expected 0 or more, or -1 for the end");
  const DrawSettings draw = parse_draw_args(DrawArgs{});

  std::vector<scene::Scene> scenes;
  std::vector<unsigned long long> shown;
  BBox world;
  for (std::size_t i = 0; i < p.logs.size(); ++i) {
    const replay::LogReader log(p.logs[i]);
    LogScenes moments(log, draw.scene);
    scene::Scene s = moments.at(moment_of(p, log));
    shown.push_back(moments.cursor().completed_steps());
    // The run's description, then the scene's phase and step ("refine · step 30 of 59"); what
    // the step did is left out, for two or more captions to fit their panels.
    const std::size_t first = s.caption.find(" \u00b7 ");
    const std::size_t second = first == std::string::npos ? first : s.caption.find(" \u00b7 ", first + 1);
    s.caption = p.captions[i] + " \u00b7 " + s.caption.substr(0, second);
    world.add(run_bounds(log).lo);
    world.add(run_bounds(log).hi);
    scenes.push_back(std::move(s));
  }
  // One camera for every panel: the union of the runs' points, fitted as each panel's
  // caption and legend allow (the panels are alike, so the fits are too).
  for (scene::Scene& s : scenes) s.bounds = world;
  // Tall enough for the box at the panel's width (less the fit's margins), plus the caption
  // band: a wide input gets no empty band above and below.
  int height = p.panel_height;
  if (height <= 0) {
    const double dx = world.hi.x - world.lo.x, dy = world.hi.y - world.lo.y;
    const double wanted = dx > 0.0 ? (p.panel_width - 48.0) * dy / dx + 48.0 + 36.0 : 560.0;
    height = static_cast<int>(std::clamp(std::ceil(wanted), 200.0, 1000.0));
  }
  const scene::Camera camera = scene::fit_scene(scenes.front(), p.panel_width, height);

  const int total = p.panel_width * static_cast<int>(scenes.size());
  if (out.ends_with(".svg")) {
    std::string doc = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      std::to_string(total) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " +
                      std::to_string(total) + " " + std::to_string(height) + "\">\n";
    for (std::size_t i = 0; i < scenes.size(); ++i)
      doc += nested_svg(scene::to_svg(scenes[i], camera), static_cast<double>(i) * p.panel_width,
                        "run" + std::to_string(i + 1) + "-");
    // A thin rule between panels.
    for (std::size_t i = 1; i < scenes.size(); ++i)
      doc += "<line x1=\"" + std::to_string(i * p.panel_width) + "\" y1=\"0\" x2=\"" + std::to_string(i * p.panel_width) +
             "\" y2=\"" + std::to_string(height) + "\" stroke=\"#888\" stroke-width=\"1\"/>\n";
    io::write_file_atomically(out, doc + "</svg>\n");
    return shown;
  }
  Painter painter(draw.gl);
  scene::Image whole;
  whole.width = total;
  whole.height = height;
  whole.rgba.assign(static_cast<std::size_t>(total) * height * 4, 255);
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const scene::Image panel = painter.paint(scenes[i], camera, draw.samples);
    for (int y = 0; y < std::min(panel.height, whole.height); ++y)
      std::copy(panel.row(y), panel.row(y) + static_cast<std::size_t>(std::min(panel.width, p.panel_width)) * 4,
                whole.row(y) + static_cast<std::size_t>(i) * p.panel_width * 4);
  }
  scene::write_png(out, whole);
  return shown;
}

}  // namespace meshstep::app
