// The format table (io/formats.hpp) and the one-file 2D mesh writers (io/mesh_formats.hpp):
// each written file read back here by a small reader of the test's own, and compared with
// the mesh: vertices, triangles, segments, regions, markers. (tests/formats/ reads them
// with meshio and gmsh, independent readers.)
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "meshstep/check/quality.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/io/mesh_formats.hpp"
#include "meshstep/io/surface_io.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;
using testing::slurp;
using testing::TempDir;

// A 2 x 1 rectangle cut in two by a segment: outer segments marker 5, the cut marker 7;
// regions 1.5 (left) and -2 (right).
TriMesh two_region_mesh() {
  Pslg p;
  p.points = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}, {0.5, 0.25}};
  p.segments = {{0, 1, 5}, {1, 2, 5}, {2, 3, 5}, {3, 4, 5}, {4, 5, 5}, {5, 0, 5}, {1, 4, 7}};
  p.has_segment_markers = true;
  p.regions = {{{0.5, 0.5}, 1.5, -1}, {{1.5, 0.5}, -2.0, -1}};
  TriMesh m = triangulate(p);
  set_vertex_markers(m, std::vector<int>(p.points.size(), 0), p.points.size());
  return m;
}

using Triangles = std::set<std::array<std::uint32_t, 3>>;

