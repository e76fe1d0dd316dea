// The mesh in SVG: its fill (one path per colour) and its edges (each edge once).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "meshstep/scene/colormap.hpp"
#include "scene/svg_parts.hpp"

namespace meshstep::scene::detail {

namespace {

// Neighbouring triangles of different colours are separate paths, and a renderer smooths
// each path's border on its own, so the background would show through along every border
// between colours as a faint line (measured with rsvg: 17% background). Stroking each
// opaque fill path with its own colour, this wide, covers that seam; round joins keep the
// stroke from poking out at the sharp corners of thin triangles.
constexpr double kSeamStrokePx = 0.75;

// The GL renderer fades the edges of triangles that are small on screen (shaders/mesh.frag:
// full edges from 14 px up, a tenth at 2 px and below, where `size` is the side of a right
// isosceles triangle of the same area), so that a dense mesh reads as its colours rather
// than a dark blob. The SVG does the same, in kFadeLevels steps: one edge path per step.
constexpr int kFadeLevels = 10;

float edge_fade(Point a, Point b, Point c) {
  const double twice_area = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  const double size = std::sqrt(twice_area);
  if (!(size >= 0.0)) return 1.0f;  // not finite: the triangle is not drawn anyway
  const double t = std::clamp((size - 2.0) / 12.0, 0.0, 1.0);
  return static_cast<float>(0.1 + 0.9 * t * t * (3.0 - 2.0 * t));  // GLSL's smoothstep
}

std::uint32_t packed(Rgba c) {
  return std::uint32_t{c.r} << 24 | std::uint32_t{c.g} << 16 | std::uint32_t{c.b} << 8 | c.a;
}
Rgba unpacked(std::uint32_t v) {
  return {static_cast<std::uint8_t>(v >> 24), static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8),
          static_cast<std::uint8_t>(v)};
}

bool valid_triangle(const MeshLayer& mesh, const std::array<std::uint32_t, 3>& t) {
  return std::max({t[0], t[1], t[2]}) < mesh.points.size();
}

// The mesh's undirected edges as adjacency lists (each edge in both endpoints' lists), with
// the fade level each edge is drawn at.
struct EdgeAdjacency {
  std::vector<std::size_t> start;      // vertex v's neighbours are [start[v], start[v + 1])
  std::vector<std::uint32_t> neighbor;
  std::vector<std::uint8_t> level;     // 1..kFadeLevels: opacity level / kFadeLevels
};

EdgeAdjacency edge_adjacency(const MeshLayer& mesh, const std::vector<Point>& screen) {
  const std::size_t n = mesh.points.size();
  struct Entry {
    std::uint32_t to;
    float fade;
  };
  // Every triangle side, both ways: an inner edge appears twice in each endpoint's list.
  std::vector<std::size_t> start(n + 1, 0);
  for (const auto& t : mesh.triangles)
    if (valid_triangle(mesh, t))
      for (int i = 0; i < 3; ++i) ++start[t[i] + 1], ++start[t[(i + 1) % 3] + 1];
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<Entry> entries(start[n]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const auto& t : mesh.triangles) {
    if (!valid_triangle(mesh, t)) continue;
    const float fade = edge_fade(screen[t[0]], screen[t[1]], screen[t[2]]);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      entries[fill[a]++] = {b, fade};
      entries[fill[b]++] = {a, fade};
    }
  }

