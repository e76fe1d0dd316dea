// Reading and writing Triangle's file formats: well-formed files, round trips, real inputs.
// (Broken files are in test_triangle_io_malformed.cpp.)
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using namespace meshstep;

namespace {

using meshstep::testing::TempDir;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Doubles that are hard to print and read back: extremes, subnormals, negative zero,
// values with 17 significant digits, and random bit patterns over the whole range.
std::vector<double> nasty_doubles(std::size_t count, std::uint64_t seed) {
  std::vector<double> v = {0.0,
                           -0.0,
                           1e300,
                           -1e300,
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::lowest(),
                           std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::denorm_min(),
                           -std::numeric_limits<double>::denorm_min(),
                           2.2250738585072009e-308,  // largest subnormal
                           1e-320,
                           0.1,
                           0.1 + 0.2,
                           1.0 / 3.0,
                           123456789.12345678,
                           9007199254740993.0,
                           -2.5e-17};
  std::mt19937_64 rng(seed);
  while (v.size() < count) {
    const double d = std::bit_cast<double>(rng());
    if (std::isfinite(d)) v.push_back(d);
  }
  return v;
}

TriMesh unit_square_mesh() {
  // 3---2
  // | / |
  // 0---1   triangles (0,1,2) and (0,2,3), counterclockwise
  TriMesh m;
  m.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.input_vertex_count = 4;
  return m;
}

}  // namespace

TEST(TriangleIo, NodeRoundTripIsBitExact) {
  TempDir dir;
  const std::vector<double> values = nasty_doubles(3000, 12345);
  TriMesh m;
  m.attributes_per_vertex = 2;
  for (std::size_t i = 0; i + 3 < values.size(); i += 4) {
    m.points.push_back({values[i], values[i + 1]});
    m.vertex_attributes.push_back(values[i + 2]);
    m.vertex_attributes.push_back(values[i + 3]);
    m.vertex_markers.push_back(static_cast<int>(i) - 1000);
  }
  m.vertex_markers.front() = std::numeric_limits<int>::min();
  m.vertex_markers.back() = std::numeric_limits<int>::max();
  const std::string path = dir.file("nasty.node");
  io::write_node(path, m);
  const Pslg p = io::read_node(path);
  ASSERT_EQ(p.points.size(), m.points.size());
  ASSERT_EQ(p.vertex_attributes.size(), m.vertex_attributes.size());
  EXPECT_EQ(p.attributes_per_vertex, 2u);
  EXPECT_TRUE(p.has_vertex_markers);
  EXPECT_EQ(p.vertex_markers, m.vertex_markers);
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    ASSERT_TRUE(same_bits(p.points[i].x, m.points[i].x)) << i << " " << m.points[i].x;
    ASSERT_TRUE(same_bits(p.points[i].y, m.points[i].y)) << i << " " << m.points[i].y;
  }
  for (std::size_t i = 0; i < m.vertex_attributes.size(); ++i) {
    ASSERT_TRUE(same_bits(p.vertex_attributes[i], m.vertex_attributes[i])) << i;
  }
  // -0.0 keeps its sign (it is the second value written).
  EXPECT_TRUE(std::signbit(p.points[0].y));
  EXPECT_EQ(p.points[0].y, 0.0);
}

TEST(TriangleIo, WritersUseShortestForm) {
  TempDir dir;
  TriMesh m;
  m.points = {{0.1, -0.0}, {1e300, 5e-324}};
  m.first_index = 1;
  const std::string path = dir.file("short.node");
  io::write_node(path, m);
  EXPECT_EQ(slurp(path), "2 2 0 0\n1 0.1 -0\n2 1e+300 5e-324\n");
}

