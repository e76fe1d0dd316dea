// Triangle surfaces in 3D (io/surface_io.hpp): every format written and read back exactly,
// the features of each format that the writers do not use (polygons, OBJ's corner forms,
// PLY's other properties and byte orders, STL's welding), the clean-surface report, and
// broken files refused with the file, the line (or the byte offset) and what is wrong.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "temp_dir.hpp"

using namespace meshstep;
using io::Surface;
using io::SurfaceFormat;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

namespace {

using meshstep::testing::TempDir;

// ---------------------------------------------------------------------------------------
// Surfaces

// The unit cube [0,1]^3 scaled and moved by float-exact amounts, counterclockwise seen from
// outside.
Surface cube(double size = 1.0, double shift = 0.0) {
  Surface s;
  for (int i = 0; i < 8; ++i) {
    s.vertices.push_back({shift + size * (i & 1), shift + size * ((i >> 1) & 1),
                          shift + size * ((i >> 2) & 1)});
  }
  // Each face's corners counterclockwise seen from outside, as two triangles.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    s.triangles.push_back({std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
    s.triangles.push_back({std::uint32_t(f[0]), std::uint32_t(f[2]), std::uint32_t(f[3])});
  }
  return s;
}

Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Six times the enclosed volume: positive when a closed surface faces outward.
double signed_volume6(const Surface& s) {
  double v = 0.0;
  for (const auto& t : s.triangles) {
    v += dot(s.vertices[t[0]], cross(s.vertices[t[1]], s.vertices[t[2]]));
  }
  return v;
}

// An icosahedron subdivided once (every triangle into 4, new vertices pushed out onto the
// sphere): 42 vertices, 80 triangles, facing outward.
Surface icosphere() {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  Surface s;
  for (const double a : {-1.0, 1.0}) {
    for (const double b : {-t, t}) {
      s.vertices.push_back({a, b, 0.0});
      s.vertices.push_back({0.0, a, b});
      s.vertices.push_back({b, 0.0, a});
    }
  }
  // The faces are the triples of vertices at mutual distance 2 (the edge length), each
  // turned to face away from the centre.
  const auto edge = [&](std::uint32_t i, std::uint32_t j) {
    const Point3 d = minus(s.vertices[i], s.vertices[j]);
    return std::fabs(dot(d, d) - 4.0) < 1e-9;
  };
  for (std::uint32_t i = 0; i < 12; ++i)
    for (std::uint32_t j = i + 1; j < 12; ++j)
      for (std::uint32_t k = j + 1; k < 12; ++k) {
        if (!edge(i, j) || !edge(j, k) || !edge(i, k)) continue;
        const Point3& a = s.vertices[i];
        const Point3 n = cross(minus(s.vertices[j], a), minus(s.vertices[k], a));
        if (dot(n, a) > 0.0) {
          s.triangles.push_back({i, j, k});
        } else {
          s.triangles.push_back({i, k, j});
        }
      }
  const double radius = std::sqrt(dot(s.vertices[0], s.vertices[0]));
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    const auto found = midpoints.find(key);
    if (found != midpoints.end()) return found->second;
    const Point3 m{(s.vertices[a].x + s.vertices[b].x) / 2, (s.vertices[a].y + s.vertices[b].y) / 2,
                   (s.vertices[a].z + s.vertices[b].z) / 2};
    const double scale = radius / std::sqrt(dot(m, m));
    s.vertices.push_back({m.x * scale, m.y * scale, m.z * scale});
    const auto v = static_cast<std::uint32_t>(s.vertices.size() - 1);
    midpoints.emplace(key, v);
    return v;
  };
  Triangles finer;
  for (const auto& [a, b, c] : s.triangles) {
    const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    finer.push_back({a, ab, ca});
    finer.push_back({b, bc, ab});
    finer.push_back({c, ca, bc});
    finer.push_back({ab, bc, ca});
  }
  s.triangles = finer;
  return s;
}

// The same surface with its vertices renumbered in order of first use by the triangles:
// the order in which an STL reader meets (and welds) them.
Surface in_first_use_order(const Surface& s) {
  constexpr auto kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> number(s.vertices.size(), kNone);
  Surface out;
  for (auto t : s.triangles) {
    for (std::uint32_t& v : t) {
      if (number[v] == kNone) {
        number[v] = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back(s.vertices[v]);
      }
      v = number[v];
    }
    out.triangles.push_back(t);
  }
  return out;
}

// Exact equality, down to the sign of zero.
bool same_bits(const std::vector<Point3>& a, const std::vector<Point3>& b) {
  if (a.size() != b.size()) return false;
  const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (bits(a[i].x) != bits(b[i].x) || bits(a[i].y) != bits(b[i].y) ||
        bits(a[i].z) != bits(b[i].z)) {
      return false;
    }
  }
  return true;
}

// Two triangles: the unit square in the plane z = 0, facing +z.
Surface square() {
  Surface s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  return s;
}

// ---------------------------------------------------------------------------------------
// Bytes of hand-made binary files

