// Scenes of recorded runs: refinements of plate.poly recorded in process, each moment's
// scene checked exactly against the log and against geometry computed here on its own:
// the bad triangle and its circumcircle, the faces the step made, flips and the circles of
// their in-circle tests, cavities, Lepp paths, encroached subsegments with their circle or
// lens, removed vertices with their star, failed criteria, walks, ages and captions.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <tuple>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/explain.hpp"
#include "temp_dir.hpp"

namespace meshstep::scene {
namespace {

using replay::Event;
using replay::EventType;
using replay::StepKind;
using Triangle = std::array<Point, 3>;

std::string plate() { return std::string(MESHSTEP_ASSETS) + "/examples/plate.poly"; }

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A refinement of plate.poly recorded into DIR/NAME, its header naming the parameters as
// `meshstep refine --record` does (the scene reads min_angle, max_area and encroachment).
std::string record(const testing::TempDir& dir, const std::string& name, const std::string& algorithm,
                   const std::function<void(RefineOptions&)>& adjust) {
  const Pslg in = io::read_poly(plate());
  RefineOptions o = options_for(*find_algorithm(algorithm));
  adjust(o);
  replay::LogHeader h;
  h.input = plate();
  h.algorithm = algorithm;
  h.parameters = "min_angle=" + number(o.criteria.min_angle_deg) + " max_area=" + number(o.criteria.max_area) +
                 " encroachment=" + (o.encroachment == Encroachment::lens ? "lens" : "circle") +
                 " lens_angle=" + number(lens_angle_deg(o.criteria)) +
                 " input_vertices=" + std::to_string(in.points.size()) +
                 " first_index=" + std::to_string(in.first_index);
  h.insertion = to_string(o.triangulate.insertion);
  replay::describe_input(h, in);  // segments and holes, as `meshstep refine --record` writes them
  const std::string path = dir.file(name);
  replay::LogWriter writer(path, h);
  o.triangulate.record = &writer;
  refine(in, o);
  writer.finish();
  return path;
}

std::function<void(RefineOptions&)> min_angle(double deg) {
  return [deg](RefineOptions& o) { o.criteria.min_angle_deg = deg; };
}

// One log per kind of run, recorded once for all the tests.
class SceneReplay : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir("meshstep_scene_");
    circumcenter_ = record(*dir_, "circumcenter.mslog", "circumcenter", [](RefineOptions& o) {
      o.criteria.min_angle_deg = 30.0;
      o.encroachment = Encroachment::circle;  // the diametral circles' log (lens_ has the lens)
    });
    offcenter_ = record(*dir_, "offcenter.mslog", "offcenter", min_angle(30.0));
    cavity_ = record(*dir_, "cavity.mslog", "circumcenter", [](RefineOptions& o) {
      o.criteria.min_angle_deg = 30.0;
      o.triangulate.insertion = Insertion::cavity;
    });
    lepp_ = record(*dir_, "lepp.mslog", "lepp-centroid", min_angle(30.0));
    bisection_ =
        record(*dir_, "bisection.mslog", "lepp-bisection", [](RefineOptions& o) { o.criteria.max_area = 0.5; });
    improve_ = record(*dir_, "improve.mslog", "improve", [](RefineOptions& o) {
      o.criteria.min_angle_deg = 30.0;
      // Worst first, with circles: the refinement that leaves vertices to remove on plate.poly.
      o.encroachment = Encroachment::circle;
      o.order = RefineOrder::worst_first;
    });
    lens_ = record(*dir_, "lens.mslog", "circumcenter", [](RefineOptions& o) {
      o.criteria.min_angle_deg = 30.0;
      o.encroachment = Encroachment::lens;
    });
    lens25_ = record(*dir_, "lens25.mslog", "circumcenter", [](RefineOptions& o) {
      o.criteria.min_angle_deg = 25.0;
      o.encroachment = Encroachment::lens;
    });
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }

  static inline testing::TempDir* dir_ = nullptr;
  static inline std::string circumcenter_, offcenter_, cavity_, lepp_, bisection_, improve_, lens_, lens25_;
};

// --- Helpers ---------------------------------------------------------------------------

const Point& at(const replay::LogReader& log, VertexId v) { return log.vertices().at(v).point; }
bool finite(const replay::LogReader& log, VertexId v) {
  return v < log.vertices().size() && log.vertices()[v].event != kNone;
}

Triangle corners(const replay::LogReader& log, std::span<const VertexId> v) {
  return {at(log, v[0]), at(log, v[1]), at(log, v[2])};
}

// The triangles of a triangles shape, three points each.
std::vector<Triangle> triangles_of(const Shape& s) {
  EXPECT_EQ(s.kind, ShapeKind::triangles) << s.role;
  std::vector<Triangle> out;
  for (std::size_t i = 0; i + 3 <= s.points.size(); i += 3)
    out.push_back({s.points[i], s.points[i + 1], s.points[i + 2]});
  return out;
}

// The first triangles shape of a role (its fill; the outline follows it).
const Shape* faces_of(const Scene& s, const std::string& role) {
  for (const Shape* shape : s.find_all(role))
    if (shape->kind == ShapeKind::triangles) return shape;
  return nullptr;
}

// Orientation kept, rotated to start at the lexicographically smallest corner: equal for
// the same triangle however a face record lists it.
Triangle canonical(Triangle t) {
  const auto lowest =
      std::min_element(t.begin(), t.end(), [](const Point& a, const Point& b) { return lex_less(a, b); });
  std::rotate(t.begin(), lowest, t.end());
  return t;
}
std::vector<Triangle> canonical_set(std::vector<Triangle> ts) {
  for (Triangle& t : ts) t = canonical(t);
  std::sort(ts.begin(), ts.end(), [](const Triangle& a, const Triangle& b) {
    for (int i = 0; i < 3; ++i) {
      if (lex_less(a[i], b[i])) return true;
      if (lex_less(b[i], a[i])) return false;
    }
    return false;
  });
  return ts;
}

