// meshstep refine on a 3D surface (.off, .obj, .ply, .stl): Rivara's longest-edge bisection
// with edges measured in 3D (surface/surface_refine.hpp).
#pragma once

#include <string>

#include "meshstep/refine/run_spec.hpp"

namespace meshstep::app {

struct SurfaceRefineArgs {
  std::string input;
  std::string output;     // empty: INPUT's name with .1 before its extension
  // The algorithm (lepp-bisection), --max-area, --max-triangles, --ds and --flip-dihedral
  // (after the bisection, flips up to that dihedral angle) as the command line gave them.
  Operation operation;
  double max_edge = 0.0;  // --size, a number
  std::string stats;
  bool no_output = false;
  bool quiet = false;
  std::string record;  // --record LOG (empty: not recorded)
};

int run_refine_surface(const SurfaceRefineArgs& args);

}  // namespace meshstep::app
