// flip_surface (surface/surface_flips.hpp): flips on the triangle list itself, with a map
// from each directed edge to the triangle corner it leaves, kept up to date as triangles
// are rewritten in place.
#include "meshstep/surface/surface_flips.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <numbers>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "meshstep/error.hpp"
#include "surface_geometry.hpp"
#include "surface_input.hpp"

namespace meshstep::surface {
namespace {

using detail::from_smallest;
using detail::Triangle;

std::uint64_t directed(std::uint32_t a, std::uint32_t b) { return std::uint64_t{a} << 32 | b; }
std::uint64_t undirected(std::uint32_t a, std::uint32_t b) { return directed(std::min(a, b), std::max(a, b)); }

std::array<double, 3> normal(const Point3& a, const Point3& b, const Point3& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

double dot(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}
double norm(const std::array<double, 3>& u) { return std::sqrt(dot(u, u)); }

// The angle between two normals, in degrees (atan2: accurate near 0).
double angle_between_deg(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  const std::array<double, 3> c = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::atan2(norm(c), dot(u, v)) * (180.0 / std::numbers::pi);
}

class Flipper {
 public:
  Flipper(const std::vector<Point3>& points, std::vector<Triangle>& triangles, double max_dihedral_deg)
      : points_(points), triangles_(triangles), max_dihedral_deg_(max_dihedral_deg) {
    corner_of_.reserve(3 * triangles_.size());
    for (std::uint32_t t = 0; t < triangles_.size(); ++t) note(t);
    std::vector<std::uint64_t> edges;
    for (const auto& [key, corner] : corner_of_) {
      const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
      if (a < b && corner_of_.count(directed(b, a))) edges.push_back(key);
    }
    std::sort(edges.begin(), edges.end());
    for (const std::uint64_t e : edges) push(e);
  }

  void run(FlipReport& report) {
    // Each flip raises the sorted angle list, so this ends; the cap only guards against
    // rounding that would let two flips undo each other.
    const std::size_t most = 16 * triangles_.size() + 16;
    while (!queue_.empty() && report.flips < most) {
      const std::uint64_t e = queue_.front();
      queue_.pop_front();
      queued_.erase(e);
      try_flip(static_cast<std::uint32_t>(e >> 32), static_cast<std::uint32_t>(e), report);
    }
  }

 private:
  const Point3& p(std::uint32_t v) const { return points_[v]; }

  double smallest_angle(const Triangle& t) const {
    const Triangle s = from_smallest(t);
    return detail::smallest_angle_deg(p(s[0]), p(s[1]), p(s[2]));
  }
  std::array<double, 3> unit_normal(const Triangle& t) const {
    const Triangle s = from_smallest(t);
    const std::array<double, 3> n = normal(p(s[0]), p(s[1]), p(s[2]));
    const double length = norm(n);
    return {n[0] / length, n[1] / length, n[2] / length};
  }

  void note(std::uint32_t t) {
    for (std::uint32_t i = 0; i < 3; ++i) corner_of_[directed(triangles_[t][i], triangles_[t][(i + 1) % 3])] = 3 * t + i;
  }
  void forget(std::uint32_t t) {
    for (std::uint32_t i = 0; i < 3; ++i) corner_of_.erase(directed(triangles_[t][i], triangles_[t][(i + 1) % 3]));
  }
  void push(std::uint64_t e) {
    if (queued_.insert(e).second) queue_.push_back(e);
  }

  void try_flip(std::uint32_t u, std::uint32_t w, FlipReport& report) {
    const auto uw = corner_of_.find(directed(u, w)), wu = corner_of_.find(directed(w, u));
    if (uw == corner_of_.end() || wu == corner_of_.end()) return;  // a border
    const std::uint32_t t = uw->second / 3, s = wu->second / 3;
    const std::uint32_t i = uw->second % 3, j = wu->second % 3;
    const std::uint32_t a = triangles_[t][i], b = triangles_[t][(i + 1) % 3], c = triangles_[t][(i + 2) % 3];
    const std::uint32_t d = triangles_[s][(j + 2) % 3];
    if (c == d || corner_of_.count(directed(c, d)) || corner_of_.count(directed(d, c))) return;
    const Triangle old_t = triangles_[t], old_s = triangles_[s];
    const Triangle new_t = {a, d, c}, new_s = {d, b, c};
    const std::array<double, 3> n_t = unit_normal(old_t), n_s = unit_normal(old_s);
    const double dihedral = angle_between_deg(n_t, n_s);
    if (!(dihedral <= max_dihedral_deg_)) return;
    // Convex seen along the mean normal: both new triangles face that way, and are not flat.
    const std::array<double, 3> mean = {n_t[0] + n_s[0], n_t[1] + n_s[1], n_t[2] + n_s[2]};
    for (const Triangle& n : {new_t, new_s}) {
      const Triangle q = from_smallest(n);
      if (!(dot(normal(p(q[0]), p(q[1]), p(q[2])), mean) > 0.0)) return;
    }
    const double before = std::min(smallest_angle(old_t), smallest_angle(old_s));
    const double after = std::min(smallest_angle(new_t), smallest_angle(new_s));
    if (!(after > before)) return;
    forget(t);
    forget(s);
    triangles_[t] = new_t;
    triangles_[s] = new_s;
    note(t);
    note(s);
    ++report.flips;
    report.largest_dihedral_flipped_deg = std::max(report.largest_dihedral_flipped_deg, dihedral);
    for (const std::uint64_t e : {undirected(a, d), undirected(d, b), undirected(b, c), undirected(c, a)}) push(e);
  }

  const std::vector<Point3>& points_;
  std::vector<Triangle>& triangles_;
  const double max_dihedral_deg_;
  std::unordered_map<std::uint64_t, std::uint32_t> corner_of_;  // directed edge -> 3t + corner
  std::deque<std::uint64_t> queue_;                             // undirected edges to try
  std::unordered_set<std::uint64_t> queued_;
};

}  // namespace

io::Surface flip_surface(const io::Surface& in, const FlipOptions& options, FlipReport* report) {
  if (!(options.max_dihedral_deg >= 0.0 && options.max_dihedral_deg <= 180.0))
    throw InputError("surface flips: the dihedral bound must be between 0 and 180 degrees, not " +
                     std::to_string(options.max_dihedral_deg));
  detail::check_surface_input(in, "surface flips");
  FlipReport result;
  io::Surface out = in;
  const detail::SurfaceMeasures before = detail::measure_surface(out.vertices, out.triangles);
  Flipper(out.vertices, out.triangles, options.max_dihedral_deg).run(result);
  for (Triangle& t : out.triangles) t = from_smallest(t);
  std::sort(out.triangles.begin(), out.triangles.end());
  const detail::SurfaceMeasures after = detail::measure_surface(out.vertices, out.triangles);
  result.smallest_angle_before_deg = before.smallest_angle_deg;
  result.smallest_angle_after_deg = after.smallest_angle_deg;
  result.area_before = before.area;
  result.area_after = after.area;
  if (report != nullptr) *report = result;
  return out;
}

}  // namespace meshstep::surface
