// meshstep refine on a 3D surface (.off, .obj, .ply, .stl): Rivara's longest-edge bisection
// with edges measured in 3D (surface/surface_refine.hpp).
#pragma once

#include <string>

namespace meshstep::app {

struct SurfaceRefineArgs {
  std::string input;
  std::string output;     // empty: INPUT's name with .1 before its extension
  std::string algorithm;  // must be lepp-bisection
  double max_edge = 0.0;  // --size, a number
  double max_area = 0.0;
  std::size_t max_triangles = 0;
  std::string ds = "tds";
  std::string stats;
  bool no_output = false;
  bool quiet = false;
  double flip_dihedral = -1.0;  // after the bisection, flips up to this dihedral angle (< 0: none)
  std::string record;           // --record LOG (empty: not recorded)
};

bool is_surface_file(const std::string& path);
int run_refine_surface(const SurfaceRefineArgs& args);

}  // namespace meshstep::app