double distance(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The circumcenter by intersecting two perpendicular bisectors, in long double: computed
// apart from the scene's own formula.
Point circumcenter_by_bisectors(const Point& a, const Point& b, const Point& c) {
  using L = long double;
  // (p - m_ab) . (b - a) = 0 and (p - m_ac) . (c - a) = 0.
  const L a1 = L(b.x) - a.x, b1 = L(b.y) - a.y, c1 = (L(b.x) * b.x - L(a.x) * a.x + L(b.y) * b.y - L(a.y) * a.y) / 2;
  const L a2 = L(c.x) - a.x, b2 = L(c.y) - a.y, c2 = (L(c.x) * c.x - L(a.x) * a.x + L(c.y) * c.y - L(a.y) * a.y) / 2;
  const L det = a1 * b2 - a2 * b1;
  return {double((c1 * b2 - c2 * b1) / det), double((a1 * c2 - a2 * c1) / det)};
}

StepKind kind_of(const replay::LogReader& log, std::uint64_t k) {
  return static_cast<StepKind>(log.event(log.step_start(k)).code);
}

// The events of step k, copied out of the reader's spans (ids and type only).
struct Brief {
  std::uint64_t index;
  EventType type;
  std::uint8_t code;
  std::array<std::uint32_t, 4> ids;
  Point point;
};
std::vector<Brief> events_of_step(const replay::LogReader& log, std::uint64_t k) {
  std::vector<Brief> out;
  for (std::uint64_t e = log.step_start(k); e < log.step_start(k + 1); ++e) {
    const Event ev = log.event(e);
    out.push_back({e, ev.type, ev.code, ev.ids, ev.point});
  }
  return out;
}

Scene scene_at(replay::Replay& cursor, std::uint64_t position, SceneOptions options = {}) {
  cursor.seek_event(position);
  return build_scene(cursor, options);
}

// --- The mesh of the moment ------------------------------------------------------------

std::set<std::pair<Point, Point>, bool (*)(const std::pair<Point, Point>&, const std::pair<Point, Point>&)> edge_set() {
  return std::set<std::pair<Point, Point>, bool (*)(const std::pair<Point, Point>&, const std::pair<Point, Point>&)>(
      [](const std::pair<Point, Point>& x, const std::pair<Point, Point>& y) {
        if (lex_less(x.first, y.first)) return true;
        if (lex_less(y.first, x.first)) return false;
        return lex_less(x.second, y.second);
      });
}
std::pair<Point, Point> ordered(const Point& a, const Point& b) {
  return lex_less(a, b) ? std::pair{a, b} : std::pair{b, a};
}

std::vector<Point> sorted_points(std::vector<Point> p) {
  std::sort(p.begin(), p.end(), lex_less);
  return p;
}

// At every position: the scene's mesh is the cursor's (Replay::mesh(), triangle by
// triangle in the same order, point for point; its points are numbered by vertex id), its
// i-th triangle is the i-th live face slot that is not a ghost face, its segments are the
// constrained edges, its markers the vertices present; every highlighted triangle is one of
// the slots written by the step so far. Before the first triangle (step 0 and the first
// step's vertices) the mesh has nothing to show and the scene shows the input instead: all
// of its vertices and all of its segments, whichever the preamble has introduced so far.
TEST_F(SceneReplay, MeshIsTheCursorsAndTrianglesFollowSlotOrder) {
  const replay::LogReader log(circumcenter_);
  replay::Replay cursor(log);
  const Pslg in = io::read_poly(plate());
  std::size_t before_first_triangle = 0;
  for (std::uint64_t p = 0; p <= log.event_count(); ++p) {
    const Scene s = scene_at(cursor, p);
    const TriMesh m = cursor.mesh();
    ASSERT_EQ(s.mesh.triangles.size(), m.triangles.size()) << "position " << p;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i)
        ASSERT_EQ(s.mesh.points[s.mesh.triangles[t][i]], m.points[m.triangles[t][i]]) << "position " << p;
    const bool input_shown = m.triangles.empty();
    before_first_triangle += input_shown;
    auto expected_segments = edge_set(), drawn_segments = edge_set();
    if (input_shown)
      for (const Segment& seg : in.segments) expected_segments.insert(ordered(in.points[seg.a], in.points[seg.b]));
    else
      for (const Segment& seg : m.segments) expected_segments.insert(ordered(m.points[seg.a], m.points[seg.b]));
    if (const Shape* seg = s.find("segments"))
      for (std::size_t i = 0; i + 1 < seg->points.size(); i += 2)
        drawn_segments.insert(ordered(seg->points[i], seg->points[i + 1]));
    EXPECT_EQ(drawn_segments, expected_segments) << "position " << p;
    const std::vector<Point> input = input_shown ? in.points
                                                 : std::vector<Point>(m.points.begin(), m.points.begin() + m.input_vertex_count),
                             steiner(m.points.begin() + m.input_vertex_count, m.points.end());
    const Shape *input_markers = s.find("input_vertices"), *steiner_markers = s.find("steiner_vertices");
    EXPECT_EQ(input_markers ? sorted_points(input_markers->points) : std::vector<Point>{}, sorted_points(input));
    EXPECT_EQ(steiner_markers ? sorted_points(steiner_markers->points) : std::vector<Point>{}, sorted_points(steiner));
    std::vector<FaceId> drawn;
    for (FaceId f = 0; f < cursor.slots().size(); ++f)
      if (!cursor.slots()[f].dead() && !cursor.slots()[f].ghost()) drawn.push_back(f);
    ASSERT_EQ(drawn.size(), s.mesh.triangles.size());
    for (std::size_t t = 0; t < drawn.size(); ++t)
      for (int i = 0; i < 3; ++i)
        ASSERT_EQ(s.mesh.points[s.mesh.triangles[t][i]], at(log, cursor.slots()[drawn[t]].v[i]))
            << "position " << p << ", triangle " << t;
    if (p == 0 || log.step_of_event(p - 1) == log.step_count()) {
      EXPECT_TRUE(s.highlighted.empty());
      continue;
    }
    std::set<FaceId> written;
    for (std::uint64_t e = log.step_start(log.step_of_event(p - 1)); e < p; ++e)
      for (const replay::SlotWrite& w : log.writes(e)) written.insert(w.slot);
    std::set<FaceId> expected;
    for (std::size_t t = 0; t < drawn.size(); ++t)
      if (written.count(drawn[t])) expected.insert(static_cast<FaceId>(t));
    EXPECT_EQ(std::set<FaceId>(s.highlighted.begin(), s.highlighted.end()), expected) << "position " << p;
    EXPECT_TRUE(std::is_sorted(s.highlighted.begin(), s.highlighted.end()));
    const Shape* changed = s.find("changed_faces");
    if (expected.empty()) {
      EXPECT_EQ(changed, nullptr);
    } else {
      ASSERT_NE(changed, nullptr);
      EXPECT_EQ(changed->layer, Layer::highlight);
      ASSERT_EQ(changed->points.size(), 3 * s.highlighted.size());
      for (std::size_t i = 0; i < s.highlighted.size(); ++i)
        for (int k = 0; k < 3; ++k)
          EXPECT_EQ(changed->points[3 * i + k], s.mesh.points[s.mesh.triangles[s.highlighted[i]][k]]);
    }
  }
  EXPECT_GE(before_first_triangle, 2u) << "the positions before the first triangle: step 0 and the first vertices";
}

// After a refinement step with flip insertion, the faces it made are exactly the faces
// round the new vertex.
TEST_F(SceneReplay, HighlightedFacesAreTheNewVertexsStar) {
  const replay::LogReader log(circumcenter_);
  replay::Replay cursor(log);
  std::size_t checked = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    if (kind_of(log, k) != StepKind::refine) continue;
    Point chosen;
    for (const Brief& e : events_of_step(log, k))
      if (e.type == EventType::point_selected) chosen = e.point;
    const Scene s = scene_at(cursor, log.step_start(k + 1));
    const TriMesh m = cursor.mesh();
    const auto v = std::find(m.points.begin(), m.points.end(), chosen);
    ASSERT_NE(v, m.points.end()) << "step " << k << ": the chosen point is not a vertex";
    const auto index = static_cast<std::uint32_t>(v - m.points.begin());
    std::vector<std::uint32_t> star;
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
      if (std::count(m.triangles[t].begin(), m.triangles[t].end(), index)) star.push_back(t);
    EXPECT_EQ(s.highlighted, star) << "step " << k;
    EXPECT_GE(star.size(), 3u);
    ++checked;
  }
  EXPECT_GT(checked, 10u);
}

