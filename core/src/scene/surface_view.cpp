// A triangle surface in 3D as a scene (surface_view.hpp): parallel projection, Lambert
// shading, height colours, back-to-front order.
#include "meshstep/scene/surface_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>

#include "meshstep/scene/colormap.hpp"
#include "fill.hpp"
#include "parts.hpp"
#include "style.hpp"

namespace meshstep::scene {

namespace {

// The wireframe: dark and thin, translucent so that it reads as a texture over the shading.
constexpr Rgba kWireLight{0, 0, 0, 90};
constexpr Rgba kWireDark{0, 0, 0, 130};

double dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Point3 sub(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Point3 scaled(const Point3& a, double k) { return {a.x * k, a.y * k, a.z * k}; }
Point3 sum(const Point3& a, const Point3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Point3 unit(const Point3& a) {
  const double n = std::sqrt(dot(a, a));
  return n > 0.0 && std::isfinite(n) ? scaled(a, 1.0 / n) : Point3{0.0, 0.0, 0.0};
}

Rgba shaded(Rgba c, double shade) {
  const auto ch = [&](std::uint8_t v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v * shade, 0.0, 255.0))); };
  return {ch(c.r), ch(c.g), ch(c.b), c.a};
}

std::string degrees_text(double deg) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g\u00B0", deg);
  return buf;
}

std::string count_text(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}


}  // namespace

ViewBasis view_basis(const SurfaceView& view) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double a = view.azimuth_deg * kDeg, e = view.elevation_deg * kDeg;
  ViewBasis b;
  b.toward_camera = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
  b.right = {-std::sin(a), std::cos(a), 0.0};
  b.up = {-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)};
  return b;
}

Scene surface_scene(const io::Surface& surface, const SurfaceView& view, Theme theme, std::string_view name) {
  SceneOptions options;
  options.theme = theme;
  Scene scene = detail::start_scene(options);
  scene.mesh.edge_color = theme == Theme::dark ? kWireDark : kWireLight;
  scene.mesh.edge_width_px = 1.0f;
  scene.mesh.painter_order = true;

  const ViewBasis basis = view_basis(view);
  const Point3 light = view.light ? unit(*view.light)
                                  : unit(sum(basis.toward_camera, sum(scaled(basis.up, 0.8), scaled(basis.right, -0.6))));
  const double k = view.z_scale;
  const std::size_t n = surface.vertices.size();

  // The vertices with their heights scaled: what the camera sees.
  std::vector<Point3> world(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point3& v = surface.vertices[i];
    world[i] = {v.x - view.pivot.x, v.y - view.pivot.y, (v.z - view.pivot.z) * k};
  }
  // Parallel projection: a vertex's screen position is its components along the screen's
  // right and up, whatever its distance from the camera.
  scene.mesh.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) scene.mesh.points[i] = {dot(world[i], basis.right), dot(world[i], basis.up)};

  // Triangles with a vertex past the end are left out.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles)
    if (t[0] < n && t[1] < n && t[2] < n) triangles.push_back(t);

  // The colour scale spans the heights of the vertices the triangles use.
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& t : triangles)
    for (const std::uint32_t v : t) lo = std::min(lo, surface.vertices[v].z), hi = std::max(hi, surface.vertices[v].z);

  // Back to front: increasing depth of the centroid toward the camera; ties by index.
  std::vector<double> depth(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    depth[i] = (dot(world[t[0]], basis.toward_camera) + dot(world[t[1]], basis.toward_camera) +
                dot(world[t[2]], basis.toward_camera)) / 3.0;
  }
  std::vector<std::uint32_t> order(triangles.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return depth[a] < depth[b]; });

  scene.mesh.triangles.reserve(triangles.size());
  scene.mesh.fill.reserve(triangles.size());
  scene.mesh.values.reserve(triangles.size());
  for (const std::uint32_t i : order) {
    auto t = triangles[i];
    const Point3 &a = world[t[0]], &b = world[t[1]], &c = world[t[2]];
    // Two-sided Lambert: the normal turned toward the camera, lit when it faces the light.
    Point3 normal = unit(cross(sub(b, a), sub(c, a)));
    if (dot(normal, basis.toward_camera) < 0.0) normal = scaled(normal, -1.0);
    const double lambert = std::max(0.0, dot(normal, light));
    const double shade = view.ambient + (1.0 - view.ambient) * lambert;

    const double mean = (surface.vertices[t[0]].z + surface.vertices[t[1]].z + surface.vertices[t[2]].z) / 3.0;
    const double at = hi > lo ? (mean - lo) / (hi - lo) : 0.5;
    scene.mesh.fill.push_back(shaded(viridis()(at), shade));
    scene.mesh.values.push_back(mean);

    // Counterclockwise on screen, as every scene's triangles are.
    const Point &p = scene.mesh.points[t[0]], &q = scene.mesh.points[t[1]], &r = scene.mesh.points[t[2]];
    if ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x) < 0.0) std::swap(t[1], t[2]);
    scene.mesh.triangles.push_back(t);
  }

  if (!triangles.empty()) scene.legend = detail::height_legend(lo, hi);
  std::string caption;
  if (!name.empty()) caption = std::string(name) + " \u00B7 ";
  caption += count_text(n, "vertex", "vertices") + ", " + count_text(triangles.size(), "triangle", "triangles") +
             " \u00B7 azimuth " + degrees_text(view.azimuth_deg) + ", elevation " + degrees_text(view.elevation_deg);
  if (k != 1.0) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " \u00B7 heights \u00D7%g", k);
    caption += buf;
  }
  scene.caption = std::move(caption);
  scene.bounds = detail::scene_bounds(scene, detail::points_box(scene.mesh.points));
  return scene;
}

}  // namespace meshstep::scene
