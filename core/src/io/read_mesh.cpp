// Reading a mesh: .node + .ele, with the optional .poly and .area beside them; and the
// .edge and .neigh files that belong to a mesh already read.
#include <filesystem>
#include <system_error>

#include "io/fields.hpp"
#include "io/record_reader.hpp"
#include "io/sections.hpp"
#include "meshstep/io/triangle_io.hpp"

namespace meshstep::io {
namespace {

using detail::Numbering;
using detail::RecordReader;

bool file_exists(const std::string& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

std::string ele_record_names(std::int64_t nodes, std::size_t attributes) {
  std::string names = "triangle number, " + std::to_string(nodes) +
                      (nodes == 3 ? " vertices" : " nodes");
  if (attributes == 1) names += ", attribute";
  if (attributes > 1) names += ", " + std::to_string(attributes) + " attributes";
  return names;
}

void read_ele(const std::string& path, Numbering& numbering, std::uint64_t vertex_count,
              TriMesh& mesh, std::vector<std::string>* warnings) {
  RecordReader r(path);
  constexpr const char* kHeader = "number of triangles, nodes per triangle, number of attributes";
  detail::read_header(r, kHeader);
  detail::expect_fields(r, 3, kHeader);
  const std::uint64_t count = detail::parse_count(r, 0, "number of triangles");
  const std::int64_t nodes = detail::parse_integer(r, 1, "nodes per triangle");
  if (nodes != 3 && nodes != 6) {
    r.fail("nodes per triangle must be 3 or 6, found " + std::to_string(nodes));
  }
  const std::uint64_t attributes = detail::parse_count(r, 2, "number of triangle attributes");
  if (attributes > detail::kMaxFields - 8) {
    r.fail("declares " + std::to_string(attributes) +
           " attributes per triangle, more than a line can hold");
  }
  const std::size_t header_line = r.line();
  const std::size_t fields = 1 + static_cast<std::size_t>(nodes + attributes);
  const std::size_t reserve = detail::check_count(r, count, fields, "triangles", detail::kMaxItems);
  if (nodes == 6) {
    detail::warn(r, warnings,
                 "6-node triangles: only the three corners are kept, the midside nodes are "
                 "dropped");
  }
  mesh.attributes_per_triangle = static_cast<std::size_t>(attributes);
  mesh.triangles.reserve(reserve);
  mesh.triangle_attributes.reserve(reserve * mesh.attributes_per_triangle);
  const std::string names = ele_record_names(nodes, mesh.attributes_per_triangle);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.next()) detail::fail_truncated(r, i, count, "triangles", header_line);
    detail::expect_fields(r, fields, names);
    detail::check_record_number(r, numbering, i, "triangle");
    std::array<std::uint32_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      t[k] = detail::parse_index(r, 1 + k, "triangle vertex", vertex_count, numbering.base,
                                 "vertices");
    }
    // Midside nodes are dropped, but a reference to a missing vertex is still an error.
    for (std::size_t k = 3; k < static_cast<std::size_t>(nodes); ++k) {
      detail::parse_index(r, 1 + k, "triangle node", vertex_count, numbering.base, "vertices");
    }
    mesh.triangles.push_back(t);
    for (std::size_t k = 0; k < mesh.attributes_per_triangle; ++k) {
      mesh.triangle_attributes.push_back(
          detail::parse_real(r, 1 + static_cast<std::size_t>(nodes) + k, "triangle attribute"));
    }
  }
  detail::warn_if_trailing(r, "triangles", header_line, warnings);
}

void read_area(const std::string& path, Numbering& numbering, TriMesh& mesh,
               std::vector<std::string>* warnings) {
  RecordReader r(path);
  detail::read_header(r, "number of triangles");
  detail::expect_fields(r, 1, "number of triangles");
  const std::uint64_t count = detail::parse_count(r, 0, "number of triangles");
  if (count != mesh.triangles.size()) {
    r.fail("declares " + std::to_string(count) + " triangles, but the .ele file has " +
           std::to_string(mesh.triangles.size()));
  }
  const std::size_t header_line = r.line();
  mesh.triangle_max_area.reserve(detail::check_count(r, count, 2, "triangles", detail::kMaxItems));
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.next()) detail::fail_truncated(r, i, count, "triangles", header_line);
    detail::expect_fields(r, 2, "triangle number, maximum area");
    detail::check_record_number(r, numbering, i, "triangle");
    mesh.triangle_max_area.push_back(detail::parse_real(r, 1, "maximum area"));
  }
  detail::warn_if_trailing(r, "triangles", header_line, warnings);
}

