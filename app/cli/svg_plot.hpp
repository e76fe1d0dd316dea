// Line plots as SVG, for figures that go into papers: axes with ticks at round numbers and
// their labels, axis titles, one line per series in a colour-blind-safe palette with its own
// dash pattern and marker (so that the figure reads in grey too), and a legend. One figure
// holds one or more panels side by side, each titled "(a) ...", "(b) ...".
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace meshstep::app {

struct PlotSeries {
  std::string name;
  std::vector<std::pair<double, double>> points;  // in x order
  bool markers = true;  // a marker at every point (off for dense lines such as a CDF)
};

struct PlotPanel {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  // The axes' ranges; none: the data's, widened to round numbers.
  std::optional<std::pair<double, double>> x_range, y_range;
  bool y_from_zero = false;  // the automatic y range starts at 0
  // A logarithmic y axis, ticked at powers of ten: for counts that span orders of magnitude
  // (one algorithm's Steiner points running away at a high bound). Values <= 0 are not drawn.
  bool y_log = false;
  // The x axis's ticks (none: round numbers); given, the automatic x range is theirs, so a
  // sweep's axis ends at its first and last bound and ticks each.
  std::vector<double> x_ticks;
};

// The whole SVG document. Panels of `width` x `height` pixels each, side by side.
std::string svg_figure(const std::vector<PlotPanel>& panels, double width = 440, double height = 320);

// Ticks at round numbers (1, 2 or 5 times a power of ten apart) covering [low, high], about
// `target` of them; the first is <= low and the last >= high.
std::vector<double> nice_ticks(double low, double high, int target = 6);

}  // namespace meshstep::app
