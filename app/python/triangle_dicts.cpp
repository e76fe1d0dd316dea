// The triangle package's dictionaries (triangle_dicts.hpp).
#include "triangle_dicts.hpp"

#include <unordered_map>

#include "meshstep/io/triangle_io.hpp"
#include "numpy_arrays.hpp"

namespace meshstep::python {
namespace {

std::string key_name(const char* key) { return std::string("tri['") + key + "']"; }

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}

}  // namespace

bool has_key(const py::dict& tri, const char* key) { return tri.contains(key) && !tri[key].is_none(); }

Pslg pslg_from_dict(const py::dict& tri, bool use_segments) {
  if (!has_key(tri, "vertices")) throw py::value_error("tri['vertices'] is missing: the input needs vertices");
  Pslg in;
  in.points = points_from(tri["vertices"], key_name("vertices"));
  const std::size_t n = in.points.size();
  if (has_key(tri, "vertex_markers")) {
    in.vertex_markers = ints_from(tri["vertex_markers"], n, key_name("vertex_markers"));
    in.has_vertex_markers = true;
  }
  if (has_key(tri, "vertex_attributes")) {
    const DoubleArray a = as_reals(tri["vertex_attributes"], key_name("vertex_attributes"));
    const std::size_t rows = a.ndim() == 0 ? 0 : static_cast<std::size_t>(a.shape(0));
    if (a.ndim() > 2 || rows != n)
      throw py::value_error(key_name("vertex_attributes") + ": expected " + std::to_string(n) +
                            " rows (one for each vertex) of attributes");
    in.attributes_per_vertex = a.ndim() == 2 ? static_cast<std::size_t>(a.shape(1)) : 1;
    in.vertex_attributes.assign(a.data(), a.data() + a.size());
  }
  if (!use_segments) return in;
  if (has_key(tri, "segments")) {
    in.segments = segments_from(tri["segments"], n, key_name("segments"));
    if (has_key(tri, "segment_markers")) {
      const std::vector<int> markers = ints_from(tri["segment_markers"], in.segments.size(), key_name("segment_markers"));
      for (std::size_t i = 0; i < markers.size(); ++i) in.segments[i].marker = markers[i];
      in.has_segment_markers = true;
    }
  }
  if (has_key(tri, "holes")) in.holes = points_from(tri["holes"], key_name("holes"));
  if (has_key(tri, "regions")) {
    const DoubleArray a = real_table(tri["regions"], 4, key_name("regions") + " (rows of x, y, attribute, max area)");
    const std::size_t rows = a.ndim() == 0 ? 0 : static_cast<std::size_t>(a.shape(0));
    const double* r = a.data();
    for (std::size_t i = 0; i < rows; ++i)
      in.regions.push_back({{r[4 * i], r[4 * i + 1]}, r[4 * i + 2], r[4 * i + 3]});
  }
  return in;
}

TriMesh mesh_from_dict(const py::dict& tri, bool areas) {
  Pslg in = pslg_from_dict(tri, true);
  if (!has_key(tri, "triangles")) throw py::value_error("switch 'r' refines a mesh: tri['triangles'] is missing");
  TriMesh mesh;
  mesh.triangles = triangles_from(tri["triangles"], in.points.size(), key_name("triangles"));
  if (areas && has_key(tri, "triangle_max_area"))
    mesh.triangle_max_area = reals_from(tri["triangle_max_area"], mesh.triangles.size(), key_name("triangle_max_area"));
  mesh.points = std::move(in.points);
  mesh.input_vertex_count = mesh.points.size();
  mesh.vertex_markers = std::move(in.vertex_markers);
  mesh.attributes_per_vertex = in.attributes_per_vertex;
  mesh.vertex_attributes = std::move(in.vertex_attributes);
  mesh.segments = std::move(in.segments);
  mesh.has_segment_markers = in.has_segment_markers;
  mesh.holes = std::move(in.holes);
  mesh.regions = std::move(in.regions);
  return mesh;
}

void mesh_edges(const TriMesh& mesh, std::vector<Segment>& edges) {
  std::unordered_map<std::uint64_t, int> segment_marker;
  for (const Segment& s : mesh.segments) segment_marker.emplace(edge_key(s.a, s.b), s.marker);
  std::unordered_map<std::uint64_t, std::uint32_t> first;  // edge -> its index in `edges`
  first.reserve(mesh.triangles.size() * 2);
  std::vector<std::uint8_t> uses;
  edges.clear();
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      const auto [it, added] = first.emplace(edge_key(a, b), static_cast<std::uint32_t>(edges.size()));
      if (added) {
        edges.push_back({a, b, 0});
        uses.push_back(1);
      } else {
        ++uses[it->second];
      }
    }
  }
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const auto it = segment_marker.find(edge_key(edges[e].a, edges[e].b));
    edges[e].marker = uses[e] == 1 ? 1 : 0;
    if (it != segment_marker.end()) edges[e].marker = it->second != 0 ? it->second : 1;
  }
}

py::dict mesh_to_dict(const TriMesh& mesh, const DictOutput& what) {
  py::dict out;
  out["vertices"] = points_array(mesh.points);
  if (!mesh.vertex_markers.empty()) out["vertex_markers"] = ints_array(mesh.vertex_markers, 1);
  if (mesh.attributes_per_vertex)
    out["vertex_attributes"] = reals_array(mesh.vertex_attributes, mesh.attributes_per_vertex);
  out["triangles"] = triangles_array(mesh.triangles);
  if (what.triangle_attributes && mesh.attributes_per_triangle)
    out["triangle_attributes"] = reals_array(mesh.triangle_attributes, mesh.attributes_per_triangle);
  if (!mesh.segments.empty()) {
    out["segments"] = segments_array(mesh.segments);
    out["segment_markers"] = segment_markers_array(mesh.segments);
  }
  if (!mesh.holes.empty()) out["holes"] = points_array(mesh.holes);
  if (!mesh.regions.empty()) {
    std::vector<double> rows;
    for (const Region& r : mesh.regions) rows.insert(rows.end(), {r.point.x, r.point.y, r.attribute, r.max_area});
    out["regions"] = reals_array(rows, 4);
  }
  if (what.edges) {
    std::vector<Segment> edges;
    mesh_edges(mesh, edges);
    out["edges"] = segments_array(edges);
    out["edge_markers"] = segment_markers_array(edges);
  }
  if (what.neighbors)
    out["neighbors"] = neighbors_array(mesh.neighbors.size() == mesh.triangles.size() ? mesh.neighbors
                                                                                      : io::compute_neighbors(mesh));
  return out;
}

}  // namespace meshstep::python
