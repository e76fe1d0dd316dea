// The viewer's 3D view of a terrain run (a replay log with heights, `meshstep terrain
// --record`): whether it is on, the orbit camera's angles and the heights' scale, the point
// the camera turns about, and the moment's planar scene lifted onto the surface
// (scene/lift.hpp). No GL and no ImGui: the viewer and the canvas's worker each keep one.
//
// The canvas's camera (scene::Camera) works in the picture's plane, which in 3D is the
// orbit's screen plane. Turning the orbit moves every point of that plane, so the camera
// alone cannot say what it looked at: the pivot, a point in space, does. It is where the
// camera's centre lies on the surface's middle depth; a pan or a zoom moves it across the
// screen plane (keeping its depth), and a turn brings the camera's centre back onto it. So
// a person who zoomed onto a ridge turns about the ridge, and one who did not keeps the
// whole run fitted (the viewer fits again after a turn then).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "meshstep/geometry/point3.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/scene.hpp"
#include "meshstep/scene/surface_view.hpp"

namespace meshstep::viewer {

// Where the 3D camera looks from (scene::SurfaceView's angles) and how high it draws heights.
struct Orbit {
  static constexpr double kMinZScale = 0.01, kMaxZScale = 1000.0;
  double azimuth_deg = -60.0;   // (-180, 180]
  double elevation_deg = 35.0;  // [-90, 90]
  double z_scale = 1.0;         // [kMinZScale, kMaxZScale]
  friend bool operator==(const Orbit&, const Orbit&) = default;

  scene::SurfaceView view() const;
};

// The orbit within its ranges: the azimuth turned into (-180, 180], the elevation and the
// scale clamped (a NaN becomes the default).
Orbit normalized(Orbit orbit);

// As `meshstep render` has it: about one vertex marker per 30 x 30 pixels of the picture.
inline std::size_t max_vertex_markers_for(int width, int height) {
  return width > 0 && height > 0 ? static_cast<std::size_t>(width) * static_cast<std::size_t>(height) / 900 : 0;
}

class View3d {
 public:
  // The run this view shows; a log without heights (or none) makes the 3D view unavailable.
  explicit View3d(const replay::LogReader* log = nullptr);

  bool available() const { return log_ != nullptr; }
  // The run's heights by vertex id (empty without heights).
  std::span<const double> heights() const { return heights_; }
  bool on() const { return on_; }
  // Switches; false (and the view stays 2D) when the run has no heights.
  bool set_on(bool on);

  const Orbit& orbit() const { return orbit_; }
  // Each returns whether the orbit changed. The pivot keeps its place in space.
  bool set_orbit(const Orbit& orbit);
  bool turn(double d_azimuth_deg, double d_elevation_deg);
  bool scale_heights(double factor);

  // The moment's planar scene (built `serial`-th) lifted as the orbit sees it: lifted again
  // only when the moment or the orbit changes. The caller sets its `visible` layers. Vertex
  // markers stay only while there are at most max_vertex_markers of them: on a foreshortened
  // surface they crowd sooner than in the plane (max_vertex_markers_for says how many).
  scene::Scene& lifted(const scene::Scene& planar, std::size_t serial, std::size_t max_vertex_markers);

  // Every vertex of the run where the orbit puts it on screen (index: vertex id, as the planar
  // scene's mesh.points), and its depth toward the camera (larger: nearer). Moment-free:
  // made again only when the orbit changes.
  const std::vector<Point>& screen_points();
  const std::vector<double>& depths();

  // The box of every vertex the run ever has, on screen: fitted, the camera holds still while
  // the surface grows, as in 2D.
  BBox run_box();

  // The pivot: at the middle of the run's box in space (after a fit) ...
  void center_pivot();
  // ... moved across the screen plane so that it is under the camera's centre (after a pan or
  // a zoom), ...
  void aim(const scene::Camera& camera);
  // ... and where it is on screen now (the camera's centre after a turn).
  Point pivot_on_screen() const;

 private:
  void project_vertices();

  const replay::LogReader* log_ = nullptr;  // null: no heights
  bool on_ = false;
  Orbit orbit_;
  Point3 pivot_{0.0, 0.0, 0.0};  // heights scaled by the orbit's z_scale

  std::vector<double> heights_;  // by vertex
  std::vector<Point> screen_;
  std::vector<double> depth_;
  bool projected_ = false;  // screen_ and depth_ are of orbit_

  scene::Scene lifted_;
  std::size_t lifted_serial_ = SIZE_MAX, lifted_markers_ = 0;
  Orbit lifted_orbit_;
};

}  // namespace meshstep::viewer
