// The level of detail of a dense mesh: its small triangles drawn on the CPU, the way the GL
// mesh pass would draw them, into an image that replaces the pass's clear and draw.
//
// llvmpipe pays about 100 ns for every triangle it sets up, bins and shades in 2x2 quads,
// whatever its size: a million triangles of two pixels each cost 100 ms at 1080p, as much as
// the plainest shader (docs/rendering.md). With one sample per pixel, a pixel shows the one
// triangle that holds its centre, so a triangle only has to be found at the few pixel
// centres it holds. This does that for every triangle whose box spans at most kMaxSpan
// pixels, with what llvmpipe does (vertices snapped to 1/256 pixel, integer edge functions
// with a tie rule, so that every pixel centre belongs to one triangle) and with the mesh
// shader's colour (shaders/mesh.vert, mesh.frag: the fill, the edges by their distance in
// pixels, faded by the triangle's size). The larger triangles are listed, for the GL pass.
//
// The picture is therefore not exact, but nearly: a pixel may differ where llvmpipe rounds
// a vertex or a colour differently (a pixel centre within 1/256 pixel of an edge, a colour
// by one unit). The tests bound how many.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "meshstep/scene/scene.hpp"
#include "helper_thread.hpp"
#include "view_uniforms.hpp"
#include "world_frame.hpp"

namespace meshstep::render {

class MeshRaster {
 public:
  // Triangles spanning more pixel columns or rows than this go to the GL pass.
  static constexpr int kMaxSpan = 16;

  // Draws, on the calling thread and one helper, the small triangles of `mesh` (opaque fill colours) into `pixels`, a view.width x
  // view.height picture (rows top to bottom, premultiplied RGBA, already holding the
  // background), with the edges when `edges_on`; the indices of the others (too large, or
  // too far outside the picture to snap) go to `large`. Allocates nothing once the buffers
  // have grown to the mesh.
  void draw(const scene::MeshLayer& mesh, const WorldFrame& frame, const View& view, bool edges_on,
            std::vector<std::uint32_t>& pixels, std::vector<std::uint32_t>& large);

  // Triangles drawn by the last draw (those that hold no pixel centre included).
  std::size_t drawn() const { return drawn_; }

 private:
  struct Snapped {
    std::int32_t x, y;  // 1/256 pixel, pixel centres at multiples of 256
  };
  // What one part of the work needs (the two halves run on two threads).
  struct Job {
    const scene::MeshLayer* mesh;
    const WorldFrame* frame;
    const View* view;
    bool edges_on;
    std::uint32_t* pixels;
  };
  void snap_points(const Job& job, std::size_t begin, std::size_t end);
  // Returns how many triangles it drew; the large ones go to `large`.
  std::size_t draw_triangles(const Job& job, std::size_t begin, std::size_t end, std::vector<std::uint32_t>& large) const;

  std::vector<Snapped> snapped_;      // per point
  std::vector<std::uint8_t> usable_;  // per point: inside the band where snapping is exact
  std::vector<std::uint32_t> helper_large_;
  std::unique_ptr<HelperThread> helper_;  // started at the first big draw
  std::size_t drawn_ = 0;
};

// A premultiplied RGBA colour packed as it lies in memory (R first), as GL reads it.
inline std::uint32_t pack_rgba(std::uint32_t r, std::uint32_t g, std::uint32_t b, std::uint32_t a) {
  return r | g << 8 | b << 16 | a << 24;
}

}  // namespace meshstep::render
