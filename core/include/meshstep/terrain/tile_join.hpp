// Joining the tiles of a tiled terrain run (terrain/tiles.hpp) into one surface, and the
// check that they met without cracks.
//
// Tiles that share a border have the same vertices along it, to the bit (tile_surface), so
// welding is exact: vertices with equal coordinates become one, nothing is snapped. The
// tiles of a whole run cover the grid's rectangle, so the joined surface is a disc: every
// edge inside it is used by two triangles, once each way, and the edges used once (its
// boundary) make one loop round the rectangle. A crack is an edge used once that is not
// on the rectangle: two tiles that disagree about the vertices of their shared side.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/io/surface_io.hpp"

namespace meshstep::terrain {

// Appends surfaces into one, merging each vertex with an earlier one at exactly the same
// coordinates (-0.0 and 0.0 are the same). Memory: the joined surface and 8 bytes a
// vertex of index.
class SurfaceWelder {
 public:
  void add(const io::Surface& s);
  const io::Surface& surface() const { return joined_; }
  io::Surface take() { return std::move(joined_); }
  std::size_t welded() const { return welded_; }  // vertices merged into earlier ones

 private:
  std::uint32_t find_or_add(const io::Point3& p);
  void grow();

  io::Surface joined_;
  std::vector<std::uint32_t> slots_;  // open addressing: vertex index + 1, 0 empty
  std::size_t welded_ = 0;
};

struct TileJoinCheck {
  io::SurfaceReport surface;        // report_surface of the joined surface
  std::size_t cracks = 0;           // edges used once, not on the bounding rectangle
  std::vector<std::array<io::Point3, 2>> first_cracks;  // the first few, for the message
  double area = 0.0;                // of the triangles in the xy plane
  double rectangle_area = 0.0;      // of the vertices' bounding rectangle
  // One boundary loop, no crack, nothing that is not a clean 2-manifold, and the triangles
  // covering the rectangle once (their area is its area, to 1e-9 of it).
  bool ok() const;
};

TileJoinCheck check_joined_tiles(const io::Surface& joined);

// "1 boundary loop, no crack, area 1.2e6 m2 = the rectangle's", or what is wrong.
std::string describe(const TileJoinCheck& check);

}  // namespace meshstep::terrain