void put(std::string& out, std::uint64_t v, std::size_t size, bool big_endian) {
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t shift = 8 * (big_endian ? size - 1 - i : i);
    out += static_cast<char>((v >> shift) & 0xFF);
  }
}
void put_float(std::string& out, float v, bool big_endian) {
  put(out, std::bit_cast<std::uint32_t>(v), 4, big_endian);
}

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `read`, which must throw an InputError for `path` at `line` (0: no line) whose
// message contains `keyword`.
void expect_error(const std::function<void()>& read, const std::string& path,
                  std::size_t line, const std::string& keyword) {
  try {
    read();
    ADD_FAILURE() << "no error for " << path << " (expected line " << line << ", \""
                  << keyword << "\")";
  } catch (const InputError& e) {
    const std::string what = e.what();
    const std::string prefix = path + (line == 0 ? "" : ":" + std::to_string(line)) + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what << "\n  expected prefix: " << prefix;
    EXPECT_EQ(e.line(), line) << what;
    EXPECT_NE(what.find(keyword), std::string::npos) << what << "\n  expected: " << keyword;
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Formats and round trips

TEST(SurfaceFormat, ChosenByExtension) {
  EXPECT_EQ(io::surface_format_for("a/b.off"), SurfaceFormat::off);
  EXPECT_EQ(io::surface_format_for("B.OBJ"), SurfaceFormat::obj);
  EXPECT_EQ(io::surface_format_for("x.ply"), SurfaceFormat::ply_binary);
  EXPECT_EQ(io::surface_format_for("x.ply", true), SurfaceFormat::ply_ascii);
  EXPECT_EQ(io::surface_format_for("x.Stl"), SurfaceFormat::stl_binary);
  EXPECT_EQ(io::surface_format_for("x.stl", true), SurfaceFormat::stl_ascii);
  EXPECT_EQ(io::surface_format_for("x.node"), std::nullopt);
  EXPECT_EQ(io::surface_format_for("folder.stl/x"), std::nullopt);  // the folder's dot
  EXPECT_EQ(io::surface_format_for("off"), std::nullopt);
}

TEST(SurfaceIo, EveryFormatRoundTripsExactly) {
  TempDir dir;
  // In first-use order so that STL, which numbers vertices as it meets them, gives back
  // the same numbering; coordinates with long or extreme decimal forms.
  Surface s = in_first_use_order(icosphere());
  s.vertices[0] = {5e-324, -1.7976931348623157e308, -0.0};
  s.vertices[1] = {0.1, 1.0 / 3.0, 123456789.123456789};
  const struct {
    SurfaceFormat format;
    const char* name;
  } formats[] = {{SurfaceFormat::off, "s.off"},         {SurfaceFormat::obj, "s.obj"},
                 {SurfaceFormat::ply_ascii, "a.ply"},   {SurfaceFormat::ply_binary, "b.ply"},
                 {SurfaceFormat::stl_ascii, "a.stl"}};
  for (const auto& f : formats) {
    SCOPED_TRACE(f.name);
    const std::string path = dir.file(f.name);
    io::write_surface(path, s, f.format);
    const Surface back = io::read_surface(path);
    EXPECT_TRUE(same_bits(back.vertices, s.vertices));
    EXPECT_EQ(back.triangles, s.triangles);
  }
  // Each binary kind is what it says (read_surface tells them apart by content).
  EXPECT_EQ(read_bytes(dir.file("b.ply")).find("format binary_little_endian 1.0\n"), 4u);
  EXPECT_EQ(read_bytes(dir.file("a.stl")).rfind("solid meshstep\n", 0), 0u);
}

TEST(SurfaceIo, BinaryStlStoresFloat32) {
  TempDir dir;
  const std::string path = dir.file("cube.stl");
  // Float-exact coordinates come back exactly.
  const Surface exact = in_first_use_order(cube(0.75, -2.5));
  io::write_surface(path, exact, SurfaceFormat::stl_binary);
  const std::string bytes = read_bytes(path);
  ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
  EXPECT_NE(bytes.rfind("solid", 0), 0u);  // a binary header must not look like ASCII STL
  const Surface back = io::read_surface(path);
  EXPECT_TRUE(same_bits(back.vertices, exact.vertices));
  EXPECT_EQ(back.triangles, exact.triangles);
  // Others are rounded to float.
  Surface rounded = exact;
  rounded.vertices[0].x = 0.1;
  io::write_surface(path, rounded, SurfaceFormat::stl_binary);
  EXPECT_EQ(io::read_surface(path).vertices[0].x, static_cast<double>(0.1f));
  EXPECT_NE(io::read_surface(path).vertices[0].x, 0.1);
}

TEST(SurfaceIo, BinaryStlWhoseHeaderStartsWithSolid) {
  TempDir dir;
  const std::string path = dir.file("solid.stl");
  const Surface s = in_first_use_order(cube());
  io::write_surface(path, s, SurfaceFormat::stl_binary);
  std::string bytes = read_bytes(path);
  bytes.replace(0, 12, "solid cube  ");  // as many exporters write
  dir.write("solid.stl", bytes);
  const Surface back = io::read_surface(path);
  EXPECT_EQ(back.vertices, s.vertices);
  EXPECT_EQ(back.triangles, s.triangles);
}

TEST(SurfaceIo, StlCornersWithEqualCoordinatesAreWelded) {
  TempDir dir;
  // Two facets sharing an edge, written with -0 in one and 0 in the other; two solids, one
  // in capitals (both occur in the wild).
  const std::string path = dir.write("two.stl",
                                     "SOLID first\n"
                                     " FACET NORMAL 0 0 1\n  OUTER LOOP\n"
                                     "   VERTEX 0 0 0\n   VERTEX 1 0 0\n   VERTEX 0 1 0\n"
                                     "  ENDLOOP\n ENDFACET\nENDSOLID first\n"
                                     "solid second\n"
                                     " facet normal 0 0 0\n  outer loop\n"
                                     "   vertex 1 0 -0\n   vertex 1.0 1 0\n   vertex -0 1e0 0\n"
                                     "  endloop\n endfacet\nendsolid\n");
  const Surface s = io::read_surface(path);
  ASSERT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.vertices[3], (Point3{1, 1, 0}));
  EXPECT_EQ(s.triangles, (Triangles{{0, 1, 2}, {1, 3, 2}}));
  EXPECT_EQ(io::report_surface(s).boundary_edges, 4u);  // the shared edge is interior
}

TEST(SurfaceIo, ObjCornerFormsRelativeIndicesAndPolygons) {
  TempDir dir;
  const std::string path = dir.write("forms.obj",
                                     "# corners in every form\n"
                                     "mtllib forms.mtl\no thing\ng part\nusemtl red\ns 1\n"
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0 1.0\nv 0 1 0 0.5 0.5 0.5\n"
                                     "vt 0 0\nvt 1 0\nvn 0 0 1\n"
                                     "f 1/1/1 2/2/1 3//1\n"
                                     "f -4 -2 -1\n"      // relative: vertices 1, 3, 4
                                     "f 1/1 2 5 4\n"     // a quad, vertex 5 defined below
                                     "l 1 2\n"
                                     "v 2 0 0\n");
  const Surface s = io::read_surface(path);
  ASSERT_EQ(s.vertices.size(), 5u);
  EXPECT_EQ(s.vertices[2], (Point3{1, 1, 0}));  // w ignored
  EXPECT_EQ(s.vertices[3], (Point3{0, 1, 0}));  // colour ignored
  EXPECT_EQ(s.triangles, (Triangles{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}, {0, 4, 3}}));
}