// --- Refinement: the bad triangle, its circle, the point ----------------------------------

TEST_F(SceneReplay, BadTriangleCircumcircleAndChosenPoint) {
  for (const std::string* path : {&circumcenter_, &offcenter_}) {
    const replay::LogReader log(*path);
    replay::Replay cursor(log);
    std::size_t checked = 0;
    for (std::uint64_t k = 0; k < log.step_count(); ++k) {
      if (kind_of(log, k) != StepKind::refine) continue;
      std::array<VertexId, 3> bad{};
      Point chosen;
      std::vector<Point> alternatives;
      std::uint64_t selected_at = 0;
      for (std::uint64_t e = log.step_start(k); e < log.step_start(k + 1); ++e) {
        const Event ev = log.event(e);
        if (ev.type != EventType::point_selected) continue;
        bad = {ev.ids[0], ev.ids[1], ev.ids[2]};
        chosen = ev.point;
        alternatives.assign(ev.points.begin(), ev.points.end());
        selected_at = e;
      }
      // From the moment the point is selected to the end of the step.
      for (const std::uint64_t p : {selected_at + 1, log.step_start(k + 1)}) {
        const Scene s = scene_at(cursor, p);
        const Shape* tri = faces_of(s, "bad_triangle");
        ASSERT_NE(tri, nullptr) << "step " << k;
        EXPECT_EQ(tri->layer, Layer::overlay);
        ASSERT_EQ(triangles_of(*tri).size(), 1u);
        EXPECT_EQ(triangles_of(*tri)[0], corners(log, bad)) << "step " << k;
        const Shape* circle = s.find("circumcircle");
        ASSERT_NE(circle, nullptr);
        ASSERT_EQ(circle->kind, ShapeKind::circles);
        ASSERT_EQ(circle->points.size(), 1u);
        const Triangle c = corners(log, bad);
        const Point expected = circumcenter_by_bisectors(c[0], c[1], c[2]);
        const double r = distance(expected, c[0]);
        EXPECT_NEAR(circle->points[0].x, expected.x, 1e-9 * r);
        EXPECT_NEAR(circle->points[0].y, expected.y, 1e-9 * r);
        for (const Point& corner : c) EXPECT_NEAR(circle->radii[0], distance(expected, corner), 1e-9 * r);
        const Shape* point = s.find("selected_point");
        ASSERT_NE(point, nullptr);
        EXPECT_EQ(point->kind, ShapeKind::markers);
        EXPECT_EQ(point->points, std::vector<Point>{chosen});
        const Shape* others = s.find("alternative_points");
        if (alternatives.empty()) {
          EXPECT_EQ(others, nullptr);
        } else {
          ASSERT_NE(others, nullptr);
          EXPECT_EQ(others->points, alternatives);
        }
        if (path == &circumcenter_) {
          // Ruppert: the chosen point is the circumcenter, named so.
          EXPECT_NEAR(chosen.x, expected.x, 1e-9 * r);
          EXPECT_NEAR(chosen.y, expected.y, 1e-9 * r);
          EXPECT_NE(point->label.find("circumcenter"), std::string::npos) << point->label;
        } else {
          // Off-centers: the refiner records the point it did not take beside the one it
          // took, so one of the two is the circumcenter, and the label names the other.
          ASSERT_EQ(alternatives.size(), 1u) << "step " << k;
          const bool took_circumcenter = distance(chosen, expected) <= 1e-9 * r;
          const Point& circumcenter = took_circumcenter ? chosen : alternatives[0];
          EXPECT_NEAR(circumcenter.x, expected.x, 1e-9 * r) << "one of the two is the circumcenter";
          EXPECT_NEAR(circumcenter.y, expected.y, 1e-9 * r) << "one of the two is the circumcenter";
          EXPECT_NE(point->label.find(took_circumcenter ? "circumcenter" : "off-center"), std::string::npos)
              << point->label;
          EXPECT_NE(others->label.find(took_circumcenter ? "off-center" : "circumcenter"), std::string::npos)
              << others->label;
        }
      }
      ++checked;
    }
    EXPECT_GT(checked, 10u) << *path;
  }
}

// The refiner tests the bad triangle before choosing its point: the failed test is drawn on
// the triangle, labelled with the angle measured against the bound.
TEST_F(SceneReplay, FailedCriterionShowsTheMeasuredAngleAgainstTheBound) {
  const replay::LogReader log(circumcenter_);
  if (log.counts_by_type()[static_cast<std::size_t>(EventType::criterion_test)] == 0)
    GTEST_SKIP() << "this build records no criterion tests";
  replay::Replay cursor(log);
  std::size_t checked = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event ev = log.event(e);
    if (ev.type != EventType::criterion_test || (ev.code & replay::kCriterionPassed)) continue;
    if (static_cast<replay::Criterion>(ev.code) != replay::Criterion::min_angle) continue;
    const Triangle t = corners(log, ev.ids);
    const double angle = triangle_min_angle_deg(t[0], t[1], t[2]);
    const Scene s = scene_at(cursor, e + 1);
    const Shape* failed = faces_of(s, "failed_criterion");
    ASSERT_NE(failed, nullptr) << "event " << e;
    EXPECT_EQ(triangles_of(*failed), std::vector<Triangle>{t});
    const auto label = std::find_if(s.labels.begin(), s.labels.end(),
                                    [](const Label& l) { return l.text.find(" < 30\u00B0") != std::string::npos; });
    ASSERT_NE(label, s.labels.end()) << "event " << e;
    EXPECT_NEAR(std::strtod(label->text.c_str(), nullptr), angle, 0.05) << label->text;
    EXPECT_LT(angle, 30.0);
    ++checked;
  }
  EXPECT_GT(checked, 10u);
}

// --- Flips ----------------------------------------------------------------------------

