// Filling the triangles by a quantity: the value behind each triangle, its colour, and the
// legend that reads the colours back as numbers.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene::detail {

struct FillInput {
  std::span<const Point> points;
  std::span<const std::array<std::uint32_t, 3>> triangles;
  // ColorBy::region: one attribute per triangle (empty: the mesh has none).
  std::span<const double> region;
  // ColorBy::age: per triangle, the step that made it (0-based step index); empty when
  // there is no history.
  std::span<const std::uint64_t> ages;
  std::uint64_t current_step = 0;  // the newest age possible (the cursor's step)
  // ColorBy::height: one height per point (empty: the mesh has none).
  std::span<const double> heights;
  double min_angle_bound = 30.0;   // ColorBy::quality, degrees
};

// Sets out.fill (one colour per triangle) and out.values (the quantity, or nothing for
// ColorBy::none) and returns the legend (none for ColorBy::none). The values are: the
// smallest angle in degrees (angle, quality), the area (area), the attribute (region), the
// step that made the triangle counted from 1 as captions count steps (age), the mean height
// of its corners (height).
std::optional<Legend> fill_triangles(ColorBy by, Theme theme, const FillInput& in, MeshLayer& out);

// The height scale, lo to hi (2D --color-by height and the 3D surfaces alike).
Legend height_legend(double lo, double hi);

// Where a smallest angle sits on the quality scale: [0, 0.5) below the bound, [0.5, 1] from
// the bound up to 60 degrees. Exposed for the legend and the tests.
double quality_position(double angle_deg, double bound_deg);

}  // namespace meshstep::scene::detail
