// The mesh: every triangle filled with its colour and its edges stroked, in one draw of
// unindexed triangles (shaders/mesh.vert, mesh.frag).
#pragma once

#include <array>
#include <cstdint>
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
  std::size_t triangles() const { return whole_.triangles; }

  // The level of detail (mesh_raster.hpp): only the listed triangles, into buffers of their
  // own (the whole mesh's stay as they are), drawn with the fill on over the raster's image.
  void upload_subset(const scene::MeshLayer& mesh, const WorldFrame& frame, const std::vector<std::uint32_t>& subset);
  void draw_subset(const View& view, const scene::MeshLayer& style, bool edges_on) const;

 private:
  struct Buffers {
    VertexArray vao;
    ArrayBuffer buffer;
    std::size_t triangles = 0;
    bool opaque = true;  // every fill colour opaque: with the fill on, no blending needed
  };
  void set_up(Buffers& b);
  void fill_staging(const scene::MeshLayer& mesh, std::size_t t, Buffers& b);
  void draw(const Buffers& b, const View& view, const scene::MeshLayer& style, bool fill_on, bool edges_on) const;

  ShaderProgram program_;
  ViewUniforms view_uniforms_;
  GLint fill_on_, edge_, edge_half_width_;
  Buffers whole_, subset_;
  // Kept between uploads so that a new mesh of a similar size allocates nothing.
  std::vector<std::array<float, 2>> local_points_;
  std::vector<MeshVertex> staging_;
};

}  // namespace meshstep::render