// Every Delaunay flip of a step draws the circle of its in-circle test: through a, b and c,
// with d inside. The edges before and after are those of the event; the latest flip is
// drawn last and stronger.
TEST_F(SceneReplay, FlipCirclesPassThroughABCAndHoldD) {
  const replay::LogReader log(circumcenter_);
  replay::Replay cursor(log);
  std::size_t circles = 0, steps_with_several = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    std::vector<std::array<std::uint32_t, 4>> flips, delaunay;
    for (const Brief& e : events_of_step(log, k)) {
      if (e.type != EventType::flip) continue;
      flips.push_back(e.ids);
      if (e.code == static_cast<std::uint8_t>(replay::FlipReason::delaunay) && finite(log, e.ids[0]) &&
          finite(log, e.ids[1]) && finite(log, e.ids[2]))
        delaunay.push_back(e.ids);
    }
    const Scene s = scene_at(cursor, log.step_start(k + 1));
    std::vector<std::pair<Point, double>> drawn;
    for (const Shape* shape : s.find_all("flip_circle")) {
      ASSERT_EQ(shape->kind, ShapeKind::circles);
      ASSERT_EQ(shape->points.size(), shape->radii.size());
      for (std::size_t i = 0; i < shape->points.size(); ++i) drawn.push_back({shape->points[i], shape->radii[i]});
    }
    ASSERT_EQ(drawn.size(), delaunay.size()) << "step " << k;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      const auto [center, r] = drawn[i];
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(distance(center, at(log, delaunay[i][j])), r, 1e-9 * r) << "step " << k << ", flip " << i;
      // Inside, or on it: cocircular points (the plate has them) flip by symbolic perturbation.
      if (finite(log, delaunay[i][3])) {
        EXPECT_LE(distance(center, at(log, delaunay[i][3])), r * (1 + 1e-12)) << "step " << k << ": d is outside";
      }
      ++circles;
    }
    if (flips.empty()) {
      EXPECT_EQ(s.find("flip_before"), nullptr);
      continue;
    }
    // The latest flip: the last shapes of its roles, alone in them and drawn wider.
    const auto befores = s.find_all("flip_before"), afters = s.find_all("flip_after");
    const auto& last = flips.back();
    if (finite(log, last[0]) && finite(log, last[1])) {
      ASSERT_FALSE(befores.empty());
      EXPECT_EQ(befores.back()->points, (std::vector<Point>{at(log, last[0]), at(log, last[1])}));
      EXPECT_TRUE(befores.back()->dashed);
    }
    if (finite(log, last[2]) && finite(log, last[3])) {
      ASSERT_FALSE(afters.empty());
      EXPECT_EQ(afters.back()->points, (std::vector<Point>{at(log, last[2]), at(log, last[3])}));
      EXPECT_FALSE(afters.back()->dashed);
    }
    if (flips.size() > 1 && befores.size() == 2 && afters.size() == 2) {
      ++steps_with_several;
      EXPECT_GT(befores[1]->width_px, befores[0]->width_px);
      EXPECT_GT(afters[1]->width_px, afters[0]->width_px);
      EXPECT_GT(afters[1]->color.a, afters[0]->color.a) << "earlier flips are faded";
    }
  }
  EXPECT_GT(circles, 50u);
  EXPECT_GT(steps_with_several, 5u);
}

// --- Bowyer-Watson ---------------------------------------------------------------------

TEST_F(SceneReplay, CavityAndNewFanAreTheWritesOfTheCavityEvent) {
  const replay::LogReader log(cavity_);
  replay::Replay cursor(log);
  std::size_t checked = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event ev = log.event(e);
    if (ev.type != EventType::cavity) continue;
    const VertexId v = ev.ids[0];
    std::vector<Triangle> removed, fan;
    std::vector<Point> boundary;
    for (const replay::SlotWrite& w : log.writes(e)) {
      if (!w.before.dead() && !w.before.ghost()) removed.push_back(corners(log, w.before.v));
      if (w.after.dead() || w.after.ghost()) continue;
      fan.push_back(corners(log, w.after.v));
      const auto i = std::find(w.after.v.begin(), w.after.v.end(), v) - w.after.v.begin();
      ASSERT_LT(i, 3);
      boundary.push_back(at(log, w.after.v[(i + 1) % 3]));
      boundary.push_back(at(log, w.after.v[(i + 2) % 3]));
    }
    const Scene s = scene_at(cursor, e + 1);
    const Shape *cavity = faces_of(s, "cavity"), *new_fan = faces_of(s, "new_fan");
    if (removed.empty()) {
      EXPECT_EQ(cavity, nullptr);
    } else {
      ASSERT_NE(cavity, nullptr) << "event " << e;
      EXPECT_EQ(triangles_of(*cavity), removed);
    }
    ASSERT_NE(new_fan, nullptr) << "event " << e;
    EXPECT_EQ(triangles_of(*new_fan), fan);
    const Shape* rim = s.find("cavity_boundary");
    ASSERT_NE(rim, nullptr);
    EXPECT_EQ(rim->points, boundary);
    // The new fan is what the mesh now holds round v: the faces highlighted.
    std::vector<Triangle> highlighted;
    for (const std::uint32_t t : s.highlighted)
      highlighted.push_back({s.mesh.points[s.mesh.triangles[t][0]], s.mesh.points[s.mesh.triangles[t][1]],
                             s.mesh.points[s.mesh.triangles[t][2]]});
    // The cavity is its step's first change: the faces made so far are the fan.
    EXPECT_EQ(canonical_set(highlighted), canonical_set(fan)) << "event " << e;
    ++checked;
  }
  EXPECT_GT(checked, 50u);
}

// --- Lepp -------------------------------------------------------------------------------

// A Lepp path is drawn in its order, each triangle's longest edge no shorter than the one
// before, ending at its terminal edge; it stays drawn into the step it was computed for.
TEST_F(SceneReplay, LeppPathInOrderWithGrowingLongestEdges) {
  for (const std::string* path : {&lepp_, &bisection_}) {
    const replay::LogReader log(*path);
    replay::Replay cursor(log);
    std::size_t checked = 0, tails = 0;
    for (std::uint64_t e = 0; e < log.event_count(); ++e) {
      const Event ev = log.event(e);
      if (ev.type != EventType::lepp_path) continue;
      std::vector<Triangle> expected;
      for (std::size_t i = 0; i + 3 <= ev.list.size(); i += 3) expected.push_back(corners(log, ev.list.subspan(i, 3)));
      const Point a = at(log, ev.ids[0]), b = at(log, ev.ids[1]);
      // Just after it; and, when it was recorded in the tail of a step (after that step's
      // mesh changes, as the Delaunay refiner records it, choosing the next triangle's
      // point), also once the next step has begun, the step it serves.
      const std::uint64_t step = log.step_of_event(e);
      bool tail = false, last_in_tail = true;
      for (std::uint64_t f = log.step_start(step); f < e; ++f) tail |= replay::schema(log.event(f).type).changes_mesh();
      for (std::uint64_t f = e + 1; f < log.step_start(step + 1); ++f)
        last_in_tail &= log.event(f).type != EventType::lepp_path;
      std::vector<std::uint64_t> positions = {e + 1};
      if (tail && last_in_tail && step + 1 < log.step_count()) positions.push_back(log.step_start(step + 1) + 1);
      tails += positions.size() == 2;
      // A path that opens its step is drawn to the step's end (the moment render --step shows).
      if (!tail && log.step_kind(step) == replay::StepKind::refine) positions.push_back(log.step_start(step + 1));
      for (const std::uint64_t p : positions) {
        const Scene s = scene_at(cursor, p);
        const Shape* lepp = faces_of(s, "lepp_path");
        ASSERT_NE(lepp, nullptr) << "event " << e << ", position " << p;
        const std::vector<Triangle> drawn = triangles_of(*lepp);
        ASSERT_EQ(drawn, expected) << "event " << e << ", position " << p;
        double longest_before = 0.0;
        for (const Triangle& t : drawn) {
          const double longest = std::max({distance(t[0], t[1]), distance(t[1], t[2]), distance(t[2], t[0])});
          EXPECT_GE(longest, longest_before * (1.0 - 1e-12)) << "event " << e;
          longest_before = longest;
        }
        const Shape* edge = s.find("terminal_edge");
        ASSERT_NE(edge, nullptr);
        EXPECT_EQ(edge->points, (std::vector<Point>{a, b}));
        EXPECT_GT(edge->width_px, 3.0f);
        EXPECT_NEAR(longest_before, distance(a, b), 1e-12 * longest_before) << "the terminal edge is the longest";
        const Shape* terminal = faces_of(s, "terminal_triangles");
        ASSERT_NE(terminal, nullptr);
        EXPECT_EQ(triangles_of(*terminal).size(), ev.ids[2]);
        for (const Triangle& t : triangles_of(*terminal)) {
          EXPECT_NE(std::find(t.begin(), t.end(), a), t.end());
          EXPECT_NE(std::find(t.begin(), t.end(), b), t.end());
        }
        // Order labels 1, 2, 3... at the triangles' centroids.
        for (std::size_t i = 0; i < drawn.size(); ++i) {
          const Point c{(drawn[i][0].x + drawn[i][1].x + drawn[i][2].x) / 3.0,
                        (drawn[i][0].y + drawn[i][1].y + drawn[i][2].y) / 3.0};
          const auto label = std::find_if(s.labels.begin(), s.labels.end(),
                                          [&](const Label& l) { return l.text == std::to_string(i + 1); });
          ASSERT_NE(label, s.labels.end());
          EXPECT_EQ(label->at, c);
        }
      }
      ++checked;
    }
    EXPECT_GT(checked, 10u) << *path;
    // The refiner records a path after its step's step_begin (logs written before issue 29
    // had it in the tail of the step before, which the scene still reads).
    EXPECT_EQ(tails, 0u) << "Lepp paths recorded before their step";
  }
}

