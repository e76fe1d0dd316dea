// Reading a recipe file (recipe_file.hpp).
#include "recipe_file.hpp"

#include <fstream>

#include "console.hpp"

namespace meshstep::app {
namespace {

std::string recipe_line_text(const std::string& line) {
  const std::string text = line.substr(0, line.find('#'));
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::optional<Recipe> read_recipe_file(const std::string& path, const std::string& ds, const std::string& insertion) {
  std::ifstream in(path);
  if (!in) {
    print_error(path + ": cannot be read");
    return std::nullopt;
  }
  Recipe recipe;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::string text = recipe_line_text(line);
    if (text.empty()) continue;
    const std::string origin = path + ":" + std::to_string(number) + ": ";
    try {
      Operation op = parse_operation(text);
      if (op.kind != OperationKind::refine)
        throw RunSpecError("a recipe's operations refine the mesh: 'refine ...' expected, not '" + text + "'");
      if (op.flip_dihedral) throw RunSpecError("--flip-dihedral is for a 3D surface: a recipe refines a planar mesh");
      // The command line's --ds and --insertion hold for every operation.
      if (!ds.empty()) set_option(op, "ds", ds);
      if (!insertion.empty()) set_option(op, "insertion", insertion);
      recipe.operations.push_back(std::move(op));
      recipe.origins.push_back(origin);
    } catch (const RunSpecError& e) {
      print_error(origin + e.what());
      return std::nullopt;
    }
  }
  if (in.bad()) {
    print_error(path + ": cannot be read");
    return std::nullopt;
  }
  if (recipe.operations.empty()) {
    print_error(path + ": no operation in the recipe (one 'refine ...' line at least)");
    return std::nullopt;
  }
  return recipe;
}

}  // namespace meshstep::app
