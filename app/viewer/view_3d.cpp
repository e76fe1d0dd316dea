#include "view_3d.hpp"

#include <algorithm>
#include <cmath>

#include "meshstep/scene/lift.hpp"

namespace meshstep::viewer {

namespace {

double dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace

scene::SurfaceView Orbit::view() const {
  scene::SurfaceView view;
  view.azimuth_deg = azimuth_deg;
  view.elevation_deg = elevation_deg;
  view.z_scale = z_scale;
  return view;
}

Orbit normalized(Orbit o) {
  const Orbit defaults;
  if (!std::isfinite(o.azimuth_deg)) o.azimuth_deg = defaults.azimuth_deg;
  if (!std::isfinite(o.elevation_deg)) o.elevation_deg = defaults.elevation_deg;
  if (!(o.z_scale > 0.0) || !std::isfinite(o.z_scale)) o.z_scale = defaults.z_scale;
  o.azimuth_deg = std::fmod(o.azimuth_deg, 360.0);
  if (o.azimuth_deg > 180.0) o.azimuth_deg -= 360.0;
  if (o.azimuth_deg <= -180.0) o.azimuth_deg += 360.0;
  o.elevation_deg = std::clamp(o.elevation_deg, -90.0, 90.0);
  o.z_scale = std::clamp(o.z_scale, Orbit::kMinZScale, Orbit::kMaxZScale);
  return o;
}

View3d::View3d(const replay::LogReader* log) {
  if (!log || !log->has_elevation()) return;
  log_ = log;
  // The planar scene of a replay has every vertex of the log as its point of the same index
  // (scene/build.hpp), at every moment: the heights go by vertex id, found once.
  heights_.reserve(log->vertices().size());
  for (const replay::VertexInfo& v : log->vertices()) heights_.push_back(v.z);
}

bool View3d::set_on(bool on) {
  if (on && !available()) return false;
  on_ = on;
  return true;
}

bool View3d::set_orbit(const Orbit& wanted) {
  const Orbit next = normalized(wanted);
  if (next == orbit_) return false;
  // The pivot stays where it is in space: its height is stored scaled.
  pivot_.z *= next.z_scale / orbit_.z_scale;
  orbit_ = next;
  projected_ = false;
  return true;
}

bool View3d::turn(double d_azimuth_deg, double d_elevation_deg) {
  Orbit next = orbit_;
  next.azimuth_deg += d_azimuth_deg;
  next.elevation_deg += d_elevation_deg;
  return set_orbit(next);
}

bool View3d::scale_heights(double factor) {
  Orbit next = orbit_;
  next.z_scale *= factor;
  return set_orbit(next);
}

scene::Scene& View3d::lifted(const scene::Scene& planar, std::size_t serial, std::size_t max_vertex_markers) {
  if (serial != lifted_serial_ || !(orbit_ == lifted_orbit_) || max_vertex_markers != lifted_markers_) {
    lifted_ = scene::lift_scene(planar, heights_, orbit_.view());
    std::size_t markers = 0;
    for (const scene::Shape& s : lifted_.shapes)
      if (s.layer == scene::Layer::vertices) markers += s.points.size();
    if (markers > max_vertex_markers)
      std::erase_if(lifted_.shapes, [](const scene::Shape& s) { return s.layer == scene::Layer::vertices; });
    lifted_serial_ = serial;
    lifted_orbit_ = orbit_;
    lifted_markers_ = max_vertex_markers;
  }
  lifted_.text_scale = planar.text_scale;  // a view's property, changed without a new lift
  return lifted_;
}

void View3d::project_vertices() {
  if (projected_) return;
  projected_ = true;
  screen_.clear();
  depth_.clear();
  if (!log_) return;
  const scene::ViewBasis basis = scene::view_basis(orbit_.view());
  const std::vector<replay::VertexInfo>& vertices = log_->vertices();
  screen_.reserve(vertices.size());
  depth_.reserve(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const Point& p = vertices[v].point;
    // As lift_scene projects a mesh point (scene::project), to the last bit.
    screen_.push_back(scene::project(p, heights_[v], orbit_.view()));
    depth_.push_back(dot({p.x, p.y, heights_[v] * orbit_.z_scale}, basis.toward_camera));
  }
}

const std::vector<Point>& View3d::screen_points() {
  project_vertices();
  return screen_;
}

const std::vector<double>& View3d::depths() {
  project_vertices();
  return depth_;
}

BBox View3d::run_box() {
  BBox box;
  if (!log_) return box;
  project_vertices();
  const std::vector<replay::VertexInfo>& vertices = log_->vertices();
  for (std::size_t v = 0; v < vertices.size(); ++v)
    if (vertices[v].event != kNone) box.add(screen_[v]);
  return box;
}

void View3d::center_pivot() {
  if (!log_) return;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  const std::vector<replay::VertexInfo>& vertices = log_->vertices();
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (vertices[v].event == kNone) continue;
    const double c[3] = {vertices[v].point.x, vertices[v].point.y, heights_[v] * orbit_.z_scale};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  if (!(lo[0] <= hi[0])) return;
  pivot_ = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
}

void View3d::aim(const scene::Camera& camera) {
  const scene::ViewBasis b = scene::view_basis(orbit_.view());
  const Point now = pivot_on_screen();
  const double dx = camera.center().x - now.x, dy = camera.center().y - now.y;
  // Along the screen's right and up (unit vectors, at right angles): the depth stays.
  pivot_ = {pivot_.x + dx * b.right.x + dy * b.up.x, pivot_.y + dx * b.right.y + dy * b.up.y,
            pivot_.z + dx * b.right.z + dy * b.up.z};
}

Point View3d::pivot_on_screen() const {
  const scene::ViewBasis b = scene::view_basis(orbit_.view());
  return {dot(pivot_, b.right), dot(pivot_, b.up)};
}

}  // namespace meshstep::viewer
