// A planar scene lifted onto its terrain and seen in 3D (lift.hpp).
#include "meshstep/scene/lift.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include "parts.hpp"

namespace meshstep::scene {

namespace {

struct PointHash {
  std::size_t operator()(const Point& p) const {
    const std::uint64_t x = std::bit_cast<std::uint64_t>(p.x), y = std::bit_cast<std::uint64_t>(p.y);
    return std::hash<std::uint64_t>()(x * 0x9E3779B97F4A7C15ull ^ y);
  }
};

using Triangle = std::array<std::uint32_t, 3>;

Triangle sorted(Triangle t) {
  std::sort(t.begin(), t.end());
  return t;
}

struct TriangleHash {
  std::size_t operator()(const Triangle& t) const {
    return std::hash<std::uint64_t>()((std::uint64_t{t[0]} << 42) ^ (std::uint64_t{t[1]} << 21) ^ t[2]);
  }
};

// The height at any point of the plane: a mesh point's own, else the plane of the triangle
// that holds the point, else the nearest mesh point's. Overlays have a few dozen points,
// so a triangle is searched linearly.
class HeightField {
 public:
  HeightField(const MeshLayer& mesh, std::span<const double> heights) : mesh_(mesh), heights_(heights) {
    at_.reserve(mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size() && i < heights.size(); ++i) at_.emplace(mesh.points[i], heights[i]);
  }

  double operator()(const Point& p) const {
    if (const auto it = at_.find(p); it != at_.end()) return it->second;
    for (const Triangle& t : mesh_.triangles) {
      if (std::max({t[0], t[1], t[2]}) >= heights_.size()) continue;
      const Point &a = mesh_.points[t[0]], &b = mesh_.points[t[1]], &c = mesh_.points[t[2]];
      const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      if (area == 0.0) continue;
      const double wa = ((b.x - p.x) * (c.y - p.y) - (b.y - p.y) * (c.x - p.x)) / area;
      const double wb = ((c.x - p.x) * (a.y - p.y) - (c.y - p.y) * (a.x - p.x)) / area;
      const double wc = 1.0 - wa - wb;
      constexpr double kSlack = -1e-12;
      if (wa >= kSlack && wb >= kSlack && wc >= kSlack)
        return wa * heights_[t[0]] + wb * heights_[t[1]] + wc * heights_[t[2]];
    }
    double best = INFINITY, z = 0.0;
    for (std::size_t i = 0; i < mesh_.points.size() && i < heights_.size(); ++i) {
      const double d = std::hypot(mesh_.points[i].x - p.x, mesh_.points[i].y - p.y);
      if (d < best) best = d, z = heights_[i];
    }
    return z;
  }

 private:
  const MeshLayer& mesh_;
  std::span<const double> heights_;
  std::unordered_map<Point, double, PointHash> at_;
};

// "-32.3°", "35°": a tenth of a degree at most (a turning camera's azimuth is any number).
std::string degrees_text(double deg) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", deg);
  std::string text = buf;
  if (text.ends_with(".0")) text.resize(text.size() - 2);
  if (text == "-0") text = "0";
  return text + "\u00B0";
}

}  // namespace

Point project(const Point& p, double z, const SurfaceView& view) {
  const ViewBasis b = view_basis(view);
  const double x = p.x - view.pivot.x, y = p.y - view.pivot.y, zs = (z - view.pivot.z) * view.z_scale;
  return {x * b.right.x + y * b.right.y + zs * b.right.z, x * b.up.x + y * b.up.y + zs * b.up.z};
}

Scene lift_scene(const Scene& planar, std::span<const double> point_heights, const SurfaceView& view) {
  io::Surface surface;
  surface.vertices.reserve(planar.mesh.points.size());
  for (std::size_t i = 0; i < planar.mesh.points.size(); ++i) {
    const Point& p = planar.mesh.points[i];
    surface.vertices.push_back({p.x, p.y, i < point_heights.size() ? point_heights[i] : 0.0});
  }
  surface.triangles = planar.mesh.triangles;
  Scene scene = surface_scene(surface, view, planar.theme);

  // The step's changed faces, by their new places in the back-to-front order.
  if (!planar.highlighted.empty()) {
    std::unordered_map<Triangle, std::uint32_t, TriangleHash> index;
    index.reserve(scene.mesh.triangles.size());
    for (std::uint32_t i = 0; i < scene.mesh.triangles.size(); ++i) index.emplace(sorted(scene.mesh.triangles[i]), i);
    for (const std::uint32_t old : planar.highlighted)
      if (old < planar.mesh.triangles.size())
        if (const auto it = index.find(sorted(planar.mesh.triangles[old])); it != index.end())
          scene.highlighted.push_back(it->second);
  }

  const HeightField height(planar.mesh, point_heights);
  const auto lifted = [&](const Point& p) { return project(p, height(p), view); };
  for (const Shape& s : planar.shapes) {
    if (s.kind == ShapeKind::circles) continue;
    Shape& out = scene.shapes.emplace_back(s);
    for (Point& p : out.points) p = lifted(p);
    // A filled triangle turned over by the view is still counterclockwise on screen.
    if (s.kind == ShapeKind::triangles)
      for (std::size_t i = 0; i + 2 < out.points.size(); i += 3) {
        const Point &a = out.points[i], &b = out.points[i + 1], &c = out.points[i + 2];
        if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < 0.0) std::swap(out.points[i + 1], out.points[i + 2]);
      }
  }
  for (const Label& l : planar.labels) {
    Label& out = scene.labels.emplace_back(l);
    out.at = lifted(l.at);
  }

  scene.caption = planar.caption + " \u00B7 3D " + degrees_text(view.azimuth_deg) + ", " + degrees_text(view.elevation_deg);
  if (view.z_scale != 1.0) {
    char scale[48];
    std::snprintf(scale, sizeof scale, ", heights \u00D7%g", view.z_scale);
    scene.caption += scale;
  }
  scene.caption_color = planar.caption_color;
  scene.visible = planar.visible;
  scene.bounds = detail::scene_bounds(scene, detail::points_box(scene.mesh.points));
  return scene;
}

std::vector<double> mesh_point_heights(const Scene& planar, const replay::LogReader& log) {
  // A log's scene indexes its points by the log's vertex ids (build_replay.cpp): the height
  // of point i is vertex i's, even where two vertices share a position in the plane (the
  // top and bottom of a closed surface).
  const std::vector<replay::VertexInfo>& vertices = log.vertices();
  std::vector<double> heights(planar.mesh.points.size(), 0.0);
  for (std::size_t i = 0; i < heights.size() && i < vertices.size(); ++i) heights[i] = vertices[i].z;
  return heights;
}

}  // namespace meshstep::scene