// The numbering of files that belong to a mesh already read.
Numbering numbering_of(const TriMesh& mesh) {
  return Numbering{mesh.first_index == 1 ? 1 : 0};
}

}  // namespace

TriMesh read_mesh(const std::string& prefix, std::vector<std::string>* warnings) {
  Pslg node = read_node(prefix + ".node", warnings);
  Numbering numbering{node.points.empty() ? -1 : node.first_index};
  TriMesh mesh;
  read_ele(prefix + ".ele", numbering, node.points.size(), mesh, warnings);
  mesh.first_index = numbering.base < 0 ? 0 : numbering.base;

  const std::string poly_path = prefix + ".poly";
  if (file_exists(poly_path)) {
    Pslg poly = detail::read_poly_file(poly_path, &node, warnings);
    mesh.segments = std::move(poly.segments);
    mesh.has_segment_markers = poly.has_segment_markers;
    mesh.holes = std::move(poly.holes);
    mesh.regions = std::move(poly.regions);
  }
  const std::string area_path = prefix + ".area";
  if (file_exists(area_path)) read_area(area_path, numbering, mesh, warnings);

  mesh.points = std::move(node.points);
  mesh.attributes_per_vertex = node.attributes_per_vertex;
  mesh.vertex_attributes = std::move(node.vertex_attributes);
  mesh.vertex_markers = std::move(node.vertex_markers);
  mesh.input_vertex_count = mesh.points.size();
  return mesh;
}

EdgeList read_edge(const std::string& path, const TriMesh& mesh,
                   std::vector<std::string>* warnings) {
  RecordReader r(path);
  constexpr const char* kHeader = "number of edges, number of boundary markers";
  detail::read_header(r, kHeader);
  detail::expect_fields(r, 2, kHeader);
  const std::uint64_t count = detail::parse_count(r, 0, "number of edges");
  EdgeList out;
  out.has_markers = detail::parse_marker_flag(r, 1, "number of boundary markers");
  const std::size_t header_line = r.line();
  const std::size_t fields = out.has_markers ? 4 : 3;
  out.edges.reserve(detail::check_count(r, count, fields, "edges", detail::kMaxItems));
  const char* names = out.has_markers ? "edge number, endpoint, endpoint, marker"
                                      : "edge number, endpoint, endpoint";
  Numbering numbering = numbering_of(mesh);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.next()) detail::fail_truncated(r, i, count, "edges", header_line);
    detail::expect_fields(r, fields, names);
    detail::check_record_number(r, numbering, i, "edge");
    Segment e;
    e.a = detail::parse_index(r, 1, "edge endpoint", mesh.points.size(), numbering.base,
                              "vertices");
    e.b = detail::parse_index(r, 2, "edge endpoint", mesh.points.size(), numbering.base,
                              "vertices");
    if (out.has_markers) e.marker = detail::parse_marker(r, 3, "edge boundary marker");
    out.edges.push_back(e);
  }
  detail::warn_if_trailing(r, "edges", header_line, warnings);
  return out;
}

std::vector<std::array<std::uint32_t, 3>> read_neigh(const std::string& path,
                                                     const TriMesh& mesh,
                                                     std::vector<std::string>* warnings) {
  RecordReader r(path);
  constexpr const char* kHeader = "number of triangles, neighbours per triangle";
  detail::read_header(r, kHeader);
  detail::expect_fields(r, 2, kHeader);
  const std::uint64_t count = detail::parse_count(r, 0, "number of triangles");
  const std::int64_t per = detail::parse_integer(r, 1, "neighbours per triangle");
  if (per != 3) r.fail("neighbours per triangle must be 3, found " + std::to_string(per));
  if (count != mesh.triangles.size()) {
    r.fail("declares " + std::to_string(count) + " triangles, but the mesh has " +
           std::to_string(mesh.triangles.size()));
  }
  const std::size_t header_line = r.line();
  std::vector<std::array<std::uint32_t, 3>> out;
  out.reserve(detail::check_count(r, count, 4, "triangles", detail::kMaxItems));
  Numbering numbering = numbering_of(mesh);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.next()) detail::fail_truncated(r, i, count, "triangles", header_line);
    detail::expect_fields(r, 4, "triangle number, neighbour, neighbour, neighbour");
    detail::check_record_number(r, numbering, i, "triangle");
    std::array<std::uint32_t, 3> n{};
    for (std::size_t k = 0; k < 3; ++k) {
      n[k] = r.field(1 + k) == "-1"
                 ? kNoIndex
                 : detail::parse_index(r, 1 + k, "neighbour", count, numbering.base,
                                       "triangles");
    }
    out.push_back(n);
  }
  detail::warn_if_trailing(r, "triangles", header_line, warnings);
  return out;
}

}  // namespace meshstep::io