  // Merge each list's repeats; an edge's fade is the mean of its triangles' (each draws
  // half the stroke in the GL renderer).
  EdgeAdjacency adj;
  adj.start.assign(n + 1, 0);
  adj.neighbor.reserve(entries.size() / 2 + n);
  adj.level.reserve(entries.size() / 2 + n);
  for (std::size_t v = 0; v < n; ++v) {
    const auto first = entries.begin() + static_cast<std::ptrdiff_t>(start[v]);
    const auto last = entries.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    std::sort(first, last, [](const Entry& x, const Entry& y) { return x.to < y.to; });
    for (auto it = first; it != last;) {
      const std::uint32_t to = it->to;
      float sum = 0.0f;
      int count = 0;
      for (; it != last && it->to == to; ++it) sum += it->fade, ++count;
      if (to == v) continue;  // a degenerate triangle's side from a vertex to itself
      adj.neighbor.push_back(to);
      adj.level.push_back(static_cast<std::uint8_t>(std::clamp<long>(std::lround(sum / count * kFadeLevels), 1, kFadeLevels)));
    }
    adj.start[v + 1] = adj.neighbor.size();
  }
  return adj;
}

// Walks the edges of one fade level into polylines (from a vertex, along unused edges for
// as long as there is one), so most edges cost one point in the path, not two.
void write_edge_chains(const SvgContext& c, const EdgeAdjacency& adj, std::uint8_t level, std::vector<std::uint8_t>& used,
                       SegmentWriter& segments) {
  const std::size_t n = adj.start.size() - 1;
  std::vector<std::size_t> cursor(adj.start.begin(), adj.start.end() - 1);
  const auto next_edge = [&](std::size_t v) -> std::size_t {
    std::size_t& s = cursor[v];
    while (s < adj.start[v + 1] && (used[s] || adj.level[s] != level)) ++s;
    return s < adj.start[v + 1] ? s : SIZE_MAX;
  };
  const auto mark_used = [&](std::size_t v, std::size_t slot) {
    used[slot] = 1;
    const std::uint32_t w = adj.neighbor[slot];
    for (std::size_t s = adj.start[w]; s < adj.start[w + 1]; ++s)
      if (adj.neighbor[s] == v) {
        used[s] = 1;
        break;
      }
  };
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t slot = next_edge(v); slot != SIZE_MAX; slot = next_edge(v)) {
      segments.lift();
      std::size_t at = v;
      for (; slot != SIZE_MAX; slot = next_edge(at)) {
        const std::uint32_t to = adj.neighbor[slot];
        mark_used(at, slot);
        segments.add(c.mesh_screen[at], c.mesh_screen[to], true);
        at = to;
      }
    }
  }
}

// A mesh in painter's order (MeshLayer::painter_order, a 3D view): one path per triangle,
// in the mesh's order, stroked with its edges, so that a nearer triangle covers the fill and
// the edges behind it as in the GL renderer. The stroke is the edge colour laid over the
// triangle's own fill (faded as the GL renderer fades small triangles' edges), so it is
// opaque: the two triangles of an edge stroke it alike, and no seam shows between them.
void write_painter_order(SvgContext& c, bool edges_on) {
  const MeshLayer& mesh = c.scene.mesh;
  SvgText& out = c.out;
  const std::size_t count = std::min(mesh.triangles.size(), mesh.fill.size());
  const bool edges = edges_on && mesh.edge_color.a > 0 && mesh.edge_width_px > 0.0f;
  Rgba edge_opaque = mesh.edge_color;
  edge_opaque.a = 255;
  for (std::size_t t = 0; t < count; ++t) {
    const auto& v = mesh.triangles[t];
    const Rgba fill = mesh.fill[t];
    if (fill.a == 0 || !valid_triangle(mesh, v)) continue;
    const Point a = c.mesh_screen[v[0]], b = c.mesh_screen[v[1]], d = c.mesh_screen[v[2]];
    Rgba stroke = fill;
    double width = kSeamStrokePx;
    if (edges) {
      stroke = mix(fill, edge_opaque, mesh.edge_color.a / 255.0 * edge_fade(a, b, d));
      stroke.a = fill.a;
      width = mesh.edge_width_px;
    }
    const std::size_t rollback = out.size();
    out.raw("<path");
    out.paint("fill", fill);
    out.paint("stroke", stroke);
    out.attr_fine("stroke-width", width);
    out.attr("stroke-linejoin", "round");
    out.raw(" d=\"");
    PathData path(out);
    TriangleWriter triangles(c, path, width);
    triangles.add(a, b, d);
    if (path.empty()) out.truncate(rollback);
    else out.raw("\"/>\n");
  }
}

}  // namespace

