// The scene builder's parts, shared by its three entry points (build.hpp).
#pragma once

#include <span>
#include <string>

#include "meshstep/pslg/pslg.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/build.hpp"
#include "step_story.hpp"

namespace meshstep::scene::detail {

// A scene with the theme's background, caption colour and the visible layers; no content.
Scene start_scene(const SceneOptions& options);

// The smallest-angle bound ColorBy::quality measures against: the options', else the run's
// (min_angle in the log's parameters, when a log is given), else 30 degrees.
double quality_bound(const SceneOptions& options, const replay::LogReader* log);

// The input's parts over the mesh: segments, vertex markers (input and Steiner told apart;
// none above options.max_vertex_markers), hole and region points.
void add_segments(Scene& scene, std::span<const Point> points, std::span<const Segment> segments);
void add_vertex_markers(Scene& scene, std::span<const Point> input, std::span<const Point> steiner,
                        const SceneOptions& options);
void add_holes(Scene& scene, std::span<const Point> holes);
void add_regions(Scene& scene, std::span<const Region> regions);

// The moment before a run's first triangle: the input's vertices (in input order, named),
// its segments and holes, from the log (build_input_moment.cpp). Returns their box.
BBox add_input_moment(Scene& scene, const replay::LogReader& log, const SceneOptions& options);
// "input: 14 vertices, 12 segments, 1 hole" (what the log's header knows of the input).
std::string input_description(const replay::LogReader& log);

// The outline of the region the refinement at `position` is limited to (--region, or a
// recipe operation's), dashed; nothing for a run over the whole domain
// (build_refine_region.cpp).
void add_refine_region(Scene& scene, const replay::LogReader& log, std::uint64_t position);

// The Voronoi layer of the scene's mesh (build_voronoi.cpp); lightens the mesh's edges.
void add_voronoi(Scene& scene, const SceneOptions& options);

// The current step explained over the mesh (overlay layer, world labels).
void add_overlays(Scene& scene, const StepStory& story, const replay::LogReader& log);

// The one-line caption of a moment of a run.
std::string step_caption(const StepStory& story, const replay::LogReader& log);

// Scene::bounds: the box of the vertices shown, grown by the shapes; see scene.hpp for how
// circles count.
BBox scene_bounds(const Scene& scene, BBox vertices);
BBox points_box(std::span<const Point> points);

}  // namespace meshstep::scene::detail
