// The moment of a run before its first triangle: the input, as the lecturer shows it before
// anything is built. Its vertices in input order (each named by its number in the input
// file), its segments and hole points from the log's header (LogHeader::segments, ::holes);
// region points are drawn by the caller as at every moment. A log written before the header
// kept the segments shows the vertices and holes only.
#include <algorithm>
#include <utility>

#include "parts.hpp"
#include "style.hpp"

namespace meshstep::scene::detail {

namespace {

// Above this many input vertices their names would cover the picture: markers only.
constexpr std::size_t kMaxVertexNames = 200;

}  // namespace

BBox add_input_moment(Scene& scene, const replay::LogReader& log, const SceneOptions& options) {
  const std::vector<replay::VertexInfo>& vertices = log.vertices();
  const std::uint64_t input_count = log.run().input_vertices;
  // The input's vertices by their input index (the log introduces them in its own order).
  std::vector<std::pair<std::uint32_t, VertexId>> by_input;
  for (VertexId v = 0; v < vertices.size(); ++v)
    if (vertices[v].event != kNone && vertices[v].input_index < input_count) by_input.push_back({vertices[v].input_index, v});
  std::sort(by_input.begin(), by_input.end());

  std::vector<Point> points;  // in input order
  points.reserve(by_input.size());
  for (const auto& [index, v] : by_input) points.push_back(vertices[v].point);
  // The segments name input indices; an index the log never introduced is left out.
  std::vector<Point> at_index(input_count);
  std::vector<bool> known(input_count, false);
  for (const auto& [index, v] : by_input) at_index[index] = vertices[v].point, known[index] = true;
  std::vector<Segment> segments;
  for (const Segment& s : log.header().segments)
    if (s.a < input_count && s.b < input_count && known[s.a] && known[s.b]) segments.push_back(s);

  add_segments(scene, at_index, segments);
  add_vertex_markers(scene, points, {}, options);
  add_holes(scene, log.header().holes);
  if (by_input.size() <= kMaxVertexNames) {
    const Rgba color = base_style(scene.theme).text;
    for (const auto& [index, v] : by_input)
      scene.labels.push_back({vertices[v].point, log.vertex_name(v), color, px::label, 7.0f, -7.0f, 0});
  }
  BBox box = points_box(points);
  for (const Point& h : log.header().holes) box.add(h);
  return box;
}

std::string input_description(const replay::LogReader& log) {
  const auto count = [](std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  const replay::LogHeader& h = log.header();
  std::string out = "input: " + count(log.run().input_vertices, "vertex", "vertices");
  if (!h.segments.empty()) out += ", " + count(h.segments.size(), "segment", "segments");
  if (!h.holes.empty()) out += ", " + count(h.holes.size(), "hole", "holes");
  if (!h.regions.empty()) out += ", " + count(h.regions.size(), "region", "regions");
  return out;
}

}  // namespace meshstep::scene::detail
