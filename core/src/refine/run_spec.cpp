// The run description's parser and printer (see run_spec.hpp).
#include "meshstep/refine/run_spec.hpp"

#include <charconv>
#include <cmath>
#include <variant>

#include "meshstep/error.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/io/triangle_io.hpp"

namespace meshstep {
namespace {

[[noreturn]] void refuse(std::string_view name, const std::string& what) {
  throw RunSpecError("--" + std::string(name) + ": " + what);
}

double number_of(const ParameterInfo& p, std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    refuse(p.name, "'" + std::string(text) + "' is not a number");
  return value;
}

std::size_t count_of(const ParameterInfo& p, std::string_view text) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size())
    refuse(p.name, "'" + std::string(text) + "' is not a whole number");
  return value;
}

// What a triangulation takes, in its own words; the rest is refinement's.
struct TriangulationParameter {
  std::string_view name, help;
};
constexpr TriangulationParameter kTriangulationParameters[] = {
    {"ds", "Mesh data structure: tds (triangle-based) or dcel (half-edge)"},
    {"insertion", "Point insertion: flip (Lawson) or cavity (Bowyer-Watson)"},
    {"convex-hull", "Keep every triangle of the convex hull (minus holes), not only those\n"
                    "enclosed by segments"},
};

const TriangulationParameter* triangulation_parameter(std::string_view name) {
  for (const TriangulationParameter& t : kTriangulationParameters)
    if (t.name == name) return &t;
  return nullptr;
}

// The position of `text` among the parameter's words (its enum's value, for an own list).
std::size_t choice_of(OperationKind kind, const ParameterInfo& p, std::string_view text) {
  const std::vector<std::string> words = accepted_words(kind, p);
  for (std::size_t i = 0; i < words.size(); ++i)
    if (words[i] == text) return i;
  std::string list;
  for (const std::string& w : words) list += (list.empty() ? "" : ", ") + w;
  refuse(p.name, "'" + std::string(text) + "' is not one of " + list);
}

// Where each option lives in an Operation: one row per parameter record, read and written
// by its type (a choice's enum takes the position of its word in the record's list).
using Field = std::variant<std::string Operation::*, std::optional<Selection> Operation::*,
                           std::optional<double> Operation::*, std::optional<std::string> Operation::*,
                           std::size_t Operation::*, PointInsertion Operation::*, RefineOrder Operation::*,
                           std::optional<Encroachment> Operation::*, SegmentSplits Operation::*,
                           DataStructure Operation::*, bool Operation::*>;
struct Binding {
  std::string_view name;
  Field field;
};
const Binding kBindings[] = {
    {"algorithm", &Operation::algorithm},         {"select", &Operation::selection},
    {"min-angle", &Operation::min_angle},         {"max-angle", &Operation::max_angle},
    {"max-aspect", &Operation::max_aspect},       {"max-area", &Operation::max_area},
    {"size", &Operation::size},                   {"flip-dihedral", &Operation::flip_dihedral},
    {"max-triangles", &Operation::max_triangles}, {"max-steiner", &Operation::max_steiner},
    {"insertion", &Operation::insertion},         {"order", &Operation::order},
    {"encroachment", &Operation::encroachment},   {"split-segments", &Operation::segment_splits},
    {"ds", &Operation::data_structure},
    {"convex-hull", &Operation::convex_hull},     {"improve", &Operation::improve},
    {"delete-free", &Operation::delete_free},     {"keep-free", &Operation::keep_free},
};

const Field& field_of(std::string_view name) {
  for (const Binding& b : kBindings)
    if (b.name == name) return b.field;
  throw std::logic_error("a parameter the run description does not hold: " + std::string(name));
}

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// Spelled out for clang 14 (the fuzz build), which does not yet deduce an aggregate's
// template arguments from its initialiser.
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// Sets the option's field from its (range-checked) text.
void set_field(Operation& op, const ParameterInfo& p, std::string_view text) {
  std::visit(Overloaded{
                 [&](std::string Operation::*f) {
                   choice_of(op.kind, p, text);
                   op.*f = std::string(text);
                 },
                 [&](std::optional<Selection> Operation::*f) {
                   op.*f = selections()[choice_of(op.kind, p, text)].selection;
                 },
                 [&](std::optional<double> Operation::*f) { op.*f = number_of(p, text); },
                 [&](std::optional<std::string> Operation::*f) { op.*f = std::string(text); },
                 [&](std::size_t Operation::*f) { op.*f = count_of(p, text); },
                 [&](bool Operation::*f) { op.*f = true; },
                 [&]<class E>(std::optional<E> Operation::*f) { op.*f = static_cast<E>(choice_of(op.kind, p, text)); },
                 [&]<class E>(E Operation::*f) { op.*f = static_cast<E>(choice_of(op.kind, p, text)); },
             },
             field_of(p.name));
}

