#include "edit_script.hpp"

#include <cstdlib>

#include "meshstep/error.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "workbench_host.hpp"

namespace meshstep::viewer {

namespace {

bool is_real(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

double real(const std::string& s) { return std::strtod(s.c_str(), nullptr); }

struct EditVerb {
  const char* name;
  std::size_t min_numbers, max_numbers;
  const char* usage;
};

constexpr EditVerb kEditVerbs[] = {
    {"add-vertex", 2, 2, "edit add-vertex X Y"},
    {"add-segment", 4, 4, "edit add-segment X0 Y0 X1 Y1"},
    {"move", 4, 4, "edit move X Y X2 Y2"},
    {"delete", 2, 2, "edit delete X Y"},
    {"hole", 2, 2, "edit hole X Y"},
    {"region", 3, 4, "edit region X Y ATTRIBUTE [MAX_AREA]"},
};

const EditVerb* find_verb(const std::string& name) {
  for (const EditVerb& v : kEditVerbs)
    if (name == v.name) return &v;
  return nullptr;
}

// The operation of `refine-region X0 Y0 X1 Y1 OPTIONS...`; throws RunSpecError.
Operation region_operation(const ScriptAction& a) {
  std::vector<std::string> words{"refine"};
  words.insert(words.end(), a.args.begin() + 4, a.args.end());
  words.push_back("--region");
  words.push_back(a.args[0] + "," + a.args[1] + "," + a.args[2] + "," + a.args[3]);
  return parse_operation(words);
}

// `refine-lasso X0 Y0 X1 Y1 X2 Y2 ... [-- OPTIONS...]`: where the numbers end (the "--" or
// the end of the line).
std::size_t lasso_numbers(const ScriptAction& a) {
  std::size_t n = 0;
  while (n < a.args.size() && a.args[n] != "--") ++n;
  return n;
}

// Its operation: the options, limited to the polygon through the points in order (written
// out as --region-polygon, which checks that it is simple). Throws RunSpecError.
Operation lasso_operation(const ScriptAction& a) {
  const std::size_t n = lasso_numbers(a);
  std::vector<std::string> words{"refine"};
  if (n < a.args.size()) words.insert(words.end(), a.args.begin() + static_cast<std::ptrdiff_t>(n) + 1, a.args.end());
  std::string ring;
  for (std::size_t i = 0; i < n; ++i) ring += (i ? "," : "") + a.args[i];
  words.push_back("--region-polygon");
  words.push_back(ring);
  return parse_operation(words);
}

// `recipe edit N WORDS...`: the operation the words make. Throws RunSpecError.
Operation edited_operation(const ScriptAction& a) {
  return parse_operation(std::vector<std::string>(a.args.begin() + 2, a.args.end()));
}

}  // namespace

bool is_edit_action(const std::string& verb) {
  return verb == "new" || verb == "edit" || verb == "undo" || verb == "redo" || verb == "save" ||
         verb == "refine-region" || verb == "refine-lasso" || verb == "recipe" || verb == "save-recipe";
}

std::string check_edit_action(const ScriptAction& a) {
  const auto n = a.args.size();
  if (a.verb == "new" || a.verb == "undo" || a.verb == "redo") return n == 0 ? "" : "expected: " + a.verb;
  if (a.verb == "save") {
    if (n == 1 && a.args[0].size() > 5 && a.args[0].ends_with(".poly")) return "";
    return "expected: save FILE.poly";
  }
  if (a.verb == "save-recipe") return n == 1 ? "" : "expected: save-recipe FILE";
  if (a.verb == "recipe") {
    const char* usage =
        "expected: recipe remove|off|on|up|down N, or recipe edit N refine OPTIONS... (an operation's number, from 1)";
    const bool edit = n >= 3 && a.args[0] == "edit";
    const bool known = edit || (n == 2 && (a.args[0] == "remove" || a.args[0] == "off" || a.args[0] == "on" ||
                                           a.args[0] == "up" || a.args[0] == "down"));
    if (!known || std::strtol(a.args[1].c_str(), nullptr, 10) < 1 || !is_real(a.args[1])) return usage;
    if (edit) {
      try {
        edited_operation(a);
      } catch (const RunSpecError& e) {
        return std::string("recipe edit: ") + e.what();
      }
    }
    return "";
  }
  if (a.verb == "refine-region") {
    if (n < 4) return "expected: refine-region X0 Y0 X1 Y1 OPTIONS...";
    for (std::size_t i = 0; i < 4; ++i)
      if (!is_real(a.args[i])) return "'" + a.args[i] + "' is not a number; expected: refine-region X0 Y0 X1 Y1 OPTIONS...";
    try {
      region_operation(a);
    } catch (const RunSpecError& e) {
      return std::string("refine-region: ") + e.what();
    }
    return "";
  }
  if (a.verb == "refine-lasso") {
    const char* usage = "expected: refine-lasso X0 Y0 X1 Y1 X2 Y2 ... [-- OPTIONS...] (3 points at least)";
    const std::size_t numbers = lasso_numbers(a);
    for (std::size_t i = 0; i < numbers; ++i)
      if (!is_real(a.args[i])) return "'" + a.args[i] + "' is not a number; " + usage;
    if (numbers < 6 || numbers % 2 != 0) return usage;
    try {
      lasso_operation(a);
    } catch (const RunSpecError& e) {
      return std::string("refine-lasso: ") + e.what();
    }
    return "";
  }
  std::string verbs;
  for (const EditVerb& v : kEditVerbs) verbs.append(verbs.empty() ? "" : ", ").append(v.name);
  if (n == 0) return "expected: edit WHAT ... (" + verbs + ")";
  const EditVerb* verb = find_verb(a.args[0]);
  if (!verb) return "unknown edit '" + a.args[0] + "' (" + verbs + ")";
  if (n - 1 < verb->min_numbers || n - 1 > verb->max_numbers) return std::string("expected: ") + verb->usage;
  for (std::size_t i = 1; i < n; ++i)
    if (!is_real(a.args[i])) return std::string("'") + a.args[i] + "' is not a number; expected: " + verb->usage;
  return "";
}

void run_edit_action(const ScriptAction& a, WorkbenchHost& host, const Session* session, const std::string& script) {
  const auto fail = [&](const std::string& why) {
    throw InputError(script, static_cast<std::size_t>(a.line), why);
  };
  if (a.verb == "new") {
    host.start_new();
    return;
  }
  if (!host.bench()) {
    if (!session) fail("no input to " + a.verb + " (new, or open one first)");
    if (const std::string why = host.start_from(*session); !why.empty()) fail(why);
  }
  Workbench& bench = *host.bench();
  PslgEditor& e = bench.editor();
  if (a.verb == "undo" || a.verb == "redo") {
    // Nothing to undo is not an error a script should stop for: a person's Ctrl+Z does nothing.
    if (a.verb == "undo") host.undo();
    else host.redo();
    return;
  }
  if (a.verb == "save") {
    bench.save(a.args[0]);
    return;
  }
  if (a.verb == "save-recipe") {
    bench.save_recipe(a.args[0]);
    return;
  }
  if (a.verb == "refine-region") {
    bench.append_operation(region_operation(a));
    return;
  }
  if (a.verb == "refine-lasso") {
    bench.append_operation(lasso_operation(a));
    return;
  }
  if (a.verb == "recipe") {
    const std::size_t i = static_cast<std::size_t>(std::strtol(a.args[1].c_str(), nullptr, 10) - 1);
    if (i >= bench.recipe().size())
      fail("recipe " + a.args[0] + ": there is no operation " + a.args[1] + " (the recipe has " +
           std::to_string(bench.recipe().size()) + ")");
    if (a.args[0] == "remove") bench.remove_operation(i);
    else if (a.args[0] == "edit") bench.replace_operation(i, edited_operation(a));
    else if (a.args[0] == "off" || a.args[0] == "on") bench.switch_operation(i, a.args[0] == "on");
    else bench.move_operation(i, a.args[0] == "up" ? -1 : +1);
    return;
  }
  const std::string& what = a.args[0];
  std::vector<double> x;
  for (std::size_t i = 1; i < a.args.size(); ++i) x.push_back(real(a.args[i]));
  const double tolerance = 1e-9 * e.extent();
  try {
    if (what == "add-vertex") e.add_vertex({x[0], x[1]});
    else if (what == "add-segment") e.add_segment(Point{x[0], x[1]}, Point{x[2], x[3]}, tolerance);
    else if (what == "hole") e.add_hole({x[0], x[1]});
    else if (what == "region") e.add_region({{x[0], x[1]}, x[2], x.size() > 3 ? x[3] : -1.0});
    else {
      const ElementRef at = e.element_near({x[0], x[1]}, tolerance);
      if (at.kind == InputElement::none) fail("edit " + what + ": nothing at " + a.args[1] + " " + a.args[2]);
      if (what == "move") e.move(at, {x[2], x[3]});
      else e.erase(at);
    }
  } catch (const EditRefused& r) {
    fail(r.what());
  }
}

}  // namespace meshstep::viewer
