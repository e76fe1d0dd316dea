// The mesh: every triangle filled with its colour and its edges stroked, in one draw of
// unindexed triangles (shaders/mesh.vert, mesh.frag).
#pragma once

#include <array>
#include <vector>

#include "gl_objects.hpp"
#include "meshstep/scene/scene.hpp"
#include "shader_program.hpp"
#include "view_uniforms.hpp"

namespace meshstep::render {

// A corner of a mesh triangle as shaders/mesh.vert reads it.
struct MeshVertex {
  std::array<float, 2> position;  // local coordinates
  scene::Rgba color;              // the triangle's
  float height;                   // of this corner over the opposite edge, local units
  float size;                     // sqrt(2 * the triangle's area), local units
};
static_assert(sizeof(MeshVertex) == 20);

class MeshPass {
 public:
  MeshPass();

  // Rebuilds the vertices from the mesh (a triangle with a corner out of range is left
  // out; a missing fill colour is grey).
  void upload(const scene::MeshLayer& mesh, const WorldFrame& frame);
  // Fill off: the inside is transparent, edges on: the edges are stroked. The mesh must be
  // the first thing drawn (over the cleared background): when it covers what it draws
  // opaquely, blending is switched off for it, which llvmpipe pays for at every pixel.
  void draw(const View& view, const scene::MeshLayer& style, bool fill_on, bool edges_on) const;
  std::size_t triangles() const { return triangles_; }

 private:
  ShaderProgram program_;
  ViewUniforms view_uniforms_;
  GLint fill_on_, edge_, edge_half_width_;
  VertexArray vao_;
  ArrayBuffer buffer_;
  std::size_t triangles_ = 0;
  bool opaque_ = true;  // every fill colour opaque: with the fill on, no blending needed
  // Kept between uploads so that a new mesh of a similar size allocates nothing.
  std::vector<std::array<float, 2>> local_points_;
  std::vector<MeshVertex> staging_;
};

}  // namespace meshstep::render