// Lepp bisection: the bisected edge, the new edges from its midpoint to the apexes, and the
// midpoint as the chosen point.
TEST_F(SceneReplay, BisectionDrawsTheEdgeAndTheNewEdges) {
  const replay::LogReader log(bisection_);
  replay::Replay cursor(log);
  std::size_t checked = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event ev = log.event(e);
    if (ev.type != EventType::split_edge || ev.code != static_cast<std::uint8_t>(replay::SplitReason::bisection))
      continue;
    const VertexId v = ev.ids[0];
    const Point a = at(log, ev.ids[1]), b = at(log, ev.ids[2]), m = at(log, v);
    std::set<VertexId> apexes;
    for (const replay::SlotWrite& w : log.writes(e))
      for (const VertexId u : w.after.v)
        if (u != v && u != ev.ids[1] && u != ev.ids[2]) apexes.insert(u);
    const Scene s = scene_at(cursor, e + 1);
    const auto shapes = s.find_all("bisection");
    ASSERT_EQ(shapes.size(), 2u) << "event " << e;
    EXPECT_EQ(shapes[0]->points, (std::vector<Point>{a, b}));
    ASSERT_EQ(shapes[1]->points.size(), 2 * apexes.size());
    for (std::size_t i = 0; i < shapes[1]->points.size(); i += 2) {
      EXPECT_EQ(shapes[1]->points[i], m);
      EXPECT_TRUE(std::any_of(apexes.begin(), apexes.end(),
                              [&](VertexId u) { return at(log, u) == shapes[1]->points[i + 1]; }));
    }
    EXPECT_EQ(m, (Point{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)})) << "bisection at the midpoint";
    const Shape* chosen = s.find("selected_point");
    ASSERT_NE(chosen, nullptr);
    EXPECT_EQ(chosen->points, std::vector<Point>{m});
    ++checked;
  }
  EXPECT_GT(checked, 10u);
}

// --- Encroachment ----------------------------------------------------------------------

TEST_F(SceneReplay, EncroachedSubsegmentWithItsDiametralCircleAndSplitPoint) {
  const replay::LogReader log(circumcenter_);
  replay::Replay cursor(log);
  std::size_t checked = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    if (kind_of(log, k) != StepKind::split_segment) continue;
    const std::vector<Brief> events = events_of_step(log, k);
    const auto enc =
        std::find_if(events.begin(), events.end(), [](const Brief& e) { return e.type == EventType::encroached; });
    ASSERT_NE(enc, events.end());
    const auto split =
        std::find_if(events.begin(), events.end(), [](const Brief& e) { return e.type == EventType::split_edge; });
    ASSERT_NE(split, events.end());
    const Point a = at(log, enc->ids[0]), b = at(log, enc->ids[1]);
    const double length = distance(a, b);
    const Scene s = scene_at(cursor, log.step_start(k + 1));
    const Shape* seg = s.find("encroached_segment");
    ASSERT_NE(seg, nullptr);
    EXPECT_EQ(seg->points, (std::vector<Point>{a, b}));
    const Shape* circle = s.find("diametral_circle");
    ASSERT_NE(circle, nullptr);
    EXPECT_EQ(s.find("diametral_lens"), nullptr);
    ASSERT_EQ(circle->points.size(), 1u);
    EXPECT_NEAR(circle->points[0].x, (a.x + b.x) / 2, 1e-12 * length);
    EXPECT_NEAR(circle->points[0].y, (a.y + b.y) / 2, 1e-12 * length);
    EXPECT_NEAR(circle->radii[0], length / 2, 1e-12 * length);
    const Shape* by = s.find("encroaching_point");
    ASSERT_NE(by, nullptr);
    EXPECT_EQ(by->points, std::vector<Point>{enc->point});
    // The encroaching point is inside the diametral circle (that is what encroaching means).
    EXPECT_LT(distance(enc->point, circle->points[0]), circle->radii[0] * (1 + 1e-12));
    const Shape* p = s.find("split_point");
    ASSERT_NE(p, nullptr);
    ASSERT_EQ(p->points.size(), 1u);
    const Point q = p->points[0];
    EXPECT_EQ(q, at(log, split->ids[0]));
    const double cross = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
    const double along = (b.x - a.x) * (q.x - a.x) + (b.y - a.y) * (q.y - a.y);
    EXPECT_LE(std::abs(cross), 1e-12 * length * length) << "the split point lies on the segment";
    EXPECT_GT(along, 0.0);
    EXPECT_LT(along, length * length);
    ++checked;
  }
  EXPECT_GT(checked, 5u);
}

// With --encroachment lens: Shewchuk's diametral lens, every point of its outline seeing the
// subsegment at exactly 180 - 2 x the bound: 120 degrees at 30, 130 at 25.
TEST_F(SceneReplay, DiametralLensSeesTheSegmentAtTheBoundsAngle) {
  for (const auto& [path, lens_angle] : {std::pair{lens_, 120.0}, std::pair{lens25_, 130.0}}) {
    SCOPED_TRACE(lens_angle);
    const replay::LogReader log(path);
    replay::Replay cursor(log);
    std::size_t checked = 0;
    for (std::uint64_t e = 0; e < log.event_count(); ++e) {
      const Event ev = log.event(e);
      if (ev.type != EventType::encroached) continue;
      const Point a = at(log, ev.ids[0]), b = at(log, ev.ids[1]);
      const Scene s = scene_at(cursor, e + 1);
      EXPECT_EQ(s.find("diametral_circle"), nullptr);
      const Shape* lens = s.find("diametral_lens");
      ASSERT_NE(lens, nullptr) << "event " << e;
      ASSERT_EQ(lens->kind, ShapeKind::lines);
      ASSERT_GE(lens->points.size(), 8u);
      // A closed outline: each piece starts where the one before ended.
      for (std::size_t i = 2; i < lens->points.size(); i += 2) EXPECT_EQ(lens->points[i], lens->points[i - 1]);
      EXPECT_EQ(lens->points.front(), lens->points.back());
      std::size_t at_a = 0, at_b = 0;
      for (const Point& p : lens->points) {
        if (p == a) {
          ++at_a;
          continue;
        }
        if (p == b) {
          ++at_b;
          continue;
        }
        const double angle =
            std::acos(((a.x - p.x) * (b.x - p.x) + (a.y - p.y) * (b.y - p.y)) / (distance(a, p) * distance(b, p)));
        EXPECT_NEAR(angle * 180.0 / M_PI, lens_angle, 1e-7);
      }
      EXPECT_GT(at_a, 0u);
      EXPECT_GT(at_b, 0u);
      ++checked;
  }
  EXPECT_GT(checked, 2u);
  }
}