TEST(SurfaceIo, OffPolygonsColoursAndComments) {
  TempDir dir;
  const std::string path = dir.write("pentagon.off",
                                     "OFF 6 2 0  # counts on the OFF line\n"
                                     "\n# a pentagon and a triangle\n"
                                     "0 0 0\n2 0 0\n3 2 0\n1 3 0\n-1 2 0\n9 9 9\n"
                                     "5 0 1 2 3 4 255 0 0\n"
                                     "3 0 4 5 0.5\n");
  const Surface s = io::read_surface(path);
  ASSERT_EQ(s.vertices.size(), 6u);
  EXPECT_EQ(s.vertices[4], (Point3{-1, 2, 0}));
  // The fan around the first corner.
  EXPECT_EQ(s.triangles, (Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}));
}

TEST(SurfaceIo, AsciiPlySkipsWhatItDoesNotNeed) {
  TempDir dir;
  const std::string path = dir.write("extra.ply",
                                     "ply\nformat ascii 1.0\ncomment made by hand\n"
                                     "obj_info nothing\n"
                                     "element vertex 4\n"
                                     "property uchar red\nproperty float x\nproperty float y\n"
                                     "property list uchar int neighbours\nproperty double z\n"
                                     "element face 1\n"
                                     "property int flags\nproperty list uint8 uint32 vertex_index\n"
                                     "property float quality\n"
                                     "element edge 2\nproperty int v1\nproperty int v2\n"
                                     "end_header\n"
                                     "255 0 0 2 1 3 0.5\n"
                                     "0 1 0 0 0.25\n"
                                     "7 1 1 3 0 1 2 -1\n"
                                     "9 0 1 1 3 0\n"
                                     "42 4 0 1 2 3 0.75\n"
                                     "0 1\n1 2\n");
  const Surface s = io::read_surface(path);
  ASSERT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.vertices[0], (Point3{0, 0, 0.5}));
  EXPECT_EQ(s.vertices[2], (Point3{1, 1, -1}));
  EXPECT_EQ(s.triangles, (Triangles{{0, 1, 2}, {0, 2, 3}}));
}

