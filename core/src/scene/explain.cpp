// The explain panel's text, from the same story of the step as the overlays and the caption
// (step_story.hpp): each line names the vertices by their number in the output's .node
// (LogReader::vertex_name), as the caption, the overlays' labels and `meshstep log dump` do.
#include "meshstep/scene/explain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "meshstep/refine/quality.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "parts.hpp"
#include "surface/surface_geometry.hpp"

namespace meshstep::scene {

namespace {

using detail::StepStory;
using detail::Triple;
using replay::FlipReason;
using replay::SplitReason;

std::string point_text(const Point& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g)", p.x, p.y);
  return buf;
}

std::string degrees(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.1f\u00B0", v);
  return buf;
}


std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

class Explainer {
 public:
  Explainer(const StepStory& story, const replay::Replay& cursor) : story_(story), cursor_(cursor) {}

  Explanation write() {
    Explanation out;
    if (story_.position == 0) {
      out.heading = "before the run";
      out.lines.push_back(count(story_.step_count, "step", "steps") + " to come");
      return out;
    }
    if (!story_.in_step) {
      out.heading = "start";
      out.lines.push_back("the input is read; no step has begun");
      return out;
    }
    std::string kind = replay::name(story_.kind);
    std::replace(kind.begin(), kind.end(), '_', ' ');
    out.heading = "step " + std::to_string(replay::step_at(cursor_.log(), story_.position).step) + " of " + std::to_string(story_.step_count) +
                  " \u00B7 " + kind;
    lines_ = &out.lines;
    if (story_.next_triangle) add("the step is done; the next bad triangle's Lepp path is found:");
    located();
    bad_triangle();
    lepp();
    selection();
    encroachment();
    recovery();
    insertion();
    removal();
    carve();
    new_triangles();
    if (out.lines.empty()) add("nothing changed yet in this step");
    return out;
  }

 private:
  // Vertices by their number in the output's .node, as every text names them (log_reader.hpp).
  std::string vertex_name(VertexId v) const { return cursor_.log().vertex_name(v); }
  std::string edge_name(VertexId a, VertexId b) const { return vertex_name(a) + "-" + vertex_name(b); }
  std::string triangle_name(const Triple& t) const {
    return vertex_name(t[0]) + " " + vertex_name(t[1]) + " " + vertex_name(t[2]);
  }

  void add(std::string line) { lines_->push_back(std::move(line)); }

  const Point* point(VertexId v) const {
    const auto& vertices = cursor_.log().vertices();
    return v < vertices.size() ? &vertices[v].point : nullptr;
  }

  std::optional<quality::Shape> shape(const Triple& t) const {
    const Point *a = point(t[0]), *b = point(t[1]), *c = point(t[2]);
    if (!a || !b || !c) return std::nullopt;
    return quality::shape(*a, *b, *c);
  }

  void located() {
    if (!story_.located || story_.located->vertex == kNone) return;
    const auto& l = *story_.located;
    const char* where = l.result == replay::LocateResult::on_edge     ? "on an edge of"
                        : l.result == replay::LocateResult::on_vertex ? "on a vertex of"
                                                                      : "in";
    std::string line = "vertex " + vertex_name(l.vertex) + " located " + where + " triangle " +
                       triangle_name(l.face.v);
    if (!l.walk.empty()) line += " after a walk through " + count(l.walk.size(), "triangle", "triangles");
    add(line);
  }

  void bad_triangle() {
    // The failed tests name the triangle and how far it is off; the selection names it too
    // when the test itself is not in the log (format 2).
    // A terrain's triangle is not bad but the worst: the one farthest from the grid.
    for (const StepStory::Criterion& f : story_.failed)
      add((f.criterion == static_cast<std::uint8_t>(replay::Criterion::vertical_error) ? "worst triangle "
                                                                                        : "bad triangle ") +
          triangle_name(f.triangle) + ": " + detail::criterion_text(f, cursor_.log()));
    if (story_.failed.empty() && story_.selected) {
      const auto s = shape(story_.selected->bad);
      add("bad triangle " + triangle_name(story_.selected->bad) +
          (s ? ": smallest angle " + degrees(s->min_angle_deg()) : ""));
    }
  }

  void lepp() {
    if (!story_.lepp) return;
    const auto& l = *story_.lepp;
    std::string line = "Lepp path of " + count(l.path.size(), "triangle", "triangles") + ", each across its longest edge";
    line += ", to terminal edge " + edge_name(l.a, l.b);
    line += l.terminal_triangles == 1 ? " (on the boundary: one terminal triangle)"
                                      : " (shared by the two terminal triangles)";
    add(line);
  }

