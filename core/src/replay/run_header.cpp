// The log header's run description, read in one place (run_header.hpp).
#include "meshstep/replay/run_header.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "meshstep/error.hpp"
#include "meshstep/io/shortest_text.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"

namespace meshstep::replay {
namespace {

template <class T>
std::optional<T> number(const std::string& text) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) return std::nullopt;
  return value;
}

// "30", "0.125", "1e-06": short and exact enough for the header's bounds (as they always were).
std::string bound_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  return buffer;
}

}  // namespace

std::string triangulate_parameters(bool convex_hull, std::uint64_t input_vertices, int first_index) {
  return "convex_hull=" + std::to_string(convex_hull) + " input_vertices=" + std::to_string(input_vertices) +
         " first_index=" + std::to_string(first_index);
}

std::string refine_parameters(const RefineOptions& o, const std::string& size_text, std::uint64_t input_vertices,
                              int first_index) {
  const RefineCriteria& c = o.criteria;
  double size = 0.0;
  const bool numeric_size = number<double>(size_text).has_value();
  if (numeric_size) size = *number<double>(size_text);
  return "selection=" + std::string(to_string(o.selection)) + " min_angle=" + bound_text(c.min_angle_deg) +
         " max_angle=" + bound_text(c.max_angle_deg) + " max_aspect=" + bound_text(c.max_aspect) +
         " max_area=" + bound_text(c.max_area) +
         " size=" + (numeric_size && size > 0.0 ? bound_text(size) : size_text.empty() ? "0" : size_text) +
         " max_triangles=" + std::to_string(c.max_triangles) + " max_steiner=" + std::to_string(c.max_steiner) +
         " order=" + to_string(o.order) +
         " insertion=" + (o.insertion == RefineInsertion::bisection ? "bisection" : to_string(o.triangulate.insertion)) +
         " encroachment=" + (o.encroachment == Encroachment::lens ? "lens" : "circle") +
         " lens_angle=" + bound_text(lens_angle_deg(c)) + " input_vertices=" + std::to_string(input_vertices) +
         " first_index=" + std::to_string(first_index) + " convex_hull=" + std::to_string(o.triangulate.convex_hull) +
         // Only when segments are kept: the headers of every other run stay as they were.
         (o.segment_splits == SegmentSplits::all ? "" : std::string(" split_segments=") + to_string(o.segment_splits));
}

std::string surface_parameters(double max_edge, double max_area, std::uint64_t input_vertices,
                               std::size_t max_triangles, double flip_dihedral) {
  return "surface=1 insertion=bisection size=" + io::shortest_text(max_edge) + " max_area=" +
         io::shortest_text(max_area) + " input_vertices=" + std::to_string(input_vertices) +
         " max_triangles=" + std::to_string(max_triangles) + " flip_dihedral=" + io::shortest_text(flip_dihedral);
}

std::string terrain_parameters(const terrain::TerrainOptions& o, const terrain::HeightGrid& grid) {
  // input_vertices=4: a terrain run starts from the grid's four corners.
  return "max_error=" + io::shortest_text(o.max_error) + " input_vertices=4 grid_columns=" + std::to_string(grid.nx) +
         " grid_rows=" + std::to_string(grid.ny) + " dx=" + io::shortest_text(grid.dx) +
         " dy=" + io::shortest_text(grid.dy) +
         " terminal=" + (o.terminal_point == terrain::TerminalPoint::midpoint ? "midpoint" : "centroid") +
         " improve=" + (o.improve ? "1" : "0") + " flips_3d=" + (o.flips_3d ? "1" : "0") +
         " max_triangles=" + std::to_string(o.max_triangles);
}

std::string describe_run(const LogHeader& h, const RunHeader& run) {
  const auto short_number = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return std::string(buffer);
  };
  std::string text = h.algorithm.empty() ? std::string("run") : h.algorithm;
  const auto add = [&text](const std::string& words) { text += ", " + words; };
  if (run.min_angle && *run.min_angle > 0.0) add("min angle " + short_number(*run.min_angle));
  if (run.max_angle && *run.max_angle < 180.0) add("max angle " + short_number(*run.max_angle));
  if (run.max_aspect && *run.max_aspect > 0.0) add("max aspect " + short_number(*run.max_aspect));
  if (run.max_area && *run.max_area > 0.0) add("max area " + short_number(*run.max_area));
  if (run.size && *run.size > 0.0) add("size " + short_number(*run.size));
  // The mode changes the mesh as much as a bound does (the boundary kept whole, triangles
  // left over the bound beside it): named as the option names it.
  if (run.segment_splits != SegmentSplits::all) add(std::string("split segments ") + to_string(run.segment_splits));
  if (!h.data_structure.empty() && h.data_structure != "tds") add(h.data_structure);
  const std::string insertion = run.insertion.empty() ? h.insertion : run.insertion;
  if (!insertion.empty() && insertion != "flip") add(insertion);
  return text;
}

