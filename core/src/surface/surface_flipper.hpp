// Surface flips (surface_flips.hpp) on any TriangleMesh the loader filled
// (surface_loader.hpp), through a recording policy: the rule is the header's, the edges are
// the mesh's.
//
// Candidates are edges by their vertex ids (an undirected pair), tried in id order and again
// when a flip changes a triangle beside them. Each directed edge of the surface maps to the
// face that holds it; a flip rewrites two faces, whose edges are noted again, and leaves
// every other face as it was, so the map stays exact without ever holding a half-edge
// (which a mutation may renumber). An edge joined only through a seam (its two sides are
// borders of the mesh, seam_table.hpp) is not flipped: the mesh has no quadrilateral
// there. Seams are few (one for a sphere, the cuts of a torus).
//
// After a bisection the flips keep its size bounds (size_bounds.hpp): a flip that would make
// a triangle over a bound is not taken, unless the pair broke the bounds already (a run
// stopped by its cap) and the flip makes neither more of its triangles over them nor its
// worst one worse. Two triangles that met an area bound can trade their diagonal for a pair
// of which one is over it (the area moves between them), and the new diagonal can be longer
// than an edge bound. The rule only refuses flips, so the flips still end.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <numbers>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "meshstep/geometry/collinear3.hpp"
#include "meshstep/geometry/point3.hpp"
#include "meshstep/mesh/concept.hpp"
#include "meshstep/replay/recorder.hpp"
#include "meshstep/surface/surface_flips.hpp"
#include "size_bounds.hpp"
#include "surface_geometry.hpp"
#include "surface_input.hpp"

namespace meshstep::surface::detail {

template <TriangleMesh Mesh, class Rec = replay::NullRecorder>
class SurfaceFlipper {
 public:
  SurfaceFlipper(Mesh& mesh, const std::vector<Point3>& points, double max_dihedral_deg, const SizeBounds& bounds,
                 Rec& rec)
      : mesh_(mesh), points_(points), max_dihedral_deg_(max_dihedral_deg), bounds_(bounds), rec_(rec) {
    face_of_.reserve(3 * mesh_.face_count());
    for (FaceId f = 0; f < mesh_.face_capacity(); ++f)
      if (mesh_.is_live(f)) note(f);
    std::vector<std::uint64_t> edges;
    for (const auto& [key, face] : face_of_) {
      const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
      if (a < b && face_of_.count(directed(b, a))) edges.push_back(key);
    }
    std::sort(edges.begin(), edges.end());
    for (const std::uint64_t e : edges) push(e);
  }

  void run(FlipReport& report) {
    // Each flip raises the sorted angle list, so this ends; the cap only guards against
    // rounding that would let two flips undo each other.
    const std::size_t most = 16 * mesh_.face_count() + 16;
    bool phase_open = false;
    while (!queue_.empty() && report.flips < most) {
      const std::uint64_t e = queue_.front();
      queue_.pop_front();
      queued_.erase(e);
      try_flip(static_cast<std::uint32_t>(e >> 32), static_cast<std::uint32_t>(e), report, phase_open);
    }
    if (phase_open) rec_.phase_end(replay::Phase::improve);
  }

 private:
  using Normal = std::array<double, 3>;

  static std::uint64_t directed(std::uint32_t a, std::uint32_t b) { return std::uint64_t{a} << 32 | b; }
  static std::uint64_t undirected(std::uint32_t a, std::uint32_t b) { return directed(std::min(a, b), std::max(a, b)); }

  const Point3& p(std::uint32_t v) const { return points_[v]; }

