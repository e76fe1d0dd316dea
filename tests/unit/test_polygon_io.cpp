// GeoJSON and WKT polygons as PSLGs (io/polygon_io.hpp): holes become holes, wherever
// their centroid falls; nested rings alternate (even-odd); shared borders stay inside; and
// every malformed file is an InputError at the right FILE:LINE, never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/polygon_io.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/quality.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::TempDir;

double mesh_area(const TriMesh& m) {
  double a = 0;
  for (const auto& t : m.triangles) a += 0.5 * quality::twice_area(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
  return a;
}

// Even-odd point-in-polygon, for the test's own check of a hole point.
bool inside(const std::vector<Point>& ring, Point p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i].y > p.y) != (ring[j].y > p.y) &&
        p.x < (ring[j].x - ring[i].x) * (p.y - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x)
      in = !in;
  return in;
}

Pslg read(const TempDir& dir, const std::string& name, const std::string& text,
          std::vector<std::string>* warnings = nullptr) {
  return io::read_pslg(dir.write(name, text), warnings);
}

// A 4 x 4 square with a C-shaped hole whose centroid (2, 2) lies in the C's mouth, outside
// the hole: a hole point at the centroid would remove nothing.
constexpr const char* kSquareWithCHole = R"({"type": "Polygon", "coordinates": [
  [[0,0],[4,0],[4,4],[0,4],[0,0]],
  [[1,1],[3,1],[3,1.5],[1.5,1.5],[1.5,2.5],[3,2.5],[3,3],[1,3],[1,1]]
]})";
const std::vector<Point> kCHole = {{1, 1}, {3, 1}, {3, 1.5}, {1.5, 1.5}, {1.5, 2.5}, {3, 2.5}, {3, 3}, {1, 3}};
constexpr double kCHoleArea = 2 * 2 - 1.5 * 1;

TEST(PolygonIo, GeoJsonHoleGetsAPointInsideItEvenWhenItsCentroidIsOutside) {
  TempDir dir;
  const Pslg p = read(dir, "c.geojson", kSquareWithCHole);
  EXPECT_EQ(p.points.size(), 12u);
  ASSERT_EQ(p.segments.size(), 12u);
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_TRUE(inside(kCHole, p.holes[0])) << p.holes[0].x << ", " << p.holes[0].y;
  int shell = 0, hole = 0;
  for (const Segment& s : p.segments) (s.marker == 1 ? shell : hole) += 1;
  EXPECT_EQ(shell, 4);
  EXPECT_EQ(hole, 8);
  EXPECT_DOUBLE_EQ(mesh_area(triangulate(p)), 16 - kCHoleArea);
}

TEST(PolygonIo, WktReadsTheSamePolygon) {
  TempDir dir;
  const Pslg p = read(dir, "c.wkt",
                      "polygon ((0 0, 4 0, 4 4, 0 4, 0 0),\n"
                      "  (1 1, 3 1, 3 1.5, 1.5 1.5, 1.5 2.5, 3 2.5, 3 3, 1 3, 1 1))\n");
  ASSERT_EQ(p.holes.size(), 1u);
  EXPECT_TRUE(inside(kCHole, p.holes[0]));
  EXPECT_DOUBLE_EQ(mesh_area(triangulate(p)), 16 - kCHoleArea);
}

// A 10 x 10 shell with a 6 x 6 lake, and in the lake a 2 x 2 island with a 1 x 1 pond: the
// island is land again, the pond water. Whatever hole point the lake gets must not fall on
// the island (it would remove it).
TEST(PolygonIo, IslandInALakeStaysAndItsPondGoes) {
  TempDir dir;
  const std::string geojson = R"({"type": "MultiPolygon", "coordinates": [
    [[[0,0],[10,0],[10,10],[0,10],[0,0]], [[2,2],[8,2],[8,8],[2,8],[2,2]]],
    [[[4,4],[6,4],[6,6],[4,6],[4,4]], [[4.5,4.5],[5.5,4.5],[5.5,5.5],[4.5,5.5],[4.5,4.5]]]
  ]})";
  const double expected = 100 - 36 + 4 - 1;
  EXPECT_DOUBLE_EQ(mesh_area(triangulate(read(dir, "lake.geojson", geojson))), expected);
  const Pslg w = read(dir, "lake.wkt",
                      "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 8 2, 8 8, 2 8, 2 2)),\n"
                      "((4 4, 6 4, 6 6, 4 6, 4 4), (4.5 4.5, 5.5 4.5, 5.5 5.5, 4.5 5.5, 4.5 4.5)))");
  EXPECT_EQ(w.holes.size(), 2u);
  EXPECT_DOUBLE_EQ(mesh_area(triangulate(w)), expected);
}