TEST(SurfaceIo, BinaryPlyBigEndianFloatsAndSkippedLists) {
  TempDir dir;
  const std::string header =
      "ply\nformat binary_big_endian 1.0\n"
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property uchar flags\n"
      "element face 1\nproperty short kind\nproperty list int int vertex_indices\n"
      "element material 1\nproperty list uchar double weights\n"
      "end_header\n";
  std::string body;
  const float xyz[4][3] = {{0, 0, 0}, {1.5f, 0, 0}, {1.5f, 2, 0}, {0, 2, -0.25f}};
  for (const auto& p : xyz) {
    for (const float c : p) put_float(body, c, true);
    put(body, 0xAB, 1, true);
  }
  put(body, 0xFFFF, 2, true);  // kind = -1
  put(body, 4, 4, true);
  for (const std::uint64_t v : {3, 2, 1, 0}) put(body, v, 4, true);
  put(body, 2, 1, true);
  put(body, std::bit_cast<std::uint64_t>(0.5), 8, true);
  put(body, std::bit_cast<std::uint64_t>(2.0), 8, true);
  const std::string path = dir.write("big.ply", header + body);
  const Surface s = io::read_surface(path);
  ASSERT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.vertices[1], (Point3{1.5, 0, 0}));
  EXPECT_EQ(s.vertices[3], (Point3{0, 2, -0.25}));
  EXPECT_EQ(s.triangles, (Triangles{{3, 2, 1}, {3, 1, 0}}));
}

TEST(SurfaceIo, WritesAreAtomicAndRefuseWhatCannotBeReadBack) {
  TempDir dir;
  const std::string path = dir.file("keep.off");
  io::write_surface(path, cube(), SurfaceFormat::off);
  const std::string before = read_bytes(path);

  Surface nan = cube();
  nan.vertices[5].y = std::numeric_limits<double>::quiet_NaN();
  expect_error([&] { io::write_surface(path, nan, SurfaceFormat::off); }, path, 0,
               "cannot write this surface: vertex 5 has a coordinate that is not finite");
  Surface past_end = cube();
  past_end.triangles[3][1] = 8;
  expect_error([&] { io::write_surface(path, past_end, SurfaceFormat::ply_binary); }, path, 0,
               "triangle 3 uses vertex 8, but there are only 8 vertices");
  expect_error([&] { io::write_surface(path, cube(1e39), SurfaceFormat::stl_binary); }, path, 0,
               "beyond the range of float");
  EXPECT_EQ(read_bytes(path), before);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"keep.off"});  // no temporary files left

  // ASCII STL keeps doubles that float cannot hold.
  const std::string stl = dir.file("big.stl");
  io::write_surface(stl, in_first_use_order(cube(1e39)), SurfaceFormat::stl_ascii);
  EXPECT_EQ(io::read_surface(stl).vertices, in_first_use_order(cube(1e39)).vertices);
}

TEST(SurfaceIo, UnknownExtensionOrMissingFile) {
  TempDir dir;
  const std::string step = dir.write("part.step", "ISO-10303-21;\n");
  expect_error([&] { io::read_surface(step); }, step, 0, "unknown surface file type");
  for (const char* name : {"none.off", "none.obj", "none.ply", "none.stl"}) {
    const std::string path = dir.file(name);
    expect_error([&] { io::read_surface(path); }, path, 0, "No such file");
  }
}

// ---------------------------------------------------------------------------------------
// The report

TEST(SurfaceReport, ClosedSurfacesAreClean) {
  for (const Surface& s : {cube(), icosphere()}) {
    SCOPED_TRACE(s.vertices.size());
    EXPECT_GT(signed_volume6(s), 0.0);  // the test surfaces do face outward
    const io::SurfaceReport r = io::report_surface(s);
    EXPECT_TRUE(r.clean());
    EXPECT_EQ(r.degenerate_triangles, 0u);
    EXPECT_EQ(r.duplicate_triangles, 0u);
    EXPECT_EQ(r.non_manifold_edges, 0u);
    EXPECT_EQ(r.inconsistent_edges, 0u);
    EXPECT_EQ(r.boundary_loops, 0u);
    EXPECT_EQ(r.boundary_edges, 0u);
    EXPECT_EQ(r.unused_vertices, 0u);
    EXPECT_EQ(io::describe(r), "clean; closed (no boundary)");
  }
  EXPECT_EQ(icosphere().triangles.size(), 80u);
  EXPECT_EQ(icosphere().vertices.size(), 42u);
}

TEST(SurfaceReport, OpenSquareHasOneBoundaryLoopOfFourEdges) {
  const io::SurfaceReport r = io::report_surface(square());
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_TRUE(r.clean());  // a border is no defect
  EXPECT_EQ(io::describe(r), "clean; 1 boundary loop (4 edges)");
}

