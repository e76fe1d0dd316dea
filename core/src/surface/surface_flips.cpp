// flip_surface (surface/surface_flips.hpp): the bisection's pipeline (surface_bisection.cpp)
// with no size bound, flips only: the surface loaded into the chosen mesh structure and
// flipped there (surface_flipper.hpp).
#include "meshstep/surface/surface_flips.hpp"

#include <string>

#include "meshstep/error.hpp"
#include "meshstep/surface/surface_refine.hpp"

namespace meshstep::surface {

io::Surface flip_surface(const io::Surface& in, const FlipOptions& options, FlipReport* report) {
  if (!(options.max_dihedral_deg >= 0.0 && options.max_dihedral_deg <= 180.0))
    throw InputError("surface flips: the dihedral bound must be between 0 and 180 degrees, not " +
                     std::to_string(options.max_dihedral_deg));
  BisectionOptions flips_only;
  flips_only.flip_dihedral_deg = options.max_dihedral_deg;
  flips_only.data_structure = options.data_structure;
  flips_only.record = options.record;
  BisectionReport r;
  io::Surface out = bisect_surface(in, flips_only, &r);
  if (report != nullptr) {
    report->flips = r.flips;
    report->largest_dihedral_flipped_deg = r.largest_dihedral_flipped_deg;
    report->smallest_angle_before_deg = r.smallest_angle_before_deg;
    report->smallest_angle_after_deg = r.smallest_angle_after_deg;
    report->area_before = r.area_before;
    report->area_after = r.area_after;
  }
  return out;
}

}  // namespace meshstep::surface