void write_mesh_fill(SvgContext& c) {
  const MeshLayer& mesh = c.scene.mesh;
  SvgText& out = c.out;
  if (mesh.painter_order) {
    write_painter_order(c, c.scene.visible.has(Layer::edges));
    return;
  }
  // (colour, triangle) pairs, sorted: one path per colour, its triangles in mesh order.
  std::vector<std::uint64_t> keyed;
  keyed.reserve(mesh.triangles.size());
  const std::size_t count = std::min(mesh.triangles.size(), mesh.fill.size());
  for (std::size_t t = 0; t < count && t <= UINT32_MAX; ++t)
    if (mesh.fill[t].a > 0 && valid_triangle(mesh, mesh.triangles[t]))
      keyed.push_back(std::uint64_t{packed(mesh.fill[t])} << 32 | t);
  std::sort(keyed.begin(), keyed.end());

  for (std::size_t i = 0; i < keyed.size();) {
    const std::uint32_t key = static_cast<std::uint32_t>(keyed[i] >> 32);
    const Rgba color = unpacked(key);
    const std::size_t rollback = out.size();
    out.raw("<path");
    out.paint("fill", color);
    // A translucent stroke would darken the borders: translucent fills go without.
    if (color.a == 255) {
      out.attr_color("stroke", color);
      out.attr_fine("stroke-width", kSeamStrokePx);
      out.attr("stroke-linejoin", "round");
    }
    out.raw(" d=\"");
    PathData path(out);
    TriangleWriter triangles(c, path, kSeamStrokePx);
    for (; i < keyed.size() && static_cast<std::uint32_t>(keyed[i] >> 32) == key; ++i) {
      const auto& t = mesh.triangles[static_cast<std::uint32_t>(keyed[i])];
      triangles.add(c.mesh_screen[t[0]], c.mesh_screen[t[1]], c.mesh_screen[t[2]]);
    }
    if (path.empty()) out.truncate(rollback);  // nothing of this colour in view
    else out.raw("\"/>\n");
  }
}

void write_mesh_edges(SvgContext& c) {
  const MeshLayer& mesh = c.scene.mesh;
  if (mesh.edge_color.a == 0 || !(mesh.edge_width_px > 0.0f)) return;
  // In painter's order the edges were written with their triangles, unless the fill is off
  // (then they are all drawn, as the GL renderer draws them over a transparent inside).
  if (mesh.painter_order && c.scene.visible.has(Layer::fill)) return;
  const EdgeAdjacency adj = edge_adjacency(mesh, c.mesh_screen);
  bool present[kFadeLevels + 1] = {};
  for (const std::uint8_t l : adj.level) present[l] = true;

  std::vector<std::uint8_t> used(adj.neighbor.size(), 0);
  // Strongest first: the usual mesh (triangles over 14 px) is a single path.
  for (int level = kFadeLevels; level >= 1; --level) {
    if (!present[level]) continue;
    Rgba color = mesh.edge_color;
    color.a = static_cast<std::uint8_t>(std::lround(color.a * level / static_cast<double>(kFadeLevels)));
    const std::size_t rollback = c.out.size();
    c.out.raw("<path fill=\"none\"");
    c.out.paint("stroke", color);
    c.out.attr_fine("stroke-width", mesh.edge_width_px);
    c.out.raw(" stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"");
    PathData path(c.out);
    SegmentWriter segments(c, path, 0.5 * mesh.edge_width_px + 1.0);
    write_edge_chains(c, adj, static_cast<std::uint8_t>(level), used, segments);
    if (path.empty()) c.out.truncate(rollback);
    else c.out.raw("\"/>\n");
  }
}

}  // namespace meshstep::scene::detail
