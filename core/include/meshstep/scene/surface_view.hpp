// A triangle surface in 3D as a scene: an orbit camera, Lambert shading, a height colour
// map and a wireframe, drawn by the same renderer and SVG writer as every 2D scene.
//
// The surface is projected onto the camera's view plane (a parallel projection: no
// perspective, so sizes do not depend on the distance and there is no near plane to clip
// against), and its triangles are sorted back to front by the depth of their centroids
// (the painter's algorithm). Both the GL renderer and the SVG writer draw a mesh whose
// MeshLayer::painter_order is set one triangle after the other, each with its edges, so a
// nearer triangle covers what lies behind it, edges included. Known limit of the painter's
// algorithm: triangles that overlap cyclically, or a long thin triangle in front of a small
// one whose centroid is nearer, can be drawn in the wrong order.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "meshstep/geometry/point3.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {

struct SurfaceView {
  // Where the camera looks from, in degrees. Azimuth is measured in the xy plane from +x
  // toward +y, elevation from the xy plane toward +z: the camera sits in the direction
  // (cos e cos a, cos e sin a, sin e) from the surface. Elevation 90 looks straight down;
  // with azimuth -90 that is the plain 2D picture (x to the right, y up).
  double azimuth_deg = -60.0;
  double elevation_deg = 35.0;
  // Heights are multiplied by this before projecting (> 0): flat terrain made readable.
  double z_scale = 1.0;
  // The direction toward the light, in world coordinates (need not be unit length).
  // nullopt: from the camera's upper left.
  std::optional<Point3> light;
  // Strength of the light that reaches every face, lit or not (0..1): nothing goes black.
  double ambient = 0.35;
  // The point the camera turns about: it projects to the screen's origin, whatever the
  // view. An animation that turns the camera about the middle of its surface keeps the
  // surface in the middle of every frame.
  Point3 pivot{0.0, 0.0, 0.0};
};

// The unit vectors of the view: toward the camera, and the screen's right and up.
struct ViewBasis {
  Point3 toward_camera, right, up;
};
ViewBasis view_basis(const SurfaceView& view);

// The scene of `surface` seen by `view`. mesh.points are the projections of the vertices
// (index for index, x along the screen's right, y up, in the surface's units with heights
// scaled); mesh.triangles are the surface's, back to front (ties in the surface's order),
// each turned counterclockwise on screen; fill is the height map (viridis over the range
// of the vertices' heights) at the triangle's mean height, darkened by its shade; values are
// the mean heights (unscaled). `name` starts the caption.
Scene surface_scene(const io::Surface& surface, const SurfaceView& view, Theme theme, std::string_view name = {});

}  // namespace meshstep::scene