// The explanation of a point rejected for encroaching names the test the run applied: the
// diametral circle, or the lens at the bound's angle.
TEST_F(SceneReplay, RejectedPointsAreExplainedByTheRunsEncroachmentTest) {
  for (const auto& [path, words] : {std::pair{circumcenter_, std::string("inside the segment's diametral circle")},
                                    std::pair{lens_, std::string("at 120\u00B0 or more: inside its diametral lens")},
                                    std::pair{lens25_, std::string("at 130\u00B0 or more: inside its diametral lens")}}) {
    SCOPED_TRACE(words);
    const replay::LogReader log(path);
    replay::Replay cursor(log);
    std::size_t checked = 0;
    for (std::uint64_t e = 0; e < log.event_count() && checked < 3; ++e) {
      const Event ev = log.event(e);
      if (ev.type != EventType::encroached || ev.ids[2] != kNone) continue;  // a rejected point's
      cursor.seek_event(e + 1);
      const Explanation x = explain_step(cursor);
      const auto said = std::find_if(x.lines.begin(), x.lines.end(),
                                     [](const std::string& l) { return l.starts_with("rejected: the point"); });
      ASSERT_NE(said, x.lines.end()) << "event " << e;
      EXPECT_NE(said->find(words), std::string::npos) << *said;
      ++checked;
    }
    EXPECT_GT(checked, 0u);
  }
}

// --- Improvement ------------------------------------------------------------------------

// A removed vertex is drawn with its star: the faces round it when its step began.
TEST_F(SceneReplay, RemovedVertexAndItsStar) {
  const replay::LogReader log(improve_);
  replay::Replay cursor(log);
  std::size_t checked = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    if (kind_of(log, k) != StepKind::remove_vertex) continue;
    const VertexId v = log.event(log.step_start(k)).ids[0];
    cursor.seek_event(log.step_start(k));
    const TriMesh before = cursor.mesh();
    const auto index = std::find(before.points.begin(), before.points.end(), at(log, v)) - before.points.begin();
    std::vector<Triangle> star;
    for (const auto& t : before.triangles)
      if (std::count(t.begin(), t.end(), static_cast<std::uint32_t>(index)))
        star.push_back({before.points[t[0]], before.points[t[1]], before.points[t[2]]});
    ASSERT_GE(star.size(), 3u);
    const Scene s = scene_at(cursor, log.step_start(k + 1));
    const Shape* marker = s.find("removed_vertex");
    ASSERT_NE(marker, nullptr) << "step " << k;
    EXPECT_EQ(marker->points, std::vector<Point>{at(log, v)});
    const Shape* drawn = faces_of(s, "star");
    ASSERT_NE(drawn, nullptr);
    EXPECT_EQ(canonical_set(triangles_of(*drawn)), canonical_set(star)) << "step " << k;
    // Named as no survivor is (it has no number in the output .node).
    EXPECT_NE(s.caption.find("vertex " + log.vertex_name(v) + " removed"), std::string::npos) << s.caption;
    EXPECT_EQ(log.vertex_name(v).front(), 'r') << s.caption;
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

// --- Point location ---------------------------------------------------------------------

// The located face is the slot's record when the walk found it (later rewritten by the
// step: the scene reads it from the writes' "before"); the walk is drawn face by face.
TEST_F(SceneReplay, LocatedTriangleAndWalk) {
  const replay::LogReader log(circumcenter_);
  replay::Replay cursor(log);
  std::size_t checked = 0, walks = 0;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const Event ev = log.event(e);
    if (ev.type != EventType::locate) continue;
    std::vector<std::array<VertexId, 3>> walk;
    for (std::size_t i = 0; i + 3 <= ev.list.size(); i += 3)
      walk.push_back({ev.list[i], ev.list[i + 1], ev.list[i + 2]});
    const FaceId slot = ev.ids[2];
    cursor.seek_event(e + 1);
    const replay::FaceRecord found = cursor.slots().at(slot);
    const std::uint64_t step_end = log.step_start(log.step_of_event(e) + 1);
    for (const std::uint64_t p : {e + 1, step_end}) {
      const Scene s = scene_at(cursor, p);
      const auto located = s.find_all("located_triangle");
      ASSERT_FALSE(located.empty()) << "event " << e;
      if (found.ghost()) {
        EXPECT_EQ(located[0]->kind, ShapeKind::lines) << "outside the hull: the hull edge";
      } else {
        EXPECT_EQ(triangles_of(*located[0]), std::vector<Triangle>{corners(log, found.v)}) << "event " << e;
      }
      const Shape* walk_faces = faces_of(s, "walk");
      std::vector<Triangle> finite_walk;
      for (const auto& f : walk)
        if (finite(log, f[0]) && finite(log, f[1]) && finite(log, f[2])) finite_walk.push_back(corners(log, f));
      if (finite_walk.empty()) {
        EXPECT_EQ(walk_faces, nullptr);
        continue;
      }
      ASSERT_NE(walk_faces, nullptr);
      EXPECT_EQ(triangles_of(*walk_faces), finite_walk);
      std::size_t lines = 0;
      for (const Shape* w : s.find_all("walk"))
        if (w->kind == ShapeKind::lines) lines += w->points.size() / 2;
      EXPECT_EQ(lines, finite_walk.size() - 1) << "a path through the centroids";
      ++walks;
    }
    if (!walk.empty()) {
      EXPECT_EQ(walk.back(), found.v) << "the walk ends at the face found";
    }
    ++checked;
  }
  EXPECT_GT(checked, 50u);
  if (log.event(log.step_start(1) + 1).list.empty()) GTEST_SKIP() << "this build records no walks";
  EXPECT_GT(walks, 50u);
}

// --- Age ---------------------------------------------------------------------------------