TEST(TriangleIo, ZeroAndOneBasedNumbering) {
  TempDir dir;
  const std::string zero = dir.write("zero.poly",
                                     "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n"
                                     "3 0\n0 0 1\n1 1 2\n2 2 0\n"
                                     "0\n");
  const std::string one = dir.write("one.poly",
                                    "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"
                                    "3 0\n1 1 2\n2 2 3\n3 3 1\n"
                                    "0\n");
  const Pslg a = io::read_poly(zero);
  const Pslg b = io::read_poly(one);
  EXPECT_EQ(a.first_index, 0);
  EXPECT_EQ(b.first_index, 1);
  ASSERT_EQ(a.segments.size(), 3u);
  ASSERT_EQ(b.segments.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    // Same 0-based segments in memory whatever the file's numbering.
    EXPECT_EQ(a.segments[i].a, i);
    EXPECT_EQ(b.segments[i].a, i);
    EXPECT_EQ(a.segments[i].b, (i + 1) % 3);
    EXPECT_EQ(b.segments[i].b, (i + 1) % 3);
  }
  EXPECT_EQ(a.points, b.points);
  EXPECT_FALSE(a.has_segment_markers);
}

TEST(TriangleIo, CommentsBlankLinesAndWhitespace) {
  TempDir dir;
  const std::string path = dir.write("c.node",
                                     "# leading comment\n"
                                     "\n"
                                     "   \t\n"
                                     "3 2 1 1   # header comment\r\n"
                                     "# between records\n"
                                     "1\t0.5 -1.5\t7 2#no space before the comment\n"
                                     "\n"
                                     "2 +3 4e2 -7 0\r\n"
                                     "  3 .5 5. 1e-3 -4   \n"
                                     "# trailing comment, no newline at the end");
  const Pslg p = io::read_node(path);
  ASSERT_EQ(p.points.size(), 3u);
  EXPECT_EQ(p.points[0], (Point{0.5, -1.5}));
  EXPECT_EQ(p.points[1], (Point{3.0, 400.0}));
  EXPECT_EQ(p.points[2], (Point{0.5, 5.0}));
  EXPECT_EQ(p.vertex_attributes, (std::vector<double>{7, -7, 1e-3}));
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{2, 0, -4}));
  EXPECT_EQ(p.first_index, 1);
}

TEST(TriangleIo, Utf8CommentsAndByteOrderMark) {
  TempDir dir;
  const std::string path = dir.write("u.node",
                                     "\xEF\xBB\xBF"
                                     "2 2 0 0 # caf\xC3\xA9, 4.1\xC2\xB0\n"
                                     "0 1 2\n1 3 4\n");
  const Pslg p = io::read_node(path);
  ASSERT_EQ(p.points.size(), 2u);
  EXPECT_EQ(p.points[1], (Point{3, 4}));
  EXPECT_EQ(p.first_index, 0);
}

TEST(TriangleIo, PolyWithMarkersHolesAndRegions) {
  TempDir dir;
  std::vector<std::string> warnings;
  const std::string path = dir.write("r.poly",
                                     "4 2 0 1\n"
                                     "1 0 0 5\n2 4 0 0\n3 4 4 0\n4 0 4 -2\n"
                                     "4 1\n1 1 2 10\n2 2 3 0\n3 3 4 -1\n4 4 1 2\n"
                                     "2\n1 1 1\n2 2.5 3\n"
                                     "2\n1 3 1 7 0.25\n2 1 3 -1.5 -1\n");
  const Pslg p = io::read_poly(path, &warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{5, 0, 0, -2}));
  ASSERT_EQ(p.segments.size(), 4u);
  EXPECT_TRUE(p.has_segment_markers);
  EXPECT_EQ(p.segments[0].marker, 10);
  EXPECT_EQ(p.segments[2].marker, -1);
  EXPECT_EQ(p.segments[3].a, 3u);
  EXPECT_EQ(p.segments[3].b, 0u);
  ASSERT_EQ(p.holes.size(), 2u);
  EXPECT_EQ(p.holes[1], (Point{2.5, 3}));
  ASSERT_EQ(p.regions.size(), 2u);
  EXPECT_EQ(p.regions[0].point, (Point{3, 1}));
  EXPECT_EQ(p.regions[0].attribute, 7);
  EXPECT_EQ(p.regions[0].max_area, 0.25);
  EXPECT_EQ(p.regions[1].attribute, -1.5);
  EXPECT_EQ(p.regions[1].max_area, -1);
}

