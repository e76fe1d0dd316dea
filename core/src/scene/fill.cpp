// Triangle fills by quantity. One pass over the triangles per quantity, a table lookup per
// colour: a million triangles in a few tens of milliseconds, without allocating per triangle.
#include "fill.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "meshstep/refine/quality.hpp"
#include "meshstep/scene/colormap.hpp"
#include "style.hpp"
#include "ticks.hpp"

namespace meshstep::scene::detail {

namespace {

constexpr std::size_t kLegendStops = 128;
// No triangle's smallest angle exceeds 60 degrees: the top of the angle scales.
constexpr double kLargestSmallestAngle = 60.0;
// Categories beyond this many are still coloured (cyclically) but not all listed.
constexpr std::size_t kMaxSwatches = 24;
constexpr std::size_t kMaxCategories = 256;

// Tables built once, on first use (thread-safe statics).
const ColorTable& table_of(const ColorMap& map) {
  if (&map == &viridis()) {
    static const ColorTable t(viridis());
    return t;
  }
  if (&map == &cividis()) {
    static const ColorTable t(cividis());
    return t;
  }
  if (&map == &magma()) {
    static const ColorTable t(magma());
    return t;
  }
  if (&map == &orange_below()) {
    static const ColorTable t(orange_below());
    return t;
  }
  static const ColorTable t(blue_above());
  return t;
}

double min_angle_deg(const FillInput& in, std::size_t t) {
  const auto& v = in.triangles[t];
  return quality::shape(in.points[v[0]], in.points[v[1]], in.points[v[2]]).min_angle_deg();
}

double area(const FillInput& in, std::size_t t) {
  const auto& v = in.triangles[t];
  return 0.5 * std::abs(quality::twice_area(in.points[v[0]], in.points[v[1]], in.points[v[2]]));
}

void add_linear_ticks(Legend& legend, double lo, double hi, int target, auto position) {
  const double step = tick_step(lo, hi, target);
  for (const double v : linear_ticks(lo, hi, target)) legend.ticks.push_back({position(v), tick_label(v, step)});
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Everything alike: the theme's neutral fill. A legend only when it has something to say.
std::optional<Legend> fill_neutral(Theme theme, MeshLayer& out, std::optional<Legend> legend = std::nullopt) {
  out.fill.assign(out.triangles.size(), base_style(theme).neutral_fill);
  return legend;
}

std::optional<Legend> fill_by_angle(const FillInput& in, MeshLayer& out) {
  const ColorTable& colors = table_of(viridis());
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const double a = min_angle_deg(in, t);
    out.values[t] = a;
    out.fill[t] = colors(a / kLargestSmallestAngle);
  }
  Legend legend;
  legend.title = "smallest angle (°)";
  legend.colors = viridis().samples(kLegendStops);
  add_linear_ticks(legend, 0.0, kLargestSmallestAngle, 7, [](double v) { return v / kLargestSmallestAngle; });
  return legend;
}

std::optional<Legend> fill_by_quality(const FillInput& in, MeshLayer& out) {
  const double bound = in.min_angle_bound;
  const ColorTable &below = table_of(orange_below()), &above = table_of(blue_above());
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const double a = min_angle_deg(in, t);
    out.values[t] = a;
    const double at = quality_position(a, bound);
    out.fill[t] = at < 0.5 ? below(2.0 * at) : above(2.0 * at - 1.0);
  }
  Legend legend;
  legend.title = "angle vs bound (°)";
  legend.colors.resize(kLegendStops);
  for (std::size_t i = 0; i < kLegendStops; ++i) {
    const double at = static_cast<double>(i) / (kLegendStops - 1);
    legend.colors[i] = at < 0.5 ? orange_below()(2.0 * at) : blue_above()(2.0 * at - 1.0);
  }
  // The round angles, but none so near the bound that the labels would collide.
  const double step = tick_step(0.0, kLargestSmallestAngle, 7);
  for (const double v : linear_ticks(0.0, kLargestSmallestAngle, 7)) {
    const double at = quality_position(v, bound);
    if (std::abs(at - 0.5) >= 0.06) legend.ticks.push_back({at, tick_label(v, step)});
  }
  Legend::Tick mark{0.5, tick_label(bound, bound == std::round(bound) ? 1.0 : 0.1) + " bound"};
  mark.emphasized = true;
  legend.ticks.insert(std::lower_bound(legend.ticks.begin(), legend.ticks.end(), mark,
                                       [](const Legend::Tick& x, const Legend::Tick& y) { return x.at < y.at; }),
                      mark);
  return legend;
}

std::optional<Legend> fill_by_area(const FillInput& in, MeshLayer& out) {
  double lo = INFINITY, hi = 0.0;
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const double a = area(in, t);
    out.values[t] = a;
    if (a > 0.0) lo = std::min(lo, a), hi = std::max(hi, a);
  }
  Legend legend;
  legend.title = "area (log scale)";
  legend.colors = cividis().samples(kLegendStops);
  if (!(hi > 0.0)) {  // no triangle with an area: all at the bottom of the scale
    std::fill(out.fill.begin(), out.fill.end(), cividis()(0.0));
    return legend;
  }
  const double log_lo = std::log(lo), log_span = std::log(hi) - log_lo;
  const auto position = [&](double a) {
    if (!(log_span > 0.0)) return 0.5;
    return a > 0.0 ? std::clamp((std::log(a) - log_lo) / log_span, 0.0, 1.0) : 0.0;
  };
  const ColorTable& colors = table_of(cividis());
  for (std::size_t t = 0; t < in.triangles.size(); ++t) out.fill[t] = colors(position(out.values[t]));
  for (const double v : log_ticks(lo, hi)) legend.ticks.push_back({position(v), log_tick_label(v)});
  return legend;
}