// Rotated to start at the smallest index, orientation kept.
std::array<std::uint32_t, 3> rotated(std::array<std::uint32_t, 3> t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

Triangles triangles_of(const TriMesh& m, double region) {
  Triangles out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (m.triangle_attributes[t] == region) out.insert(rotated(m.triangles[t]));
  return out;
}

TEST(FileFormats, TableHasEachExtensionOnceAndChoosesWritersByExtension) {
  std::set<std::string> seen;
  for (const io::FileFormat& f : io::file_formats()) {
    EXPECT_TRUE(seen.insert(std::string(f.extension)).second) << f.extension;
    EXPECT_EQ(f.write_mesh != nullptr, !f.carries.empty()) << f.extension << ": a mesh writer says what it keeps";
    if (f.read_pslg) {
      EXPECT_TRUE(f.read);
      EXPECT_TRUE(f.kind == io::FileKind::pslg || f.kind == io::FileKind::points) << f.extension;
    }
  }
  for (const char* ext : {".msh", ".vtu", ".obj", ".off", ".ply", ".stl"}) {
    const io::FileFormat* f = io::mesh_writer_for(std::string("out") + ext);
    ASSERT_NE(f, nullptr) << ext;
    EXPECT_EQ(f->extension, ext);
  }
  EXPECT_EQ(io::mesh_writer_for("dir/OUT.MSH")->extension, ".msh");
  // Everything else stays a PREFIX for Triangle's files, as before.
  for (const char* prefix : {"box.1", "plate_q", "out.node", "out.poly", "a.msh/b", "lake.geojson", "x.mslog"})
    EXPECT_EQ(io::mesh_writer_for(prefix), nullptr) << prefix;
  EXPECT_TRUE(io::is_planar_input("lake.geojson"));
  EXPECT_TRUE(io::is_planar_input("lake.wkt"));
  EXPECT_FALSE(io::is_planar_input("lake.msh"));
}

// A mesh PREFIX is Triangle's files: which ones a reader opens and a writer may leave, when
// one is on disk (the .node and the .ele, not either alone), and how a file names its prefix.
TEST(FileFormats, AMeshPrefixIsTrianglesFiles) {
  using Files = std::vector<std::string>;
  EXPECT_EQ(io::mesh_prefix_files("m.1", io::MeshPrefixFiles::read), (Files{"m.1.node", "m.1.ele", "m.1.poly", "m.1.area"}));
  EXPECT_EQ(io::mesh_prefix_files("m.1", io::MeshPrefixFiles::written),
            (Files{"m.1.node", "m.1.ele", "m.1.poly", "m.1.area", "m.1.edge", "m.1.neigh"}));
  EXPECT_EQ(io::mesh_prefix_of("dir/m.1.node"), "dir/m.1");
  EXPECT_EQ(io::mesh_prefix_of("dir/m.1.ele"), "dir/m.1");
  EXPECT_EQ(io::mesh_prefix_of("dir/m.1"), "dir/m.1");
  EXPECT_EQ(io::mesh_prefix_of(".node"), ".node");  // a name, not an extension on nothing
  EXPECT_EQ(io::mesh_prefix_of("m.poly"), "m.poly");

  TempDir dir("meshstep_prefix_");
  const std::string prefix = dir.file("m");
  EXPECT_FALSE(io::is_mesh_prefix(prefix));
  std::ofstream(prefix + ".node") << "0 2 0 0\n";
  EXPECT_FALSE(io::is_mesh_prefix(prefix)) << "a .node alone is a point set";
  std::ofstream(prefix + ".ele") << "0 3 0\n";
  EXPECT_TRUE(io::is_mesh_prefix(prefix));
  EXPECT_FALSE(io::is_mesh_prefix(prefix + ".node"));
}

// The sections of a .msh file, each as its lines of words.
std::map<std::string, std::vector<std::vector<std::string>>> msh_sections(const std::string& text) {
  std::map<std::string, std::vector<std::vector<std::string>>> sections;
  std::istringstream in(text);
  std::string line, open;
  while (std::getline(in, line)) {
    if (line.starts_with("$End")) {
      open.clear();
    } else if (line.starts_with("$")) {
      open = line.substr(1);
      sections[open];
    } else {
      std::istringstream words(line);
      std::vector<std::string> row;
      for (std::string w; words >> w;) row.push_back(w);
      sections[open].push_back(row);
    }
  }
  return sections;
}

TEST(MeshFormats, GmshKeepsTrianglesByRegionAndSegmentsByMarkerAsPhysicalGroups) {
  TempDir dir;
  const TriMesh m = two_region_mesh();
  const std::string path = dir.file("m.msh");
  io::write_gmsh(path, m);
  auto s = msh_sections(slurp(path));
  ASSERT_EQ(s["MeshFormat"].size(), 1u);
  EXPECT_EQ(s["MeshFormat"][0], (std::vector<std::string>{"4.1", "0", "8"}));

  // Physical names: curves "marker 5", "marker 7"; surfaces "region -2", "region 1.5".
  std::map<std::string, std::string> names;  // "dim tag" -> name
  const auto& pn = s["PhysicalNames"];
  ASSERT_EQ(pn.at(0).at(0), "4");
  for (std::size_t i = 1; i < pn.size(); ++i) {
    std::string name;
    for (std::size_t k = 2; k < pn[i].size(); ++k) name += (k > 2 ? " " : "") + pn[i][k];
    names[pn[i][0] + " " + pn[i][1]] = name;
  }
  EXPECT_EQ(names["1 1"], "\"marker 5\"");
  EXPECT_EQ(names["1 2"], "\"marker 7\"");
  EXPECT_EQ(names["2 1"], "\"region -2\"");
  EXPECT_EQ(names["2 2"], "\"region 1.5\"");
  // Entities: 0 points, 2 curves, 2 surfaces; each its own physical group.
  EXPECT_EQ(s["Entities"].at(0), (std::vector<std::string>{"0", "2", "2", "0"}));
  for (std::size_t i = 1; i <= 4; ++i) {
    EXPECT_EQ(s["Entities"][i].at(7), "1");
    EXPECT_EQ(s["Entities"][i].at(8), s["Entities"][i].at(0));
  }

  // Nodes: tags 1..N, then coordinates, in the mesh's order.
  const auto& nodes = s["Nodes"];
  const std::size_t n = m.points.size();
  ASSERT_EQ(nodes.size(), 2 + 2 * n);
  EXPECT_EQ(nodes[0], (std::vector<std::string>{"1", std::to_string(n), "1", std::to_string(n)}));
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(nodes[2 + i].at(0), std::to_string(i + 1));
    EXPECT_EQ(std::stod(nodes[2 + n + i].at(0)), m.points[i].x);
    EXPECT_EQ(std::stod(nodes[2 + n + i].at(1)), m.points[i].y);
  }

  // Elements: per block, its entity's triangles or segments.
  const auto& el = s["Elements"];
  std::map<std::pair<int, int>, Triangles> triangles;      // (dim, entity) -> triangles
  std::map<std::pair<int, int>, std::set<std::pair<std::uint32_t, std::uint32_t>>> lines;
  std::set<int> tags;
  for (std::size_t i = 1; i < el.size();) {
    const int dim = std::stoi(el[i][0]), entity = std::stoi(el[i][1]), type = std::stoi(el[i][2]);
    const std::size_t count = std::stoul(el[i][3]);
    EXPECT_EQ(type, dim == 2 ? 2 : 1);
    for (std::size_t k = 1; k <= count; ++k) {
      const auto& e = el[i + k];
      EXPECT_TRUE(tags.insert(std::stoi(e[0])).second);
      if (dim == 2)
        triangles[{dim, entity}].insert(rotated({static_cast<std::uint32_t>(std::stoul(e[1]) - 1),
                                                 static_cast<std::uint32_t>(std::stoul(e[2]) - 1),
                                                 static_cast<std::uint32_t>(std::stoul(e[3]) - 1)}));
      else
        lines[{dim, entity}].insert({static_cast<std::uint32_t>(std::stoul(e[1]) - 1),
                                     static_cast<std::uint32_t>(std::stoul(e[2]) - 1)});
    }
    i += count + 1;
  }
  EXPECT_EQ(tags.size(), m.triangles.size() + m.segments.size());
  EXPECT_EQ(triangles[std::pair(2, 1)], triangles_of(m, -2.0));
  EXPECT_EQ(triangles[std::pair(2, 2)], triangles_of(m, 1.5));
  std::set<std::pair<std::uint32_t, std::uint32_t>> marker5, marker7;
  for (const Segment& seg : m.segments) (seg.marker == 5 ? marker5 : marker7).insert({seg.a, seg.b});
  EXPECT_EQ(lines[std::pair(1, 1)], marker5);
  EXPECT_EQ(lines[std::pair(1, 2)], marker7);
}