TEST(SurfaceReport, HolesAndBowtiesCountOneLoopEach) {
  // A cube without its top and bottom: a tube with two rims of 4 edges.
  Surface tube = cube();
  tube.triangles.erase(tube.triangles.begin(), tube.triangles.begin() + 4);
  io::SurfaceReport r = io::report_surface(tube);
  EXPECT_EQ(r.boundary_loops, 2u);
  EXPECT_EQ(r.boundary_edges, 8u);
  EXPECT_TRUE(r.clean());
  // Two triangles touching at one vertex: two loops, whichever way the walk turns there.
  for (const bool swap : {false, true}) {
    Surface bowtie;
    bowtie.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    bowtie.triangles = {{0, 1, 2}, {0, 3, 4}};
    if (swap) std::swap(bowtie.triangles[0], bowtie.triangles[1]);
    r = io::report_surface(bowtie);
    EXPECT_EQ(r.boundary_loops, 2u);
    EXPECT_EQ(r.boundary_edges, 6u);
  }
  // Two squares touching at vertex 5, numbered so that the walk around the first one
  // (from vertex 0) turns into the second at vertex 5 and comes back there: the second
  // loop closes in the middle of the walk.
  Surface squares;
  squares.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {2, 2, 0},
                      {0, 1, 0}, {1, 1, 0}, {1, 2, 0}};
  squares.triangles = {{0, 1, 5}, {0, 5, 4}, {5, 2, 3}, {5, 3, 6}};
  r = io::report_surface(squares);
  EXPECT_EQ(r.boundary_loops, 2u);
  EXPECT_EQ(r.boundary_edges, 8u);
  EXPECT_TRUE(r.clean());
}

TEST(SurfaceReport, LoopsTouchingAtSeveralVerticesFollowTheFans) {
  // A triangle (0 5 8) joined to a band only at its three corners: its own rim is a loop,
  // and the band's rim another, although a walk along the edges alone could pair them up
  // at 0, 5 and 8 into three loops or two. Renumbering the vertices must not change that.
  Surface s;
  s.vertices = {{0, 0, 0}, {9, 0, 0}, {2, 0.3, 0}, {-0.1, 3, 0}, {2.3, 1.1, 0},
                {2.3, 0.7, 0}, {0, 1.8, 0}, {1, 2, 0}, {1.6, 1.8, 0}};
  s.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}, {0, 5, 8}, {4, 8, 7}};
  io::SurfaceReport r = io::report_surface(s);
  EXPECT_EQ(r.boundary_edges, 12u);
  EXPECT_EQ(r.boundary_loops, 2u);
  for (std::uint32_t shift = 1; shift < 9; ++shift) {
    Surface renumbered = s;
    for (std::uint32_t v = 0; v < 9; ++v) renumbered.vertices[(v + shift) % 9] = s.vertices[v];
    for (auto& t : renumbered.triangles)
      for (auto& v : t) v = (v + shift) % 9;
    EXPECT_EQ(io::report_surface(renumbered).boundary_loops, 2u) << "shift " << shift;
  }
}

TEST(SurfaceReport, FlippedTriangleMakesInconsistentEdges) {
  Surface s = cube();
  std::swap(s.triangles[4][1], s.triangles[4][2]);
  const io::SurfaceReport r = io::report_surface(s);
  EXPECT_EQ(r.inconsistent_edges, 3u);  // all three of its edges
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.boundary_edges, 0u);
  EXPECT_FALSE(r.clean());
  EXPECT_EQ(io::describe(r),
            "not clean: 3 edges between triangles of opposite orientation; closed (no boundary)");
}

TEST(SurfaceReport, ThreeTrianglesOnOneEdgeAreNonManifold) {
  Surface s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  s.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const io::SurfaceReport r = io::report_surface(s);
  EXPECT_EQ(r.non_manifold_edges, 1u);
  EXPECT_EQ(r.boundary_edges, 6u);
  EXPECT_EQ(r.inconsistent_edges, 0u);  // an edge used 3 times counts as non-manifold only
  EXPECT_FALSE(r.clean());
  EXPECT_NE(io::describe(r).find("1 non-manifold edge"), std::string::npos);
}

TEST(SurfaceReport, DuplicatesDegeneratesAndUnusedVertices) {
  Surface s = square();
  s.triangles.push_back({2, 0, 1});  // the first again, rotated
  s.triangles.push_back({0, 3, 2});  // the second again, reversed
  io::SurfaceReport r = io::report_surface(s);
  EXPECT_EQ(r.duplicate_triangles, 2u);
  EXPECT_EQ(r.degenerate_triangles, 0u);
  EXPECT_FALSE(r.clean());

  s = square();
  s.vertices.push_back({0.5, 0.5, 0.0});      // 4: on the diagonal 0-2
  s.vertices.push_back({7, 7, 7});            // 5: used by nothing
  s.vertices.push_back({0.5, 0.5, 1e-300});   // 6: just off that diagonal
  s.triangles.push_back({0, 2, 4});           // collinear corners
  s.triangles.push_back({1, 1, 3});           // a repeated vertex
  s.triangles.push_back({0, 2, 6});           // tiny, but not zero
  r = io::report_surface(s);
  EXPECT_EQ(r.degenerate_triangles, 2u);
  EXPECT_EQ(r.unused_vertices, 1u);
  EXPECT_EQ(r.duplicate_triangles, 0u);
  EXPECT_FALSE(r.clean());
  EXPECT_EQ(io::describe(r).rfind("not clean: 2 degenerate triangles, ", 0), 0u) << io::describe(r);
  EXPECT_NE(io::describe(r).find("1 unused vertex"), std::string::npos);

  // Rounding would call this one collinear: the cross product of its edges computed in
  // doubles is exactly zero, but the corners are not on one line (exactly, it is 2^-50).
  Surface near;
  near.vertices = {{0, 0, 0}, {7, 4.8999999999999995, 0}, {11, 7.699999999999999, 0}};
  near.triangles = {{0, 1, 2}};
  ASSERT_EQ(cross(near.vertices[1], near.vertices[2]).z, 0.0);
  EXPECT_EQ(io::report_surface(near).degenerate_triangles, 0u);
}