std::string header_parameter(const LogHeader& header, const std::string& key, const std::string& fallback) {
  std::istringstream words(header.parameters);
  std::string word;
  while (words >> word)
    if (word.size() > key.size() && word.compare(0, key.size(), key) == 0 && word[key.size()] == '=')
      return word.substr(key.size() + 1);
  return fallback;
}

std::vector<Operation> recorded_recipe(const LogHeader& header, const RunHeader& run) {
  if (!run.operations.empty()) return run.operations;
  if (header.algorithm == "triangulate") return {};
  const auto text = [&](const char* key) { return header_parameter(header, key); };
  Operation op;
  op.algorithm = header.algorithm;
  op.selection = run.selection;
  op.encroachment = run.encroachment;
  op.min_angle = run.min_angle;
  op.max_angle = run.max_angle;
  op.max_aspect = run.max_aspect;
  op.max_area = run.max_area;
  if (run.size) op.size = io::shortest_text(*run.size);
  else if (const std::string s = text("size"); !s.empty() && s != "0") op.size = s;  // a grid's name
  op.max_triangles = number<std::size_t>(text("max_triangles")).value_or(0);
  op.max_steiner = number<std::size_t>(text("max_steiner")).value_or(0);
  for (const RefineOrder order : {RefineOrder::smallest_first, RefineOrder::worst_first, RefineOrder::fifo})
    if (text("order") == to_string(order)) op.order = order;
  if (run.insertion == "bisection") op.insertion = PointInsertion::bisection;
  else if (run.insertion == "cavity") op.insertion = PointInsertion::cavity;
  op.segment_splits = run.segment_splits;
  if (header.data_structure == to_string(DataStructure::dcel)) op.data_structure = DataStructure::dcel;
  op.convex_hull = text("convex_hull") == "1";
  if (run.region && run.region->kind() == RefineRegion::Kind::box)
    op.region = RegionSpec{std::pair{run.region->low(), run.region->high()}, {}, {}};
  else if (run.region)
    op.region = RegionSpec{std::nullopt, {}, run.region->vertices()};  // a polygon, written out
  return {op};
}

RunHeader read_run_header(const LogHeader& header, const std::string& path) {
  RunHeader run;
  const auto text = [&](const char* key) { return header_parameter(header, key); };
  // A count the reader sizes things by: refused when it is no number, not read as 0.
  const auto count = [&]<class T>(const char* key, T& out) {
    const std::string t = text(key);
    if (t.empty()) return;
    const std::optional<T> v = number<T>(t);
    if (!v) throw InputError(path, 0, "the header's parameter " + std::string(key) + "=" + t + " is not a number");
    out = *v;
  };
  count("input_vertices", run.input_vertices);
  count("first_index", run.first_index);
  if (const std::string s = text("selection"); !s.empty()) run.selection = parse_selection(s);
  run.insertion = header_parameter(header, "insertion", header.insertion);
  if (const std::string e = text("encroachment"); e == "lens" || e == "circle")
    run.encroachment = e == "lens" ? Encroachment::lens : Encroachment::circle;
  // The header writes 0 for a bound not set.
  const auto bound = [&](const char* key) -> std::optional<double> {
    const std::optional<double> v = number<double>(text(key));
    return v && *v > 0.0 ? v : std::nullopt;
  };
  run.lens_angle = bound("lens_angle");
  run.min_angle = bound("min_angle");
  run.max_angle = bound("max_angle");
  run.max_aspect = bound("max_aspect");
  run.max_area = bound("max_area");
  run.size = bound("size");
  run.max_error = bound("max_error");
  for (const SegmentSplits mode : {SegmentSplits::interior, SegmentSplits::none})
    if (text("split_segments") == to_string(mode)) run.segment_splits = mode;
  if (const std::string r = text("region"); !r.empty()) {
    try {
      run.region = RefineRegion::parse_text(r);
    } catch (const InputError& e) {
      throw InputError(path, 0, "the header's parameter region=" + r + ": " + e.message());
    }
  }
  // A recipe's operations, one a line, each read by the recipe's own parser.
  std::istringstream lines(header.operations);
  std::size_t number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    try {
      run.operations.push_back(parse_operation(line));
    } catch (const std::invalid_argument& e) {
      throw InputError(path, 0, "the header's operation " + std::to_string(number) + " (" + line + "): " + e.what());
    }
  }
  return run;
}

}  // namespace meshstep::replay
