// The inspector's element history: segments picked and traced back to their input segment,
// their pieces and splits; a triangle's making and replacement; the vertices on a
// Bowyer-Watson cavity's boundary. Each is checked against a scan of the log that does not
// use the index (geometry for segments, every write for triangles), in process and through
// the viewer program's `select X Y` and `state`.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "program_support.hpp"
#include "element_index.hpp"
#include "element_story.hpp"
#include "golden_runs.hpp"
#include "inspector.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"

namespace meshstep::viewer {
namespace {

using testing::has;
using testing::read_text;

namespace fs = std::filesystem;
using Edge = std::pair<VertexId, VertexId>;

constexpr const char* kLesson30 = "--min-angle 30";

void wait_ready(const ElementIndex& index) {
  while (!index.ready()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

Edge sorted_edge(VertexId a, VertexId b) { return {std::min(a, b), std::max(a, b)}; }

// Does p lie on the segment a-b? Within rounding: a split on a concentric shell rounds its
// point off the line by about an ulp.
bool on_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double cross = (p.x - a.x) * dy - (p.y - a.y) * dx;
  const double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2;
  return std::abs(cross) <= 1e-9 * l2 && t >= -1e-12 && t <= 1.0 + 1e-12;
}

// The input's segments, by the log's vertex ids (from the .poly itself, not the log).
std::vector<Edge> input_segments(const replay::LogReader& log, const std::string& poly) {
  const Pslg input = io::read_poly(poly);
  std::vector<VertexId> id_of(input.points.size(), kNone);
  for (VertexId v = 0; v < log.vertices().size(); ++v) {
    const replay::VertexInfo& info = log.vertices()[v];
    if (info.event != kNone && info.same_as == kNone && info.input_index < id_of.size()) id_of[info.input_index] = v;
  }
  std::vector<Edge> out;
  for (const Segment& s : input.segments) out.emplace_back(id_of[s.a], id_of[s.b]);
  return out;
}

// The constrained edges of the mesh after `position` events, from the face slots' flags.
std::set<Edge> constrained_at(replay::Replay& cursor, std::uint64_t position) {
  cursor.seek_event(position);
  std::set<Edge> out;
  for (const replay::FaceRecord& r : cursor.slots()) {
    if (r.dead() || r.ghost()) continue;
    for (int i = 0; i < 3; ++i)
      if (r.constrained >> i & 1) out.insert(sorted_edge(r.v[static_cast<std::size_t>(i)], r.v[static_cast<std::size_t>((i + 1) % 3)]));
  }
  return out;
}

// The constrained edges that lie on the input segment a-b: its pieces.
std::set<Edge> pieces_on(const std::set<Edge>& constrained, const replay::LogReader& log, Edge segment) {
  const auto& v = log.vertices();
  std::set<Edge> out;
  for (const Edge& e : constrained)
    if (on_segment(v[e.first].point, v[segment.first].point, v[segment.second].point) &&
        on_segment(v[e.second].point, v[segment.first].point, v[segment.second].point))
      out.insert(e);
  return out;
}

// The events that split a piece of the segment: a split_edge whose vertices all lie on it.
std::vector<std::uint64_t> splits_on(const replay::LogReader& log, Edge segment) {
  const auto& v = log.vertices();
  const Point &a = v[segment.first].point, &b = v[segment.second].point;
  std::vector<std::uint64_t> out;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const replay::Event ev = log.event(e);
    if (ev.type != replay::EventType::split_edge) continue;
    if (on_segment(v[ev.ids[0]].point, a, b) && on_segment(v[ev.ids[1]].point, a, b) && on_segment(v[ev.ids[2]].point, a, b))
      out.push_back(e);
  }
  return out;
}

// The table's input segment with these endpoints (looked up by its ends, not a piece: a
// segment through an input vertex never has a piece from end to end).
std::uint32_t find_input(const SegmentTable& table, Edge ends) {
  for (std::uint32_t s = 0; s < table.size(); ++s)
    if (sorted_edge(table.input(s).a, table.input(s).b) == sorted_edge(ends.first, ends.second)) return s;
  return kNone;
}

bool holds(const replay::FaceRecord& r, std::array<VertexId, 3> sorted) {
  if (r.dead()) return false;
  auto v = r.v;
  std::sort(v.begin(), v.end());
  return v == sorted;
}

// Every write of the log, for the face: the last event before `position` that wrote it where
// it was not, and the first from `position` on that wrote something else over it.
std::pair<std::uint64_t, std::uint64_t> face_life_by_scan(const replay::LogReader& log, std::array<VertexId, 3> face,
                                                          std::uint64_t position) {
  std::sort(face.begin(), face.end());
  std::uint64_t made = kNoEvent, replaced = kNoEvent;
  for (std::uint64_t e = 0; e < log.event_count(); ++e)
    for (const replay::SlotWrite& w : log.writes(e)) {
      if (e < position && holds(w.after, face) && !holds(w.before, face)) made = e;
      if (e >= position && replaced == kNoEvent && holds(w.before, face) && !holds(w.after, face)) replaced = e;
    }
  return {made, replaced};
}

TEST(InspectorHistory, SegmentPiecesAndSplitsAgreeWithAScanOfTheLog) {
  const replay::LogReader* log = golden::lesson_run(kLesson30);
  ASSERT_NE(log, nullptr);
  ElementIndex index;
  index.build(log->path());
  wait_ready(index);
  ASSERT_TRUE(index.error().empty()) << index.error();
  const SegmentTable& table = index.segments();
  const std::vector<Edge> inputs = input_segments(*log, golden::asset("lesson.poly"));
  ASSERT_EQ(table.size(), inputs.size());
  replay::Replay cursor(*log);
  std::size_t split_segments = 0;
  for (const Edge& input : inputs) {
    const std::uint32_t s = table.segment_of(input.first, input.second);
    ASSERT_NE(s, kNone) << input.first << "-" << input.second;
    EXPECT_EQ(sorted_edge(table.input(s).a, table.input(s).b), sorted_edge(input.first, input.second));
    std::vector<std::uint64_t> splits;
    for (const SegmentTable::Change& c : table.changes(s))
      if (c.kind == SegmentTable::Change::Kind::split) splits.push_back(c.event);
    const std::vector<std::uint64_t> expected = splits_on(*log, input);
    EXPECT_EQ(splits, expected) << "segment " << input.first << "-" << input.second;
    split_segments += !expected.empty();
    // Its pieces at every step boundary: the constrained edges on it, as a chain from its
    // first endpoint to its other.
    for (std::uint64_t k = 0; k <= log->step_count(); ++k) {
      const std::uint64_t position = k < log->step_count() ? log->step_start(k) : log->event_count();
      const std::set<Edge> want = pieces_on(constrained_at(cursor, position), *log, input);
      const auto chain = table.pieces_at(s, position);
      std::set<Edge> got;
      for (const auto& [a, b] : chain) got.insert(sorted_edge(a, b));
      ASSERT_EQ(got, want) << "segment " << input.first << "-" << input.second << " after " << k << " steps";
      if (chain.empty()) continue;
      EXPECT_EQ(chain.front().first, table.input(s).a);
      EXPECT_EQ(chain.back().second, table.input(s).b);
      for (std::size_t i = 1; i < chain.size(); ++i) EXPECT_EQ(chain[i].first, chain[i - 1].second);
    }
  }
  EXPECT_GE(split_segments, 3u) << "the lesson at 30 degrees splits several segments";
}

// Two segments that cross, and an input vertex on one of them: segment recovery puts the
// first's pieces through the vertex, then splits one of them where the second crosses it (a
// point rounded off both lines), and makes the second's pieces through that point.
TEST(InspectorHistory, CrossingSegmentsKeepTheirOwnPieces) {
  const fs::path dir = fs::temp_directory_path() / ("inspector_crossing_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path poly = dir / "x.poly", log_path = dir / "x.mslog";
  std::ofstream(poly) << "9 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 3\n7 1 3.3\n8 3 1\n9 2.5 2.5\n"
                         "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 7 8\n0\n";
  const std::string command = std::string(MESHSTEP_BINARY) + " triangulate " + poly.string() + " --record " +
                              log_path.string() + " --no-output -q";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const replay::LogReader log(log_path.string());
  ElementIndex index;
  index.build(log_path.string());
  wait_ready(index);
  ASSERT_TRUE(index.error().empty()) << index.error();
  const SegmentTable& table = index.segments();
  const std::vector<Edge> inputs = input_segments(log, poly.string());
  ASSERT_EQ(table.size(), inputs.size());
  replay::Replay cursor(log);
  const std::set<Edge> constrained = constrained_at(cursor, log.event_count());
  std::size_t total = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const Edge& input = inputs[i];
    const std::uint32_t s = find_input(table, input);
    ASSERT_NE(s, kNone) << "segment " << i + 1;
    std::set<Edge> got;
    for (const auto& [a, b] : table.pieces_at(s, log.event_count())) {
      got.insert(sorted_edge(a, b));
      EXPECT_EQ(table.segment_of(a, b), s) << a << "-" << b;
    }
    EXPECT_EQ(got, pieces_on(constrained, log, input)) << "segment " << i + 1;
    // The square's sides are one piece each; the first diagonal is three (through vertex 9
    // and the crossing), the second two.
    EXPECT_EQ(got.size(), i == 4 ? 3u : i == 5 ? 2u : 1u) << "segment " << i + 1;
    total += got.size();
  }
  // Every constrained edge of the mesh is the piece of exactly one input segment.
  EXPECT_EQ(total, constrained.size());
  std::size_t crossings = 0;
  for (std::uint32_t s = 0; s < table.size(); ++s)
    for (const SegmentTable::Change& c : table.changes(s))
      crossings += c.kind == SegmentTable::Change::Kind::split && c.reason == replay::SplitReason::crossing;
  EXPECT_EQ(crossings, 1u);
  fs::remove_all(dir);
}

TEST(InspectorHistory, ATrianglesStoryIsTheWriteThatMadeItAndTheOneThatReplacedIt) {
  for (const char* args : {"--algorithm offcenter --min-angle 30", "--min-angle 30 --insertion cavity"}) {
    const replay::LogReader* log = golden::lesson_run(args);
    ASSERT_NE(log, nullptr);
    ElementIndex index;
    index.build(log->path());
    wait_ready(index);
    replay::Replay cursor(*log);
    std::size_t checked = 0, replaced = 0;
    // Step boundaries and the middle of steps, all through the run.
    for (std::uint64_t position = 0; position <= log->event_count(); position += 7) {
      cursor.seek_event(position);
      for (const replay::FaceRecord& r : cursor.slots()) {
        if (r.dead() || r.ghost()) continue;
        const TriangleStory story = triangle_story(*log, index, r.v, position);
        const auto [made, gone] = face_life_by_scan(*log, r.v, position);
        ASSERT_NE(story.slot, kNone);
        ASSERT_EQ(story.created, made) << args << ": face " << r.v[0] << " " << r.v[1] << " " << r.v[2] << " at " << position;
        EXPECT_EQ(story.removed, gone) << args << ": face " << r.v[0] << " " << r.v[1] << " " << r.v[2] << " at " << position;
        EXPECT_EQ(cursor.slots()[story.slot], r);
        ++checked;
        replaced += gone != kNoEvent;
      }
    }
    EXPECT_GT(checked, 500u) << args;
    EXPECT_GT(replaced, 100u) << args;
  }
}

TEST(InspectorHistory, ACavitysBoundaryVerticesHaveTheCavityInTheirHistory) {
  const replay::LogReader* log = golden::lesson_run("--min-angle 30 --insertion cavity");
  ASSERT_NE(log, nullptr);
  ElementIndex index;
  index.build(log->path());
  wait_ready(index);
  std::size_t cavities = 0, boundary_vertices = 0;
  for (std::uint64_t e = 0; e < log->event_count(); ++e) {
    const replay::Event ev = log->event(e);
    if (ev.type != replay::EventType::cavity) continue;
    ++cavities;
    // The removed faces' corners: the cavity's boundary (no vertex lies inside a cavity).
    std::set<VertexId> boundary;
    for (const replay::SlotWrite& w : log->writes(e))
      for (const VertexId v : w.before.v)
        if (!w.before.dead() && v < log->vertices().size()) boundary.insert(v);
    for (const VertexId v : boundary) {
      const auto events = index.events_of_vertex(v);
      EXPECT_TRUE(std::binary_search(events.begin(), events.end(), e)) << "vertex " << v << ", cavity at event " << e;
      boundary_vertices += v != ev.ids[0];
    }
    // And no vertex off it.
    for (VertexId v = 0; v < log->vertices().size(); ++v) {
      if (boundary.count(v) || v == ev.ids[0]) continue;
      const auto events = index.events_of_vertex(v);
      EXPECT_FALSE(std::binary_search(events.begin(), events.end(), e)) << "vertex " << v << ", cavity at event " << e;
    }
  }
  EXPECT_GT(cavities, 20u);
  EXPECT_GT(boundary_vertices, 3 * cavities);
}

// A click picks a vertex before the segment it lies on, a segment before the triangles on
// either side of it.
TEST(InspectorPick, VertexBeforeSegmentBeforeTriangle) {
  const replay::LogReader* log = golden::lesson_run(kLesson30);
  ASSERT_NE(log, nullptr);
  replay::Replay cursor(*log);
  cursor.seek_event(log->event_count());
  const scene::Scene scene = scene::build_scene(cursor, {});
  const std::vector<MeshEdge> edges = constrained_edges(scene);
  std::set<Edge> got;
  for (const MeshEdge& e : edges) got.insert({e[0], e[1]});
  EXPECT_EQ(got, constrained_at(cursor, log->event_count()));

  const MeshEdge e = edges.front();
  const Point a = scene.mesh.points[e[0]], b = scene.mesh.points[e[1]];
  const Point middle{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  const double length = std::hypot(b.x - a.x, b.y - a.y), r = length / 20;
  // Beside the segment's middle, within the segment's radius: the segment.
  const Point beside{middle.x + 0.5 * r * (a.y - b.y) / length, middle.y + 0.5 * r * (b.x - a.x) / length};
  EXPECT_EQ(pick(scene.mesh, edges, beside, r, r), (Picked{Picked::Kind::segment, e[0], e[1]}));
  // At its end: the vertex.
  EXPECT_EQ(pick(scene.mesh, edges, a, r, r), (Picked{Picked::Kind::vertex, e[0], 0}));
  // Farther than its radius: the triangle under the point.
  const Point off{middle.x + 3 * r * (a.y - b.y) / length, middle.y + 3 * r * (b.x - a.x) / length};
  EXPECT_EQ(pick(scene.mesh, edges, off, r, r).kind, pick(scene.mesh, off, r).kind);
  EXPECT_NE(pick(scene.mesh, edges, off, r, r).kind, Picked::Kind::segment);
}

std::string run_program(const std::string& command) {
  std::string out;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return "cannot run " + command;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = ::pclose(pipe);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? "" : out.empty() ? "failed" : out;
}



// The part of the state's line for `key` (one field per line).
std::string line_of(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  return json.substr(at, json.find('\n', at) - at);
}

// The viewer program, scripted: a click (`select X Y`) on a split segment's piece, then on a
// triangle; the state says what the log says.
TEST(InspectorHistory, TheProgramSaysASelectedSegmentsPiecesAndSplitsAndATrianglesMaking) {
  const replay::LogReader* log = golden::lesson_run(kLesson30);
  ASSERT_NE(log, nullptr);
  // The input segment split most often, and the piece of it at the end whose middle is
  // farthest from any other vertex (a click there means the segment).
  Edge segment{kNone, kNone};
  std::vector<std::uint64_t> splits;
  for (const Edge& input : input_segments(*log, golden::asset("lesson.poly")))
    if (const auto s = splits_on(*log, input); s.size() > splits.size()) segment = input, splits = s;
  ASSERT_GE(splits.size(), 2u);
  replay::Replay cursor(*log);
  const std::set<Edge> pieces_at_end = pieces_on(constrained_at(cursor, log->event_count()), *log, segment);
  const auto& v = log->vertices();
  Point click{};
  double clearance = -1;
  for (const Edge& piece : pieces_at_end) {
    const Point m{0.5 * (v[piece.first].point.x + v[piece.second].point.x), 0.5 * (v[piece.first].point.y + v[piece.second].point.y)};
    double nearest = INFINITY;
    for (const replay::VertexInfo& info : v) nearest = std::min(nearest, std::hypot(info.point.x - m.x, info.point.y - m.y));
    if (nearest > clearance) clearance = nearest, click = m;
  }
  // Between its first two splits: the pieces then.
  const std::uint64_t between = log->step_of_event(splits[0]) + 1;
  const std::set<Edge> pieces_between = pieces_on(constrained_at(cursor, log->step_start(between)), *log, segment);
  // A triangle of the end's mesh far from segments: the one whose centroid is.
  cursor.seek_event(log->event_count());
  std::array<VertexId, 3> face{};
  Point centroid{};
  double best = -1;
  const std::set<Edge> constrained = constrained_at(cursor, log->event_count());
  for (const replay::FaceRecord& r : cursor.slots()) {
    if (r.dead() || r.ghost()) continue;
    const Point c{(v[r.v[0]].point.x + v[r.v[1]].point.x + v[r.v[2]].point.x) / 3,
                  (v[r.v[0]].point.y + v[r.v[1]].point.y + v[r.v[2]].point.y) / 3};
    double nearest = INFINITY;
    for (const Edge& e : constrained)
      for (const Point& p : {v[e.first].point, v[e.second].point}) nearest = std::min(nearest, std::hypot(p.x - c.x, p.y - c.y));
    if (nearest > best) best = nearest, face = r.v, centroid = c;
  }
  const auto [made, gone] = face_life_by_scan(*log, face, log->event_count());
  ASSERT_NE(made, kNoEvent);
  EXPECT_EQ(gone, kNoEvent);

  const fs::path dir = fs::temp_directory_path() / ("inspector_program_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path script = dir / "s.txt", a = dir / "a.json", b = dir / "b.json", c = dir / "c.json";
  char text[512];
  std::snprintf(text, sizeof text,
                "frames 1\nseek end\nwait\nselect %.17g %.17g\nframes 1\nstate %s\nseek step %llu\nframes 1\nstate %s\n"
                "seek end\nframes 1\nselect %.17g %.17g\nframes 1\nstate %s\nquit\n",
                click.x, click.y, a.c_str(), static_cast<unsigned long long>(between), b.c_str(), centroid.x, centroid.y,
                c.c_str());
  std::ofstream(script) << text;
  const std::string failed = run_program(std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() + " --offscreen -q --script " + script.string());
  if (has(failed, "cannot open a window or draw")) GTEST_SKIP() << failed;
  ASSERT_EQ(failed, "");
  const std::string at_end = read_text(a), then = read_text(b), triangle = read_text(c);

  const std::string story = line_of(at_end, "selection_story");
  EXPECT_TRUE(has(at_end, "\"selection\": \"segment ")) << at_end;
  const std::string ends[2] = {"\"input\": [" + std::to_string(segment.first) + ", " + std::to_string(segment.second) + "]",
                               "\"input\": [" + std::to_string(segment.second) + ", " + std::to_string(segment.first) + "]"};
  EXPECT_TRUE(has(story, ends[0]) || has(story, ends[1])) << story;
  // Its pieces: as many as the constrained edges on it; its splits: the scan's, in order.
  const auto count_pieces = [](const std::string& line) {
    const auto from = line.find("\"pieces\": ["), to = line.find("], \"splits\"");
    if (from == std::string::npos || to == std::string::npos) return std::size_t{0};
    const std::string part = line.substr(from + 11, to - from - 11);
    return static_cast<std::size_t>(std::count(part.begin(), part.end(), '['));
  };
  EXPECT_EQ(count_pieces(story), pieces_at_end.size()) << story;
  EXPECT_EQ(count_pieces(line_of(then, "selection_story")), pieces_between.size()) << line_of(then, "selection_story");
  std::size_t from = 0;
  for (const std::uint64_t e : splits) {
    const std::string one = "{\"step\": " + std::to_string(log->step_of_event(e) + 1) + ", \"event\": " + std::to_string(e) + ",";
    const auto at = story.find(one, from);
    EXPECT_NE(at, std::string::npos) << one << " in " << story;
    from = at == std::string::npos ? from : at;
  }
  EXPECT_EQ(static_cast<std::size_t>(std::count(story.begin(), story.end(), '{')) - 1, splits.size()) << story;
  // The history's steps include every split's.
  const std::string history = line_of(at_end, "selection_history");
  for (const std::uint64_t e : splits) EXPECT_TRUE(has(history, std::to_string(log->step_of_event(e) + 1))) << history;

  // The triangle: made by the event whose writes put that face in, never replaced.
  EXPECT_TRUE(has(triangle, "\"selection\": \"triangle ")) << triangle;
  EXPECT_TRUE(has(line_of(triangle, "selection_story"), "{\"created\": {\"step\": " + std::to_string(log->step_of_event(made) + 1) +
                                                            ", \"event\": " + std::to_string(made) + "}, \"removed\": null"))
      << triangle;
  EXPECT_TRUE(has(triangle, "it lasts to the end of the run")) << triangle;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace meshstep::viewer
