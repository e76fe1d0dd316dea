// A recipe file (docs/recipes.md): one 'refine ...' operation a line, '#' starts a comment.
// Read by `meshstep run` and `meshstep compare --recipes`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "meshstep/refine/run_spec.hpp"

namespace meshstep::app {

// A recipe's operations, each with the "RECIPE:LINE: " its errors start with.
struct Recipe {
  std::vector<Operation> operations;
  std::vector<std::string> origins;
};

// Reads and checks every line; `ds` and `insertion` (empty: none) hold for every operation.
// Prints the first problem ("RECIPE:LINE: what is wrong") and returns nothing.
std::optional<Recipe> read_recipe_file(const std::string& path, const std::string& ds, const std::string& insertion);

}  // namespace meshstep::app
