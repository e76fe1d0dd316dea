// Labels placed so that they avoid each other, the vertices, the caption band and the
// legend (scene/label_placement.hpp): greedy, in priority order, among a fixed list of
// places round each label's point.
#include "meshstep/scene/label_placement.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "meshstep/scene/layout.hpp"

namespace meshstep::scene {

namespace {

// DejaVu Sans's ascent and descent, in ems.
constexpr double kAscentEm = 0.928, kDescentEm = 0.236;
// The halo reaches this far left and right of the text (as the renderers draw it).
constexpr double kHaloPx = 2.0;
// Between a label and its point, at text scale 1.
constexpr double kGapPx = 6.0;

struct Box {
  double x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// What no label may cover: the vertex markers (and the step's points), the caption band,
// the legend.
std::vector<Box> obstacles(const Scene& scene, const Camera& camera) {
  std::vector<Box> out;
  const double w = camera.width(), h = camera.height();
  for (const Shape& s : scene.shapes) {
    if (s.kind != ShapeKind::markers || !scene.visible.has(s.layer)) continue;
    if (s.layer != Layer::vertices && s.layer != Layer::overlay) continue;
    const double r = 0.5 * s.marker_px + 1.0;
    for (const Point& p : s.points) {
      const Point at = camera.to_screen(p);
      if (at.x < -r || at.y < -r || at.x > w + r || at.y > h + r) continue;
      out.push_back({at.x - r, at.y - r, at.x + r, at.y + r});
    }
  }
  const Layout l = layout(scene, camera.width(), camera.height());
  if (l.caption_band) out.push_back({l.caption_band->x, l.caption_band->y, l.caption_band->x + l.caption_band->w,
                                     l.caption_band->y + l.caption_band->h});
  if (l.legend) {
    const Rect& p = l.legend->panel;
    out.push_back({p.x, p.y, p.x + p.w, p.y + p.h});
  }
  return out;
}

// Obstacles by the cells of a coarse grid over the picture, so that a label looks only at
// the few near it (a picture may mark a thousand vertices).
class Grid {
 public:
  Grid(std::vector<Box> boxes, int width, int height)
      : boxes_(std::move(boxes)), columns_(width / kCell + 1), rows_(height / kCell + 1),
        cells_(static_cast<std::size_t>(columns_) * rows_) {
    for (std::size_t i = 0; i < boxes_.size(); ++i) visit(boxes_[i], [&](std::vector<std::size_t>& cell) { cell.push_back(i); });
  }
  bool hits(const Box& b) {
    bool hit = false;
    visit(b, [&](std::vector<std::size_t>& cell) {
      for (const std::size_t i : cell) hit = hit || boxes_[i].overlaps(b);
    });
    return hit;
  }

