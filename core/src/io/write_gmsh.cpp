// write_gmsh (mesh_formats.hpp): gmsh's MSH 4.1 ASCII, as the gmsh reference manual's
// "MSH file format" section lays it out: $MeshFormat, $PhysicalNames, $Entities, $Nodes,
// $Elements. Elements belong to entities and physical groups are attached to entities, so
// each region attribute is one surface entity (and its physical group), each segment
// marker one curve entity (and its).
#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <vector>

#include "io/atomic_writer.hpp"
#include "io/planar_mesh_check.hpp"
#include "meshstep/io/mesh_formats.hpp"
#include "meshstep/io/shortest_text.hpp"

namespace meshstep::io {
namespace {

// Items sorted into groups by a key, the groups in increasing key order: the members of
// group g are order[start[g], start[g + 1]). A stable counting sort: within a group, items
// keep the mesh's order.
template <class Key>
struct Groups {
  std::vector<Key> keys;
  std::vector<std::size_t> start, order;
};

template <class Key, class KeyOf>
Groups<Key> group_by(std::size_t count, KeyOf key_of) {
  Groups<Key> g;
  g.keys.reserve(count);
  for (std::size_t i = 0; i < count; ++i) g.keys.push_back(key_of(i));
  std::vector<Key> all = g.keys;
  std::sort(g.keys.begin(), g.keys.end());
  g.keys.erase(std::unique(g.keys.begin(), g.keys.end()), g.keys.end());
  std::vector<std::size_t> group_of(count);
  g.start.assign(g.keys.size() + 1, 0);
  for (std::size_t i = 0; i < count; ++i) {
    group_of[i] = static_cast<std::size_t>(std::lower_bound(g.keys.begin(), g.keys.end(), all[i]) - g.keys.begin());
    ++g.start[group_of[i] + 1];
  }
  std::partial_sum(g.start.begin(), g.start.end(), g.start.begin());
  g.order.resize(count);
  std::vector<std::size_t> next(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < count; ++i) g.order[next[group_of[i]]++] = i;
  return g;
}

struct Box {
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  void add(const Point& p) {
    lo[0] = std::min(lo[0], p.x), lo[1] = std::min(lo[1], p.y);
    hi[0] = std::max(hi[0], p.x), hi[1] = std::max(hi[1], p.y);
  }
  bool empty() const { return lo[0] > hi[0]; }
};

// "tag minX minY minZ maxX maxY maxZ 1 tag 0": an entity that is its own physical group,
// with no bounding entities listed (they are optional for a mesh without a CAD model).
void entity_line(detail::AtomicWriter& w, std::size_t tag, const Box& box) {
  w.integer(static_cast<std::int64_t>(tag));
  const Box b = box.empty() ? Box{{0, 0}, {0, 0}} : box;
  for (const double v : {b.lo[0], b.lo[1], 0.0, b.hi[0], b.hi[1], 0.0}) {
    w.ch(' ');
    w.real(v);
  }
  w.text(" 1 ");
  w.integer(static_cast<std::int64_t>(tag));
  w.text(" 0\n");
}

}  // namespace

void write_gmsh(const std::string& path, const TriMesh& mesh) {
  detail::check_planar_mesh(path, mesh);
  const auto regions = group_by<double>(mesh.triangles.size(), [&](std::size_t t) { return detail::region_of(mesh, t); });
  const auto markers = group_by<int>(mesh.segments.size(), [&](std::size_t s) { return mesh.segments[s].marker; });
  // The nodes need an entity to live on: the first surface, which exists even without a
  // triangle (gmsh then reads the vertices alone).
  const std::size_t surfaces = std::max<std::size_t>(regions.keys.size(), 1);
  const std::size_t curves = markers.keys.size();

  const auto box_of = [&](const auto& groups, std::size_t g, auto corners) {
    Box box;
    for (std::size_t k = groups.start[g]; k < groups.start[g + 1]; ++k)
      for (const std::uint32_t v : corners(groups.order[k])) box.add(mesh.points[v]);
    return box;
  };
  const auto triangle_corners = [&](std::size_t t) { return mesh.triangles[t]; };
  const auto segment_ends = [&](std::size_t s) { return std::array{mesh.segments[s].a, mesh.segments[s].b}; };

  detail::AtomicWriter w(path);
  w.text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");

  // Physical tags count per dimension, from 1 (gmsh wants them positive; markers may be 0).
  w.text("$PhysicalNames\n");
  w.integer(static_cast<std::int64_t>(curves + regions.keys.size()));
  w.ch('\n');
  for (std::size_t c = 0; c < curves; ++c) {
    w.text("1 ");
    w.integer(static_cast<std::int64_t>(c + 1));
    w.text(mesh.has_segment_markers ? " \"marker " + std::to_string(markers.keys[c]) + "\"\n" : " \"segments\"\n");
  }
  for (std::size_t r = 0; r < regions.keys.size(); ++r) {
    w.text("2 ");
    w.integer(static_cast<std::int64_t>(r + 1));
    w.text(mesh.attributes_per_triangle ? " \"region " + shortest_text(regions.keys[r]) + "\"\n" : " \"domain\"\n");
  }
  w.text("$EndPhysicalNames\n");

  w.text("$Entities\n0 ");
  w.integer(static_cast<std::int64_t>(curves));
  w.ch(' ');
  w.integer(static_cast<std::int64_t>(surfaces));
  w.text(" 0\n");
  for (std::size_t c = 0; c < curves; ++c) entity_line(w, c + 1, box_of(markers, c, segment_ends));
  if (regions.keys.empty()) {
    Box all;
    for (const Point& p : mesh.points) all.add(p);
    entity_line(w, 1, all);
  }
  for (std::size_t r = 0; r < regions.keys.size(); ++r) entity_line(w, r + 1, box_of(regions, r, triangle_corners));
  w.text("$EndEntities\n");

  // One block: every node on surface 1, tags 1..N in the mesh's order.
  const std::size_t n = mesh.points.size();
  w.text("$Nodes\n");
  w.text(n ? "1 " : "0 ");
  w.integer(static_cast<std::int64_t>(n));
  w.text(n ? " 1 " : " 0 ");
  w.integer(static_cast<std::int64_t>(n));
  w.ch('\n');
  if (n) {
    w.text("2 1 0 ");
    w.integer(static_cast<std::int64_t>(n));
    w.ch('\n');
    for (std::size_t i = 1; i <= n; ++i) {
      w.integer(static_cast<std::int64_t>(i));
      w.ch('\n');
    }
    for (const Point& p : mesh.points) {
      w.real(p.x);
      w.ch(' ');
      w.real(p.y);
      w.text(" 0\n");
    }
  }
  w.text("$EndNodes\n");

  // Triangles first (tags 1..T, by region), then the segments' lines (T+1.., by marker).
  const std::size_t elements = mesh.triangles.size() + mesh.segments.size();
  w.text("$Elements\n");
  w.integer(static_cast<std::int64_t>(regions.keys.size() + curves));
  w.ch(' ');
  w.integer(static_cast<std::int64_t>(elements));
  w.text(elements ? " 1 " : " 0 ");
  w.integer(static_cast<std::int64_t>(elements));
  w.ch('\n');
  std::int64_t tag = 1;
  const auto block = [&](int dim, std::size_t entity, int type, const auto& groups, std::size_t g, auto corners) {
    w.integer(dim);
    w.ch(' ');
    w.integer(static_cast<std::int64_t>(entity));
    w.ch(' ');
    w.integer(type);
    w.ch(' ');
    w.integer(static_cast<std::int64_t>(groups.start[g + 1] - groups.start[g]));
    w.ch('\n');
    for (std::size_t k = groups.start[g]; k < groups.start[g + 1]; ++k) {
      w.integer(tag++);
      for (const std::uint32_t v : corners(groups.order[k])) {
        w.ch(' ');
        w.integer(static_cast<std::int64_t>(v) + 1);
      }
      w.ch('\n');
    }
  };
  for (std::size_t r = 0; r < regions.keys.size(); ++r) block(2, r + 1, 2, regions, r, triangle_corners);
  for (std::size_t c = 0; c < curves; ++c) block(1, c + 1, 1, markers, c, segment_ends);
  w.text("$EndElements\n");
  w.commit();
}

}  // namespace meshstep::io
