// Re-refinement of an existing mesh (refine.hpp: refine_mesh): the mesh becomes a PSLG whose
// constrained Delaunay triangulation covers the same domain, and its per-triangle area
// bounds bound every new triangle that overlaps the old one.
#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>

#include "meshstep/error.hpp"
#include "meshstep/geometry/triangle_field.hpp"
#include "meshstep/refine/refine.hpp"

namespace meshstep {
namespace {

std::pair<std::uint32_t, std::uint32_t> undirected(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

TriangleField field_of(const TriMesh& mesh, const std::vector<double>& values) {
  TriangleField field;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    field.add(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], values[t]);
  }
  field.build();
  return field;
}

Point centroid(const TriMesh& m, std::size_t t) {
  const auto& v = m.triangles[t];
  return {(m.points[v[0]].x + m.points[v[1]].x + m.points[v[2]].x) / 3.0,
          (m.points[v[0]].y + m.points[v[1]].y + m.points[v[2]].y) / 3.0};
}

// The PSLG of a mesh: its vertices; its segments, and every boundary edge (an edge of one
// triangle only) not among them, with marker 1.
Pslg pslg_of(const TriMesh& mesh) {
  Pslg in;
  in.points = mesh.points;
  in.first_index = mesh.first_index;
  in.regions = mesh.regions;
  in.holes = mesh.holes;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) ++uses[undirected(t[i], t[(i + 1) % 3])];
  std::map<std::pair<std::uint32_t, std::uint32_t>, bool> listed;
  for (const Segment& s : mesh.segments) {
    in.segments.push_back(s);
    listed[undirected(s.a, s.b)] = true;
  }
  for (const auto& [edge, count] : uses)
    if (count == 1 && !listed.count(edge)) in.segments.push_back({edge.first, edge.second, 1});
  return in;
}

}  // namespace

TriMesh refine_mesh_chain(const TriMesh& mesh, std::vector<RefineOptions> operations, std::span<RefineReport> reports,
                          const std::function<void(std::size_t)>& before) {
  if (mesh.triangles.empty()) throw InputError("the mesh has no triangles to refine");
  if (operations.empty()) throw InputError("a refinement needs at least one operation");
  RefineOptions& options = operations.front();
  Pslg in = pslg_of(mesh);
  // Holes: the segments enclose the domain, but a hole inside it needs a point. Every
  // triangle of the domain's CDT whose centroid lies in no old triangle is in a hole.
  const TriangleField inside = field_of(mesh, std::vector<double>(mesh.triangles.size(), 1.0));
  {
    TriangulateOptions plain;
    plain.data_structure = options.triangulate.data_structure;
    const TriMesh cdt = triangulate(in, plain);
    for (std::size_t t = 0; t < cdt.triangles.size(); ++t)
      if (inside.at(centroid(cdt, t), 0.0) == 0.0) in.holes.push_back(centroid(cdt, t));
  }
  // The old triangles' areas bound the first operation, as Triangle's -r -a does.
  const bool has_areas = std::any_of(mesh.triangle_max_area.begin(), mesh.triangle_max_area.end(),
                                     [](double a) { return a > 0.0; });
  if (has_areas && mesh.triangle_max_area.size() == mesh.triangles.size()) {
    auto areas = std::make_shared<TriangleField>(field_of(mesh, mesh.triangle_max_area));
    auto global = options.criteria.max_area_for;
    options.criteria.max_area_for = [areas, global](const Point& a, const Point& b, const Point& c) {
      const double own = areas->min_positive_over(a, b, c, -1.0);
      const double theirs = global ? global(a, b, c) : -1.0;
      if (own > 0.0 && theirs > 0.0) return std::min(own, theirs);
      return own > 0.0 ? own : theirs;
    };
  }
  return refine_chain(std::move(in), operations, reports, before);
}

TriMesh refine_mesh(const TriMesh& mesh, RefineOptions options, RefineReport* report) {
  RefineReport local;
  return refine_mesh_chain(mesh, {std::move(options)}, std::span<RefineReport>(report ? report : &local, 1));
}

}  // namespace meshstep