  static Normal normal(const Point3& a, const Point3& b, const Point3& c) {
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
  }
  static double dot(const Normal& u, const Normal& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
  static double norm(const Normal& u) { return std::sqrt(dot(u, u)); }
  // The angle between two normals, in degrees (atan2: accurate near 0).
  static double angle_between_deg(const Normal& u, const Normal& v) {
    const Normal c = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    return std::atan2(norm(c), dot(u, v)) * (180.0 / std::numbers::pi);
  }

  // Angles and normals from the triangle's smallest vertex id: the last bits of every
  // measure then do not depend on where a data structure starts a face.
  double smallest_angle(const Triangle& t) const {
    const Triangle s = from_smallest(t);
    return smallest_angle_deg(p(s[0]), p(s[1]), p(s[2]));
  }
  Normal unit_normal(const Triangle& t) const {
    const Triangle s = from_smallest(t);
    const Normal n = normal(p(s[0]), p(s[1]), p(s[2]));
    const double length = norm(n);
    return {n[0] / length, n[1] / length, n[2] / length};
  }

  // Whether the pair `after` keeps to the size bounds as well as the pair `before` did:
  // every triangle within them, or no more triangles over them and the worst no worse.
  bool keeps_bounds(const std::array<Triangle, 2>& before, const std::array<Triangle, 2>& after) const {
    double worst_before = 0.0, worst_after = 0.0;
    int over_before = 0, over_after = 0;
    for (const Triangle& t : before) {
      const double e = excess(t);
      worst_before = std::max(worst_before, e);
      over_before += e > 0.0;
    }
    for (const Triangle& t : after) {
      const double e = excess(t);
      worst_after = std::max(worst_after, e);
      over_after += e > 0.0;
    }
    return over_after == 0 || (over_after <= over_before && worst_after <= worst_before);
  }
  double excess(const Triangle& t) const {
    const Triangle s = from_smallest(t);
    return bounds_.excess(p(s[0]), p(s[1]), p(s[2]));
  }

  void note(FaceId f) {
    const HalfEdge h = mesh_.half_edge(f);
    for (const HalfEdge e : {h, mesh_.next(h), mesh_.prev(h)}) face_of_[directed(mesh_.origin(e), mesh_.dest(e))] = f;
  }
  void forget(const Triangle& t) {
    for (std::uint32_t i = 0; i < 3; ++i) face_of_.erase(directed(t[i], t[(i + 1) % 3]));
  }
  void push(std::uint64_t e) {
    if (queued_.insert(e).second) queue_.push_back(e);
  }
  // The half-edge u -> w of face f.
  HalfEdge half_edge_of(FaceId f, VertexId u, VertexId w) const {
    const HalfEdge h = mesh_.half_edge(f);
    for (const HalfEdge e : {h, mesh_.next(h), mesh_.prev(h)})
      if (mesh_.origin(e) == u && mesh_.dest(e) == w) return e;
    return kNone;
  }

  void try_flip(std::uint32_t u, std::uint32_t w, FlipReport& report, bool& phase_open) {
    const auto uw = face_of_.find(directed(u, w)), wu = face_of_.find(directed(w, u));
    if (uw == face_of_.end() || wu == face_of_.end()) return;  // a border
    const HalfEdge h = half_edge_of(uw->second, u, w);
    if (h == kNone || mesh_.twin(h) == kNone || mesh_.face(mesh_.twin(h)) != wu->second) return;  // a seam
    const VertexId a = u, b = w, c = mesh_.apex(h), d = mesh_.apex(mesh_.twin(h));
    if (c == d || face_of_.count(directed(c, d)) || face_of_.count(directed(d, c))) return;
    const Triangle old_t = {a, b, c}, old_s = {b, a, d};
    const Triangle new_t = {a, d, c}, new_s = {d, b, c};
    const Normal n_t = unit_normal(old_t), n_s = unit_normal(old_s);
    const double dihedral = angle_between_deg(n_t, n_s);
    if (!(dihedral <= max_dihedral_deg_)) return;
    // Convex seen along the mean normal: both new triangles face that way, and are not flat.
    const Normal mean = {n_t[0] + n_s[0], n_t[1] + n_s[1], n_t[2] + n_s[2]};
    for (const Triangle& n : {new_t, new_s}) {
      const Triangle q = from_smallest(n);
      if (!(dot(normal(p(q[0]), p(q[1]), p(q[2])), mean) > 0.0)) return;
      // A rounded cross product can be nonzero for exactly collinear corners.
      if (collinear(p(q[0]), p(q[1]), p(q[2]))) return;
    }
    const double before = std::min(smallest_angle(old_t), smallest_angle(old_s));
    const double after = std::min(smallest_angle(new_t), smallest_angle(new_s));
    if (!(after > before)) return;
    if (bounds_.any() && !keeps_bounds({old_t, old_s}, {new_t, new_s})) return;
    if (!phase_open) {
      rec_.phase_begin(replay::Phase::improve);
      phase_open = true;
    }
    rec_.step_begin(mesh_, replay::StepKind::flip_3d, a, b);
    forget(old_t);
    forget(old_s);
    const HalfEdge n = rec_.flip(mesh_, h, replay::FlipReason::angles_3d);  // c -> d
    note(mesh_.face(n));
    note(mesh_.face(mesh_.twin(n)));
    ++report.flips;
    report.largest_dihedral_flipped_deg = std::max(report.largest_dihedral_flipped_deg, dihedral);
    for (const std::uint64_t e : {undirected(a, d), undirected(d, b), undirected(b, c), undirected(c, a)}) push(e);
  }

  Mesh& mesh_;
  const std::vector<Point3>& points_;
  const double max_dihedral_deg_;
  const SizeBounds bounds_;
  Rec& rec_;
  std::unordered_map<std::uint64_t, FaceId> face_of_;  // directed edge (vertex ids) -> its face
  std::deque<std::uint64_t> queue_;                    // undirected edges to try
  std::unordered_set<std::uint64_t> queued_;
};

}  // namespace meshstep::surface::detail
