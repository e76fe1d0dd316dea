// --region X0,Y0,X1,Y1 and --region-poly FILE.poly: refinement limited to part of the plane
// (meshstep/refine/region.hpp).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "command.hpp"
#include "console.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/region.hpp"

namespace meshstep::app {

struct RegionArgs {
  std::string box;   // X0,Y0,X1,Y1
  std::string poly;  // a .poly whose segments make one closed simple polygon

  bool given() const { return !box.empty() || !poly.empty(); }
};

inline void add_region_options(CLI::App& cmd, RegionArgs& args) {
  cmd.add_option("--region", args.box,
                 "Refine only where a triangle's centroid lies in the box X0,Y0,X1,Y1 (border\n"
                 "included); elsewhere triangles are held to no bound, and change only where\n"
                 "the algorithm's own rules reach them (docs/recipes.md, Regions)")
      ->type_name("X0,Y0,X1,Y1");
  cmd.add_option("--region-poly", args.poly,
                 "As --region, in the polygon the segments of FILE.poly make (one closed\n"
                 "simple polygon; its holes and regions are not used)")
      ->type_name("FILE.poly");
}

// The region the arguments name, or none: `status` is kExitOk, or the exit status after the
// error is printed (2 for an option's text, 1 for a file that is no region).
inline std::optional<RefineRegion> region_of(const RegionArgs& args, int& status) {
  status = kExitOk;
  if (!args.box.empty() && !args.poly.empty()) {
    print_error("--region and --region-poly both name a region: give one");
    status = kExitUsage;
    return std::nullopt;
  }
  try {
    if (!args.box.empty()) return RefineRegion::parse_box(args.box);
  } catch (const InputError& e) {
    print_error(std::string("--region: ") + e.what());
    status = kExitUsage;
    return std::nullopt;
  }
  if (args.poly.empty()) return std::nullopt;
  try {
    const Pslg pslg = io::read_pslg(args.poly);
    try {
      return RefineRegion::polygon_of(pslg);
    } catch (const InputError& e) {
      throw InputError(args.poly, 0, e.message());
    }
  } catch (const InputError& e) {
    print_error(std::string("--region-poly: ") + e.what());
    status = kExitBadInput;
    return std::nullopt;
  }
}

}  // namespace meshstep::app