// The text of option `p` in `op`, or nothing when it has its default.
std::optional<std::string> option_text(const Operation& op, const ParameterInfo& p) {
  using Text = std::optional<std::string>;
  return std::visit(
      Overloaded{
          [&](std::string Operation::*f) { return op.*f == p.default_text ? Text() : Text(op.*f); },
          [&](std::optional<Selection> Operation::*f) {
            return op.*f ? Text(std::string(selection_info(*(op.*f)).name)) : Text();
          },
          [&](std::optional<double> Operation::*f) { return op.*f ? Text(io::shortest_text(*(op.*f))) : Text(); },
          [&](std::optional<std::string> Operation::*f) { return op.*f; },
          [&](std::size_t Operation::*f) { return op.*f ? Text(std::to_string(op.*f)) : Text(); },
          [&](bool Operation::*f) { return op.*f ? Text("") : Text(); },
          [&]<class E>(std::optional<E> Operation::*f) {
            return op.*f ? Text(choices(p)[static_cast<std::size_t>(*(op.*f))]) : Text();
          },
          // An enum's first word is its default.
          [&]<class E>(E Operation::*f) {
            const auto i = static_cast<std::size_t>(op.*f);
            return i == 0 ? Text() : Text(choices(p)[i]);
          },
      },
      field_of(p.name));
}

std::vector<std::string> split_words(std::string_view line) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) words.emplace_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

const ParameterInfo* find_by_word(std::string_view word) {
  if (word.starts_with("--")) return find_parameter(word.substr(2));
  if (word.size() == 2 && word[0] == '-')
    for (const ParameterInfo& p : refine_parameters())
      if (!p.short_name.empty() && p.short_name == word.substr(1)) return &p;
  return nullptr;
}

// --region, --region-polygon and --region-poly: not registry parameters (a region is no
// bound of an algorithm), but options of every refine operation all the same.
bool is_region_option(std::string_view name) {
  return name == "region" || name == "region-polygon" || name == "region-poly";
}

void set_region(Operation& op, std::string_view name, std::string_view text) {
  if (op.kind != OperationKind::refine) refuse(name, "does not apply to triangulate");
  if (text.empty()) refuse(name, "needs a value");
  RegionSpec region = op.region.value_or(RegionSpec{});
  try {
    if (name == "region") {
      const RefineRegion box = RefineRegion::parse_box(text);
      region.box = std::pair{box.low(), box.high()};
    } else if (name == "region-polygon") {
      region.polygon = RefineRegion::parse_polygon(text);
    } else {
      region.polygon_file = std::string(text);
    }
  } catch (const InputError& e) {
    refuse(name, e.message());
  }
  if (int(region.box.has_value()) + int(!region.polygon.empty()) + int(!region.polygon_file.empty()) > 1)
    throw RunSpecError("more than one of --region, --region-polygon and --region-poly names a region: give one");
  op.region = region;
}

std::string region_words(const RegionSpec& region) {
  if (region.box) {
    const auto& [low, high] = *region.box;
    return " --region " + io::shortest_text(low.x) + "," + io::shortest_text(low.y) + "," +
           io::shortest_text(high.x) + "," + io::shortest_text(high.y);
  }
  if (!region.polygon.empty()) {
    std::string words = " --region-polygon ";
    for (std::size_t i = 0; i < region.polygon.size(); ++i)
      words += (i ? "," : "") + io::shortest_text(region.polygon[i].x) + "," + io::shortest_text(region.polygon[i].y);
    return words;
  }
  return region.polygon_file.empty() ? "" : " --region-poly " + region.polygon_file;
}

}  // namespace

