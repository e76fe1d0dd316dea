// TINs as 3D surfaces: a whole grid's, with an optional solid base, and a tile's.
#include "meshstep/terrain/tin_surface.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "meshstep/terrain/tiles.hpp"

namespace meshstep::terrain {

io::Surface to_surface(const HeightGrid& grid, const Tin& tin) {
  io::Surface s;
  s.vertices.reserve(tin.samples.size());
  for (std::uint32_t v = 0; v < tin.samples.size(); ++v) {
    const auto p = vertex_position(grid, tin, v);
    s.vertices.push_back({p[0], p[1], p[2]});
  }
  s.triangles = tin.triangles;
  return s;
}

io::Surface tile_surface(const Tile& tile, const Tin& tin) {
  const HeightGrid& g = tile.grid;
  io::Surface s;
  s.vertices.reserve(tin.samples.size());
  for (std::uint32_t v = 0; v < tin.samples.size(); ++v) {
    // The global indices first, then the one product to_surface computes (vertex_position).
    const std::size_t i = tile.i0 + tin.samples[v] % g.nx, j = tile.j0 + tin.samples[v] / g.nx;
    s.vertices.push_back({static_cast<double>(i) * g.dx, static_cast<double>(j) * g.dy, tin.heights[v]});
  }
  s.triangles = tin.triangles;
  return s;
}

namespace {

// Where a border sample lies along the rectangle's boundary, counter-clockwise from the
// corner (0, 0): south side, east, north, west.
double perimeter_position(const HeightGrid& grid, std::uint32_t sample) {
  const double i = static_cast<double>(sample % grid.nx), j = static_cast<double>(sample / grid.nx);
  const double w = static_cast<double>(grid.nx - 1), h = static_cast<double>(grid.ny - 1);
  if (j == 0) return i;
  if (i == w) return w + j;
  if (j == h) return w + h + (w - i);
  return 2 * w + h + (h - j);
}

}  // namespace

void add_solid_base(io::Surface& surface, const HeightGrid& grid, const Tin& tin, double depth) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& p : surface.vertices) lowest = std::min(lowest, p.z);
  const double floor_z = lowest - depth;

  std::vector<std::uint32_t> border;  // vertices on the rectangle, counter-clockwise
  for (std::uint32_t v = 0; v < tin.samples.size(); ++v) {
    const std::size_t i = tin.samples[v] % grid.nx, j = tin.samples[v] / grid.nx;
    if (i == 0 || j == 0 || i == grid.nx - 1 || j == grid.ny - 1) border.push_back(v);
  }
  std::sort(border.begin(), border.end(), [&](std::uint32_t a, std::uint32_t b) {
    return perimeter_position(grid, tin.samples[a]) < perimeter_position(grid, tin.samples[b]);
  });

  const auto bottom_of = [&, first = static_cast<std::uint32_t>(surface.vertices.size())](std::size_t k) {
    return static_cast<std::uint32_t>(first + k);
  };
  for (const std::uint32_t v : border) surface.vertices.push_back({surface.vertices[v].x, surface.vertices[v].y, floor_z});
  const std::uint32_t centre = static_cast<std::uint32_t>(surface.vertices.size());
  surface.vertices.push_back({static_cast<double>(grid.nx - 1) * grid.dx / 2,
                              static_cast<double>(grid.ny - 1) * grid.dy / 2, floor_z});
  for (std::size_t k = 0; k < border.size(); ++k) {
    const std::size_t next = (k + 1) % border.size();
    const std::uint32_t p = border[k], q = border[next];
    // The wall under p -> q faces out, to the right of the counter-clockwise border.
    surface.triangles.push_back({p, bottom_of(k), bottom_of(next)});
    surface.triangles.push_back({p, bottom_of(next), q});
    // The bottom faces down.
    surface.triangles.push_back({centre, bottom_of(next), bottom_of(k)});
  }
}

}  // namespace meshstep::terrain
