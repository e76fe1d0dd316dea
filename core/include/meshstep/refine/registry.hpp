// The named refinement algorithms and the parts they are made of, in one table that the
// command line, the viewer and the tests all read (meshstep list prints it).
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "meshstep/refine/refine.hpp"

namespace meshstep {

struct AlgorithmInfo {
  std::string_view name;
  std::string_view description;
  Selection selection;
  double default_min_angle_deg;  // when the command line gives no bound at all (0: none)
  RefineInsertion insertion = RefineInsertion::delaunay;
  double default_max_aspect = 0.0;  // likewise (0: none)
  // Runs in two phases: an aspect-ratio phase, then a min-angle phase (combined criteria).
  bool aspect_then_angle = false;
  // Removes Steiner vertices after refining (improvement + refinement, RefineOptions::improve).
  bool improve = false;
  // The highest angle bound it ended at on every input of the corpus where Triangle 1.6 ends
  // (../shared/data/pslg at 20-34 degrees; docs/refinement.md); above it the command warns
  // and relies on a cap. 0: not meant for an angle bound.
  double known_to_end_deg = 34.0;
};

// The refinement meshstep refine runs without --algorithm (Triangle's own choice).
inline constexpr std::string_view kDefaultAlgorithm = "offcenter";

// 1 / sin(20.7 degrees): a triangle whose aspect ratio (longest edge over shortest altitude,
// which is at least 1 / sin of the smallest angle) is below it has no angle under 20.7.
inline constexpr double kDefaultMaxAspect = 2.83;

// Every registered algorithm, in the order `meshstep list` shows them.
std::span<const AlgorithmInfo> algorithms();
const AlgorithmInfo* find_algorithm(std::string_view name);

// The other parts, by name, with a line of description each.
struct PartInfo {
  std::string_view name;
  std::string_view description;
};
std::span<const PartInfo> selections();
std::span<const PartInfo> insertions();
std::span<const PartInfo> criteria();
std::span<const PartInfo> data_structures();
std::span<const PartInfo> file_formats();

std::optional<Selection> parse_selection(std::string_view name);

// Options that run `algorithm` with its own parts (criteria and triangulation options are
// the caller's).
RefineOptions options_for(const AlgorithmInfo& algorithm);

// The two phases of an aspect_then_angle algorithm from the caller's criteria: the aspect
// phase to criteria.max_aspect (or kDefaultMaxAspect), then the min-angle phase to
// criteria.min_angle_deg (or the algorithm's default); size bounds and caps in both.
std::vector<RefinePhase> aspect_then_angle_phases(const RefineCriteria& criteria, const AlgorithmInfo& algorithm);

}  // namespace meshstep
