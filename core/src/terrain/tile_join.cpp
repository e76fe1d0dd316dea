// Welding tile surfaces into one and looking for cracks (meshstep/terrain/tile_join.hpp).
#include "meshstep/terrain/tile_join.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "meshstep/error.hpp"

namespace meshstep::terrain {
namespace {

std::uint64_t bits_of(double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); }

std::uint64_t hash_of(const io::Point3& p) {
  // A multiply-xorshift mix of the three coordinates' bits: tile vertices are regular
  // multiples of the cell size, which a plain xor would pile into few slots.
  std::uint64_t h = 0x9E3779B97F4A7C15ull;
  for (const double v : {p.x, p.y, p.z}) {
    h ^= bits_of(v);
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
  }
  return h;
}

std::string point_text(const io::Point3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.10g, %.10g, %.10g)", p.x, p.y, p.z);
  return text;
}

}  // namespace

void SurfaceWelder::add(const io::Surface& s) {
  std::vector<std::uint32_t> index(s.vertices.size());
  for (std::size_t v = 0; v < s.vertices.size(); ++v) index[v] = find_or_add(s.vertices[v]);
  joined_.triangles.reserve(joined_.triangles.size() + s.triangles.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      if (s.triangles[t][k] >= s.vertices.size())
        throw InputError("triangle " + std::to_string(t) + " uses vertex " + std::to_string(s.triangles[t][k]) +
                         ", but there are only " + std::to_string(s.vertices.size()) + " vertices");
      tri[k] = index[s.triangles[t][k]];
    }
    joined_.triangles.push_back(tri);
  }
}

std::uint32_t SurfaceWelder::find_or_add(const io::Point3& p) {
  if (2 * (joined_.vertices.size() + 1) > slots_.size()) grow();
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t at = hash_of(p) & mask;; at = (at + 1) & mask) {
    if (slots_[at] == 0) {
      if (joined_.vertices.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
        throw InputError("the joined surface has more vertices than 32-bit indices can name");
      joined_.vertices.push_back(p);
      slots_[at] = static_cast<std::uint32_t>(joined_.vertices.size());
      return slots_[at] - 1;
    }
    const io::Point3& q = joined_.vertices[slots_[at] - 1];
    if (q.x == p.x && q.y == p.y && q.z == p.z) {
      ++welded_;
      return slots_[at] - 1;
    }
  }
}

void SurfaceWelder::grow() {
  std::vector<std::uint32_t> old = std::move(slots_);
  slots_.assign(std::max<std::size_t>(1024, 2 * old.size()), 0);
  const std::size_t mask = slots_.size() - 1;
  for (const std::uint32_t v : old) {
    if (v == 0) continue;
    std::size_t at = hash_of(joined_.vertices[v - 1]) & mask;
    while (slots_[at] != 0) at = (at + 1) & mask;
    slots_[at] = v;
  }
}

bool TileJoinCheck::ok() const {
  return surface.clean() && surface.boundary_loops == 1 && cracks == 0 &&
         std::fabs(area - rectangle_area) <= 1e-9 * rectangle_area;
}

TileJoinCheck check_joined_tiles(const io::Surface& joined) {
  TileJoinCheck check;
  check.surface = io::report_surface(joined);
  if (joined.vertices.empty()) return check;
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& p : joined.vertices) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  check.rectangle_area = (x1 - x0) * (y1 - y0);

  // Edges as (lo, hi) pairs, sorted: an edge that appears once is on the boundary.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(3 * joined.triangles.size());
  for (const auto& t : joined.triangles) {
    const auto &a = joined.vertices[t[0]], &b = joined.vertices[t[1]], &c = joined.vertices[t[2]];
    check.area += ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2.0;
    for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
  }
  std::sort(edges.begin(), edges.end());
  const auto on_rectangle = [&](const io::Point3& a, const io::Point3& b) {
    return (a.x == x0 && b.x == x0) || (a.x == x1 && b.x == x1) || (a.y == y0 && b.y == y0) ||
           (a.y == y1 && b.y == y1);
  };
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) {
      const auto &a = joined.vertices[edges[i].first], &b = joined.vertices[edges[i].second];
      if (!on_rectangle(a, b)) {
        ++check.cracks;
        if (check.first_cracks.size() < 5) check.first_cracks.push_back({a, b});
      }
    }
    i = j;
  }
  return check;
}

std::string describe(const TileJoinCheck& check) {
  std::string text = io::describe(check.surface);
  char area[160];
  std::snprintf(area, sizeof area, "; triangles' area %.10g, the rectangle's %.10g", check.area, check.rectangle_area);
  text += area;
  if (check.cracks == 0) return text + "; no crack";
  text += "; " + std::to_string(check.cracks) + (check.cracks == 1 ? " crack" : " cracks") +
          " (edges of one triangle inside the rectangle), e.g.";
  for (const auto& [a, b] : check.first_cracks) {
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about " " + string + ...
    text += ' ';
    text += point_text(a);
    text += '-';
    text += point_text(b);
  }
  return text;
}

}  // namespace meshstep::terrain