  void selection() {
    if (!story_.selected) return;
    const auto& s = *story_.selected;
    if (s.strategy >= replay::kFirstSampleChoice) return sample_choice(s);
    std::string line = "chosen: the " + detail::chosen_point_name(s, story_.lepp) + " " + point_text(s.chosen);
    if (!s.alternatives.empty()) {
      line += "; also considered:";
      for (const Point& p : s.alternatives) {
        // The alternative of a non-circumcenter choice is the circumcenter; when the
        // circumcenter won, the alternative is the point the strategy would have taken.
        const char* what = s.chose_circumcenter ? "the off-center" : "the circumcenter";
        line += std::string(" ") + what + " " + point_text(p);
      }
    }
    add(line);
    if (s.chose_circumcenter && !s.alternatives.empty())
      add("the circumcenter lies nearer the shortest edge than the off-center would: it is taken (Üngör)");
    else if (!s.chose_circumcenter && s.strategy == static_cast<std::uint8_t>(Selection::offcenter))
      add("the off-center: on the shortest edge's bisector, where the new triangle on that edge just meets the "
          "angle bound, nearer than the circumcenter (Üngör)");
  }

  // A terrain's step: which grid sample goes in, and why there.
  void sample_choice(const StepStory::Selected& s) {
    std::string line = "next sample: the " + detail::chosen_point_name(s, story_.lepp) + " " + point_text(s.chosen);
    if (const std::optional<double> z = height_of_sample(s.chosen)) {
      char height[48];
      std::snprintf(height, sizeof height, ", height %.6g", *z);
      line += height;
    }
    add(line);
    switch (static_cast<replay::SampleChoice>(s.strategy)) {
      case replay::SampleChoice::worst_sample:
        add("greedy insertion (Garland-Heckbert): the sample farthest from the surface goes in");
        break;
      case replay::SampleChoice::terminal_worst:
        add("a terminal triangle still misses the bound: its worst sample goes in, where the split keeps the "
            "shapes");
        break;
      case replay::SampleChoice::terminal_point:
        if (!s.alternatives.empty())
          add("the terminal point " + point_text(s.alternatives[0]) +
              " rounded to the nearest grid sample (the terminal triangles are within the bound)");
        break;
      case replay::SampleChoice::own_worst:
        add("the sample nearest the terminal point is taken or has no data: the bad triangle's own worst instead");
        break;
      default: break;
    }
  }
  // The height the run gave the vertex at p, once it is in.
  std::optional<double> height_of_sample(const Point& p) const {
    if (!cursor_.log().has_elevation()) return std::nullopt;
    for (const VertexId v : story_.inserted)
      if (v < cursor_.log().vertices().size() && cursor_.log().vertices()[v].point == p)
        return cursor_.log().vertices()[v].z;
    return std::nullopt;
  }

  void encroachment() {
    if (!story_.encroached) return;
    const auto& e = *story_.encroached;
    if (e.by == kNone) {
      const double angle = detail::encroachment_angle(cursor_.log());
      char inside[96] = "it lies inside the segment's diametral circle";
      if (angle > 90.0)
        std::snprintf(inside, sizeof inside, "it sees the segment at %g\u00B0 or more: inside its diametral lens", angle);
      add("rejected: the point " + point_text(e.point) + " encroaches segment " + edge_name(e.a, e.b) + " (" + inside +
          "), so the segment is split instead");
    } else {
      add("segment " + edge_name(e.a, e.b) + " is encroached by vertex " + vertex_name(e.by) + " " +
          point_text(e.point));
    }
    if (e.split == kNone) return;
    const Point *a = point(e.a), *b = point(e.b), *p = point(e.split);
    if (!a || !b || !p) return;
    const bool middle = *p == Point{0.5 * (a->x + b->x), 0.5 * (a->y + b->y)};
    add("split by vertex " + vertex_name(e.split) + " " + point_text(*p) +
        (middle ? ": at its midpoint"
                : ": on a concentric shell round the end where another segment meets it (a power-of-two "
                  "distance), so that splits near a small input angle cannot cascade"));
  }

  void recovery() {
    if (story_.kind != replay::StepKind::recover_segment) return;
    std::size_t flips = 0, crossings = 0;
    for (const StepStory::Flip& f : story_.flips) flips += f.reason == FlipReason::segment_recovery;
    for (const StepStory::Split& s : story_.splits) crossings += s.reason == SplitReason::crossing;
    const std::string segment = "segment " + edge_name(story_.subject[0], story_.subject[1]);
    if (crossings) add(segment + " crosses another segment: split at " + count(crossings, "crossing", "crossings"));
    if (flips) add(segment + " recovered by " + count(flips, "flip", "flips") + " of the edges crossing it");
    if (!flips && !crossings && story_.constrained) add(segment + " is already an edge of the triangulation");
    if (story_.constrained) add("the edge is marked constrained: no flip will remove it");
  }

