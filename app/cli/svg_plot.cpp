// The SVG plot writer (svg_plot.hpp). Everything is placed in pixels here; the SVG has no
// transforms, so what a test reads from it is where the line is drawn.
#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace meshstep::app {
namespace {

// Okabe and Ito's palette (Color Universal Design): distinguishable with every common
// colour-vision deficiency. Black first: the reference algorithm.
constexpr const char* kColours[] = {"#000000", "#E69F00", "#56B4E9", "#009E73", "#D55E00", "#0072B2", "#CC79A7",
                                    "#F0E442"};
constexpr const char* kDashes[] = {"", "7,3", "1.5,2.5", "9,3,2,3", "3,3", "12,3,2,3,2,3", "16,4", "5,2,1,2"};
constexpr int kStyles = 8;

// Plot-area margins within a panel: room for the tick labels and the axis titles (the left
// one grows with the widest y tick label, so that the axis title never runs into it).
constexpr double kLeft = 62, kRight = 14, kTop = 30, kBottom = 46;
constexpr double kTickCharWidth = 6.4;  // an 11-pixel digit, about

std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  std::string s = buffer;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

// A tick's label: as few digits as tell the ticks apart (20, 22.5, 0.25, 1e+06).
std::string tick_label(double v, double spacing) {
  if (std::abs(v) < spacing * 1e-9) v = 0.0;
  char buffer[32];
  if (std::abs(v) >= 1e6) {
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return buffer;
  }
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(spacing) - 1e-9)));
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

std::string marker(int style, double x, double y, const char* colour) {
  const double r = 3.2;
  switch (style % 4) {
    case 0:
      return "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"" + num(r) + "\" fill=\"" + colour + "\"/>";
    case 1:
      return "<rect x=\"" + num(x - r) + "\" y=\"" + num(y - r) + "\" width=\"" + num(2 * r) + "\" height=\"" +
             num(2 * r) + "\" fill=\"white\" stroke=\"" + colour + "\" stroke-width=\"1.3\"/>";
    case 2:
      return "<path d=\"M" + num(x) + " " + num(y - 1.2 * r) + "L" + num(x + 1.1 * r) + " " + num(y + 0.8 * r) + "L" +
             num(x - 1.1 * r) + " " + num(y + 0.8 * r) + "Z\" fill=\"" + colour + "\"/>";
    default:
      return "<path d=\"M" + num(x) + " " + num(y - 1.3 * r) + "L" + num(x + 1.3 * r) + " " + num(y) + "L" + num(x) +
             " " + num(y + 1.3 * r) + "L" + num(x - 1.3 * r) + " " + num(y) + "Z\" fill=\"white\" stroke=\"" + colour +
             "\" stroke-width=\"1.3\"/>";
  }
}

// A log axis's label: 1, 10, 100, 1000, then 10⁴, 10⁵ ... (exponents as superscripts).
std::string decade_label(double exponent) {
  const int e = static_cast<int>(std::lround(exponent));
  if (e >= 0 && e <= 3) return std::to_string(static_cast<int>(std::lround(std::pow(10.0, e))));
  static const char* const kSuperscript[] = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                                             "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string label = e < 0 ? "10\u207B" : "10";
  for (const char digit : std::to_string(std::abs(e))) label += kSuperscript[digit - '0'];
  return label;
}

std::pair<double, double> data_range(const PlotPanel& panel, bool x_axis) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const PlotSeries& s : panel.series)
    for (const auto& [x, y] : s.points) {
      double v = x_axis ? x : y;
      if (!x_axis && panel.y_log) v = v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
      if (!std::isfinite(v)) continue;
      low = std::min(low, v);
      high = std::max(high, v);
    }
  if (!std::isfinite(low)) return {0.0, 1.0};
  if (!x_axis && panel.y_from_zero && !panel.y_log) low = std::min(low, 0.0);
  if (high - low <= 0.0) {
    const double pad = low == 0.0 ? 1.0 : std::abs(low) * 0.1;
    return {low - pad, high + pad};
  }
  return {low, high};
}