TEST(SurfaceReport, RefusesIndicesPastTheEnd) {
  Surface s = square();
  s.triangles[1][2] = 4;
  try {
    io::report_surface(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "triangle 1 uses vertex 4, but there are only 4 vertices");
  }
}

// ---------------------------------------------------------------------------------------
// Broken files

namespace {

struct BrokenFile {
  const char* name;  // its extension picks the reader
  std::string content;
  std::size_t line;  // 0 for the binary formats' byte offsets
  std::string keyword;
};

// Comment lines that keep a file too long for the size checks, so that the check named in
// a case is the one that fails.
const std::string kPad = "# padding: a comment long enough to rule out the size checks\n";

const std::string kOffTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
const std::string kObjVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
std::string ply_ascii_header(std::uint64_t vertices, int faces) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
}
const std::string kPlyVertices = "0 0 0\n1 0 0\n0 1 0\n";
const std::string kStlStart = "solid t\nfacet normal 0 0 1\nouter loop\n";

std::vector<BrokenFile> broken_text_files() {
  return {
      // OFF
      {"empty.off", "", 1, "the file is empty"},
      {"header.off", "OF\n3 1 0\n", 1,
       "not an OFF file: the first line should be 'OFF', found 'OF'"},
      {"counts.off", "OFF\n3 1\n", 2,
       "expected 3 numbers (number of vertices, number of faces, number of edges), found 2"},
      {"count_word.off", "OFF\nthree 1 0\n", 2,
       "number of vertices should be a number, found 'three'"},
      {"negative.off", "OFF\n3 -1 0\n", 2, "number of faces is negative"},
      {"huge.off", "OFF\n1000000000 1 0\n0 0 0\n", 2, "can hold at most"},
      {"truncated.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n" + kPad, 5,
       "unexpected end of file: found 2 of the 3 vertices declared on line 2"},
      {"no_faces.off", kOffTriangle + kPad, 6, "found 0 of the 1 faces declared on line 2"},
      {"nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", 4, "finite"},
      {"inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n", 5, "finite"},
      {"word.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", 4,
       "y coordinate should be a number, found 'zero'"},
      {"vertex_fields.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 4,
       "expected 3 numbers (x, y, z), found 2"},
      {"range.off", kOffTriangle + "3 0 1 7\n", 6,
       "vertex index 7 is out of range (vertices are numbered 0..2)"},
      {"negative_index.off", kOffTriangle + "3 0 -1 2\n", 6, "vertex index -1 is out of range"},
      {"two.off", kOffTriangle + "2 0 1\n", 6, "a face needs at least 3 vertices, found 2"},
      {"short_face.off", kOffTriangle + "4 0 1 2\n", 6,
       "the face has 4 vertices, but the line lists only 3 indices"},
      {"long_face.off", kOffTriangle + "3 0 1 2 0 1\n", 6, "a colour takes 1, 3 or 4"},
      {"trailing.off", kOffTriangle + "3 0 1 2\n3 2 1 0\n", 7,
       "more data after the 1 faces declared on line 2"},
      {"binary.off", "OFF\n3 1 0\n0 0 0\n1 \x01 0\n" + kPad, 4, "binary data (byte 0x01"},
      // OBJ
      {"nan.obj", "v 0 0 0\nv 0 0 nan\n", 2, "z coordinate should be a finite number, found 'nan'"},
      {"short_v.obj", "v 0 0\n", 1, "expected 3 coordinates after 'v', found 2"},
      {"word.obj", "v 0 zero 0\n", 1, "y coordinate should be a number, found 'zero'"},
      {"two.obj", kObjVertices + "f 1 2\n", 4, "a face needs at least 3 vertices, found 2"},
      {"range.obj", kObjVertices + "f 1 2 3\nf 1 2 9\nf 1 2 3\n", 5,
       "vertex index 9 is out of range (vertices are numbered 1..3)"},
      {"zero.obj", kObjVertices + "f 0 1 2\n", 4, "vertex index 0 is out of range"},
      {"back.obj", kObjVertices + "f -1 -2 -4\n", 4,
       "vertex index -4 is out of range (it counts back from the latest vertex, and there are 3 "
       "so far)"},
      {"before.obj", "f -1 -2 -3\n" + kObjVertices, 1, "vertex index -1 is out of range"},
      {"corner.obj", kObjVertices + "f 1/1 x/2 3\n", 4,
       "a face corner should be a vertex index (then optionally /texture/normal), found 'x/2'"},
      {"slash.obj", kObjVertices + "f 1 /2 3\n", 4, "found '/2'"},
      {"huge_index.obj", kObjVertices + "f 1 2 99999999999999999999\n", 4,
       "vertex index '99999999999999999999' is out of range"},
      // PLY, ASCII (and the header of any PLY)
      {"empty.ply", "", 1, "the file is empty"},
      {"magic.ply", "plx\nformat ascii 1.0\n", 1, "not a PLY file: the first line should be 'ply'"},
      {"format.ply", "ply\nformat text 1.0\nend_header\n", 2, "unknown PLY format 'text'"},
      {"version.ply", "ply\nformat ascii 2.0\nend_header\n", 2, "unsupported PLY version '2.0'"},
      {"no_format.ply", "ply\nelement vertex 3\n", 2,
       "the second line should be 'format ascii 1.0'"},
      {"keyword.ply", "ply\nformat ascii 1.0\nelemnt vertex 3\n", 3,
       "unknown header line 'elemnt'"},
      {"type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty flt x\n", 4,
       "unknown property type 'flt'"},
      {"count_word.ply", "ply\nformat ascii 1.0\nelement vertex three\n", 3,
       "element count should be a number, found 'three'"},
      {"twice.ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
       "property float x\nend_header\n",
       6, "property 'x' is declared twice (first on line 4)"},
      {"element_twice.ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nelement vertex 0\n"
       "property float y\nend_header\n",
       5, "element 'vertex' is declared twice (first on line 3)"},
      {"orphan.ply", "ply\nformat ascii 1.0\nproperty float x\n", 3,
       "a property before any element"},
      {"no_end.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n", 4,
       "unexpected end of file: expected more of the header, up to 'end_header'"},
      {"no_z.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "end_header\n0 0\n",
       3, "the vertex element has no property 'z'"},
      {"int_x.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty float y\n"
       "property float z\nend_header\n0 0 0\n",
       4, "property 'x' should be a float or a double"},
      {"no_vertex.ply",
       "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\n"
       "end_header\n",
       5, "the header declares no vertex element"},
      {"no_indices.ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
       "property float z\nelement face 0\nproperty list uchar int corners\nend_header\n",
       7, "the face element has no property 'vertex_indices'"},
      {"huge.ply", ply_ascii_header(1000000000000, 0), 3,
       "declares 1000000000000 vertices; at most 4294967294 are supported"},
      {"too_many_for_size.ply", ply_ascii_header(100000, 0) + kPlyVertices, 3, "can hold at most"},
      {"truncated.ply", ply_ascii_header(3, 1) + "0 0 0\n1 0 0\n" + kPad, 12,
       "unexpected end of file: found 2 of the 3 'vertex' elements declared on line 3"},
      {"nan.ply", ply_ascii_header(3, 1) + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", 11, "finite"},
      {"word.ply", ply_ascii_header(3, 1) + "0 0 0\n1 0 0\n0 1 zero\n3 0 1 2\n", 12,
       "z coordinate should be a number, found 'zero'"},
      {"range.ply", ply_ascii_header(3, 1) + kPlyVertices + "3 0 1 5\n", 13,
       "vertex index 5 is out of range (vertices are numbered 0..2)"},
      {"two.ply", ply_ascii_header(3, 1) + kPlyVertices + "2 0 1\n", 13,
       "a face needs at least 3 vertices, found 2"},
      {"short_face.ply", ply_ascii_header(3, 1) + kPlyVertices + "4 0 1 2\n", 13,
       "list 'vertex_indices' has 4 items, but the line holds only 3 more values"},
      {"few_values.ply", ply_ascii_header(3, 1) + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 11,
       "too few values for a 'vertex' element: none for property 'z'"},
      {"many_values.ply", ply_ascii_header(3, 1) + "0 0 0 7\n1 0 0\n0 1 0\n3 0 1 2\n", 10,
       "too many values for a 'vertex' element"},
      {"trailing.ply", ply_ascii_header(3, 1) + kPlyVertices + "3 0 1 2\n3 0 1 2\n", 14,
       "more data after the last element"},
      // STL, ASCII
      {"two.stl", kStlStart + "vertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid t\n", 6,
       "a facet needs 3 vertices, found 2"},
      {"four.stl",
       kStlStart + "vertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\n", 7,
       "a facet has more than 3 vertices"},
      {"word.stl", kStlStart + "vertex 0 0 0\nvertex 1 zero 0\n", 5,
       "y coordinate should be a number, found 'zero'"},
      {"nan.stl", kStlStart + "vertex 0 0 0\nvertex 1 0 nan\n", 5, "finite"},
      {"fields.stl", kStlStart + "vertex 0 0 0 0\n", 4,
       "expected 4 numbers (vertex, x, y, z), found 5"},
      {"endloop.stl", kStlStart + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\n", 7,
       "expected 'vertex' or 'endloop', found 'endfacet'"},
      {"outer.stl", "solid t\nfacet normal 0 0 1\nouter lop\n", 3,
       "expected 'outer loop', found 'outer lop'"},
      {"normal.stl", "solid t\nfacet 0 0 1\n", 2, "expected 'facet normal nx ny nz'"},
      {"facet.stl", "solid t\nfacets normal 0 0 1\n", 2,
       "expected 'facet' or 'endsolid', found 'facets'"},
      {"truncated.stl", kStlStart + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n",
       8, "unexpected end of file: expected 'facet' or 'endsolid'"},
      {"after.stl", "solid t\nendsolid t\nsolid u\nendsolid u\nfacet\n", 5,
       "expected 'solid', found 'facet'"},
  };
}

}  // namespace

