// A terrain's moment in 3D: the planar scene of a replay log with heights (a `meshstep
// terrain --record` run) lifted onto its surface and seen by an orbit camera.
//
// The planar scene says what the step did (the worst triangle and its error, the Lepp path,
// the sample chosen, the flips); lifting keeps all of it. The mesh becomes the shaded,
// height-coloured surface of surface_scene(), back to front; every overlay point and label
// goes to where it lies on the surface and is projected like the vertices. Circles are left
// out: a Delaunay circle is a planar notion, and it is no circle in the picture anyway.
// Overlays are drawn over the surface whatever their depth (an x-ray: the step stays
// visible behind a ridge).
#pragma once

#include <span>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/scene.hpp"
#include "meshstep/scene/surface_view.hpp"

namespace meshstep::scene {

// Where a point of the plane goes on screen, at height z (parallel projection about
// view.pivot, heights scaled by view.z_scale): the projection surface_scene() gives the
// vertices.
Point project(const Point& p, double z, const SurfaceView& view);

// The planar scene lifted. point_heights: the height of each of planar.mesh.points. A point
// of a shape takes the height of the mesh point at its position, else of the plane of the
// triangle that holds it, else of the nearest mesh point (outside the mesh). On a surface
// that is not a height field (two points at one position), a shape's point may take
// either's height.
Scene lift_scene(const Scene& planar, std::span<const double> point_heights, const SurfaceView& view);

// The heights of the points of a log's planar scene (build_scene of a Replay, whose points
// are indexed by the log's vertex ids): each vertex's own (0 for a planar run's).
std::vector<double> mesh_point_heights(const Scene& planar, const replay::LogReader& log);

}  // namespace meshstep::scene
