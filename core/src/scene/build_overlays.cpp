// The current step explained: shapes over the mesh, drawn from the step's story in a fixed
// order (regions first, then edges and circles, points on top), whatever order the events
// came in. Each role's translucent faces come first and their outline after, under one role.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <span>
#include <vector>
#include <utility>
#include <tuple>
#include <optional>
#include <limits>

#include "meshstep/refine/quality.hpp"
#include "meshstep/scene/colormap.hpp"
#include "parts.hpp"
#include "style.hpp"

namespace meshstep::scene::detail {

namespace {

// Segments per arc of a diametral lens: smooth at any zoom a picture shows it whole.
constexpr int kLensArcSegments = 24;
constexpr Rgba kHollow{0, 0, 0, 0};

std::string printed(const char* format, double value) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

std::string degrees_text(double deg) { return printed("%.1f", deg) + "\u00B0"; }

Point midpoint(const Point& a, const Point& b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

Point centroid(const std::array<Point, 3>& p) {
  return {(p[0].x + p[1].x + p[2].x) / 3.0, (p[0].y + p[1].y + p[2].y) / 3.0};
}

// Draws a step's story into a scene, with the vertices' coordinates from the log.
class OverlayPainter {
 public:
  OverlayPainter(Scene& scene, const replay::LogReader& log)
      : scene_(scene), vertices_(log.vertices()), style_(overlay_style(scene.theme)), log_(log) {}

  void paint(const StepStory& story) {
    if (story.located) {
      walk(story.located->walk);
      located(*story.located);
    }
    for (const StepStory::Cavity& c : story.cavities)
      faces("cavity", "cavity: the triangles whose circumcircle holds the point", style_.cavity, c.removed, true);
    if (story.removed) faces("star", "its star when the step began", style_.star, story.removed->star);
    if (story.lepp) lepp_faces(*story.lepp);
    for (const StepStory::Cavity& c : story.cavities) {
      faces("new_fan", "the new fan", style_.new_fan, c.fan);
      cavity_boundary(c);
    }
    if (story.selected) bad_triangle(*story.selected);
    failed_criteria(story.failed);
    if (story.lepp) terminal_edge(*story.lepp);
    if (story.in_step && story.kind == replay::StepKind::recover_segment) recovered_segment(story.subject);
    bisections(story);
    flips(story.flips);
    // A terrain's bad triangle is bad by its error: its circumcircle explains nothing.
    if (story.selected && story.selected->strategy < replay::kFirstSampleChoice) circumcircle(*story.selected);
    if (story.encroached) encroachment(*story.encroached);
    points(story);
  }

 private:
  bool finite(VertexId v) const { return v < vertices_.size() && vertices_[v].event != kNone; }
  const Point& at(VertexId v) const { return vertices_[v].point; }
  template <class Ids>
  bool all_finite(const Ids& ids) const {
    for (const VertexId v : ids)
      if (!finite(v)) return false;
    return true;
  }
  std::array<Point, 3> corners(const Triple& t) const { return {at(t[0]), at(t[1]), at(t[2])}; }

  Shape& add(ShapeKind kind, std::string role, std::string label, Rgba color, float width) {
    Shape& s = scene_.shapes.emplace_back();
    s.layer = Layer::overlay;
    s.kind = kind;
    s.role = std::move(role);
    s.label = std::move(label);
    s.color = color;
    s.width_px = width;
    return s;
  }
  // Shapes left empty (a face at infinity, an edge to it) are taken out again.
  void drop_if_empty() {
    if (!scene_.shapes.empty() && scene_.shapes.back().points.empty()) scene_.shapes.pop_back();
  }
  void label(const Point& p, std::string text, float dx = 10.0f, float dy = -10.0f) {
    scene_.labels.push_back({p, std::move(text), style_.label, px::label, dx, dy});
  }
  // Labels are placed by their left end on the baseline: a short one is centred on p by an
  // estimate of its width (digits are about 0.55 em wide).
  void centred_label(const Point& p, std::string text) {
    const float width = 0.55f * px::label * static_cast<float>(text.size());
    label(p, std::move(text), -0.5f * width, 0.35f * px::label);
  }
  void line(Shape& s, const Point& a, const Point& b) { s.points.insert(s.points.end(), {a, b}); }

  // The circle through a, b, c (center, radius), or none: when they are collinear, or so
  // nearly that its radius passes kFlatRadius times their longest side, where `chord` gets
  // the straight line through them instead, across the run's extent. Within any picture the
  // two then differ by less than the triangle's size in a view a thousand times as wide; and
  // a ring that big, drawn in floats, filled a block of the canvas (a flip of a triangle
  // 1e-15 from flat, in a lepp-midpoint run shown side by side).
  std::optional<std::pair<Point, double>> circle_through(const Point& a, const Point& b, const Point& c,
                                                         std::vector<Point>& chord) {
    static constexpr double kFlatRadius = 1e6;
    const Point center = quality::circumcenter(a, b, c);
    const double radius = std::sqrt(quality::squared_distance(center, a));
    // The two farthest apart of the three: the chord's ends.
    std::array<Point, 2> ends{a, b};
    for (const auto& [p, q] : {std::pair{b, c}, std::pair{a, c}})
      if (quality::squared_distance(p, q) > quality::squared_distance(ends[0], ends[1])) ends = {p, q};
    const double longest = std::sqrt(quality::squared_distance(ends[0], ends[1]));
    if (std::isfinite(center.x) && std::isfinite(center.y) && radius <= kFlatRadius * longest)
      return std::pair{center, radius};
    if (longest > 0.0 && std::isfinite(longest)) clip_to_extent(ends[0], ends[1], chord);
    return std::nullopt;
  }
  // The line through p and q, cut to the run's vertices' box (grown by a tenth, as a circle's
  // is in scene_bounds): its two ends appended to `out`.
  void clip_to_extent(const Point& p, const Point& q, std::vector<Point>& out) {
    if (!extent_) {
      BBox box;
      for (const replay::VertexInfo& v : vertices_)
        if (v.event != kNone && std::isfinite(v.point.x) && std::isfinite(v.point.y)) box.add(v.point);
      const double grow = box.empty() ? 0.0 : 0.1 * std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
      extent_ = BBox{{box.lo.x - grow, box.lo.y - grow}, {box.hi.x + grow, box.hi.y + grow}};
    }
    // Liang-Barsky: the parameters t of p + t (q - p) inside the box.
    const double dx = q.x - p.x, dy = q.y - p.y;
    double t0 = -std::numeric_limits<double>::infinity(), t1 = std::numeric_limits<double>::infinity();
    for (const auto& [delta, low, high, at] : {std::tuple{dx, extent_->lo.x, extent_->hi.x, p.x},
                                               std::tuple{dy, extent_->lo.y, extent_->hi.y, p.y}}) {
      if (delta == 0.0) {
        if (at < low || at > high) return;
        continue;
      }
      const double ta = (low - at) / delta, tb = (high - at) / delta;
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    }
    if (!(t0 < t1)) return;
    out.push_back({p.x + t0 * dx, p.y + t0 * dy});
    out.push_back({p.x + t1 * dx, p.y + t1 * dy});
  }
  // Markers: `paint.stroke` outlines them, `paint.fill` fills them (alpha 0: hollow).
  Shape& markers(std::string role, std::string text, const Paint& paint, Marker kind, float size,
                 std::span<const Point> at_points) {
    Shape& s = add(ShapeKind::markers, std::move(role), std::move(text), paint.stroke, 2.0f);
    s.fill = paint.fill;
    s.marker = kind;
    s.marker_px = size;
    s.points.assign(at_points.begin(), at_points.end());
    return s;
  }
  Shape& marker(std::string role, std::string text, const Paint& paint, Marker kind, float size, const Point& p) {
    return markers(std::move(role), std::move(text), paint, kind, size, std::span<const Point>(&p, 1));
  }

  // Finite faces as translucent triangles with an outline (dashed: faces no longer there;
  // width 0: none).
  template <class Faces>
  void faces(const char* role, const std::string& text, const Paint& paint, const Faces& list, bool dashed = false,
             float outline = px::outline) {
    std::vector<Point> points;
    for (const auto& f : list)
      if (all_finite(vertex_ids(f))) {
        const auto c = corners(vertex_ids(f));
        points.insert(points.end(), c.begin(), c.end());
      }
    if (points.empty()) return;
    const std::size_t fill = scene_.shapes.size();
    add(ShapeKind::triangles, role, text, paint.fill, 0.0f).points = std::move(points);
    if (outline <= 0.0f) return;
    Shape& edges = add(ShapeKind::lines, role, text, paint.stroke, outline);
    edges.dashed = dashed;
    const std::vector<Point>& c = scene_.shapes[fill].points;  // after the last add: stays put
    for (std::size_t i = 0; i < c.size(); i += 3)
      for (int k = 0; k < 3; ++k) line(edges, c[i + k], c[i + (k + 1) % 3]);
  }
  static const Triple& vertex_ids(const Triple& t) { return t; }
  static const Triple& vertex_ids(const FaceRecord& r) { return r.v; }

  void walk(const std::vector<Triple>& visited) {
    if (visited.empty()) return;
    const std::string text =
        "point location walk (" + std::to_string(visited.size()) + (visited.size() == 1 ? " face)" : " faces)");
    // No outlines: the path through the faces' centroids tells the order.
    faces("walk", text, style_.walk, visited, false, 0.0f);
    Shape& path = add(ShapeKind::lines, "walk", text, style_.walk.stroke, 2.0f);
    bool have = false;
    Point previous;
    for (const Triple& f : visited) {
      if (!all_finite(f)) continue;
      const Point c = centroid(corners(f));
      if (have) line(path, previous, c);
      previous = c;
      have = true;
    }
    drop_if_empty();
  }

  void located(const StepStory::Located& l) {
    const char* where = l.result == replay::LocateResult::on_edge     ? "located: on an edge of this triangle"
                        : l.result == replay::LocateResult::on_vertex ? "located: on a vertex of this triangle"
                                                                      : "located triangle";
    if (l.face.dead()) return;
    if (!l.face.ghost()) return faces("located_triangle", where, style_.located, std::array<FaceRecord, 1>{l.face});
    // A face at infinity: the point lies outside the hull, beyond this hull edge.
    Shape& edge = add(ShapeKind::lines, "located_triangle", "located: outside the hull, beyond this edge",
                      style_.located.stroke, px::thick);
    for (int i = 0; i < 3; ++i)
      if (finite(l.face.v[i]) && finite(l.face.v[(i + 1) % 3])) line(edge, at(l.face.v[i]), at(l.face.v[(i + 1) % 3]));
    drop_if_empty();
  }

  void lepp_faces(const StepStory::Lepp& lepp) {
    faces("lepp_path", "Lepp path (" + std::to_string(lepp.path.size()) + " triangles)", style_.lepp, lepp.path);
    std::vector<Triple> terminal;
    for (std::size_t i = 0; i < lepp.path.size(); ++i) {
      const Triple& t = lepp.path[i];
      if (all_finite(t)) centred_label(centroid(corners(t)), std::to_string(i + 1));
      const bool has_a = std::find(t.begin(), t.end(), lepp.a) != t.end();
      const bool has_b = std::find(t.begin(), t.end(), lepp.b) != t.end();
      if (has_a && has_b) terminal.push_back(t);
    }
    faces("terminal_triangles", "terminal triangles", style_.terminal_triangles, terminal);
  }

  void terminal_edge(const StepStory::Lepp& lepp) {
    if (!finite(lepp.a) || !finite(lepp.b)) return;
    Shape& s = add(ShapeKind::lines, "terminal_edge", "terminal edge (the longest, shared by its triangles)",
                   style_.terminal_edge.stroke, px::thick);
    line(s, at(lepp.a), at(lepp.b));
  }

  void cavity_boundary(const StepStory::Cavity& c) {
    Shape& s = add(ShapeKind::lines, "cavity_boundary", "cavity boundary", style_.cavity_boundary.stroke, 3.5f);
    for (const FaceRecord& f : c.fan)
      for (int i = 0; i < 3; ++i)
        if (f.v[i] == c.vertex) {
          const VertexId p = f.v[(i + 1) % 3], q = f.v[(i + 2) % 3];
          if (finite(p) && finite(q)) line(s, at(p), at(q));
        }
    drop_if_empty();
  }

  void bad_triangle(const StepStory::Selected& sel) {
    if (!all_finite(sel.bad)) return;
    const auto c = corners(sel.bad);
    const double angle = quality::shape(c[0], c[1], c[2]).min_angle_deg();
    const bool terrain = sel.strategy >= replay::kFirstSampleChoice;
    faces("bad_triangle",
          terrain ? std::string("worst triangle (largest vertical error)")
                  : "bad triangle (smallest angle " + degrees_text(angle) + ")",
          style_.bad,
          std::array<Triple, 1>{sel.bad}, false, 3.0f);
  }

  void circumcircle(const StepStory::Selected& sel) {
    if (!all_finite(sel.bad)) return;
    const auto c = corners(sel.bad);
    std::vector<Point> chord;
    const auto circle = circle_through(c[0], c[1], c[2], chord);
    Shape& s = add(circle ? ShapeKind::circles : ShapeKind::lines, "circumcircle",
                   circle ? "circumcircle of the bad triangle" : "circumcircle of the bad triangle (nearly a straight line)",
                   style_.circumcircle.stroke, 2.0f);
    s.dashed = true;
    if (circle) {
      s.points.push_back(circle->first);
      s.radii.push_back(circle->second);
    } else {
      s.points = std::move(chord);
    }
    drop_if_empty();
  }

  void failed_criteria(const std::vector<StepStory::Criterion>& failed) {
    if (failed.empty()) return;
    std::vector<Triple> tris;
    for (const StepStory::Criterion& f : failed) tris.push_back(f.triangle);
    faces("failed_criterion", "failed criterion test", style_.failed, tris);
    // Below the triangle's lowest corner: the names of the points chosen go above them.
    for (const StepStory::Criterion& f : failed) {
      if (!all_finite(f.triangle)) continue;
      const auto c = corners(f.triangle);
      const Point lowest =
          *std::min_element(c.begin(), c.end(), [](const Point& p, const Point& q) { return p.y < q.y; });
      label(lowest, criterion_text(f, log_), -20.0f, 2.0f * px::label);
    }
  }

  // The segment a recovery step makes an edge of the mesh (by flips, or split where other
  // segments cross it).
  void recovered_segment(const std::array<VertexId, 2>& ends) {
    if (!finite(ends[0]) || !finite(ends[1])) return;
    Shape& s = add(ShapeKind::lines, "recovered_segment", "segment being recovered", style_.recovered.stroke, px::thick);
    line(s, at(ends[0]), at(ends[1]));
  }

  void bisections(const StepStory& story) {
    for (const StepStory::Split& s : story.splits) {
      if (s.reason != replay::SplitReason::bisection || !finite(s.a) || !finite(s.b)) continue;
      Shape& old_edge = add(ShapeKind::lines, "bisection", "bisected edge", style_.bisected.stroke, px::thick);
      line(old_edge, at(s.a), at(s.b));
      // From the midpoint to the apexes of the bisected triangles (each edge is in two of
      // the new faces: drawn once).
      std::vector<VertexId> apexes;
      for (const FaceRecord& f : s.made)
        for (const VertexId w : f.v)
          if (w != s.vertex && w != s.a && w != s.b && finite(w) &&
              std::find(apexes.begin(), apexes.end(), w) == apexes.end())
            apexes.push_back(w);
      if (apexes.empty() || !finite(s.vertex)) continue;
      Shape& fresh =
          add(ShapeKind::lines, "bisection", "new edges from its midpoint", style_.bisection_new.stroke, 3.0f);
      for (const VertexId w : apexes) line(fresh, at(s.vertex), at(w));
    }
  }

  // Every flip of the step, the latest emphasised and the earlier ones faded behind it;
  // a Delaunay flip with the circle of its in-circle test (through a, b, c; d inside).
  void flips(const std::vector<StepStory::Flip>& list) {
    if (list.empty()) return;
    const auto fade = [&](Rgba c) { return with_alpha(c, style_.faded_alpha); };
    const std::size_t latest = list.size() - 1;
    for (const bool emphasised : {false, true}) {
      const std::size_t begin = emphasised ? latest : 0, end = emphasised ? list.size() : latest;
      if (begin == end) continue;
      const std::string which = emphasised ? "" : " (earlier flips)";
      Shape& circle =
          add(ShapeKind::circles, "flip_circle", "in-circle test: d inside the circle through a, b, c" + which,
              emphasised ? style_.flip_circle.stroke : fade(style_.flip_circle.stroke), emphasised ? 2.0f : 1.0f);
      std::vector<Point> chords;  // the circles of nearly flat triangles, as lines
      for (std::size_t i = begin; i < end; ++i) {
        const auto& v = list[i].v;
        if (list[i].reason != replay::FlipReason::delaunay || !all_finite(std::array{v[0], v[1], v[2]})) continue;
        if (const auto c = circle_through(at(v[0]), at(v[1]), at(v[2]), chords)) {
          circle.points.push_back(c->first);
          circle.radii.push_back(c->second);
        }
      }
      const Rgba color = circle.color;
      const float width = circle.width_px;
      drop_if_empty();
      if (!chords.empty())
        add(ShapeKind::lines, "flip_circle", "in-circle test: d inside the circle through a, b, c (nearly a straight line)" + which,
            color, width)
            .points = std::move(chords);
      for (const bool after : {false, true}) {
        const Paint& paint = after ? style_.flip_after : style_.flip_before;
        Shape& s =
            add(ShapeKind::lines, after ? "flip_after" : "flip_before",
                (after ? "edge after the flip" : "edge flipped away") + which,
                emphasised ? paint.stroke : fade(paint.stroke), emphasised ? (after ? 3.0f : px::stroke) : px::thin);
        s.dashed = !after;
        for (std::size_t i = begin; i < end; ++i) {
          const VertexId p = list[i].v[after ? 2 : 0], q = list[i].v[after ? 3 : 1];
          if (finite(p) && finite(q)) line(s, at(p), at(q));
        }
        drop_if_empty();
      }
    }
  }

  void encroachment(const StepStory::Encroachment& e) {
    if (!finite(e.a) || !finite(e.b)) return;
    const Point a = at(e.a), b = at(e.b), m = midpoint(a, b);
    Shape& seg =
        add(ShapeKind::lines, "encroached_segment", "encroached subsegment", style_.encroached.stroke, px::thick);
    line(seg, a, b);
    if (const double angle = encroachment_angle(log_); angle > 90.0) {
      lens(a, b, angle);
    } else {
      Shape& c = add(ShapeKind::circles, "diametral_circle", "diametral circle", style_.diametral.stroke, 2.0f);
      c.dashed = true;
      c.points.push_back(m);
      c.radii.push_back(0.5 * std::sqrt(quality::squared_distance(a, b)));
    }
  }

  // Shewchuk's diametral lens: the points that see a-b at `angle` degrees or more (180 - 2
  // theta for the bound theta; 90 is the diametral circle), bounded by two arcs through a
  // and b whose circles are centred on the perpendicular bisector, each on the far side of
  // a-b (inscribed angle: radius |ab| / (2 sin angle), centre |cos angle| radii from a-b).
  void lens(const Point& a, const Point& b, double angle) {
    const double length = std::sqrt(quality::squared_distance(a, b));
    if (!(length > 0.0) || !(angle >= 90.0 && angle < 180.0)) return;
    const Point m = midpoint(a, b);
    const Point u{(b.x - a.x) / length, (b.y - a.y) / length}, n{-u.y, u.x};
    const double phi = angle * std::numbers::pi / 180.0;
    const double radius = length / (2.0 * std::sin(phi)), offset = -radius * std::cos(phi);
    char label[64];
    std::snprintf(label, sizeof label, "diametral lens (sees the segment at %g\u00B0)", angle);
    Shape& s = add(ShapeKind::lines, "diametral_lens", label, style_.diametral.stroke, 2.0f);
    s.dashed = true;
    std::vector<Point> outline;
    // Above a-b: the circle centred below, from a (psi = -(180 - angle) degrees) to b.
    for (const double side : {1.0, -1.0}) {
      const Point c{m.x - side * offset * n.x, m.y - side * offset * n.y};
      for (int i = 0; i <= kLensArcSegments; ++i) {
        const double psi = side * (-1.0 + 2.0 * i / kLensArcSegments) * (std::numbers::pi - phi);
        outline.push_back({c.x + radius * (std::sin(psi) * u.x + side * std::cos(psi) * n.x),
                           c.y + radius * (std::sin(psi) * u.y + side * std::cos(psi) * n.y)});
      }
    }
    // The arcs meet at a and b exactly.
    outline[0] = outline.back() = a;
    outline[kLensArcSegments] = outline[kLensArcSegments + 1] = b;
    for (std::size_t i = 0; i + 1 < outline.size(); ++i)
      if (!(outline[i] == outline[i + 1])) line(s, outline[i], outline[i + 1]);
  }

  void points(const StepStory& story) {
    if (story.selected) {
      // The refiner weighs its point against the circumcenter; when it takes the
      // circumcenter, the alternative is the off-center it did not take.
      const std::vector<Point>& others = story.selected->alternatives;
      if (!others.empty()) {
        // A terrain's alternative is the terminal point its sample was rounded from.
        const char* other = story.selected->strategy >= replay::kFirstSampleChoice ? "terminal point"
                            : story.selected->chose_circumcenter                  ? "off-center"
                                                                                  : "circumcenter";
        markers("alternative_points", std::string(other) + " (not chosen)", {style_.alternative.stroke, kHollow},
                Marker::ring, px::small_point, others);
        scene_.shapes.back().width_px = 2.5f;
        for (const Point& p : others) label(p, other, 10.0f, 16.0f);
      }
    }
    if (story.encroached) {
      const bool vertex = story.encroached->by != kNone;
      marker("encroaching_point", vertex ? "encroaching vertex" : "rejected point (it encroaches)",
             {style_.marker_outline, style_.encroacher.fill}, Marker::diamond, px::small_point,
             story.encroached->point);
      label(story.encroached->point, vertex ? "encroaches" : "rejected: encroaches");
    }
    if (story.removed && finite(story.removed->vertex)) {
      marker("removed_vertex", "removed vertex", {style_.removed.stroke, kHollow}, Marker::ring, 15.0f,
             at(story.removed->vertex));
      scene_.shapes.back().width_px = 3.0f;
      label(at(story.removed->vertex), "removed vertex " + log_.vertex_name(story.removed->vertex));
    }
    if (story.encroached && finite(story.encroached->split)) {
      const Point p = at(story.encroached->split), a = at(story.encroached->a), b = at(story.encroached->b);
      const bool middle = p == midpoint(a, b);
      marker("split_point", middle ? "split point: the midpoint" : "split point: on a concentric shell",
             {style_.marker_outline, style_.split.fill}, Marker::square, px::small_point, p);
      label(p, middle ? "midpoint" : "on a shell", 10.0f, 16.0f);
    }
    if (story.selected) {
      const std::string name = chosen_point_name(*story.selected, story.lepp);
      const bool inserted = std::any_of(story.inserted.begin(), story.inserted.end(),
                                        [&](VertexId v) { return finite(v) && at(v) == story.selected->chosen; });
      marker("selected_point", name + (inserted ? " (inserted)" : " (selected)"),
             {style_.marker_outline, style_.selected.fill}, Marker::disc, px::point, story.selected->chosen);
      label(story.selected->chosen, name);
      return;
    }
    // A Lepp bisection chooses no point but the terminal edge's midpoint: its new vertex.
    bool bisected = false;
    for (const StepStory::Split& s : story.splits)
      if (s.reason == replay::SplitReason::bisection && finite(s.vertex)) {
        marker("selected_point", "terminal-edge midpoint (inserted)", {style_.marker_outline, style_.selected.fill},
               Marker::disc, px::point, at(s.vertex));
        label(at(s.vertex), "midpoint");
        bisected = true;
      }
    if (bisected || story.encroached) return;
    // Otherwise (triangulation, segment recovery) the vertex the step inserts: the one being
    // located, then the ones inserted.
    std::vector<VertexId> fresh = story.inserted;
    if (story.located && std::find(fresh.begin(), fresh.end(), story.located->vertex) == fresh.end())
      fresh.insert(fresh.begin(), story.located->vertex);
    for (const VertexId v : fresh) {
      if (!finite(v)) continue;
      const bool in = std::find(story.inserted.begin(), story.inserted.end(), v) != story.inserted.end();
      marker("new_vertex", in ? "vertex inserted" : "vertex being located",
             {style_.marker_outline, style_.selected.fill}, Marker::disc, px::small_point, at(v));
      label(at(v), "vertex " + log_.vertex_name(v));  // its number in the output's .node
    }
  }

  Scene& scene_;
  const std::vector<replay::VertexInfo>& vertices_;
  const OverlayStyle& style_;
  const replay::LogReader& log_;
  std::optional<BBox> extent_;  // of the run's vertices, grown: made when a flat circle needs it
};

}  // namespace

void add_overlays(Scene& scene, const StepStory& story, const replay::LogReader& log) {
  OverlayPainter(scene, log).paint(story);
}

}  // namespace meshstep::scene::detail