TEST(TriangleIo, PolyWithoutRegionSectionAndShortRegions) {
  TempDir dir;
  const std::string no_regions =
      dir.write("a.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2\n0\n");
  const Pslg a = io::read_poly(no_regions);
  EXPECT_TRUE(a.regions.empty());
  EXPECT_TRUE(a.holes.empty());

  // Four numbers per region (as in Triangle's la.poly): the one value is both attribute and
  // area bound, and the reader says so once.
  std::vector<std::string> warnings;
  const std::string short_regions = dir.write(
      "b.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2\n0\n2\n1 0.2 0.2 0.05\n2 0.1 0.1 3\n");
  const Pslg b = io::read_poly(short_regions, &warnings);
  ASSERT_EQ(b.regions.size(), 2u);
  EXPECT_EQ(b.regions[0].attribute, 0.05);
  EXPECT_EQ(b.regions[0].max_area, 0.05);
  EXPECT_EQ(b.regions[1].max_area, 3);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].rfind(short_regions + ":9: ", 0), 0u) << warnings[0];
}

TEST(TriangleIo, EmptyPolyVertexSectionReadsNodeBeside) {
  TempDir dir;
  dir.write("shape.node", "3 2 1 1\n0 0 0 9 1\n1 2 0 8 1\n2 0 2 7 0\n");
  const std::string poly = dir.write("shape.poly",
                                     "0 2 0 1  # vertices are in shape.node\n"
                                     "2 1\n0 0 1 3\n1 1 2 4\n"
                                     "1\n0 0.25 0.25\n");
  const Pslg p = io::read_pslg(poly);
  ASSERT_EQ(p.points.size(), 3u);
  EXPECT_EQ(p.points[1], (Point{2, 0}));
  EXPECT_EQ(p.vertex_attributes, (std::vector<double>{9, 8, 7}));
  EXPECT_EQ(p.vertex_markers, (std::vector<int>{1, 1, 0}));
  EXPECT_EQ(p.first_index, 0);
  ASSERT_EQ(p.segments.size(), 2u);
  EXPECT_EQ(p.segments[1].b, 2u);
  EXPECT_EQ(p.segments[1].marker, 4);
  ASSERT_EQ(p.holes.size(), 1u);
}

TEST(TriangleIo, ZeroLengthAndDuplicateSegmentsAreDroppedWithWarnings) {
  TempDir dir;
  std::vector<std::string> warnings;
  const std::string path = dir.write("d.poly",
                                     "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"
                                     "5 0\n"
                                     "1 1 2\n"
                                     "2 2 2\n"   // line 7: zero length
                                     "3 2 3\n"
                                     "4 2 1\n"   // line 9: duplicate of segment 1, reversed
                                     "5 3 1\n"
                                     "0\n");
  const Pslg p = io::read_poly(path, &warnings);
  ASSERT_EQ(p.segments.size(), 3u);
  EXPECT_EQ(p.segments[2].a, 2u);
  EXPECT_EQ(p.segments[2].b, 0u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].rfind(path + ":7: ", 0), 0u) << warnings[0];
  EXPECT_NE(warnings[0].find("itself"), std::string::npos) << warnings[0];
  EXPECT_EQ(warnings[1].rfind(path + ":9: ", 0), 0u) << warnings[1];
  EXPECT_NE(warnings[1].find("duplicates segment 1"), std::string::npos) << warnings[1];
  // Without a warnings vector the same file reads the same.
  EXPECT_EQ(io::read_poly(path).segments.size(), 3u);
}

TEST(TriangleIo, ReadMeshWithAreaAndPoly) {
  TempDir dir;
  dir.write("m.node", "4 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n");
  dir.write("m.ele", "2 3 1\n1 1 2 3 0.5\n2 1 3 4 -2\n");
  dir.write("m.poly", "0 2 0 1\n1 1\n1 4 1 6\n1\n1 9 9\n");
  dir.write("m.area", "2\n1 0.125\n2 -1\n");
  const TriMesh m = io::read_mesh(dir.file("m"));
  EXPECT_EQ(m.first_index, 1);
  ASSERT_EQ(m.points.size(), 4u);
  EXPECT_EQ(m.input_vertex_count, 4u);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
  EXPECT_EQ(m.attributes_per_triangle, 1u);
  EXPECT_EQ(m.triangle_attributes, (std::vector<double>{0.5, -2}));
  EXPECT_EQ(m.triangle_max_area, (std::vector<double>{0.125, -1}));
  ASSERT_EQ(m.segments.size(), 1u);
  EXPECT_EQ(m.segments[0].a, 3u);
  EXPECT_EQ(m.segments[0].b, 0u);
  EXPECT_EQ(m.segments[0].marker, 6);
  ASSERT_EQ(m.holes.size(), 1u);
  EXPECT_EQ(m.vertex_markers, (std::vector<int>{1, 1, 1, 1}));
}