 private:
  static constexpr int kCell = 32;
  template <class F>
  void visit(const Box& b, F&& f) {
    const auto cell = [](double v, int n) { return std::clamp(static_cast<int>(std::floor(v / kCell)), 0, n - 1); };
    for (int y = cell(b.y0, rows_); y <= cell(b.y1, rows_); ++y)
      for (int x = cell(b.x0, columns_); x <= cell(b.x1, columns_); ++x) f(cells_[static_cast<std::size_t>(y) * columns_ + x]);
  }
  std::vector<Box> boxes_;
  int columns_, rows_;
  std::vector<std::vector<std::size_t>> cells_;
};

// Does the segment a-b pass through the box? (Liang-Barsky: the part of it inside.)
bool crosses(const Box& b, const Point& a, const Point& c) {
  double t0 = 0.0, t1 = 1.0;
  const double d[2] = {c.x - a.x, c.y - a.y};
  const double lo[2] = {b.x0 - a.x, b.y0 - a.y}, hi[2] = {b.x1 - a.x, b.y1 - a.y};
  for (int i = 0; i < 2; ++i) {
    if (d[i] == 0.0) {
      if (lo[i] > 0.0 || hi[i] < 0.0) return false;
      continue;
    }
    double ta = lo[i] / d[i], tb = hi[i] / d[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// The visible segments (the input's outline), which a name should rather not cross: a
// vertex's name on its own segment reads as part of the drawing. Soft: a name that finds
// no place clear of them takes one that crosses them. Each segment is filed under the grid
// cells it passes through (sampled every few pixels), so a label looks at the few near it.
class SegmentGrid {
 public:
  SegmentGrid(const Scene& scene, const Camera& camera)
      : columns_(camera.width() / kCell + 1), rows_(camera.height() / kCell + 1),
        cells_(static_cast<std::size_t>(columns_) * rows_) {
    if (!scene.visible.has(Layer::segments)) return;
    for (const Shape& s : scene.shapes) {
      if (s.layer != Layer::segments || s.kind != ShapeKind::lines) continue;
      if (s.points.size() > 2 * kMaxSegments) return;  // a refined mesh's: too many to matter
      for (std::size_t i = 0; i + 1 < s.points.size(); i += 2) {
        const Point a = camera.to_screen(s.points[i]), b = camera.to_screen(s.points[i + 1]);
        if (!std::isfinite(a.x + a.y + b.x + b.y)) continue;
        const std::size_t id = ends_.size();
        ends_.push_back({a, b});
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const int samples = static_cast<int>(std::min(length / 8.0, 4000.0)) + 1;
        std::size_t last = SIZE_MAX;
        for (int k = 0; k <= samples; ++k) {
          const double t = static_cast<double>(k) / samples;
          const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
          if (x < -kCell || y < -kCell || x > camera.width() + kCell || y > camera.height() + kCell) continue;
          const std::size_t cell = index(x, y);
          if (cell != last && (cells_[cell].empty() || cells_[cell].back() != id)) cells_[cell].push_back(id);
          last = cell;
        }
      }
    }
  }
  bool hits(const Box& b) const {
    for (int y = clamp_cell(b.y0, rows_); y <= clamp_cell(b.y1, rows_); ++y)
      for (int x = clamp_cell(b.x0, columns_); x <= clamp_cell(b.x1, columns_); ++x)
        for (const std::size_t id : cells_[static_cast<std::size_t>(y) * columns_ + x])
          if (crosses(b, ends_[id].first, ends_[id].second)) return true;
    return false;
  }

 private:
  static constexpr int kCell = 32;
  static constexpr std::size_t kMaxSegments = 5000;
  static int clamp_cell(double v, int n) { return std::clamp(static_cast<int>(std::floor(v / kCell)), 0, n - 1); }
  std::size_t index(double x, double y) const {
    return static_cast<std::size_t>(clamp_cell(y, rows_)) * columns_ + clamp_cell(x, columns_);
  }
  int columns_, rows_;
  std::vector<std::vector<std::size_t>> cells_;
  std::vector<std::pair<Point, Point>> ends_;
};

}  // namespace

// DejaVu Sans's advances, in ems, by groups: narrow punctuation and i l j (about 0.3), r t f
// and the hyphen (0.35-0.41), s c z (0.52-0.55), most lower-case letters and the digits
// (0.61-0.64), capitals (about 0.7), m and w (0.82-0.97). The middle dot of the captions is
// narrow; other characters beyond ASCII count as a wide letter. A little wide rather than
// narrow: a label's halo and a caption's fit must hold the text.
double estimated_text_width(std::string_view text, double size_px) {
  double ems = 0.0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    const unsigned char b = static_cast<unsigned char>(ch);
    if ((b & 0xC0) == 0x80) continue;  // a UTF-8 continuation byte: counted with its lead byte
    if (b == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0xB7) ems += 0.32;  // middle dot
    else if (b >= 0x80) ems += 0.65;
    else if (std::string_view(" .,:;'!|ilj()[]").find(ch) != std::string_view::npos) ems += 0.32;
    else if (std::string_view("rtf-").find(ch) != std::string_view::npos) ems += 0.41;
    else if (std::string_view("scz").find(ch) != std::string_view::npos) ems += 0.55;
    else if (ch >= 'A' && ch <= 'Z') ems += 0.70;
    else if (ch == 'm' || ch == 'w' || ch == 'M' || ch == 'W') ems += 0.90;
    else ems += 0.64;
  }
  return ems * size_px;
}

TextExtent estimated_text_extent(std::string_view text, double size_px) {
  return {estimated_text_width(text, size_px), std::ceil(kAscentEm * size_px), std::ceil(kDescentEm * size_px)};
}

std::vector<PlacedLabel> place_labels(const Scene& scene, const Camera& camera, const MeasureText& measure) {
  const double width = camera.width(), height = camera.height();
  const double k = scene.text_scale;
  Grid blocked(obstacles(scene, camera), camera.width(), camera.height());
  const SegmentGrid segments(scene, camera);
  std::vector<Box> placed_boxes;

  std::vector<std::size_t> order(scene.labels.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return scene.labels[a].priority > scene.labels[b].priority; });

  std::vector<PlacedLabel> out;
  for (const std::size_t i : order) {
    const Label& label = scene.labels[i];
    if (label.text.empty()) continue;
    const Point at = camera.to_screen(label.at);
    if (!(at.x >= 0.0 && at.x <= width && at.y >= 0.0 && at.y <= height)) continue;  // off the picture, or not finite
    const double size = label.size_px * k;
    const TextExtent e = measure(label.text, size);
    // The place the label asks for, then round its point: beside it right and left, above
    // and below it, level with it; each ring a line further out than the one before.
    std::vector<Point> spots{{at.x + label.dx_px * k, at.y + label.dy_px * k}};
    const double line = e.ascent + e.descent;
    for (int ring = 0; ring < 3; ++ring) {
      const double g = kGapPx * k + ring * line;
      const double above = at.y - g - e.descent, below = at.y + g + e.ascent, level = at.y + 0.5 * (e.ascent - e.descent);
      const double right = at.x + g, left = at.x - g - e.width, centred = at.x - 0.5 * e.width;
      for (const Point& p : std::array<Point, 8>{{{right, above}, {left, above}, {right, below}, {left, below},
                                                   {centred, above}, {centred, below}, {right, level}, {left, level}}})
        spots.push_back(p);
    }
    // Names (of vertices, regions) first look for a place clear of the segments too, then
    // for one that only crosses them; the step's words stay near their points instead.
    bool done = false;
    for (const bool avoid_segments : {true, false}) {
      if (avoid_segments && label.priority >= 2) continue;
      for (const Point& spot : spots) {
        const double x = std::round(spot.x), base = std::round(spot.y);
        const Box box{x - kHaloPx, base - e.ascent, x + e.width + kHaloPx, base + e.descent};
        if (box.x0 < 0.0 || box.y0 < 0.0 || box.x1 > width || box.y1 > height) continue;
        if (blocked.hits(box)) continue;
        if (std::any_of(placed_boxes.begin(), placed_boxes.end(), [&](const Box& b) { return b.overlaps(box); })) continue;
        if (avoid_segments && segments.hits(box)) continue;
        placed_boxes.push_back(box);
        out.push_back({i, x, base, size, box.x0, box.y0, box.x1, box.y1});
        done = true;
        break;
      }
      if (done) break;
    }
  }
  std::sort(out.begin(), out.end(), [](const PlacedLabel& a, const PlacedLabel& b) { return a.label < b.label; });
  return out;
}

}  // namespace meshstep::scene