// Adjacent parcels share a border: that edge, used twice, separates no hole. They share the
// vertices of it too.
TEST(PolygonIo, AdjacentFeaturesShareTheirBorderWithoutAHole) {
  TempDir dir;
  std::vector<std::string> warnings;
  const Pslg p = read(dir, "parcels.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "a"}, "geometry":
      {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,1],[0,0]]]}},
    {"type": "Feature", "properties": null, "geometry":
      {"type": "Polygon", "coordinates": [[[1,0],[2,0],[2,1],[1,1],[1,0]]]}},
    {"type": "Feature", "properties": {}, "geometry": null},
    {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [5, 5]}}
  ]})", &warnings);
  EXPECT_EQ(p.points.size(), 6u);
  EXPECT_EQ(p.segments.size(), 7u);
  EXPECT_TRUE(p.holes.empty());
  EXPECT_DOUBLE_EQ(mesh_area(triangulate(p)), 2.0);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("parcels.geojson:6: a Feature without a geometry"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("parcels.geojson:7: a Point is not a polygon"), std::string::npos) << warnings[1];
}

// A zero-width spike, as real coastlines have: the ring goes down a line and back up it,
// over segments that overlap. Each piece is run twice, so crossing it changes nothing: no
// hole, the whole square meshed.
TEST(PolygonIo, ASpikeThatDoublesBackMakesNoHole) {
  TempDir dir;
  const Pslg p = read(dir, "spike.wkt", "POLYGON ((0 0, 4 0, 4 4, 2 4, 2 1, 2 3, 2 4, 0 4, 0 0))");
  EXPECT_TRUE(p.holes.empty()) << p.holes.size() << " holes, the first at " << p.holes[0].x << ", " << p.holes[0].y;
  EXPECT_DOUBLE_EQ(mesh_area(triangulate(p)), 16.0);
  // And the same spike into a hole: the hole is still one hole.
  const Pslg h = read(dir, "spike_hole.wkt",
                      "POLYGON ((0 0, 8 0, 8 8, 0 8, 0 0), (2 2, 6 2, 6 6, 4 6, 4 3, 4 5, 4 6, 2 6, 2 2))");
  EXPECT_EQ(h.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(mesh_area(triangulate(h)), 64.0 - 16.0);
}

TEST(PolygonIo, WktVariantsReadTheSameSquare) {
  TempDir dir;
  for (const char* text : {"POLYGON((0 0,1 0,1 1,0 1,0 0))", "POLYGON Z ((0 0 5, 1 0 5, 1 1 5, 0 1 5, 0 0 5))",
                           "SRID=4326;Polygon ((0 0, 1 0, 1 1, 0 1))", "POLYGON EMPTY\nPOLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))",
                           "GEOMETRYCOLLECTION (POINT (3 3), POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0)))",
                           "MULTIPOLYGON (EMPTY, ((0 0, 1 0, 1 1, 0 1, 0 0)))"}) {
    const Pslg p = read(dir, "v.wkt", text);
    EXPECT_EQ(p.points.size(), 4u) << text;
    EXPECT_EQ(p.segments.size(), 4u) << text;
    EXPECT_DOUBLE_EQ(mesh_area(triangulate(p)), 1.0) << text;
  }
}

struct Malformed {
  const char* name;
  const char* text;
  std::size_t line;
  const char* message;  // a part of what() after "FILE:LINE: "
};

void expect_refused(const Malformed& m) {
  TempDir dir;
  const std::string path = dir.write(m.name, m.text);
  try {
    io::read_pslg(path);
    ADD_FAILURE() << m.name << ": accepted " << m.text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), m.line) << e.what();
    const std::string where = m.line ? path + ":" + std::to_string(m.line) + ": " : path + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
    EXPECT_NE(e.message().find(m.message), std::string::npos) << e.what();
  }
}

