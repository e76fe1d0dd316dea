// Degrees to metres on a spherical Earth (geographic.hpp).
#include "terrain/geographic.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "meshstep/terrain/height_grid.hpp"

namespace meshstep::terrain::detail {

bool looks_geographic(const GridExtent& extent) {
  return extent.cellsize <= kLargestGuessedDegreeCell && extent.west >= -180.0 && extent.east() <= 180.0 &&
         latitudes_valid(extent);
}

bool latitudes_valid(const GridExtent& extent) { return extent.south >= -90.0 && extent.north() <= 90.0; }

GroundCells degree_cells_in_metres(double degrees, double latitude) {
  constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
  const double along_meridian = kEarthMeanRadius * degrees * kRadiansPerDegree;
  return {along_meridian * std::cos(latitude * kRadiansPerDegree), along_meridian};
}

std::string geographic_note(double degrees, double latitude, const GroundCells& cells) {
  char text[160];
  std::snprintf(text, sizeof text, "%.4g arc-second cells at %.1f %s: %.1f m x %.1f m (spherical Earth, R = %.1f m)",
                degrees * 3600.0, std::fabs(latitude), latitude < 0.0 ? "S" : "N", cells.dx, cells.dy,
                kEarthMeanRadius);
  return text;
}

}  // namespace meshstep::terrain::detail
