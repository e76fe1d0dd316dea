// The named refinement algorithms and the parts they are made of, in one table that the
// command line, the viewer and the tests all read (meshstep list prints it).
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "meshstep/refine/refine.hpp"

namespace meshstep {

struct AlgorithmInfo {
  std::string_view name;
  std::string_view description;
  Selection selection;
  double default_min_angle_deg;  // when the command line gives no bound at all
};

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

}  // namespace meshstep