TEST(PolygonIo, MalformedGeoJsonIsRefusedAtItsLine) {
  const std::string deep = std::string(3000, '[') + std::string(3000, ']');
  const Malformed cases[] = {
      {"empty.geojson", "", 1, "unexpected end of file"},
      {"trailing_comma.geojson", "{\"type\": \"Polygon\",\n \"coordinates\": [[[0,0],[1,0],[0,1],]]}", 2, "expected a JSON value"},
      {"unclosed.geojson", "{\"type\": \"Polygon\",\n\"coordinates\": [[[0,0],[1,0],[0,1]]\n", 3, "expected ',' or ']'"},
      {"type.geojson", "{\"type\": \"Polygn\", \"coordinates\": []}", 1, "unknown GeoJSON type \"Polygn\""},
      {"no_type.geojson", "\n{\"coordinates\": []}", 2, "no \"type\" member"},
      {"two_points.geojson", "{\"type\": \"Polygon\", \"coordinates\": [\n[[0,0],[1,1],[0,0]]]}", 2,
       "at least 3 distinct vertices"},
      {"string.geojson", "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,\"0\"],[0,1]]]}", 1,
       "coordinates are numbers, found a string"},
      {"short.geojson", "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1],[0,1]]]}", 1, "two or more numbers"},
      {"nan.geojson", "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[NaN,0],[0,1]]]}", 1, "expected a JSON value"},
      {"zero.geojson", "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[01,0],[0,1]]]}", 1, "start with 0"},
      {"huge.geojson", "{\"type\": \"Polygon\",\n\"coordinates\": [[[0,0],[1e999,0],[0,1]]]}", 2, "too large"},
      {"deep.geojson", deep.c_str(), 1, "nesting deeper"},
      {"escape.geojson", "{\"type\": \"Poly\\qgon\"}", 1, "unknown escape"},
      {"after.geojson", "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[1,0],[0,1]]]}\n}", 2, "after the JSON value"},
      {"features.geojson", "{\"type\": \"FeatureCollection\", \"features\": [\n{\"type\": \"Polygon\"}]}", 2,
       "must be a Feature"},
      {"points.geojson", "{\"type\": \"Point\", \"coordinates\": [0, 0]}", 0, "no polygon"},
      {"flat.geojson", "{\"type\": \"Polygon\",\n\"coordinates\": [0, 0, 1, 0, 0, 1]}", 2,
       "expected an array of rings (arrays of positions), found an array of numbers"},
      {"flat_ring.geojson", "{\"type\": \"Polygon\", \"coordinates\": [[0, 0, 1, 0, 0, 1]]}", 1,
       "expected an array of positions [x, y], found an array of numbers"},
      {"flat_multi.geojson", "{\"type\": \"MultiPolygon\", \"coordinates\": [1]}", 1, "found an array of numbers"},
      {"flat_features.geojson", "{\"type\": \"FeatureCollection\", \"features\": [1, 2]}", 1,
       "expected an array of Features"},
      {"empty_position.geojson", "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[],[0,1]]]}", 1,
       "two or more numbers"},
  };
  for (const Malformed& m : cases) expect_refused(m);
}

TEST(PolygonIo, MalformedWktIsRefusedAtItsLine) {
  const Malformed cases[] = {
      {"empty.wkt", "\n\n", 0, "no polygon"},
      {"unclosed.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 0)\n", 2, "',' or ')' in a polygon"},
      {"letter.wkt", "POLYGON ((0 0,\n 1 x, 1 1, 0 0))", 2, "expected a finite number"},
      {"circle.wkt", "\nCIRCLE (0 0, 1)", 2, "unknown geometry CIRCLE"},
      {"two.wkt", "POLYGON ((0 0, 1 1, 0 0))", 1, "at least 3 distinct vertices"},
      {"hole.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 0),\n(1 1, 1 1, 1 1))", 2, "a hole ring needs at least 3"},
      {"inf.wkt", "POLYGON ((0 0, inf 0, 1 1, 0 0))", 1, "expected a finite number"},
      {"modifier.wkt", "POLYGON Q ((0 0, 1 0, 1 1, 0 0))", 1, "unexpected 'Q'"},
      {"nothing.wkt", "POLYGON", 1, "expected '(' to open a polygon"},
      {"open.wkt", "LINESTRING (0 0, 1 1", 1, "never closed"},
      // fuzz_polygons' first finding: two spikes, no area.
      {"spikes.wkt", "\nPOLYGON ((0 1,1  3 1, 0 1, 1 1))", 2, "runs back over itself: it has only 2 distinct segments"},
  };
  for (const Malformed& m : cases) expect_refused(m);
}