// Ages follow the cursor forward; backward they are counted again, and agree with a count
// from scratch. A face made by the step just done has that step's number.
TEST_F(SceneReplay, AgeFollowsTheCursorAndMatchesARecount) {
  const replay::LogReader log(circumcenter_);
  replay::Replay cursor(log);
  SceneOptions o;
  o.color_by = ColorBy::age;
  FaceAges ages;
  std::vector<double> previous;
  std::size_t changes = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    cursor.seek_event(log.step_start(k + 1));
    ages.update(cursor);
    const Scene s = build_scene(cursor, o, &ages);
    ASSERT_EQ(s.mesh.values.size(), s.mesh.triangles.size());
    // Constraining an edge keeps its triangles' ages: recovery steps are left out.
    if (kind_of(log, k) != StepKind::recover_segment) {
      for (const std::uint32_t t : s.highlighted) EXPECT_EQ(s.mesh.values[t], double(k + 1)) << "step " << k;
    }
    for (const double v : s.mesh.values) EXPECT_LE(v, double(k + 1));
    if (s.mesh.values != previous) ++changes;
    previous = s.mesh.values;
  }
  EXPECT_GT(changes, log.step_count() / 2);
  // Backward, to several places: the same as a fresh count.
  for (const std::uint64_t p :
       {log.event_count() / 2, log.event_count() / 3, std::uint64_t{5}, log.event_count() - 7}) {
    cursor.seek_event(p);
    ages.update(cursor);
    FaceAges fresh;
    fresh.update(cursor);
    const Scene kept = build_scene(cursor, o, &ages), counted = build_scene(cursor, o, &fresh);
    EXPECT_EQ(kept.mesh.values, counted.mesh.values) << "position " << p;
    EXPECT_EQ(kept.mesh.fill, counted.mesh.fill) << "position " << p;
  }
  // Not updated to the cursor: refused, not silently wrong.
  cursor.seek_event(log.event_count());
  EXPECT_THROW(build_scene(cursor, o, &ages), std::logic_error);
}

// --- Caption, colours, bounds -------------------------------------------------------------

TEST_F(SceneReplay, CaptionSaysWhereAndWhat) {
  const replay::LogReader log(circumcenter_);
  replay::Replay cursor(log);
  const std::string n = std::to_string(log.step_count());
  // Before the first triangle the picture is the input, and the caption says what it holds
  // (plate.poly: its vertices, segments and holes, from the log's header).
  const Pslg in = io::read_poly(plate());
  EXPECT_EQ(scene_at(cursor, 0).caption, "before the run \u00B7 " + n + " steps \u00B7 input: " +
                                             std::to_string(in.points.size()) + " vertices, " +
                                             std::to_string(in.segments.size()) + " segments, " +
                                             std::to_string(in.holes.size()) + " holes");
  std::size_t refine = 0, split = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    const std::string c = scene_at(cursor, log.step_start(k + 1)).caption;
    const std::string where = " \u00B7 step " + std::to_string(k + 1) + " of " + n + " \u00B7 ";
    EXPECT_NE(c.find(where), std::string::npos) << c;
    switch (kind_of(log, k)) {
      case StepKind::insert_vertex: EXPECT_EQ(c.rfind("insert vertices", 0), 0u) << c; break;
      case StepKind::recover_segment: EXPECT_EQ(c.rfind("recover segments", 0), 0u) << c; break;
      case StepKind::carve: EXPECT_EQ(c.rfind("carve", 0), 0u) << c; break;
      case StepKind::refine:
        EXPECT_EQ(c.rfind("refine", 0), 0u) << c;
        EXPECT_NE(c.find("circumcenter of a"), std::string::npos) << c;
        EXPECT_NE(c.find("\u00B0 triangle inserted"), std::string::npos) << c;
        ++refine;
        break;
      case StepKind::split_segment:
        EXPECT_NE(c.find("encroached by"), std::string::npos) << c;
        ++split;
        break;
      default: break;
    }
  }
  EXPECT_GT(refine, 0u);
  EXPECT_GT(split, 0u);
}

// WCAG contrast ratio of two colours (alpha ignored).
double contrast(Rgba x, Rgba y) {
  const auto lum = [](Rgba c) {
    const auto lin = [](std::uint8_t v) {
      const double s = v / 255.0;
      return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * lin(c.r) + 0.7152 * lin(c.g) + 0.0722 * lin(c.b);
  };
  const double a = lum(x), b = lum(y);
  return (std::max(a, b) + 0.05) / (std::min(a, b) + 0.05);
}

// Overlays stand out in both themes: every stroke (or, for a marker, its fill or outline)
// has a contrast of at least 3 with the background, wider than the mesh edges.
TEST_F(SceneReplay, OverlaysStandOutInBothThemes) {
  std::set<std::string> roles;
  for (const std::string* path : {&circumcenter_, &cavity_, &lepp_, &improve_, &lens_, &bisection_}) {
    const replay::LogReader log(*path);
    replay::Replay cursor(log);
    for (const Theme theme : {Theme::light, Theme::dark}) {
      SceneOptions o;
      o.theme = theme;
      for (std::uint64_t k = 0; k < log.step_count(); ++k) {
        const Scene s = scene_at(cursor, log.step_start(k + 1), o);
        for (const Shape& shape : s.shapes) {
          if (shape.layer != Layer::overlay) continue;
          roles.insert(shape.role);
          EXPECT_FALSE(shape.label.empty()) << shape.role;
          if (shape.kind == ShapeKind::markers) {
            EXPECT_GE(
                std::max(contrast(shape.color, s.background), shape.fill.a ? contrast(shape.fill, s.background) : 0.0),
                3.0)
                << shape.role;
          } else if (shape.kind != ShapeKind::triangles && shape.color.a == 255) {
            EXPECT_GE(contrast(shape.color, s.background), 3.0) << shape.role << " in theme " << int(theme);
            EXPECT_GT(shape.width_px, s.mesh.edge_width_px) << shape.role;
          }
        }
      }
    }
  }
  for (const char* role : {"bad_triangle",       "circumcircle",     "selected_point", "flip_before",
                           "flip_after",         "flip_circle",      "cavity",         "new_fan",
                           "cavity_boundary",    "lepp_path",        "terminal_edge",  "terminal_triangles",
                           "encroached_segment", "diametral_circle", "diametral_lens", "encroaching_point",
                           "split_point",        "bisection",        "removed_vertex", "star",
                           "located_triangle",   "new_vertex",       "walk",           "recovered_segment"})
    EXPECT_TRUE(roles.count(role)) << role << " never drawn";
}

// A huge circle (the in-circle test of a nearly flat triangle) does not blow up the bounds
// a camera fits: circles count only within the mesh's box grown by half its larger side.
TEST(SceneReplayBounds, HugeCirclesDoNotBlowTheFit) {
  testing::TempDir dir("meshstep_scene_");
  Pslg in;
  for (int i = 0; i <= 20; ++i) in.points.push_back({double(i), 1e-4 * i * i});  // a nearly flat arc
  in.points.push_back({10.0, 3.0});
  in.points.push_back({4.0, -2.0});
  const std::string path = dir.file("flat.mslog");
  {
    replay::LogHeader h;
    h.parameters = "input_vertices=" + std::to_string(in.points.size());
    replay::LogWriter writer(path, h);
    TriangulateOptions o;
    o.record = &writer;
    triangulate(in, o);
    writer.finish();
  }
  const replay::LogReader log(path);
  replay::Replay cursor(log);
  std::size_t huge = 0;
  for (std::uint64_t p = 1; p <= log.event_count(); ++p) {
    const Scene s = scene_at(cursor, p);
    BBox box;  // the vertices present (Replay::mesh() lists them) and every shape but circles
    for (const Point& q : cursor.mesh().points) box.add(q);
    for (const Shape& shape : s.shapes)
      if (shape.kind != ShapeKind::circles)
        for (const Point& q : shape.points) box.add(q);
    const double side = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y), grow = side / 10 * (1 + 1e-12);
    EXPECT_LE(s.bounds.lo.x, box.lo.x);
    EXPECT_LE(s.bounds.lo.y, box.lo.y);
    EXPECT_GE(s.bounds.hi.x, box.hi.x);
    EXPECT_GE(s.bounds.hi.y, box.hi.y);
    EXPECT_GE(s.bounds.lo.x, box.lo.x - grow);
    EXPECT_GE(s.bounds.lo.y, box.lo.y - grow);
    EXPECT_LE(s.bounds.hi.x, box.hi.x + grow);
    EXPECT_LE(s.bounds.hi.y, box.hi.y + grow);
    for (const Shape* c : s.find_all("flip_circle"))
      for (const double r : c->radii) huge += r > 10 * side;
  }
  EXPECT_GT(huge, 0u) << "the test no longer makes a huge circle";
}


