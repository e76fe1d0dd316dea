// Builds the scene of a mesh, of a PSLG, or of one moment of a recorded run.
//
// The moment of a run is a replay cursor's position: the mesh is the cursor's mesh, exactly,
// and the overlays explain the step that the last applied event belongs to, with every
// event of that step up to the cursor (so an export one frame per event builds the
// explanation up as the step goes): the located triangle, the bad triangle, the point
// selected and the alternatives (with the circumcircle), the Lepp path, a cavity, flips
// with the circle of their in-circle test, an encroached subsegment with its diametral
// circle or lens, a bisection, a removed vertex and its star, a failed criterion test.
// The faces the step made are highlighted; the caption says what happened.
#pragma once

#include <cstdint>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene {

struct SceneOptions {
  ColorBy color_by = ColorBy::none;
  Theme theme = Theme::light;
  // Layer::voronoi is built only when it is in the set (its shapes cost a sort of the edges).
  LayerSet layers = LayerSet::standard();
  // The smallest-angle bound that ColorBy::quality measures against, in degrees. 0: the
  // run's own (min_angle in the log's parameters), else 30.
  double min_angle_bound = 0.0;
  // Vertex markers are left out above this many vertices (they would cover the mesh).
  std::size_t max_vertex_markers = 20000;
  // Scene::text_scale: the caption, legend and labels this many times their size.
  float text_scale = 1.0f;
};

// The age of every face slot: the step that last wrote a live face into it. Kept up to
// date as a cursor moves (forward cheaply; backward by recounting from the start).
class FaceAges {
 public:
  void update(const replay::Replay& cursor);
  // Step index of the face in slot s at the last update (0 for slots never written).
  std::uint64_t age(std::size_t slot) const { return slot < age_.size() ? age_[slot] : 0; }
  // Was the last update to this cursor's log and position?
  bool current(const replay::Replay& cursor) const {
    return log_ == &cursor.log() && position_ == cursor.position();
  }

 private:
  std::vector<std::uint64_t> age_;
  std::uint64_t position_ = 0;
  const replay::LogReader* log_ = nullptr;
};

// A mesh alone (a mesh PREFIX, or a triangulated input): no event, no caption but its size.
// ColorBy::age colours every triangle alike (a mesh file has no history).
Scene build_scene(const TriMesh& mesh, const SceneOptions& options);

// An input before triangulation: its vertices, segments and holes.
Scene build_scene(const Pslg& input, const SceneOptions& options);

// The moment of a run at the cursor. `ages` (updated to the cursor) is needed for
// ColorBy::age; without it age colours are those of a mesh alone. Throws std::logic_error
// for ages not updated to the cursor.
//
// mesh.triangles lists the live faces that are not ghost faces in slot order, as
// Replay::mesh() does (Scene::highlighted indexes both); mesh.points is indexed by the log's
// vertex ids (the numbering of the caption and of `meshstep log dump`), every vertex of the
// run, those not in the mesh at this moment referenced by no triangle. With ColorBy::age the
// values are the step that made each triangle counted from 1, as the caption counts steps.
Scene build_scene(const replay::Replay& cursor, const SceneOptions& options, const FaceAges* ages = nullptr);

}  // namespace meshstep::scene