std::optional<Legend> fill_by_region(const FillInput& in, Theme theme, MeshLayer& out) {
  Legend legend;
  legend.title = "region";
  legend.categorical = true;
  if (in.region.size() != in.triangles.size()) {
    legend.colors = {base_style(theme).neutral_fill};
    legend.ticks = {{0.5, "none in this mesh"}};
    return fill_neutral(theme, out, legend);
  }
  // The distinct attributes (a handful): the last one matched is tried first, since
  // neighbouring triangles mostly share a region.
  // Attributes are categories, a handful of them; past kMaxCategories (a mesh whose
  // attribute is really continuous) the rest share the colour of the nearest one below.
  std::vector<double> distinct;
  double last = NAN;
  for (const double a : in.region) {
    if (a == last || std::isnan(a)) continue;
    last = a;
    if (std::find(distinct.begin(), distinct.end(), a) != distinct.end()) continue;
    distinct.push_back(a);
    if (distinct.size() == kMaxCategories) break;
  }
  std::sort(distinct.begin(), distinct.end());
  if (distinct.empty()) distinct.push_back(0.0);
  std::size_t index = 0;
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const double a = in.region[t];
    if (distinct[index] != a) {
      const auto above = std::upper_bound(distinct.begin(), distinct.end(), a);
      index = above == distinct.begin() ? 0 : static_cast<std::size_t>(above - distinct.begin()) - 1;
    }
    out.values[t] = a;
    out.fill[t] = category_color(index);
  }
  const std::size_t shown = std::min(distinct.size(), kMaxSwatches);
  for (std::size_t i = 0; i < shown; ++i) {
    legend.colors.push_back(category_color(i));
    legend.ticks.push_back({(i + 0.5) / shown, number_text(distinct[i])});
  }
  if (shown < distinct.size())
    legend.title += " (" + std::to_string(shown) + " of " + std::to_string(distinct.size()) + ")";
  return legend;
}

std::optional<Legend> fill_by_age(const FillInput& in, Theme theme, MeshLayer& out) {
  Legend legend;
  legend.title = "age (step made)";
  if (in.ages.size() != in.triangles.size()) {
    legend.colors = {base_style(theme).neutral_fill};
    legend.categorical = true;
    legend.ticks = {{0.5, "no history (a mesh alone)"}};
    return fill_neutral(theme, out, legend);
  }
  // Steps counted from 1, as the caption counts them; the newest faces are the lightest.
  const double newest = static_cast<double>(std::max<std::uint64_t>(in.current_step, 1));
  const ColorTable& colors = table_of(magma());
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    out.values[t] = static_cast<double>(in.ages[t] + 1);
    out.fill[t] = colors(static_cast<double>(in.ages[t]) / newest);
  }
  legend.colors = magma().samples(kLegendStops);
  add_linear_ticks(legend, 1.0, static_cast<double>(in.current_step + 1), 6,
                   [newest](double step) { return (step - 1.0) / newest; });
  return legend;
}

}  // namespace

