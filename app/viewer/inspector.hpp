// The inspector's geometry, without GL or ImGui: which triangle or vertex of the picture is
// under a world point, what a triangle measures, and its Lepp path (Rivara: from the
// triangle across longest edges until the longest edge is shared by both its triangles, or
// lies on the boundary).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "meshstep/scene/scene.hpp"

namespace meshstep::viewer {

struct Picked {
  enum class Kind { none, triangle, vertex } kind = Kind::none;
  std::uint32_t index = 0;  // into mesh.triangles, or mesh.points
  friend bool operator==(const Picked&, const Picked&) = default;
};

// The vertex within `radius` (world units) of `at` that is nearest, else the triangle that
// contains `at`, else nothing. Vertices count only when a triangle uses them.
Picked pick(const scene::MeshLayer& mesh, Point at, double radius);

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
// The triangles' neighbours are found from the mesh (an edge map, built per call).
LeppPath lepp_path(const scene::MeshLayer& mesh, std::uint32_t triangle);

}  // namespace meshstep::viewer