// A square cut in two by a segment, with region points in both halves: on the left an
// earlier point (attribute 7) overwritten by a later one (1), on the right 2 then 5, and one
// point outside the domain. The output's attributes say which wins where.
Pslg two_regions() {
  Pslg in;
  in.points = {{0, 0}, {2, 0}, {4, 0}, {4, 4}, {2, 4}, {0, 4}};
  in.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {1, 4}};
  in.regions = {{{1, 3}, 7, -1}, {{1, 2}, 1, -1}, {{3, 2}, 2, -1}, {{3, 1}, 5, 0.25}, {{10, 10}, 9, -1}};
  return in;
}

// Each triangle's corners, sorted, as the key that finds it in another numbering.
std::array<Point, 3> corner_key(std::span<const Point> points, const std::array<std::uint32_t, 3>& t) {
  std::array<Point, 3> key{points[t[0]], points[t[1]], points[t[2]]};
  std::sort(key.begin(), key.end(), [](const Point& a, const Point& b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); });
  return key;
}

// The log keeps the input's region points exactly, and every moment's triangles carry the
// attribute the run's output gives them: at the end, each triangle's equals the written
// mesh's; before that, every triangle is in the half its attribute names.
TEST(SceneReplayRegions, TrianglesCarryTheRegionalAttributeOfTheOutput) {
  testing::TempDir dir("meshstep_scene_");
  const Pslg in = two_regions();
  const std::string path = dir.file("regions.mslog");
  TriMesh out;
  {
    replay::LogHeader h;
    h.parameters = "input_vertices=" + std::to_string(in.points.size());
    h.regions = in.regions;
    h.regions[0].point.x = 1.0 / 3.0;  // a number whose text must carry every bit
    replay::LogWriter writer(path, h);
    RefineOptions o = options_for(*find_algorithm("circumcenter"));
    o.criteria.min_angle_deg = 30.0;
    o.triangulate.record = &writer;
    Pslg copy = in;
    copy.regions[0].point.x = 1.0 / 3.0;
    out = refine(copy, o);
    writer.finish();
  }
  const replay::LogReader log(path);
  ASSERT_EQ(log.header().regions.size(), in.regions.size());
  EXPECT_EQ(log.header().regions[0].point.x, 1.0 / 3.0);
  EXPECT_EQ(log.header().regions[3].max_area, 0.25);
  EXPECT_EQ(log.header().regions[4].attribute, 9.0);

  std::map<std::array<Point, 3>, double, decltype([](const auto& a, const auto& b) {
             return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), [](const Point& p, const Point& q) {
               return std::tie(p.x, p.y) < std::tie(q.x, q.y);
             });
           })>
      expected;
  ASSERT_EQ(out.attributes_per_triangle, 1u);
  for (std::size_t t = 0; t < out.triangles.size(); ++t) expected[corner_key(out.points, out.triangles[t])] = out.triangle_attributes[t];

  replay::Replay cursor(log);
  const Scene end = scene_at(cursor, log.event_count());
  ASSERT_EQ(end.mesh.region.size(), end.mesh.triangles.size());
  ASSERT_EQ(end.mesh.triangles.size(), out.triangles.size());
  std::set<double> seen;
  for (std::size_t t = 0; t < end.mesh.triangles.size(); ++t) {
    const auto it = expected.find(corner_key(end.mesh.points, end.mesh.triangles[t]));
    ASSERT_NE(it, expected.end()) << "triangle " << t << " is not in the output";
    EXPECT_EQ(end.mesh.region[t], it->second) << "triangle " << t;
    seen.insert(end.mesh.region[t]);
  }
  EXPECT_EQ(seen, (std::set<double>{1.0, 5.0}));
  ASSERT_NE(end.find("regions"), nullptr);
  EXPECT_EQ(end.find("regions")->points.size(), in.regions.size());

  // Every tenth moment: the left half is 1 and the right 5 once the middle segment is in.
  for (std::uint64_t p = log.event_count() / 2; p < log.event_count(); p += 10) {
    const Scene s = scene_at(cursor, p);
    ASSERT_EQ(s.mesh.region.size(), s.mesh.triangles.size());
    for (std::size_t t = 0; t < s.mesh.triangles.size(); ++t) {
      const auto& v = s.mesh.triangles[t];
      const double cx = (s.mesh.points[v[0]].x + s.mesh.points[v[1]].x + s.mesh.points[v[2]].x) / 3;
      EXPECT_EQ(s.mesh.region[t], cx < 2 ? 1.0 : 5.0) << "at event " << p << ", triangle " << t;
    }
  }
  // Colouring by region reads the same attributes.
  SceneOptions by_region;
  by_region.color_by = ColorBy::region;
  const Scene coloured = scene_at(cursor, log.event_count(), by_region);
  EXPECT_EQ(coloured.mesh.values, coloured.mesh.region);
}

// A log without regions has none, and a damaged regions field is refused by name.
TEST(SceneReplayRegions, ALogWithoutRegionsHasNoneAndABadFieldIsRefused) {
  testing::TempDir dir("meshstep_scene_");
  const std::string plain = dir.file("plain.mslog"), bad = dir.file("bad.mslog");
  for (const std::string& path : {plain, bad}) {
    replay::LogHeader h;
    h.parameters = "input_vertices=3";
    if (path == bad) h.regions = {{{0.5, 0.5}, std::nan(""), -1}};
    replay::LogWriter writer(path, h);
    TriangulateOptions o;
    o.record = &writer;
    Pslg triangle;
    triangle.points = {{0, 0}, {1, 0}, {0, 1}};
    triangulate(triangle, o);
    writer.finish();
  }
  const replay::LogReader log(plain);
  EXPECT_TRUE(log.header().regions.empty());
  replay::Replay cursor(log);
  EXPECT_TRUE(scene_at(cursor, log.event_count()).mesh.region.empty());
  try {
    const replay::LogReader broken(bad);
    FAIL() << "a NaN attribute was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("regions field is malformed"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace meshstep::scene