TEST(TriangleIo, ReadMeshWithoutOptionalFiles) {
  TempDir dir;
  dir.write("m.node", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n");
  dir.write("m.ele", "1 3 0\n0 0 1 2\n");
  const TriMesh m = io::read_mesh(dir.file("m"));
  EXPECT_EQ(m.first_index, 0);
  EXPECT_TRUE(m.segments.empty());
  EXPECT_TRUE(m.triangle_max_area.empty());
  EXPECT_TRUE(m.vertex_markers.empty());
  EXPECT_EQ(m.triangles.size(), 1u);
}

TEST(TriangleIo, SixNodeTrianglesKeepCorners) {
  TempDir dir;
  std::vector<std::string> warnings;
  dir.write("q.node", "6 2 0 0\n1 0 0\n2 2 0\n3 0 2\n4 1 0\n5 1 1\n6 0 1\n");
  dir.write("q.ele", "1 6 0\n1 1 2 3 5 6 4\n");
  const TriMesh m = io::read_mesh(dir.file("q"), &warnings);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(warnings.size(), 1u);
}

TEST(TriangleIo, ComputeNeighborsOppositeVertex) {
  const TriMesh m = unit_square_mesh();
  const auto n = io::compute_neighbors(m);
  ASSERT_EQ(n.size(), 2u);
  // Triangle 0 = (0,1,2): the edge opposite vertex 1 (edge 2-0) is shared with triangle 1.
  EXPECT_EQ(n[0], (std::array<std::uint32_t, 3>{kNoIndex, 1, kNoIndex}));
  // Triangle 1 = (0,2,3): the edge opposite vertex 3 (edge 0-2) is shared with triangle 0.
  EXPECT_EQ(n[1], (std::array<std::uint32_t, 3>{kNoIndex, kNoIndex, 0}));
}

TEST(TriangleIo, ComputeNeighborsOnAFanAndANonManifoldEdge) {
  TriMesh fan;
  // A closed fan of 8 triangles around vertex 0: every triangle has 2 neighbours.
  fan.points.resize(9);
  for (std::uint32_t i = 0; i < 8; ++i) fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % 8});
  const auto n = io::compute_neighbors(fan);
  for (std::uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(n[i][0], kNoIndex);
    EXPECT_EQ(n[i][1], (i + 1) % 8) << i;  // opposite vertex 1+i: edge 0 -- 1+(i+1)%8
    EXPECT_EQ(n[i][2], (i + 7) % 8) << i;
  }
  TriMesh three;  // three triangles on edge 0-1: none is anybody's neighbour there
  three.points.resize(5);
  three.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  for (const auto& t : io::compute_neighbors(three)) {
    EXPECT_EQ(t, (std::array<std::uint32_t, 3>{kNoIndex, kNoIndex, kNoIndex}));
  }
}

TEST(TriangleIo, ComputeNeighborsMatchesBruteForce) {
  // Random triangles over few vertices: many shared edges, some shared by 3+ triangles.
  std::mt19937 rng(3);
  TriMesh m;
  m.points.resize(12);
  for (int t = 0; t < 60; ++t) {
    std::uint32_t a = rng() % 12, b = rng() % 12, c = rng() % 12;
    if (a == b || b == c || a == c) continue;
    m.triangles.push_back({a, b, c});
  }
  // Also a triangle with vertex indices near 2^32 (a broken mesh must not cost memory).
  m.triangles.push_back({4000000000u, 4000000001u, 5});
  m.triangles.push_back({4000000001u, 4000000000u, 7});
  const auto n = io::compute_neighbors(m);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = m.triangles[t][(i + 1) % 3];
      const std::uint32_t b = m.triangles[t][(i + 2) % 3];
      std::vector<std::uint32_t> sharing;
      for (std::size_t u = 0; u < m.triangles.size(); ++u) {
        if (u == t) continue;
        const auto& v = m.triangles[u];
        const bool has_a = v[0] == a || v[1] == a || v[2] == a;
        const bool has_b = v[0] == b || v[1] == b || v[2] == b;
        if (has_a && has_b) sharing.push_back(static_cast<std::uint32_t>(u));
      }
      const std::uint32_t expected = sharing.size() == 1 ? sharing[0] : kNoIndex;
      EXPECT_EQ(n[t][i], expected) << "triangle " << t << " side " << i;
    }
  }
  EXPECT_EQ(n[n.size() - 1][2], n.size() - 2);
}