// The two readers share one number scanner: the same numbers read the same, in either
// syntax. An underflow is 0 (as strtod rounds it) in both; an overflow is refused in both.
TEST(PolygonIo, WktAndGeoJsonReadTheSameNumbers) {
  TempDir dir;
  const Pslg w = read(dir, "n.wkt", "POLYGON ((0 0, 2 1e-400, 4 0, 0.5e1 +5E-1, -0 4, 0 0))");
  const Pslg j = read(dir, "n.geojson", R"({"type": "Polygon", "coordinates": [
    [[0,0],[2,1e-400],[4,0],[0.5e1,5E-1],[-0,4],[0,0]]]})");
  ASSERT_EQ(w.points.size(), j.points.size());
  for (std::size_t i = 0; i < w.points.size(); ++i) {
    EXPECT_EQ(w.points[i].x, j.points[i].x) << i;
    EXPECT_EQ(w.points[i].y, j.points[i].y) << i;
  }
  EXPECT_NE(std::find(w.points.begin(), w.points.end(), Point{5, 0.5}), w.points.end());
  EXPECT_NE(std::find(w.points.begin(), w.points.end(), Point{2, 0}), w.points.end());
  expect_refused({"huge.wkt", "POLYGON ((0 0,\n1e999 0, 1 1, 0 0))", 2, "expected a finite number"});
}

}  // namespace
}  // namespace meshstep

namespace meshstep {
namespace {

// Real water polygons (OpenStreetMap, via mapbox/earcut's fixtures, kept in ../shared/data
// as .poly files whose segments run ring after ring, the shell first): written back as a
// GeoJSON Polygon, read by read_geojson, meshed. Each hole ring of the data holds a hole
// point, and the mesh's area is the polygon's (shell's area less the holes'), to the little
// the data's crossing rings and zero-width spikes make of it. (The .poly's own hole points,
// one per hole ring, leave the pockets its spikes enclose in the mesh: its area is twice
// the polygon's, so it is no reference.)
TEST(PolygonIoSharedData, WaterPolygonsAsGeoJsonHaveTheirHoles) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(MESHSTEP_SHARED_DATA) / "pslg";
  if (!fs::exists(dir / "earcut_water.poly")) GTEST_SKIP() << "no shared data at " << dir << ": water polygons skipped";
  TempDir tmp;
  for (const char* name : {"earcut_water.poly", "earcut_water2.poly"}) {
    const Pslg poly = io::read_poly((dir / name).string());
    std::vector<std::vector<Point>> rings;
    std::size_t start = 0;
    for (std::size_t s = 0; s < poly.segments.size(); ++s) {
      if (s == start) rings.emplace_back();
      rings.back().push_back(poly.points[poly.segments[s].a]);
      if (poly.segments[s].b == poly.segments[start].a) start = s + 1;
    }
    ASSERT_EQ(start, poly.segments.size()) << name << ": the segments are not closed rings";
    std::string json = "{\"type\": \"Polygon\", \"coordinates\": [";
    double polygon_area = 0;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      json += r ? ",\n[" : "\n[";
      for (const Point& p : rings[r]) json += "[" + io::shortest_text(p.x) + "," + io::shortest_text(p.y) + "],";
      json += "[" + io::shortest_text(rings[r][0].x) + "," + io::shortest_text(rings[r][0].y) + "]]";
      double twice = 0;
      for (std::size_t i = 0, j = rings[r].size() - 1; i < rings[r].size(); j = i++)
        twice += rings[r][j].x * rings[r][i].y - rings[r][i].x * rings[r][j].y;
      polygon_area += (r == 0 ? 0.5 : -0.5) * std::fabs(twice);
    }
    json += "]}";
    const Pslg geo = io::read_geojson(tmp.write("water.geojson", json));
    for (std::size_t r = 1; r < rings.size(); ++r) {
      bool found = false;
      for (const Point& h : geo.holes) found = found || inside(rings[r], h);
      EXPECT_TRUE(found) << name << ": hole ring " << r << " has no hole point";
    }
    EXPECT_NEAR(mesh_area(triangulate(geo)), polygon_area, 1e-3 * polygon_area) << name;
  }
}

}  // namespace
}  // namespace meshstep
