// Step 0 of a recorded run shows the input (issue 29, item 2): before the first triangle the
// scene draws the input's vertices in input order, named by their numbers in the input file,
// its segments and its hole points. Checked against lesson.poly read here on its own (a few
// lines of parsing, not the project's reader), through a log recorded by the command line as
// a user records it. A log from before the header kept the segments still shows the rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/build.hpp"
#include "run_cli.hpp"
#include "scene_at_step.hpp"
#include "temp_dir.hpp"

namespace meshstep::scene {
namespace {

using meshstep::testing::scene_at_step;

std::string lesson() { return std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly"; }

// A .poly file as numbers: its vertices (in file order, numbered from the first index the
// file uses), its segments by those numbers, its holes.
struct Poly {
  std::vector<Point> points;
  int first_index = 0;
  std::vector<std::pair<int, int>> segments;
  std::vector<Point> holes;
};

Poly read_poly_numbers(const std::string& path) {
  std::ifstream file(path);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(file, line);) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<double> row;
    for (double v; words >> v;) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  Poly p;
  std::size_t r = 0;
  const auto vertices = static_cast<std::size_t>(rows.at(r++)[0]);
  for (std::size_t i = 0; i < vertices; ++i, ++r) {
    if (i == 0) p.first_index = static_cast<int>(rows.at(r)[0]);
    p.points.push_back({rows.at(r)[1], rows.at(r)[2]});
  }
  const auto segments = static_cast<std::size_t>(rows.at(r++)[0]);
  for (std::size_t i = 0; i < segments; ++i, ++r)
    p.segments.push_back({static_cast<int>(rows.at(r)[1]), static_cast<int>(rows.at(r)[2])});
  const auto holes = static_cast<std::size_t>(rows.at(r++)[0]);
  for (std::size_t i = 0; i < holes; ++i, ++r) p.holes.push_back({rows.at(r)[1], rows.at(r)[2]});
  return p;
}

bool less(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// The segments of a lines shape as ends in a fixed order, sorted.
std::vector<std::pair<Point, Point>> pieces(const std::vector<Point>& ends) {
  std::vector<std::pair<Point, Point>> out;
  for (std::size_t i = 0; i + 1 < ends.size(); i += 2)
    out.push_back(less(ends[i], ends[i + 1]) ? std::pair{ends[i], ends[i + 1]} : std::pair{ends[i + 1], ends[i]});
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
    return less(x.first, y.first) || (x.first == y.first && less(x.second, y.second));
  });
  return out;
}

TEST(SceneStepZero, LessonShowsExactlyItsInputBeforeTheFirstTriangle) {
  testing::TempDir dir("meshstep_step_zero_");
  const std::string log_path = dir.file("lesson.mslog");
  const testing::CommandResult run = testing::run_meshstep(
      "refine " + lesson() + " --algorithm offcenter --min-angle 30 --record " + log_path + " -o " + dir.file("out") + " -q",
      dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const Poly poly = read_poly_numbers(lesson());
  ASSERT_EQ(poly.points.size(), 14u);
  ASSERT_EQ(poly.segments.size(), 12u);
  ASSERT_EQ(poly.holes.size(), 1u);

  const replay::LogReader log(log_path);
  const Scene s = scene_at_step(log, 0);
  EXPECT_TRUE(s.mesh.triangles.empty()) << "step 0 is before the first triangle";

  // The vertices, in input order, and no Steiner vertex.
  const Shape* vertices = s.find("input_vertices");
  ASSERT_NE(vertices, nullptr);
  EXPECT_EQ(vertices->points, poly.points);
  EXPECT_EQ(s.find("steiner_vertices"), nullptr);
  // Each named by its number in the file.
  ASSERT_EQ(s.labels.size(), poly.points.size());
  for (std::size_t i = 0; i < poly.points.size(); ++i) {
    const std::string number = std::to_string(poly.first_index + static_cast<int>(i));
    const auto named = std::find_if(s.labels.begin(), s.labels.end(), [&](const Label& l) { return l.text == number; });
    ASSERT_NE(named, s.labels.end()) << "no label " << number;
    EXPECT_EQ(named->at, poly.points[i]) << "label " << number;
  }
  // The segments, every one, between the points the file names.
  const Shape* segments = s.find("segments");
  ASSERT_NE(segments, nullptr);
  std::vector<Point> expected;
  for (const auto& [a, b] : poly.segments) {
    expected.push_back(poly.points.at(a - poly.first_index));
    expected.push_back(poly.points.at(b - poly.first_index));
  }
  EXPECT_EQ(pieces(segments->points), pieces(expected));
  // The hole point.
  const Shape* holes = s.find("holes");
  ASSERT_NE(holes, nullptr);
  EXPECT_EQ(holes->points, poly.holes);
  // The caption says what the input is; the picture frames all of it.
  EXPECT_NE(s.caption.find("input: 14 vertices, 12 segments, 1 hole"), std::string::npos) << s.caption;
  for (const Point& p : poly.points) {
    EXPECT_GE(p.x, s.bounds.lo.x);
    EXPECT_LE(p.x, s.bounds.hi.x);
    EXPECT_GE(p.y, s.bounds.lo.y);
    EXPECT_LE(p.y, s.bounds.hi.y);
  }

  // After the first step a triangle stands, and the scene is the mesh's again: three vertices.
  const Scene after = scene_at_step(log, 1);
  ASSERT_FALSE(after.mesh.triangles.empty());
  ASSERT_NE(after.find("input_vertices"), nullptr);
  EXPECT_EQ(after.find("input_vertices")->points.size(), 3u);
  EXPECT_EQ(after.caption.find("input:"), std::string::npos);
}

// A log whose header has no segments field (written before it existed): step 0 still shows
// the input's vertices and holes, and no segments it cannot know.
TEST(SceneStepZero, AnOlderLogShowsWhatItKnows) {
  testing::TempDir dir("meshstep_step_zero_");
  const std::string path = dir.file("old.mslog");
  Pslg in;
  in.points = {{0, 0}, {4, 0}, {4, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
  in.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}, {4, 5, 0}, {5, 6, 0}, {6, 7, 0}, {7, 4, 0}};
  in.holes = {{1.5, 1.5}};
  replay::LogHeader header;
  header.parameters = "input_vertices=8 first_index=0";
  replay::describe_input(header, in);
  header.segments.clear();  // as an older meshstep wrote it
  replay::LogWriter writer(path, header);
  TriangulateOptions options;
  options.record = &writer;
  triangulate(in, options);
  writer.finish();

  const replay::LogReader log(path);
  const Scene s = scene_at_step(log, 0);
  ASSERT_TRUE(s.mesh.triangles.empty());
  ASSERT_NE(s.find("input_vertices"), nullptr);
  EXPECT_EQ(s.find("input_vertices")->points, in.points);
  EXPECT_EQ(s.find("segments"), nullptr);
  ASSERT_NE(s.find("holes"), nullptr);
  EXPECT_EQ(s.find("holes")->points, in.holes);
  EXPECT_NE(s.caption.find("input: 8 vertices, 1 hole"), std::string::npos) << s.caption;
}

}  // namespace
}  // namespace meshstep::scene