// The height scale of 2D and 3D pictures alike: viridis, its ends labelled to one decimal more
// than the round ticks between them.
Legend height_legend(double lo, double hi) {
  Legend legend;
  legend.title = "height";
  legend.colors = viridis().samples(kLegendStops);
  if (!(hi > lo)) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", lo);
    legend.ticks.push_back({0.5, buf});
    return legend;
  }
  const double step = tick_step(lo, hi, 7);
  const auto at = [&](double v) { return (v - lo) / (hi - lo); };
  // The ends, to one decimal more than the round ticks between (trailing zeros dropped:
  // "0.01" and "2", not "0.009656" and "2.00"), and the round ticks not crowding them.
  const auto end_label = [step](double v) {
    std::string text = tick_label(v, step / 10.0);
    if (text.find('.') != std::string::npos && text.find('e') == std::string::npos) {
      text.erase(text.find_last_not_of('0') + 1);
      if (text.back() == '.') text.pop_back();
      if (text == "-0") text = "0";
    }
    return text;
  };
  legend.ticks.push_back({0.0, end_label(lo)});
  for (const double v : linear_ticks(lo, hi, 7))
    if (at(v) > 0.08 && at(v) < 0.92) legend.ticks.push_back({at(v), tick_label(v, step)});
  legend.ticks.push_back({1.0, end_label(hi)});
  return legend;
}

namespace {

// The mean height of each triangle's corners, viridis from the lowest to the highest of the
// triangles' corners (the colours a 3D view gives the same run, unshaded).
std::optional<Legend> fill_by_height(const FillInput& in, Theme theme, MeshLayer& out) {
  Legend legend;
  legend.title = "height";
  legend.colors = viridis().samples(kLegendStops);
  if (in.heights.size() != in.points.size()) {
    legend.colors = {base_style(theme).neutral_fill};
    legend.categorical = true;
    legend.ticks = {{0.5, "no heights (a planar run)"}};
    return fill_neutral(theme, out, legend);
  }
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const auto& v = in.triangles[t];
    out.values[t] = (in.heights[v[0]] + in.heights[v[1]] + in.heights[v[2]]) / 3.0;
    for (const std::uint32_t k : v) lo = std::min(lo, in.heights[k]), hi = std::max(hi, in.heights[k]);
  }
  const auto position = [&](double z) { return hi > lo ? std::clamp((z - lo) / (hi - lo), 0.0, 1.0) : 0.5; };
  const ColorTable& colors = table_of(viridis());
  for (std::size_t t = 0; t < in.triangles.size(); ++t) out.fill[t] = colors(position(out.values[t]));
  if (!(hi >= lo)) return legend;
  return height_legend(lo, hi);
}

}  // namespace

double quality_position(double angle_deg, double bound_deg) {
  bound_deg = std::clamp(bound_deg, 1.0, kLargestSmallestAngle - 1.0);
  if (!(angle_deg > 0.0)) return 0.0;
  if (angle_deg < bound_deg) return 0.5 * angle_deg / bound_deg;
  return std::min(1.0, 0.5 + 0.5 * (angle_deg - bound_deg) / (kLargestSmallestAngle - bound_deg));
}

std::optional<Legend> fill_triangles(ColorBy by, Theme theme, const FillInput& in, MeshLayer& out) {
  out.fill.resize(in.triangles.size());
  if (by == ColorBy::none) {
    out.values.clear();
    return fill_neutral(theme, out);
  }
  out.values.resize(in.triangles.size());
  switch (by) {
    case ColorBy::angle: return fill_by_angle(in, out);
    case ColorBy::quality: return fill_by_quality(in, out);
    case ColorBy::area: return fill_by_area(in, out);
    case ColorBy::region: return fill_by_region(in, theme, out);
    case ColorBy::age: return fill_by_age(in, theme, out);
    case ColorBy::height: return fill_by_height(in, theme, out);
    default: return fill_neutral(theme, out);
  }
}

}  // namespace meshstep::scene::detail