TEST(TriangleIo, EdgeFileMarksBoundaryAndSegments) {
  TempDir dir;
  TriMesh m = unit_square_mesh();
  m.first_index = 1;
  m.segments = {{1, 2, 7}, {0, 2, 0}};  // one boundary segment, the diagonal constrained
  const std::string path = dir.file("s.edge");
  io::write_edge(path, m);
  const io::EdgeList e = io::read_edge(path, m);
  ASSERT_EQ(e.edges.size(), 5u);
  EXPECT_TRUE(e.has_markers);
  int boundary = 0;
  for (const Segment& s : e.edges) {
    const auto lo = std::min(s.a, s.b);
    const auto hi = std::max(s.a, s.b);
    if (lo == 1 && hi == 2) {
      EXPECT_EQ(s.marker, 7);  // the segment's own marker
    } else if (lo == 0 && hi == 2) {
      EXPECT_EQ(s.marker, 1);  // constrained interior edge with marker 0
    } else {
      EXPECT_EQ(s.marker, 1);
      ++boundary;
    }
  }
  EXPECT_EQ(boundary, 3);
  // Without segments the diagonal is an ordinary interior edge.
  m.segments.clear();
  io::write_edge(path, m);
  EXPECT_EQ(slurp(path), "5 1\n1 2 3 1\n2 3 1 0\n3 1 2 1\n4 3 4 1\n5 4 1 1\n");
}

TEST(TriangleIo, NeighFileRoundTrip) {
  TempDir dir;
  TriMesh m = unit_square_mesh();
  const std::string path = dir.file("s.neigh");
  io::write_neigh(path, m);  // neighbors empty: computed
  EXPECT_EQ(slurp(path), "2 3\n0 -1 1 -1\n1 -1 -1 0\n");
  EXPECT_EQ(io::read_neigh(path, m), io::compute_neighbors(m));
  m.first_index = 1;
  io::write_neigh(path, m);
  EXPECT_EQ(slurp(path), "2 3\n1 -1 2 -1\n2 -1 -1 1\n");
  EXPECT_EQ(io::read_neigh(path, m), io::compute_neighbors(m));
}