TEST(SurfaceMalformed, TextFilesNameFileLineAndProblem) {
  TempDir dir;
  const auto cases = broken_text_files();
  ASSERT_GE(cases.size(), 60u);
  for (const BrokenFile& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.write(c.name, c.content);
    expect_error([&] { io::read_surface(path); }, path, c.line, c.keyword);
  }
}

TEST(SurfaceMalformed, BinaryPlyNamesTheByteOffset) {
  TempDir dir;
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const std::size_t body = header.size();
  const auto vertices = [](float bad_y) {
    std::string b;
    const float xyz[3][3] = {{0, 0, 0}, {1, bad_y, 0}, {0, 1, 0}};
    for (const auto& p : xyz)
      for (const float c : p) put_float(b, c, false);
    return b;
  };
  const auto face = [](std::uint64_t n, std::vector<std::uint64_t> corners) {
    std::string b;
    put(b, n, 1, false);
    for (const std::uint64_t v : corners) put(b, v, 4, false);
    return b;
  };
  const std::string good = header + vertices(0) + face(3, {0, 1, 2});
  ASSERT_EQ(io::read_surface(dir.write("good.ply", good)).triangles, (Triangles{{0, 1, 2}}));

  const struct {
    const char* name;
    std::string content;
    std::size_t line;
    std::string keyword;
  } cases[] = {
      {"truncated.ply", good.substr(0, good.size() - 5), 0,
       "byte offset " + std::to_string(body + 36) +
           ": 'face' element 0: list 'vertex_indices' of 3 items runs past the end of the file"},
      {"nan.ply", header + vertices(std::numeric_limits<float>::quiet_NaN()) + face(3, {0, 1, 2}),
       0, "byte offset " + std::to_string(body + 16) +
              ": 'vertex' element 1: y coordinate is not finite (nan)"},
      {"inf.ply", header + vertices(std::numeric_limits<float>::infinity()) + face(3, {0, 1, 2}),
       0, "y coordinate is not finite (inf)"},
      {"range.ply", header + vertices(0) + face(3, {0, 1, 3}), 0,
       "byte offset " + std::to_string(body + 45) +
           ": 'face' element 0: vertex index 3 is out of range (vertices are numbered 0..2)"},
      {"negative.ply", header + vertices(0) + face(3, {0, 0xFFFFFFFF, 2}), 0,
       "vertex index -1 is out of range"},
      {"two.ply", header + vertices(0) + face(2, {0, 1}), 0,
       "byte offset " + std::to_string(body + 36) +
           ": 'face' element 0: a face needs at least 3 vertices, found 2"},
      {"trailing.ply", good + "abc", 0,
       "byte offset " + std::to_string(good.size()) + ": 3 bytes after the last element"},
      // A count the file cannot hold is refused at its header line, before any allocation.
      {"huge.ply", std::string(header).replace(header.find("vertex 3"), 8, "vertex 4000000000") +
                       vertices(0),
       3, "declares 4000000000 'vertex' elements of at least 12 bytes each, but only 36 bytes"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.write(c.name, c.content);
    expect_error([&] { io::read_surface(path); }, path, c.line, c.keyword);
  }
}

TEST(SurfaceMalformed, BinaryStlNamesTheByteOffset) {
  TempDir dir;
  const std::string path = dir.file("cube.stl");
  io::write_surface(path, cube(), SurfaceFormat::stl_binary);
  const std::string good = read_bytes(path);

  std::string nan = good;
  const float bad = std::numeric_limits<float>::quiet_NaN();
  std::string bad_bytes;
  put_float(bad_bytes, bad, false);
  nan.replace(84 + 50 + 12 + 12 + 4, 4, bad_bytes);  // triangle 1, corner 1, y
  std::string solid_truncated = good.substr(0, 84 + 50 * 5);
  solid_truncated.replace(0, 5, "solid");
  const struct {
    const char* name;
    std::string content;
    std::string keyword;
  } cases[] = {
      {"empty.stl", "", "byte offset 0: the file is empty"},
      {"short.stl", "abc",
       "byte offset 3: unexpected end of file: a binary STL file has at least 84 bytes"},
      {"truncated.stl", good.substr(0, good.size() - 50),
       "byte offset 80: the triangle count 12 makes a binary STL file of 684 bytes, but this one "
       "has 634 (truncated file?)"},
      {"solid_truncated.stl", solid_truncated, "the triangle count 12 makes a binary STL file"},
      {"long.stl", good + "x", "but this one has 685"},
      {"nan.stl", nan, "byte offset 162: triangle 1 has a coordinate that is not finite (nan)"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string p = dir.write(c.name, c.content);
    expect_error([&] { io::read_surface(p); }, p, 0, c.keyword);
  }
}