// The value of attribute `key` in the XML tag that starts at `tag` ("" when absent).
std::string xml_attribute(const std::string& text, std::size_t tag, const std::string& key) {
  const std::size_t end = text.find('>', tag);
  const std::size_t at = text.find(" " + key + "=\"", tag);
  if (at == std::string::npos || at > end) return "";
  const std::size_t start = at + key.size() + 3;
  return text.substr(start, text.find('"', start) - start);
}

// The array NAME of a .vtu with appended raw data, as numbers: its <DataArray> gives its type
// and offset, counted from the '_' that opens <AppendedData>; there a UInt64 byte count,
// then the values, in the byte order the header names (this machine's).
std::vector<double> vtu_array(const std::string& text, const std::string& name) {
  const std::size_t tag = text.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) return {};
  const std::size_t open = text.rfind("<DataArray", tag);
  EXPECT_EQ(xml_attribute(text, open, "format"), "appended") << name;
  const std::string type = xml_attribute(text, open, "type");
  const std::size_t appended = text.find("<AppendedData encoding=\"raw\">");
  EXPECT_NE(appended, std::string::npos);
  const std::size_t base = text.find('_', appended) + 1;
  std::size_t at = base + std::stoull(xml_attribute(text, open, "offset"));
  const auto read = [&](auto v) {
    EXPECT_LE(at + sizeof v, text.size()) << name;
    std::memcpy(&v, text.data() + at, sizeof v);
    at += sizeof v;
    return v;
  };
  const std::uint64_t bytes = read(std::uint64_t{0});
  std::vector<double> v;
  const std::size_t end = at + bytes;
  while (at < end && at < text.size()) {
    if (type == "Float64") v.push_back(read(0.0));
    else if (type == "Int64") v.push_back(static_cast<double>(read(std::int64_t{0})));
    else if (type == "Int32") v.push_back(read(std::int32_t{0}));
    else if (type == "UInt8") v.push_back(read(std::uint8_t{0}));
    else ADD_FAILURE() << name << ": type " << type;
  }
  return v;
}

