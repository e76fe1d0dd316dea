#include "orbit_options.hpp"

#include <cmath>
#include <cstdlib>
#include <optional>

#include "draw_options.hpp"

namespace meshstep::app {
namespace {

// A whole string as a finite number, or nullopt.
std::optional<double> number_of(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

void add_orbit_options(CLI::App& cmd, OrbitArgs& args, const std::string& what) {
  cmd.add_option("--orbit", args.orbit,
                 what + ": where the camera looks from, AZ,EL in degrees (azimuth from +x toward +y, "
                        "elevation -90..90 above the xy plane; default -60,35; 90 looks straight down)");
  cmd.add_option("--z-scale", args.z_scale, what + ": heights multiplied by K > 0 before drawing (default 1)");
}

scene::SurfaceView surface_view_of(const OrbitArgs& args) {
  scene::SurfaceView view;
  if (!args.orbit.empty()) {
    const std::size_t comma = args.orbit.find(',');
    const std::optional<double> az = comma == std::string::npos ? std::nullopt : number_of(args.orbit.substr(0, comma));
    const std::optional<double> el = comma == std::string::npos ? std::nullopt : number_of(args.orbit.substr(comma + 1));
    if (!az || !el)
      throw UsageError("--orbit " + args.orbit + ": expected two numbers AZ,EL (azimuth and elevation in degrees)");
    if (*el < -90.0 || *el > 90.0)
      throw UsageError("--orbit " + args.orbit + ": the elevation must be from -90 to 90 degrees");
    view.azimuth_deg = *az;
    view.elevation_deg = *el;
  }
  if (!args.z_scale.empty()) {
    const std::optional<double> k = number_of(args.z_scale);
    if (!k || !(*k > 0.0)) throw UsageError("--z-scale " + args.z_scale + ": expected a number > 0");
    view.z_scale = *k;
  }
  return view;
}

}  // namespace meshstep::app
