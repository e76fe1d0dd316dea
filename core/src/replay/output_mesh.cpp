// Replay::output_mesh: a moment of a run as the run's own output writes it (the builder's
// to_tri_mesh, delaunay/builder.hpp, is the rule this follows).
#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "meshstep/replay/replay.hpp"
#include "replay/regions.hpp"

namespace meshstep::replay {

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;  // (smaller, larger)

Edge undirected(std::uint32_t a, std::uint32_t b) { return {std::min(a, b), std::max(a, b)}; }

// The marker of every constrained edge after the first `events` events, by its vertices'
// ids in the log: set and cleared by constrain events, and passed on to both pieces when a
// split_edge event splits the edge.
std::map<Edge, int> segment_markers(const LogReader& log, std::uint64_t events) {
  std::map<Edge, int> marker;
  for (std::uint64_t e = 0; e < events; ++e) {
    const Event ev = log.event(e);
    if (ev.type == EventType::constrain) {
      if (ev.code != 0) marker[undirected(ev.ids[0], ev.ids[1])] = static_cast<std::int32_t>(ev.ids[2]);
      else marker.erase(undirected(ev.ids[0], ev.ids[1]));
    } else if (ev.type == EventType::split_edge) {
      const auto it = marker.find(undirected(ev.ids[1], ev.ids[2]));
      if (it == marker.end()) continue;
      const int m = it->second;
      marker.erase(it);
      marker[undirected(ev.ids[1], ev.ids[0])] = m;
      marker[undirected(ev.ids[0], ev.ids[2])] = m;
    }
  }
  return marker;
}

}  // namespace

TriMesh Replay::output_mesh() const {
  std::vector<std::uint32_t> index;
  std::vector<std::uint8_t> bits;
  TriMesh out = build_mesh(&index, &bits);
  const LogHeader& header = log_->header();

  // Segments: the constrained edges with their markers, then the edges of one triangle
  // that carving (or the hull) made boundary, marker 1; sorted as the output sorts them.
  std::map<Edge, int> by_output;
  for (const auto& [edge, m] : segment_markers(*log_, position_))
    if (edge.first < index.size() && edge.second < index.size() && index[edge.first] != kNoIndex &&
        index[edge.second] != kNoIndex)
      by_output[undirected(index[edge.first], index[edge.second])] = m;
  std::vector<std::pair<Edge, bool>> edges;  // every triangle's edges, constrained or not
  edges.reserve(3 * out.triangles.size());
  for (std::size_t t = 0; t < out.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i)
      edges.push_back({undirected(out.triangles[t][i], out.triangles[t][(i + 1) % 3]), (bits[t] >> i & 1) != 0});
  std::sort(edges.begin(), edges.end());
  out.segments.clear();
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    bool constrained = false;
    for (; j < edges.size() && edges[j].first == edges[i].first; ++j) constrained |= edges[j].second;
    const Edge e = edges[i].first;
    if (constrained) {
      const auto it = by_output.find(e);
      out.segments.push_back({e.first, e.second, it == by_output.end() ? 1 : it->second});
    } else if (j - i == 1) {
      out.segments.push_back({e.first, e.second, 1});
    }
    i = j;
  }
  out.has_segment_markers = header.has_segment_markers;
  out.holes = header.holes;
  out.regions = header.regions;

  // The vertices: the input's markers and attributes; Steiner vertices take the marker of
  // the first segment that ends at them, and attributes of 0.
  const std::size_t n = out.points.size();
  const std::uint64_t inputs = log_->run().input_vertices;
  if (!header.vertex_markers.empty()) set_vertex_markers(out, header.vertex_markers, inputs);
  out.attributes_per_vertex = header.attributes_per_vertex;
  out.vertex_attributes = header.vertex_attributes;
  out.vertex_attributes.resize(n * out.attributes_per_vertex, 0.0);

  // The triangles: their region's attribute and area bound.
  if (!header.regions.empty()) {
    const std::vector<std::uint32_t> region =
        detail::region_of_triangles(out.points, out.triangles, bits, header.regions);
    out.attributes_per_triangle = 1;
    out.triangle_attributes.assign(region.size(), 0.0);
    out.triangle_max_area.assign(region.size(), -1.0);
    for (std::size_t t = 0; t < region.size(); ++t)
      if (region[t] != 0) {
        out.triangle_attributes[t] = header.regions[region[t] - 1].attribute;
        out.triangle_max_area[t] = header.regions[region[t] - 1].max_area;
      }
  }
  return out;
}

}  // namespace meshstep::replay
