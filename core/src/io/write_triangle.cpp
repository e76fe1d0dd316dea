// Writers of Triangle's .node, .ele, .poly, .edge, .neigh and .area files.
//
// A mesh that cannot be written faithfully (array sizes that disagree, an index past the
// end, a coordinate that is not finite, which the readers would refuse) is rejected with an
// InputError before its file is replaced, rather than written as a file nobody can read.
#include <cmath>
#include <unordered_map>

#include "io/atomic_writer.hpp"
#include "io/edge_groups.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"

namespace meshstep::io {
namespace {

using detail::AtomicWriter;

[[noreturn]] void bad_mesh(const std::string& path, const std::string& message) {
  throw InputError(path, 0, "cannot write this mesh: " + message);
}

std::int64_t base_of(const std::string& path, const TriMesh& mesh) {
  if (mesh.first_index != 0 && mesh.first_index != 1) {
    bad_mesh(path, "first_index must be 0 or 1, not " + std::to_string(mesh.first_index));
  }
  return mesh.first_index;
}

void finite_real(AtomicWriter& w, double v, const char* what, std::size_t index) {
  if (!std::isfinite(v)) {
    bad_mesh(w.path(), std::string(what) + " " + std::to_string(index) + " is not finite");
  }
  w.ch(' ');
  w.real(v);
}

void check_vertex(const std::string& path, const TriMesh& mesh, std::uint32_t v,
                  const char* user, std::size_t index) {
  if (v >= mesh.points.size()) {
    bad_mesh(path, std::string(user) + " " + std::to_string(index) + " uses vertex " +
                       std::to_string(v) + ", but there are only " +
                       std::to_string(mesh.points.size()) + " vertices");
  }
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}

}  // namespace

void write_node(const std::string& path, const TriMesh& mesh) {
  const std::int64_t base = base_of(path, mesh);
  const std::size_t n = mesh.points.size();
  const std::size_t attributes = mesh.attributes_per_vertex;
  if (mesh.vertex_attributes.size() != n * attributes) {
    bad_mesh(path, "vertex_attributes has " + std::to_string(mesh.vertex_attributes.size()) +
                       " values, expected " + std::to_string(n * attributes));
  }
  const bool markers = !mesh.vertex_markers.empty();
  if (markers && mesh.vertex_markers.size() != n) {
    bad_mesh(path, "vertex_markers has " + std::to_string(mesh.vertex_markers.size()) +
                       " values for " + std::to_string(n) + " vertices");
  }
  AtomicWriter w(path);
  w.integer(static_cast<std::int64_t>(n));
  w.text(" 2 ");
  w.integer(static_cast<std::int64_t>(attributes));
  w.text(markers ? " 1\n" : " 0\n");
  for (std::size_t i = 0; i < n; ++i) {
    w.integer(static_cast<std::int64_t>(i) + base);
    finite_real(w, mesh.points[i].x, "x coordinate of vertex", i);
    finite_real(w, mesh.points[i].y, "y coordinate of vertex", i);
    for (std::size_t k = 0; k < attributes; ++k) {
      finite_real(w, mesh.vertex_attributes[i * attributes + k], "attribute of vertex", i);
    }
    if (markers) {
      w.ch(' ');
      w.integer(mesh.vertex_markers[i]);
    }
    w.ch('\n');
  }
  w.commit();
}

void write_ele(const std::string& path, const TriMesh& mesh) {
  const std::int64_t base = base_of(path, mesh);
  const std::size_t count = mesh.triangles.size();
  const std::size_t attributes = mesh.attributes_per_triangle;
  if (mesh.triangle_attributes.size() != count * attributes) {
    bad_mesh(path, "triangle_attributes has " +
                       std::to_string(mesh.triangle_attributes.size()) + " values, expected " +
                       std::to_string(count * attributes));
  }
  AtomicWriter w(path);
  w.integer(static_cast<std::int64_t>(count));
  w.text(" 3 ");
  w.integer(static_cast<std::int64_t>(attributes));
  w.ch('\n');
  for (std::size_t t = 0; t < count; ++t) {
    w.integer(static_cast<std::int64_t>(t) + base);
    for (const std::uint32_t v : mesh.triangles[t]) {
      check_vertex(path, mesh, v, "triangle", t);
      w.ch(' ');
      w.integer(v + base);
    }
    for (std::size_t k = 0; k < attributes; ++k) {
      finite_real(w, mesh.triangle_attributes[t * attributes + k], "attribute of triangle", t);
    }
    w.ch('\n');
  }
  w.commit();
}

void write_poly(const std::string& path, const TriMesh& mesh) {
  const std::int64_t base = base_of(path, mesh);
  AtomicWriter w(path);
  // No vertices here: they are in the .node file beside this one.
  w.text("0 2 0 1\n");
  w.integer(static_cast<std::int64_t>(mesh.segments.size()));
  w.text(" 1\n");
  for (std::size_t i = 0; i < mesh.segments.size(); ++i) {
    const Segment& s = mesh.segments[i];
    check_vertex(path, mesh, s.a, "segment", i);
    check_vertex(path, mesh, s.b, "segment", i);
    w.integer(static_cast<std::int64_t>(i) + base);
    w.ch(' ');
    w.integer(s.a + base);
    w.ch(' ');
    w.integer(s.b + base);
    w.ch(' ');
    w.integer(s.marker);
    w.ch('\n');
  }
  w.integer(static_cast<std::int64_t>(mesh.holes.size()));
  w.ch('\n');
  for (std::size_t i = 0; i < mesh.holes.size(); ++i) {
    w.integer(static_cast<std::int64_t>(i) + base);
    finite_real(w, mesh.holes[i].x, "x coordinate of hole", i);
    finite_real(w, mesh.holes[i].y, "y coordinate of hole", i);
    w.ch('\n');
  }
  w.integer(static_cast<std::int64_t>(mesh.regions.size()));
  w.ch('\n');
  for (std::size_t i = 0; i < mesh.regions.size(); ++i) {
    const Region& r = mesh.regions[i];
    w.integer(static_cast<std::int64_t>(i) + base);
    finite_real(w, r.point.x, "x coordinate of region", i);
    finite_real(w, r.point.y, "y coordinate of region", i);
    finite_real(w, r.attribute, "attribute of region", i);
    finite_real(w, r.max_area, "maximum area of region", i);
    w.ch('\n');
  }
  w.commit();
}

void write_edge(const std::string& path, const TriMesh& mesh) {
  const std::int64_t base = base_of(path, mesh);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const std::uint32_t v : mesh.triangles[t]) check_vertex(path, mesh, v, "triangle", t);
  }
  std::unordered_map<std::uint64_t, int> segment_marker;
  segment_marker.reserve(mesh.segments.size());
  for (const Segment& s : mesh.segments) segment_marker.emplace(edge_key(s.a, s.b), s.marker);

  // Each edge is written where it first occurs (lowest triangle, then lowest side), in the
  // orientation of that triangle, so the output does not depend on how edges were grouped.
  const detail::EdgeGroups groups = detail::group_edges(mesh);
  std::vector<int> marker_at(mesh.triangles.size() * 3, 0);
  std::vector<bool> written_at(mesh.triangles.size() * 3, false);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const std::uint32_t first = groups.sides[groups.start[g]];
    const bool boundary = groups.start[g + 1] - groups.start[g] == 1;
    const auto it =
        segment_marker.find(edge_key(detail::side_from(mesh, first), detail::side_to(mesh, first)));
    int marker = boundary ? 1 : 0;
    if (it != segment_marker.end()) marker = it->second != 0 ? it->second : 1;
    written_at[first] = true;
    marker_at[first] = marker;
  }

  AtomicWriter w(path);
  w.integer(static_cast<std::int64_t>(groups.size()));
  w.text(" 1\n");
  std::int64_t number = base;
  for (std::uint32_t side = 0; side < written_at.size(); ++side) {
    if (!written_at[side]) continue;
    w.integer(number++);
    w.ch(' ');
    w.integer(detail::side_from(mesh, side) + base);
    w.ch(' ');
    w.integer(detail::side_to(mesh, side) + base);
    w.ch(' ');
    w.integer(marker_at[side]);
    w.ch('\n');
  }
  w.commit();
}