bool takes(OperationKind kind, const ParameterInfo& parameter) {
  return kind == OperationKind::refine || triangulation_parameter(parameter.name);
}

std::vector<std::string> accepted_words(OperationKind kind, const ParameterInfo& parameter) {
  std::vector<std::string> words = choices(parameter);
  // Bisection is a refinement's way of adding points, not a triangulation's.
  if (kind == OperationKind::triangulate && parameter.name == "insertion") std::erase(words, "bisection");
  return words;
}

std::string_view help_for(OperationKind kind, const ParameterInfo& parameter) {
  const TriangulationParameter* t = triangulation_parameter(parameter.name);
  return kind == OperationKind::triangulate && t ? t->help : parameter.help;
}

void set_option(Operation& op, std::string_view name, std::string_view text) {
  if (is_region_option(name)) return set_region(op, name, text);
  const ParameterInfo* p = find_parameter(name);
  if (!p) throw RunSpecError("unknown option --" + std::string(name));
  if (!takes(op.kind, *p)) refuse(name, "does not apply to triangulate");
  if (p->kind == ParameterKind::flag) {
    if (!text.empty()) refuse(name, "a flag takes no value, not '" + std::string(text) + "'");
  } else if (text.empty()) {
    refuse(name, "needs a value");
  }
  if (const std::string problem = range_problem(*p, text); !problem.empty()) refuse(name, problem);
  set_field(op, *p, text);
}

Operation parse_operation(const std::vector<std::string>& words) {
  if (words.empty()) throw RunSpecError("an empty operation: refine or triangulate expected");
  Operation op;
  if (words[0] == "refine") {
    op.kind = OperationKind::refine;
  } else if (words[0] == "triangulate") {
    op.kind = OperationKind::triangulate;
  } else {
    throw RunSpecError("unknown operation '" + words[0] + "': refine or triangulate expected");
  }
  for (std::size_t i = 1; i < words.size(); ++i) {
    const std::string& word = words[i];
    const std::size_t equals = word.find('=');
    const std::string_view head = std::string_view(word).substr(0, equals);
    if (head.starts_with("--") && is_region_option(head.substr(2))) {
      if (equals != std::string::npos) {
        set_option(op, head.substr(2), std::string_view(word).substr(equals + 1));
      } else {
        if (i + 1 == words.size()) refuse(head.substr(2), "needs a value");
        set_option(op, head.substr(2), words[++i]);
      }
      continue;
    }
    const ParameterInfo* p = find_by_word(head);
    if (!p) throw RunSpecError(word.starts_with("-") ? "unknown option " + std::string(head)
                                                     : "'" + word + "' is not an option (--NAME expected)");
    if (equals != std::string::npos) {
      set_option(op, p->name, std::string_view(word).substr(equals + 1));
    } else if (p->kind == ParameterKind::flag) {
      set_option(op, p->name, "");
    } else {
      if (i + 1 == words.size()) refuse(p->name, "needs a value");
      set_option(op, p->name, words[++i]);
    }
  }
  return op;
}

Operation parse_operation(std::string_view line) { return parse_operation(split_words(line)); }

std::string print_operation(const Operation& op) {
  std::string out = op.kind == OperationKind::refine ? "refine" : "triangulate";
  for (const ParameterInfo& p : refine_parameters()) {
    if (!takes(op.kind, p)) continue;
    const std::optional<std::string> text = option_text(op, p);
    if (!text) continue;
    out += " --" + std::string(p.name);
    if (p.kind != ParameterKind::flag) out += " " + *text;
  }
  if (op.region) out += region_words(*op.region);
  return out;
}

std::optional<double> size_length(const Operation& op) {
  if (!op.size) return std::nullopt;
  double length = 0.0;
  const auto [end, error] = std::from_chars(op.size->data(), op.size->data() + op.size->size(), length);
  if (op.size->empty() || error != std::errc{} || end != op.size->data() + op.size->size()) return std::nullopt;
  return length;
}

bool has_bound(const Operation& op) {
  return op.min_angle || op.max_angle || op.max_aspect || op.max_area || op.size;
}

