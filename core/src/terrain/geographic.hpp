// Cell sizes in degrees: telling them from metres, and their size on the ground
// (the approximation is described in meshstep/terrain/height_grid.hpp).
#pragma once

#include <cstddef>
#include <string>

namespace meshstep::terrain::detail {

// A grid's rectangle in its own units: the outer edges of its cells.
struct GridExtent {
  double west = 0, south = 0, cellsize = 0;
  std::size_t ncols = 0, nrows = 0;
  double east() const { return west + cellsize * static_cast<double>(ncols); }
  double north() const { return south + cellsize * static_cast<double>(nrows); }
  double central_latitude() const { return (south + north()) / 2.0; }
};

// The largest cell size read as degrees without being told: one arc-minute (ETOPO1,
// GEBCO), with room for the rounding of a file that writes it as 0.0166667.
inline constexpr double kLargestGuessedDegreeCell = 1.0 / 60.0 * (1.0 + 1e-5);

// The guess made when the user does not say: cells of at most one arc-minute, and the
// whole grid within longitude -180..180 and latitude -90..90. A metric grid passes only
// with centimetre cells lying within 180 m of its own origin.
bool looks_geographic(const GridExtent& extent);

// Whether every latitude of the grid is a latitude: needed to convert at all.
bool latitudes_valid(const GridExtent& extent);

struct GroundCells {
  double dx = 0, dy = 0;  // metres, east-west and north-south
};

// A cell of `degrees` on a side at `latitude` degrees, on the sphere of kEarthMeanRadius.
GroundCells degree_cells_in_metres(double degrees, double latitude);

// "3 arc-second cells at 36.6 N: 74.4 m x 92.6 m (spherical Earth, R = 6371008.8 m)".
std::string geographic_note(double degrees, double latitude, const GroundCells& cells);

}  // namespace meshstep::terrain::detail