  void insertion() {
    for (const StepStory::Split& s : story_.splits) {
      if (s.reason == SplitReason::bisection)
        add("edge " + edge_name(s.a, s.b) + " bisected at its midpoint (vertex " + vertex_name(s.vertex) + ")");
      else if (s.reason == SplitReason::insert && s.a != kNone)
        add("vertex " + vertex_name(s.vertex) + " splits edge " + edge_name(s.a, s.b));
    }
    for (const StepStory::Cavity& c : story_.cavities)
      add("went in by a Bowyer-Watson cavity: " + count(c.removed.size(), "triangle", "triangles") +
          " whose circumcircles hold vertex " + vertex_name(c.vertex) + " removed, a fan of " +
          count(c.fan.size(), "triangle", "triangles") + " put in");
    std::vector<std::string> delaunay;
    for (const StepStory::Flip& f : story_.flips)
      if (f.reason == FlipReason::delaunay) delaunay.push_back(edge_name(f.v[0], f.v[1]) + " \u2192 " + edge_name(f.v[2], f.v[3]));
    if (delaunay.empty()) {
      if (!story_.inserted.empty() && story_.cavities.empty()) add("no flip needed: the new triangles are Delaunay");
      return;
    }
    std::string line = count(delaunay.size(), "Lawson flip", "Lawson flips") + " (each edge failed the in-circle test): ";
    constexpr std::size_t kShown = 8;
    for (std::size_t i = 0; i < std::min(delaunay.size(), kShown); ++i) line += (i ? ", " : "") + delaunay[i];
    if (delaunay.size() > kShown) line += ", and " + std::to_string(delaunay.size() - kShown) + " more";
    add(line);
  }

  void removal() {
    if (story_.kind != replay::StepKind::remove_vertex) return;
    std::size_t flips = 0;
    for (const StepStory::Flip& f : story_.flips) flips += f.reason == FlipReason::vertex_removal;
    const std::string v = vertex_name(story_.subject[0]);
    if (story_.removed)
      add("vertex " + v + " removed: its star of " + count(story_.removed->star.size(), "triangle", "triangles") +
          " flipped down to " + count(flips, "flip", "flips") + " and retriangulated");
    else
      add("removing vertex " + v + ": " + count(flips, "flip", "flips") + " so far");
  }

  void carve() {
    static constexpr const char* kKinds[] = {"ghost (outside the convex hull)", "in a hole", "outside the domain"};
    for (std::size_t i = 0; i < 3; ++i)
      if (story_.faces_removed[i]) add("removed " + count(story_.faces_removed[i], "triangle", "triangles") + " " + kKinds[i]);
  }

  // The triangles the step made that are still there at the cursor.
  void new_triangles() {
    double smallest = INFINITY, largest = 0.0;
    std::size_t n = 0;
    const auto& slots = cursor_.slots();
    const bool terrain = cursor_.log().has_elevation();
    for (const FaceId s : story_.written) {
      if (s >= slots.size() || slots[s].dead() || slots[s].ghost()) continue;
      const auto q = terrain ? angles_3d(slots[s].v) : planar_angles(slots[s].v);
      if (!q) continue;
      ++n;
      smallest = std::min(smallest, (*q)[0]);
      largest = std::max(largest, (*q)[1]);
    }
    if (n == 0) return;
    add("new triangles: " + std::to_string(n) + (terrain ? ", 3D angles from " : ", angles from ") +
        degrees(smallest) + " to " + degrees(largest));
  }

  std::optional<std::array<double, 2>> planar_angles(const Triple& t) const {
    const auto q = shape(t);
    if (!q) return std::nullopt;
    return std::array<double, 2>{q->min_angle_deg(), q->max_angle_deg()};
  }
  // A terrain triangle's smallest and largest angle in 3D (its corners at their heights),
  // in degrees, measured as the surface code measures them.
  std::optional<std::array<double, 2>> angles_3d(const Triple& t) const {
    const auto& vertices = cursor_.log().vertices();
    std::array<Point3, 3> p{};
    for (int k = 0; k < 3; ++k) {
      if (t[k] >= vertices.size()) return std::nullopt;
      const replay::VertexInfo& v = vertices[t[k]];
      p[k] = {v.point.x, v.point.y, v.z};
    }
    if (!(surface::detail::area(p[0], p[1], p[2]) > 0.0)) return std::nullopt;
    const std::array<double, 3> angles = {surface::detail::angle_deg(p[0], p[1], p[2]),
                                          surface::detail::angle_deg(p[1], p[2], p[0]),
                                          surface::detail::angle_deg(p[2], p[0], p[1])};
    return std::array<double, 2>{*std::min_element(angles.begin(), angles.end()),
                                 *std::max_element(angles.begin(), angles.end())};
  }

  const StepStory& story_;
  const replay::Replay& cursor_;
  std::vector<std::string>* lines_ = nullptr;
};

}  // namespace

Explanation explain_step(const replay::Replay& cursor) {
  const StepStory story = detail::read_step(cursor);
  return Explainer(story, cursor).write();
}

}  // namespace meshstep::scene