TEST(TriangleIo, WriteMeshThenReadMeshIsEqual) {
  TempDir dir;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-1e3, 1e3);
  TriMesh m;
  // A 20 x 20 grid of jittered points, two triangles per cell.
  const std::uint32_t k = 20;
  m.attributes_per_vertex = 1;
  for (std::uint32_t j = 0; j < k; ++j) {
    for (std::uint32_t i = 0; i < k; ++i) {
      m.points.push_back({i + coord(rng) * 1e-6, j + coord(rng) * 1e-6});
      m.vertex_attributes.push_back(coord(rng));
      m.vertex_markers.push_back((i == 0 || j == 0 || i == k - 1 || j == k - 1) ? 1 : 0);
    }
  }
  m.attributes_per_triangle = 1;
  for (std::uint32_t j = 0; j + 1 < k; ++j) {
    for (std::uint32_t i = 0; i + 1 < k; ++i) {
      const std::uint32_t a = j * k + i;
      m.triangles.push_back({a, a + 1, a + k + 1});
      m.triangles.push_back({a, a + k + 1, a + k});
      m.triangle_attributes.push_back(coord(rng));
      m.triangle_attributes.push_back(coord(rng));
      m.triangle_max_area.push_back(i % 2 ? coord(rng) : -1.0);
      m.triangle_max_area.push_back(0.5);
    }
  }
  for (std::uint32_t i = 0; i + 1 < k; ++i) m.segments.push_back({i, i + 1, 3});
  m.has_segment_markers = true;
  m.holes = {{0.5, 0.5}};
  m.regions = {{{2.5, 2.5}, 4.0, 0.01}, {{5.5, 2.5}, -0.0, -1.0}};
  m.input_vertex_count = m.points.size();
  m.first_index = 1;

  const std::string prefix = dir.file("grid.1");
  io::write_mesh(prefix, m, io::WriteOptions{true, true});
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"grid.1.area", "grid.1.edge", "grid.1.ele",
                                                      "grid.1.neigh", "grid.1.node",
                                                      "grid.1.poly"}));
  const TriMesh r = io::read_mesh(prefix);
  EXPECT_EQ(r.points, m.points);
  EXPECT_EQ(r.attributes_per_vertex, m.attributes_per_vertex);
  EXPECT_EQ(r.vertex_attributes, m.vertex_attributes);
  EXPECT_EQ(r.vertex_markers, m.vertex_markers);
  EXPECT_EQ(r.triangles, m.triangles);
  EXPECT_EQ(r.attributes_per_triangle, m.attributes_per_triangle);
  EXPECT_EQ(r.triangle_attributes, m.triangle_attributes);
  EXPECT_EQ(r.triangle_max_area, m.triangle_max_area);
  ASSERT_EQ(r.segments.size(), m.segments.size());
  for (std::size_t i = 0; i < m.segments.size(); ++i) {
    EXPECT_EQ(r.segments[i].a, m.segments[i].a);
    EXPECT_EQ(r.segments[i].b, m.segments[i].b);
    EXPECT_EQ(r.segments[i].marker, m.segments[i].marker);
  }
  EXPECT_TRUE(r.has_segment_markers);
  EXPECT_EQ(r.holes, m.holes);
  ASSERT_EQ(r.regions.size(), 2u);
  EXPECT_EQ(r.regions[0].point, m.regions[0].point);
  EXPECT_EQ(r.regions[0].max_area, 0.01);
  EXPECT_TRUE(std::signbit(r.regions[1].attribute));
  EXPECT_EQ(r.first_index, 1);
  EXPECT_EQ(r.input_vertex_count, m.points.size());

  // The optional files agree with the mesh too.
  EXPECT_EQ(io::read_neigh(prefix + ".neigh", r), io::compute_neighbors(m));
  const std::size_t edges = io::read_edge(prefix + ".edge", r).edges.size();
  EXPECT_EQ(edges, 3u * (k - 1) * (k - 1) + 2u * (k - 1));  // V - 1 + T edges (Euler)
}

TEST(TriangleIo, FailedWriteLeavesTargetUntouchedAndNoTemporaryFile) {
  TempDir dir;
  TriMesh m = unit_square_mesh();
  const std::string path = dir.file("keep.node");
  io::write_node(path, m);
  const std::string before = slurp(path);
  m.points[3].y = std::nan("");
  try {
    io::write_node(path, m);
    FAIL() << "a NaN coordinate was written";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(path), before);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"keep.node"}));

  m = unit_square_mesh();
  m.triangles[1][2] = 17;  // past the last vertex
  EXPECT_THROW(io::write_ele(dir.file("bad.ele"), m), InputError);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"keep.node"}));
}

TEST(TriangleIo, CannotOpenOrWriteReportsLineZero) {
  TempDir dir;
  const std::string missing = dir.file("missing.node");
  try {
    io::read_node(missing);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open: No such file or directory");
  }
  const std::string nowhere = dir.file("no/such/folder/x.node");
  try {
    io::write_node(nowhere, unit_square_mesh());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 0u);
    EXPECT_EQ(e.file(), nowhere);
    EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos);
  }
  EXPECT_THROW(io::read_mesh(dir.file("nothing")), InputError);
  try {
    io::read_pslg(dir.file("x.txt"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".node or .poly"), std::string::npos);
  }
}