RefineOptions refine_options(const Operation& op, std::function<double(const Point&)> size_from_grid) {
  const AlgorithmInfo* algorithm = find_algorithm(op.algorithm);
  if (!algorithm) {
    std::string names;
    for (const AlgorithmInfo& a : algorithms()) names += (names.empty() ? "" : ", ") + std::string(a.name);
    throw RunSpecError("unknown algorithm '" + op.algorithm + "'; registered: " + names);
  }
  RefineOptions o = options_for(*algorithm);
  if (op.selection) o.selection = *op.selection;
  o.order = op.order;
  o.encroachment = op.encroachment.value_or(default_encroachment(o.selection));
  o.triangulate.data_structure = op.data_structure;
  o.triangulate.insertion = op.insertion == PointInsertion::cavity ? Insertion::cavity : Insertion::flip;
  if (op.insertion == PointInsertion::bisection) o.insertion = RefineInsertion::bisection;
  o.triangulate.convex_hull = op.convex_hull;
  o.improve = o.improve || op.improve;
  if (op.delete_free && op.keep_free)
    throw RunSpecError("--delete-free and --keep-free contradict each other: give one");
  if (op.delete_free) o.delete_free = FreeVertexDeletion::always;
  if (op.keep_free) o.delete_free = FreeVertexDeletion::never;
  o.segment_splits = op.segment_splits;
  if (o.segment_splits != SegmentSplits::all && o.insertion == RefineInsertion::bisection)
    throw RunSpecError(std::string("--split-segments ") + to_string(o.segment_splits) +
                       ": bisection splits whatever terminal edge it reaches, segments included; it does not go "
                       "with bisection (use a Delaunay algorithm)");
  if ((o.improve || op.delete_free) && o.insertion == RefineInsertion::bisection)
    throw RunSpecError(std::string(o.improve ? "--improve" : "--delete-free") +
                       " removes vertices from a Delaunay mesh: it does not go with bisection");

  RefineCriteria& c = o.criteria;
  c.min_angle_deg = op.min_angle.value_or(0.0);
  c.max_angle_deg = op.max_angle.value_or(180.0);
  c.max_aspect = op.max_aspect.value_or(0.0);
  c.max_area = op.max_area.value_or(0.0);
  c.max_triangles = op.max_triangles;
  c.max_steiner = op.max_steiner;
  if (op.size) {
    if (const std::optional<double> length = size_length(op)) {
      c.size = [length = *length](const Point&) { return length; };
    } else if (size_from_grid) {
      c.size = std::move(size_from_grid);
    } else {
      throw RunSpecError("--size: '" + *op.size + "' is a grid, and no reader was given for it");
    }
  }
  if (!has_bound(op)) {
    c.min_angle_deg = algorithm->default_min_angle_deg;
    c.max_aspect = algorithm->default_max_aspect;
  }
  if (algorithm->aspect_then_angle) o.phases = aspect_then_angle_phases(c, *algorithm);
  return o;
}

std::size_t recorded_phases(const Operation& op) {
  const AlgorithmInfo* algorithm = find_algorithm(op.algorithm);
  if (!algorithm) return 1;
  const std::size_t refinements = algorithm->aspect_then_angle ? 2 : 1;
  const bool improves = op.improve || algorithm->improve;
  return refinements * (improves ? 2 : 1);
}

std::string insertion_name(const RefineOptions& options) {
  return options.insertion == RefineInsertion::bisection ? "bisection" : to_string(options.triangulate.insertion);
}

std::optional<RefineRegion> region_of(const Operation& op) {
  if (!op.region) return std::nullopt;
  if (op.region->box) return RefineRegion::box(op.region->box->first, op.region->box->second);
  if (!op.region->polygon.empty()) {
    try {
      return RefineRegion::polygon(op.region->polygon);
    } catch (const InputError& e) {  // (parse_operation checked it; a description built by hand may not be)
      throw InputError("--region-polygon: " + e.message());
    }
  }
  if (op.region->polygon_file.empty()) return std::nullopt;
  const std::string& file = op.region->polygon_file;
  const Pslg pslg = io::read_pslg(file);
  try {
    return RefineRegion::polygon_of(pslg);
  } catch (const InputError& e) {
    throw InputError(file, 0, e.message());
  }
}

}  // namespace meshstep
