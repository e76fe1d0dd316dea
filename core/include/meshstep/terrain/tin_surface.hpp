// A TIN as a 3D surface, for the surface writers (.obj, .off, .ply, .stl).
#pragma once

#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"

namespace meshstep::terrain {

// The TIN's vertices in metres with their heights, its triangles facing up.
io::Surface to_surface(const HeightGrid& grid, const Tin& tin);

// Closes the surface into a solid: a wall under every border edge down to a flat bottom
// `depth` below the lowest vertex, and the bottom as a fan round its centre. Every face
// faces out, and every edge is shared by exactly two triangles.
void add_solid_base(io::Surface& surface, const HeightGrid& grid, const Tin& tin, double depth);

}  // namespace meshstep::terrain
