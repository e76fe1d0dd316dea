// The floor under the renderer's frame: the same triangles drawn the plainest way OpenGL
// can (unindexed, one flat colour each, no edges, no blending) into a framebuffer of the
// same size, then read back. The renderer's mesh pass cannot be cheaper than this on the
// same machine in the same minute, so bench_render prints both and their ratio.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::bench {

class PlainFrame {
 public:
  // Uploads the mesh once; a GL context must be current for its whole life.
  PlainFrame(const TriMesh& mesh, int width, int height);
  ~PlainFrame();
  PlainFrame(const PlainFrame&) = delete;
  PlainFrame& operator=(const PlainFrame&) = delete;

  // Clears, draws every triangle, reads the pixels back.
  void draw_and_read();

 private:
  struct Gl;
  std::unique_ptr<Gl> gl_;
  int width_, height_;
  std::size_t vertex_count_ = 0;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace meshstep::bench