TEST(TriangleIo, LargeNodeFileStreamsAcrossChunks) {
  // 1,000,000 vertices (about 40 MB): many 1 MiB chunk boundaries fall inside lines.
  TempDir dir;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  TriMesh m;
  const std::size_t n = 1000000;
  m.points.reserve(n);
  m.vertex_markers.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    m.points.push_back({coord(rng), coord(rng)});
    m.vertex_markers.push_back(static_cast<int>(i % 3));
  }
  m.first_index = 1;
  const std::string path = dir.file("big.node");
  const auto t0 = std::chrono::steady_clock::now();
  io::write_node(path, m);
  const auto t1 = std::chrono::steady_clock::now();
  const Pslg p = io::read_node(path);
  const auto t2 = std::chrono::steady_clock::now();
  using ms = std::chrono::duration<double, std::milli>;
  std::printf("[ timing   ] %zu vertices, %.1f MB: write %.0f ms, read %.0f ms\n", n,
              static_cast<double>(fs::file_size(path)) / 1e6, ms(t1 - t0).count(),
              ms(t2 - t1).count());
  ASSERT_EQ(p.points.size(), n);
  EXPECT_TRUE(p.points == m.points);
  EXPECT_TRUE(p.vertex_markers == m.vertex_markers);
}

TEST(TriangleIo, LongLinesAcrossChunksKeepLineNumbers) {
  // Comment lines of 900 kB put record lines across the 1 MiB chunk boundaries; the error on
  // the last line must still name the right line.
  TempDir dir;
  const std::string comment = "#" + std::string(900000, 'c') + "\n";
  std::string text = "4 2 0 0\n" + comment + "1 0.5 0.25\n" + comment + "2 1 2\n" + comment +
                     "3 3 4\n";
  const std::string good = dir.write("long.node", text + "4 5 6\n");
  const Pslg p = io::read_node(good);
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_EQ(p.points[0], (Point{0.5, 0.25}));
  EXPECT_EQ(p.points[3], (Point{5, 6}));
  const std::string bad = dir.write("long_bad.node", text + "4 5 six\n");
  try {
    io::read_node(bad);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 8u) << e.what();
  }
}

TEST(TriangleIo, ReadsFromAPipe) {
  // A FIFO has no size to check counts against: the reader must still stream it.
  TempDir dir;
  const std::string fifo = dir.file("pipe.node");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string text = "3000 2 0 1\n";
  for (int i = 1; i <= 3000; ++i) {
    text += std::to_string(i) + " " + std::to_string(i * 0.5) + " -" + std::to_string(i) + " 1\n";
  }
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << text; });
  Pslg p;
  EXPECT_NO_THROW(p = io::read_node(fifo));
  writer.join();
  ASSERT_EQ(p.points.size(), 3000u);
  EXPECT_EQ(p.points[2999], (Point{1500, -3000}));
}

TEST(TriangleIo, SharedDataFilesRead) {
  const fs::path dir = fs::path(MESHSTEP_SHARED_DATA) / "pslg";
  if (!fs::is_directory(dir)) GTEST_SKIP() << "shared data folder " << dir << " is absent";
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string ext = entry.path().extension();
    if (ext != ".poly" && ext != ".node") continue;
    std::vector<std::string> warnings;
    Pslg p;
    ASSERT_NO_THROW(p = io::read_pslg(entry.path().string(), &warnings)) << entry.path();
    EXPECT_FALSE(p.points.empty()) << entry.path();
    if (ext == ".poly") {
      EXPECT_FALSE(p.segments.empty()) << entry.path();
    }
    for (const auto& w : warnings) std::printf("[ warning  ] %s\n", w.c_str());
    ++files;
  }
  EXPECT_GT(files, 30u);

  const TriMesh g = io::read_mesh((dir / "greenland").string());
  EXPECT_EQ(g.points.size(), 33343u);
  EXPECT_EQ(g.triangles.size(), 64125u);
  EXPECT_EQ(g.first_index, 1);
  EXPECT_EQ(g.triangles[0], (std::array<std::uint32_t, 3>{8663, 8664, 8660}));
  EXPECT_EQ(g.points[1], (Point{106.5, 40}));

  const TriMesh b = io::read_mesh((dir / "bbox.1").string());
  EXPECT_EQ(b.triangles.size(), 12u);
  ASSERT_EQ(b.triangle_max_area.size(), 12u);
  EXPECT_EQ(b.triangle_max_area[2], 0.02);
  EXPECT_EQ(b.vertex_markers[3], 33);

  const Pslg a = io::read_poly((dir / "A.poly").string());
  EXPECT_EQ(a.points.size(), 29u);
  EXPECT_EQ(a.attributes_per_vertex, 1u);
  EXPECT_EQ(a.segments.size(), 29u);
  EXPECT_EQ(a.holes.size(), 1u);
}