std::string draw_panel(const PlotPanel& panel, std::size_t index, double left, double top, double width, double height) {
  std::string svg;
  // A log axis is drawn in decades: y is log10 of the value from here on, and its ticks are
  // whole exponents.
  const auto y_of = [&](double value) {
    return !panel.y_log ? value : value > 0.0 ? std::log10(value) : std::numeric_limits<double>::quiet_NaN();
  };
  std::pair<double, double> yr = panel.y_range.value_or(data_range(panel, false));
  if (panel.y_log && panel.y_range) yr = {y_of(yr.first), y_of(yr.second)};
  std::vector<double> y_ticks = panel.y_log ? nice_ticks(std::floor(yr.first), std::ceil(yr.second))
                                            : nice_ticks(yr.first, yr.second);
  if (panel.y_log && y_ticks.size() > 1 && y_ticks[1] - y_ticks[0] < 1.0) {
    y_ticks.clear();  // decades only: no tick at 10^0.5
    for (double e = std::floor(yr.first); e <= std::ceil(yr.second) + 0.5; ++e) y_ticks.push_back(e);
  }
  const double y_spacing = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  const auto y_tick_label = [&](double t) { return panel.y_log ? decade_label(t) : tick_label(t, y_spacing); };
  std::size_t widest = 0;
  for (const double t : y_ticks) widest = std::max(widest, y_tick_label(t).size());
  const double margin = std::max(kLeft, 34 + kTickCharWidth * static_cast<double>(widest));
  const double x0 = left + margin, x1 = left + width - kRight, y0 = top + height - kBottom, y1 = top + kTop;
  const std::pair<double, double> xr = panel.x_range.value_or(
      panel.x_ticks.size() > 1 ? std::pair{panel.x_ticks.front(), panel.x_ticks.back()} : data_range(panel, true));
  std::vector<double> x_ticks = panel.x_ticks.size() > 1 ? panel.x_ticks : nice_ticks(xr.first, xr.second);
  // Automatic ranges end at the outer ticks, so that the axes end at labelled numbers.
  const double xa = panel.x_range ? xr.first : x_ticks.front(), xb = panel.x_range ? xr.second : x_ticks.back();
  const double ya = panel.y_range ? yr.first : y_ticks.front(), yb = panel.y_range ? yr.second : y_ticks.back();
  const auto px = [&](double x) { return x0 + (x - xa) / (xb - xa) * (x1 - x0); };
  const auto py = [&](double y) { return y0 - (y - ya) / (yb - ya) * (y0 - y1); };
  const double x_spacing = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;

  // Light grid lines at the ticks, then the frame over them.
  svg += "<g stroke=\"#e4e4e4\" stroke-width=\"0.8\">";
  for (const double t : x_ticks)
    if (t >= xa - 1e-12 && t <= xb + 1e-12)
      svg += "<line x1=\"" + num(px(t)) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(px(t)) + "\" y2=\"" + num(y1) + "\"/>";
  for (const double t : y_ticks)
    if (t >= ya - 1e-12 && t <= yb + 1e-12)
      svg += "<line x1=\"" + num(x0) + "\" y1=\"" + num(py(t)) + "\" x2=\"" + num(x1) + "\" y2=\"" + num(py(t)) + "\"/>";
  svg += "</g>\n";

  // The lines, clipped to the plot area.
  const std::string clip = "plotarea" + std::to_string(index);
  svg += "<clipPath id=\"" + clip + "\"><rect x=\"" + num(x0) + "\" y=\"" + num(y1) + "\" width=\"" + num(x1 - x0) +
         "\" height=\"" + num(y0 - y1) + "\"/></clipPath>\n";
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    const PlotSeries& series = panel.series[s];
    const char* colour = kColours[s % kStyles];
    std::string d;
    for (const auto& [x, y] : series.points) {
      if (!std::isfinite(x) || !std::isfinite(y_of(y))) continue;
      d += (d.empty() ? "M" : "L") + num(px(x)) + " " + num(py(y_of(y)));
    }
    if (d.empty()) continue;
    svg += "<path class=\"series\" data-name=\"" + escaped(series.name) + "\" clip-path=\"url(#" + clip + ")\" d=\"" +
           d + "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.6\" stroke-linejoin=\"round\"" +
           (kDashes[s % kStyles][0] ? std::string(" stroke-dasharray=\"") + kDashes[s % kStyles] + "\"" : "") + "/>\n";
    if (series.markers)
      for (const auto& [x, y] : series.points)
        if (std::isfinite(x) && std::isfinite(y_of(y))) svg += marker(static_cast<int>(s), px(x), py(y_of(y)), colour) + "\n";
  }

  // Frame, ticks and their labels.
  svg += "<rect x=\"" + num(x0) + "\" y=\"" + num(y1) + "\" width=\"" + num(x1 - x0) + "\" height=\"" + num(y0 - y1) +
         "\" fill=\"none\" stroke=\"#222\" stroke-width=\"1\"/>\n";
  svg += "<g stroke=\"#222\" stroke-width=\"1\">";
  for (const double t : x_ticks)
    if (t >= xa - 1e-12 && t <= xb + 1e-12)
      svg += "<line x1=\"" + num(px(t)) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(px(t)) + "\" y2=\"" + num(y0 + 4) + "\"/>";
  for (const double t : y_ticks)
    if (t >= ya - 1e-12 && t <= yb + 1e-12)
      svg += "<line x1=\"" + num(x0 - 4) + "\" y1=\"" + num(py(t)) + "\" x2=\"" + num(x0) + "\" y2=\"" + num(py(t)) + "\"/>";
  svg += "</g>\n<g font-size=\"11\" fill=\"#222\">";
  for (const double t : x_ticks)
    if (t >= xa - 1e-12 && t <= xb + 1e-12)
      svg += "<text x=\"" + num(px(t)) + "\" y=\"" + num(y0 + 16) + "\" text-anchor=\"middle\">" +
             tick_label(t, x_spacing) + "</text>";
  for (const double t : y_ticks)
    if (t >= ya - 1e-12 && t <= yb + 1e-12)
      svg += "<text x=\"" + num(x0 - 7) + "\" y=\"" + num(py(t) + 4) + "\" text-anchor=\"end\">" +
             y_tick_label(t) + "</text>";
  svg += "</g>\n";

  // Axis titles and the panel's title.
  svg += "<text x=\"" + num((x0 + x1) / 2) + "\" y=\"" + num(y0 + 36) + "\" font-size=\"12\" text-anchor=\"middle\">" +
         escaped(panel.x_label) + "</text>\n";
  svg += "<text transform=\"rotate(-90 " + num(left + 16) + " " + num((y0 + y1) / 2) + ")\" x=\"" + num(left + 16) +
         "\" y=\"" + num((y0 + y1) / 2) + "\" font-size=\"12\" text-anchor=\"middle\">" + escaped(panel.y_label) +
         "</text>\n";
  svg += "<text x=\"" + num(x0) + "\" y=\"" + num(top + 18) + "\" font-size=\"13\" font-weight=\"bold\">" +
         escaped(panel.title) + "</text>\n";

  // The legend: a white box in the plot's upper left corner, a line sample and a name per
  // series.
  std::size_t longest = 0;
  for (const PlotSeries& s : panel.series) longest = std::max(longest, s.name.size());
  const double row = 15, box_w = 40 + 6.3 * static_cast<double>(longest), box_h = 8 + row * panel.series.size();
  const double bx = x0 + 8, by = y1 + 8;
  svg += "<g class=\"legend\"><rect x=\"" + num(bx) + "\" y=\"" + num(by) + "\" width=\"" + num(box_w) +
         "\" height=\"" + num(box_h) + "\" fill=\"white\" fill-opacity=\"0.92\" stroke=\"#999\" stroke-width=\"0.6\"/>";
  for (std::size_t s = 0; s < panel.series.size(); ++s) {
    const double ly = by + 4 + row * (static_cast<double>(s) + 0.5);
    const char* colour = kColours[s % kStyles];
    svg += "<line x1=\"" + num(bx + 6) + "\" y1=\"" + num(ly) + "\" x2=\"" + num(bx + 30) + "\" y2=\"" + num(ly) +
           "\" stroke=\"" + colour + "\" stroke-width=\"1.6\"" +
           (kDashes[s % kStyles][0] ? std::string(" stroke-dasharray=\"") + kDashes[s % kStyles] + "\"" : "") + "/>";
    if (panel.series[s].markers) svg += marker(static_cast<int>(s), bx + 18, ly, colour);
    svg += "<text x=\"" + num(bx + 36) + "\" y=\"" + num(ly + 4) + "\" font-size=\"11\">" +
           escaped(panel.series[s].name) + "</text>";
  }
  svg += "</g>\n";
  return svg;
}

}  // namespace

std::vector<double> nice_ticks(double low, double high, int target) {
  if (!(high > low)) return {low};
  const double raw = (high - low) / std::max(target - 1, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double spacing = power * 10;
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (raw <= m * power * (1 + 1e-9)) {
      spacing = m * power;
      break;
    }
  std::vector<double> ticks;
  const double first = std::floor(low / spacing + 1e-9), last = std::ceil(high / spacing - 1e-9);
  for (double i = first; i <= last + 0.5; ++i) ticks.push_back(i * spacing);
  return ticks;
}

std::string svg_figure(const std::vector<PlotPanel>& panels, double width, double height) {
  const double total = width * static_cast<double>(std::max<std::size_t>(panels.size(), 1));
  std::string svg = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                    num(total) + "\" height=\"" + num(height) + "\" viewBox=\"0 0 " + num(total) + " " + num(height) +
                    "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n<rect width=\"100%\" "
                    "height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t i = 0; i < panels.size(); ++i)
    svg += draw_panel(panels[i], i, width * static_cast<double>(i), 0.0, width, height);
  return svg + "</svg>\n";
}

}  // namespace meshstep::app