void write_neigh(const std::string& path, const TriMesh& mesh) {
  const std::int64_t base = base_of(path, mesh);
  const std::size_t count = mesh.triangles.size();
  std::vector<std::array<std::uint32_t, 3>> computed;
  const auto* neighbors = &mesh.neighbors;
  if (mesh.neighbors.empty()) {
    computed = compute_neighbors(mesh);
    neighbors = &computed;
  } else if (mesh.neighbors.size() != count) {
    bad_mesh(path, "neighbors has " + std::to_string(mesh.neighbors.size()) +
                       " entries for " + std::to_string(count) + " triangles");
  }
  AtomicWriter w(path);
  w.integer(static_cast<std::int64_t>(count));
  w.text(" 3\n");
  for (std::size_t t = 0; t < count; ++t) {
    w.integer(static_cast<std::int64_t>(t) + base);
    for (const std::uint32_t n : (*neighbors)[t]) {
      if (n != kNoIndex && n >= count) {
        bad_mesh(path, "triangle " + std::to_string(t) + " has neighbour " + std::to_string(n) +
                           ", but there are only " + std::to_string(count) + " triangles");
      }
      w.ch(' ');
      w.integer(n == kNoIndex ? -1 : n + base);
    }
    w.ch('\n');
  }
  w.commit();
}

void write_area(const std::string& path, const TriMesh& mesh) {
  const std::int64_t base = base_of(path, mesh);
  const std::size_t count = mesh.triangles.size();
  if (mesh.triangle_max_area.size() != count) {
    bad_mesh(path, "triangle_max_area has " + std::to_string(mesh.triangle_max_area.size()) +
                       " values for " + std::to_string(count) + " triangles");
  }
  AtomicWriter w(path);
  w.integer(static_cast<std::int64_t>(count));
  w.ch('\n');
  for (std::size_t t = 0; t < count; ++t) {
    w.integer(static_cast<std::int64_t>(t) + base);
    finite_real(w, mesh.triangle_max_area[t], "maximum area of triangle", t);
    w.ch('\n');
  }
  w.commit();
}

void write_mesh(const std::string& prefix, const TriMesh& mesh, const WriteOptions& options) {
  write_node(prefix + ".node", mesh);
  write_ele(prefix + ".ele", mesh);
  write_poly(prefix + ".poly", mesh);
  if (!mesh.triangle_max_area.empty()) write_area(prefix + ".area", mesh);
  if (options.edges) write_edge(prefix + ".edge", mesh);
  if (options.neighbors) write_neigh(prefix + ".neigh", mesh);
}

}  // namespace meshstep::io