TEST(MeshFormats, VtuHasTheTrianglesAndTheirRegionAngleAndQuality) {
  TempDir dir;
  const TriMesh m = two_region_mesh();
  const std::string path = dir.file("m.vtu");
  io::write_vtu(path, m);
  const std::string text = slurp(path);
  EXPECT_NE(text.find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
  const std::string order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  EXPECT_NE(text.find("byte_order=\"" + order + "\" header_type=\"UInt64\""), std::string::npos);
  EXPECT_TRUE(text.ends_with("\n  </AppendedData>\n</VTKFile>\n"));
  const auto points = vtu_array(text, "points"), connectivity = vtu_array(text, "connectivity"),
             offsets = vtu_array(text, "offsets"), types = vtu_array(text, "types"), region = vtu_array(text, "region"),
             angle = vtu_array(text, "min_angle"), q = vtu_array(text, "quality"), marker = vtu_array(text, "marker");
  const std::size_t t = m.triangles.size();
  ASSERT_EQ(points.size(), 3 * m.points.size());
  ASSERT_EQ(connectivity.size(), 3 * t);
  ASSERT_EQ(offsets.size(), t);
  ASSERT_EQ(types.size(), t);
  ASSERT_EQ(region.size(), t);
  ASSERT_EQ(angle.size(), t);
  ASSERT_EQ(q.size(), t);
  ASSERT_EQ(marker.size(), m.points.size());
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    EXPECT_EQ(points[3 * i], m.points[i].x);
    EXPECT_EQ(points[3 * i + 1], m.points[i].y);
    EXPECT_EQ(points[3 * i + 2], 0.0);
    EXPECT_EQ(marker[i], m.vertex_markers[i]);
  }
  for (std::size_t k = 0; k < t; ++k) {
    const auto& tri = m.triangles[k];
    for (int c = 0; c < 3; ++c) EXPECT_EQ(connectivity[3 * k + c], tri[c]);
    EXPECT_EQ(offsets[k], 3.0 * (k + 1));
    EXPECT_EQ(types[k], 5.0);
    EXPECT_EQ(region[k], m.triangle_attributes[k]);
    const double expected = triangle_min_angle_deg(m.points[tri[0]], m.points[tri[1]], m.points[tri[2]]);
    EXPECT_NEAR(angle[k], expected, 1e-9);
    EXPECT_NEAR(q[k], expected / 60.0, 1e-11);
  }
}

TEST(MeshFormats, SurfaceFormatsKeepTheTrianglesAtZeroHeight) {
  TempDir dir;
  const TriMesh m = two_region_mesh();
  Triangles expected;
  for (const auto& t : m.triangles) expected.insert(rotated(t));
  for (const char* ext : {".obj", ".off", ".ply", ".stl"}) {
    const std::string path = dir.file(std::string("m") + ext);
    io::mesh_writer_for(path)->write_mesh(path, m);
    const io::Surface s = io::read_surface(path);
    // STL welds by coordinates and numbers by first appearance: compare by coordinates.
    std::set<std::vector<double>> read_back, wanted;
    const auto point_key = [](const std::array<Point3, 3>& c) {
      // Rotated to start at the lexicographically least corner, orientation kept.
      std::size_t first = 0;
      for (std::size_t i = 1; i < 3; ++i)
        if (std::tie(c[i].x, c[i].y) < std::tie(c[first].x, c[first].y)) first = i;
      std::vector<double> key;
      for (std::size_t i = 0; i < 3; ++i) {
        const Point3& p = c[(first + i) % 3];
        key.insert(key.end(), {p.x, p.y, p.z});
      }
      return key;
    };
    for (const auto& t : s.triangles) read_back.insert(point_key({s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]}));
    for (const auto& t : m.triangles) {
      std::array<Point3, 3> c;
      for (int i = 0; i < 3; ++i) c[i] = {m.points[t[i]].x, m.points[t[i]].y, 0.0};
      if (std::string(ext) == ".stl")
        for (Point3& p : c) p = {static_cast<float>(p.x), static_cast<float>(p.y), 0.0};
      wanted.insert(point_key(c));
    }
    EXPECT_EQ(read_back, wanted) << ext;
    EXPECT_EQ(s.triangles.size(), m.triangles.size()) << ext;
  }
}

TEST(MeshFormats, AWriterThatFailsLeavesTheTargetAsItWas) {
  TempDir dir;
  TriMesh bad = two_region_mesh();
  bad.points[2].x = std::nan("");
  for (const char* ext : {".msh", ".vtu", ".obj", ".off", ".ply", ".stl"}) {
    const std::string path = dir.write(std::string("old") + ext, "old contents\n");
    try {
      io::mesh_writer_for(path)->write_mesh(path, bad);
      ADD_FAILURE() << ext << ": a NaN coordinate was written";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": cannot write this"), std::string::npos) << e.what();
    }
    EXPECT_EQ(slurp(path), "old contents\n") << ext;
  }
  // Into a folder that does not exist: an error, and no file anywhere.
  EXPECT_THROW(io::write_gmsh(dir.file("missing/m.msh"), two_region_mesh()), InputError);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 6u);  // the six old files, no temporary one left behind
}

}  // namespace
}  // namespace meshstep
