// --orbit AZ,EL and --z-scale K: the 3D camera of render and export (surfaces, and terrain
// runs' logs), parsed and checked in one place.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "meshstep/scene/surface_view.hpp"

namespace meshstep::app {

struct OrbitArgs {
  std::string orbit;    // "AZ,EL" in degrees; empty: not given
  std::string z_scale;  // empty: not given
  bool given() const { return !orbit.empty() || !z_scale.empty(); }
  // The option named in messages: the first one given.
  std::string name() const { return orbit.empty() ? "--z-scale" : "--orbit"; }
};

// `what` says what the options apply to ("Surfaces and terrain logs").
void add_orbit_options(CLI::App& cmd, OrbitArgs& args, const std::string& what);

// The camera the options ask for (the defaults where not given). Throws UsageError.
scene::SurfaceView surface_view_of(const OrbitArgs& args);

}  // namespace meshstep::app
