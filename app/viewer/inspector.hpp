// The inspector's geometry, without GL or ImGui: which vertex, segment or triangle of the
// picture is under a world point, what a triangle measures, and its Lepp path (Rivara: from the
// triangle across longest edges until the longest edge is shared by both its triangles, or
// lies on the boundary).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "meshstep/scene/scene.hpp"

namespace meshstep::viewer {

struct Picked {
  enum class Kind { none, triangle, vertex, segment } kind = Kind::none;
  std::uint32_t index = 0;  // into mesh.triangles, or mesh.points (a segment: its piece's first end)
  std::uint32_t other = 0;  // a segment: its piece's other end (a constrained edge of the mesh)
  friend bool operator==(const Picked&, const Picked&) = default;
};

// The vertex within `radius` (world units) of `at` that is nearest, else the triangle that
// contains `at`, else nothing. Vertices count only when a triangle uses them.
Picked pick(const scene::MeshLayer& mesh, Point at, double radius);

// An edge of the mesh by its two points' indices.
using MeshEdge = std::array<std::uint32_t, 2>;
// The scene's constrained edges (its "segments" shape, which has their points' coordinates)
// as edges of its mesh, each once, smaller index first.
std::vector<MeshEdge> constrained_edges(const scene::Scene& scene);
// As pick above, with the constrained edges between vertices and triangles: the nearest
// vertex within vertex_radius, else the nearest edge within edge_radius, else the
// triangle. A vertex comes first because it lies on its segments (a click on it means it);
// a segment before the triangles either side of it, since a click within a few pixels of
// a line means the line (a triangle has its whole inside to be clicked in).
Picked pick(const scene::MeshLayer& mesh, std::span<const MeshEdge> edges, Point at, double vertex_radius,
            double edge_radius);

// What is under a point of a 3D view's picture. `shown` is the lifted mesh (scene/lift.hpp):
// its points are the vertices on screen, index for index; its triangles go back to front,
// each counterclockwise on screen. The front triangle that holds `at` (the last drawn), or a
// vertex of it within `radius` of `at`; nothing when no triangle holds it. A vertex hidden
// behind a ridge is not picked through it. A triangle's index is into shown.triangles.
Picked pick_front(const scene::MeshLayer& shown, Point at, double radius);

// The triangle of `mesh` with these three vertices (in any order), or kNoIndex.
std::uint32_t find_triangle(const scene::MeshLayer& mesh, std::array<std::uint32_t, 3> vertices);

struct TriangleFacts {
  std::array<std::uint32_t, 3> vertices{};
  std::array<double, 3> angles{};  // at each vertex, degrees
  double area = 0.0;
  double min_angle = 0.0;
};
TriangleFacts triangle_facts(const scene::MeshLayer& mesh, std::uint32_t triangle);

struct LeppPath {
  std::vector<std::uint32_t> triangles;  // from the start to a terminal triangle
  std::uint32_t a = 0, b = 0;            // the terminal edge's vertices
  bool boundary = false;                 // the terminal edge has one triangle
};
// The triangles' neighbours are found from the mesh (an edge map, built per call). With
// `heights` (a terrain's, by vertex), edges are measured in 3D as Lepp-surface measures them.
LeppPath lepp_path(const scene::MeshLayer& mesh, std::uint32_t triangle, std::span<const double> heights = {});

}  // namespace meshstep::viewer
