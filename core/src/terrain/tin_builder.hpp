// The terrain engine: Delaunay insertion of grid samples, each triangle's largest error
// kept exact, and a policy that picks the next sample (greedy or Lepp-surface).
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "meshstep/delaunay/triangulation.hpp"
#include "meshstep/delaunay/vertex_removal.hpp"
#include "meshstep/error.hpp"
#include "meshstep/terrain/tin.hpp"
#include "planar_scale.hpp"
#include "triangle_scan.hpp"

namespace meshstep::terrain::detail {

// Rec records the run into a replay log (replay/recorder.hpp): every insertion is a refine
// step that names the worst triangle and its error (a vertical_error criterion_test), the
// Lepp path, the sample chosen (point_selected, a SampleChoice) and its height (elevation);
// every removal of the improvement and every 3D flip is a step of its own.
template <TriangleMesh Mesh, class Rec = replay::NullRecorder>
class TinBuilder {
 public:
  // Without `border`, the TIN starts from the grid's four corners; with it, from the given
  // border vertices (the four corners first: approximate_within_border checks them), and no
  // sample on the rectangle is ever searched or inserted.
  TinBuilder(const HeightGrid& grid, const TerrainOptions& options, const BorderVertices* border = nullptr,
             Rec recorder = {})
      : grid_(grid), options_(options), border_(border), scale_(planar_scale(grid)),
        tri_(initial_points(grid, border), Insertion::flip, std::move(recorder)),
        used_(grid.nx * grid.ny, false),
        window_(border ? SampleWindow{1, static_cast<std::int64_t>(grid.nx) - 2, 1, static_cast<std::int64_t>(grid.ny) - 2}
                       : kEverySample),
        hull_vertices_(tri_.points().size()) {}

  Tin run(TerrainReport& report) {
    const auto start = std::chrono::steady_clock::now();
    // The log stores points in metres, as the grid's samples are.
    if constexpr (Rec::enabled) rec().set_vertex_context({}, scale_.exponent);
    tri_.insert_all();
    for (VertexId v = 0; v < hull_vertices_; ++v) {
      samples_.push_back(border_ ? border_->samples[v] : corner_sample(v));
      heights_.push_back(border_ ? border_->heights[v] : corner_height(v));
      used_[samples_.back()] = true;
      rec().elevation(v, heights_.back());
    }
    for (FaceId f = 0; f < mesh().face_capacity(); ++f)
      if (mesh().is_live(f) && !tri_.is_ghost(f)) measure(f);

    rec().phase_begin(replay::Phase::refine);
    while (true) {
      const Worst worst = pop_current();
      if (worst.face == kNone || worst.error <= options_.max_error) {
        report.worst_error = worst.face == kNone ? 0.0 : worst.error;
        break;
      }
      if (options_.max_triangles > 0 && triangle_count() >= options_.max_triangles) {
        report.worst_error = worst.error;
        report.capped = true;
        break;
      }
      // The next sample, and a triangle at or near it where the point location starts: the
      // samples go in all over the grid, and a walk from the last one would cross it.
      if constexpr (Rec::enabled) record_worst(worst);
      Choice next{worst.sample, worst.face, replay::SampleChoice::worst_sample};
      if (options_.algorithm == TerrainAlgorithm::lepp_surface) next = lepp_sample(worst.face, report);
      if constexpr (Rec::enabled) record_choice(worst.face, next);
      insert(next.sample, mesh().half_edge(next.near));
      if ((++report.insertions & 0xFFFF) == 0 && options_.progress) options_.progress(triangle_count(), worst.error);
    }
    rec().phase_end(replay::Phase::refine);
    const double bound = std::max(options_.max_error, report.worst_error);
    if (options_.improve && !report.capped) report.removed = remove_vertices(bound);
    if (options_.flips_3d) report.flips_3d = improve_by_3d_flips(bound);
    rec().run_end(mesh());
    Tin tin = result();
    report.vertices = tin.samples.size();
    report.triangles = tin.triangles.size();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return tin;
  }

 private:
  static constexpr std::uint32_t kNoSample = std::numeric_limits<std::uint32_t>::max();

  // A triangle's largest error and the sample where it is (error -1 when it covers no
  // sample with data).
  struct FaceWorst {
    double error;
    std::uint32_t sample;
  };

  // The next sample to insert, why, and a triangle that holds it or one near it (where the
  // point location starts).
  struct Choice {
    std::uint32_t sample;
    FaceId near;
    replay::SampleChoice choice;
  };

  // A queue entry: a triangle's largest error and the sample where it is. 16 bytes: the
  // queue's sifts are a good part of a run. An entry is current while its face is live and
  // still has that worst (pop_current): a face remeasured to the same error at the same
  // sample leaves two current entries, and the second goes stale when the first's sample
  // is inserted (a vertex has no error).
  struct Worst {
    double error;
    std::uint32_t sample;
    FaceId face;
    // Larger errors first, then the smaller sample. Two triangles share their worst sample
    // when it is on their common edge: canonical_face settles which one is meant.
    bool operator<(const Worst& o) const { return error != o.error ? error < o.error : sample > o.sample; }
  };

  const Mesh& mesh() const { return tri_.mesh(); }
  Rec& rec() { return tri_.recorder(); }

  // The step's opening: the worst triangle, and how far it misses the bound.
  void record_worst(const Worst& worst) {
    const HalfEdge h = mesh().half_edge(worst.face);
    const VertexId a = mesh().origin(h), b = mesh().dest(h), c = mesh().apex(h);
    rec().step_begin(mesh(), replay::StepKind::refine);
    rec().criterion_test(replay::Criterion::vertical_error, false, a, b, c, worst.error);
  }
  // The sample chosen for the worst triangle f: where it goes, and (nearest a terminal
  // point) the point it stands for.
  void record_choice(FaceId f, const Choice& next) {
    const HalfEdge h = mesh().half_edge(f);
    const Point at = sample_point(next.sample);
    const std::span<const Point> alternatives =
        next.choice == replay::SampleChoice::terminal_point ? std::span<const Point>(&terminal_point_, 1)
                                                            : std::span<const Point>();
    rec().point_selected(static_cast<std::uint8_t>(next.choice), mesh().origin(h), mesh().dest(h), mesh().apex(h), at,
                         alternatives);
  }
  // Sample s where the triangulation has it: scaled by 2^scale_.exponent.
  Point sample_point(std::uint32_t s) const {
    return {static_cast<double>(s % grid_.nx) * scale_.dx, static_cast<double>(s / grid_.nx) * scale_.dy};
  }
  // Vertex v in metres, for what mixes in heights (3D lengths and angles).
  Point metres(VertexId v) const {
    const std::uint32_t s = samples_[v];
    return {static_cast<double>(s % grid_.nx) * grid_.dx, static_cast<double>(s / grid_.nx) * grid_.dy};
  }

  std::vector<Point> corners(const HeightGrid& g) const {
    const double x = static_cast<double>(g.nx - 1) * scale_.dx, y = static_cast<double>(g.ny - 1) * scale_.dy;
    return {{0, 0}, {x, 0}, {x, y}, {0, y}};
  }
  // The corners, then the rest of a given border: the first three start the triangulation
  // as a proper triangle, and every later border vertex falls on a hull edge and splits it.
  std::vector<Point> initial_points(const HeightGrid& g, const BorderVertices* border) const {
    std::vector<Point> points = corners(g);
    if (!border) return points;
    for (std::size_t k = 4; k < border->samples.size(); ++k) {
      const std::uint32_t s = border->samples[k];
      points.push_back(sample_point(s));
    }
    return points;
  }
  std::uint32_t corner_sample(VertexId v) const {
    const std::size_t i = (v == 1 || v == 2) ? grid_.nx - 1 : 0, j = v >= 2 ? grid_.ny - 1 : 0;
    return static_cast<std::uint32_t>(i + j * grid_.nx);
  }
  // A corner without data takes the height of the nearest sample that has some, by rings
  // of growing Chebyshev distance, the first found in row order: the TIN must cover the
  // whole rectangle, and a made-up height there is better than a hole in it.
  float corner_height(VertexId v) const {
    const std::size_t ci = samples_[v] % grid_.nx, cj = samples_[v] / grid_.nx;
    if (grid_.has_data(ci, cj)) return grid_.at(ci, cj);
    const std::size_t reach = std::max(grid_.nx, grid_.ny);
    for (std::size_t r = 1; r < reach; ++r)
      for (std::size_t j = cj >= r ? cj - r : 0; j <= std::min(grid_.ny - 1, cj + r); ++j)
        for (std::size_t i = ci >= r ? ci - r : 0; i <= std::min(grid_.nx - 1, ci + r); ++i)
          if (grid_.has_data(i, j)) return grid_.at(i, j);
    return 0.0f;  // unreachable: the grid reader refuses a grid without data
  }

  GridIndex index_of(VertexId v) const {
    return {static_cast<std::int64_t>(samples_[v] % grid_.nx), static_cast<std::int64_t>(samples_[v] / grid_.nx)};
  }

  // The largest error among the samples of the counter-clockwise triangle abc, and where.
  FaceWorst scan_worst(VertexId a, VertexId b, VertexId c) const {
    // From the smallest vertex id round, so that the sums below, and with them the last
    // bits of every error, do not depend on where the data structure starts a face.
    while (a > b || a > c) std::tie(a, b, c) = std::tuple(b, c, a);
    const WorstSample w = worst_sample(grid_.z.data(), grid_.nx, index_of(a), index_of(b), index_of(c),
                                       heights_[a], heights_[b], heights_[c], kNoSample, window_);
    const FaceWorst worst{w.error, static_cast<std::uint32_t>(w.sample)};
    return worst;
  }

  // Measures face f and queues it.
  void measure(FaceId f) {
    const HalfEdge h = mesh().half_edge(f);
    const VertexId a = mesh().origin(h), b = mesh().dest(h), c = mesh().apex(h);
    const FaceWorst worst = scan_worst(a, b, c);
    if (worst_.size() <= f) worst_.resize(mesh().face_capacity(), {0.0, kNoSample});
    worst_[f] = worst;
    // A triangle within the bound never leaves the queue first: it stays out, and the queue
    // stays a fraction of the mesh (its sifts were a quarter of a run).
    if (worst.sample != kNoSample && worst.error > options_.max_error)
      queue_.push({worst.error, worst.sample, f});
  }

  // The worst triangle still current, without taking it off the queue; face kNone when
  // none misses the bound.
  Worst pop_current() {
    while (!queue_.empty()) {
      const Worst top = queue_.top();
      if (mesh().is_live(top.face) && worst_[top.face].error == top.error && worst_[top.face].sample == top.sample)
        return {top.error, top.sample, canonical_face(top.face, top.sample)};
      queue_.pop();
    }
    return {0.0, kNoSample, kNone};
  }

  // Of f and the triangle across the edge of f that holds `sample`, when both have it as
  // their worst, the one with the smaller vertex ids: which of the two the queue gives
  // first depends on the data structure, and Lepp-surface's path starts from it.
  FaceId canonical_face(FaceId f, std::uint32_t sample) const {
    const HalfEdge first = mesh().half_edge(f);
    const GridIndex p{static_cast<std::int64_t>(sample % grid_.nx), static_cast<std::int64_t>(sample / grid_.nx)};
    for (HalfEdge h = first;;) {
      if (edge_function(index_of(mesh().origin(h)), index_of(mesh().dest(h)), p) == 0) {
        const FaceId g = mesh().face(mesh().twin(h));
        if (tri_.is_ghost(g) || worst_[g].error != worst_[f].error || worst_[g].sample != sample) return f;
        return sorted_corners(g) < sorted_corners(f) ? g : f;
      }
      h = mesh().next(h);
      if (h == first) return f;
    }
  }

  std::array<VertexId, 3> sorted_corners(FaceId f) const {
    const HalfEdge h = mesh().half_edge(f);
    std::array<VertexId, 3> k{mesh().origin(h), mesh().dest(h), mesh().apex(h)};
    std::sort(k.begin(), k.end());
    return k;
  }

  HalfEdge insert(std::uint32_t sample, HalfEdge hint) {
    // Each insertion takes a sample that is not yet a vertex, so a run ends after at most
    // nx * ny of them. A sample chosen twice would not end it (it once did, on a vertex a
    // rounding-level error off its own plane: triangle_scan.hpp), and would make the
    // hull's count in triangle_count() wrap: it is a bug, stopped here.
    if (used_[sample])
      throw std::logic_error("terrain: sample " + std::to_string(sample) + " chosen again: it is a vertex already");
    used_[sample] = true;
    samples_.push_back(sample);
    heights_.push_back(grid_.z[sample]);
    const VertexId v = tri_.add_point(sample_point(sample));
    // Recorded, the step is open already (record_worst); else insert() opens its own.
    const HalfEdge out = Rec::enabled ? tri_.insert_in_step(v, hint) : tri_.insert(v, hint);
    rec().elevation(v, heights_.back());
    // Delaunay insertion changes exactly the triangles round the new vertex.
    HalfEdge h = out;
    do {
      const FaceId f = mesh().face(h);
      if (!tri_.is_ghost(f)) measure(f);
      h = mesh().twin(mesh().prev(h));
    } while (h != out);
    border_vertices_ += on_border(sample);
    return out;
  }

  // The data structure has a ghost face on every hull edge; the hull is the grid's
  // rectangle, with an edge for every vertex on it: those it started with, and those
  // inserted on it since.
  std::size_t triangle_count() const { return mesh().face_count() - hull_vertices_ - border_vertices_; }
  bool in_window(std::size_t i, std::size_t j) const {
    const auto ii = static_cast<std::int64_t>(i), jj = static_cast<std::int64_t>(j);
    return ii >= window_.i_first && ii <= window_.i_last && jj >= window_.j_first && jj <= window_.j_last;
  }
  bool on_border(std::uint32_t s) const {
    const std::size_t i = s % grid_.nx, j = s / grid_.nx;
    return i == 0 || j == 0 || i == grid_.nx - 1 || j == grid_.ny - 1;
  }

  // The edge flips that raise the smallest 3D angle of the two triangles beside an edge
  // without raising their error past `bound`, until none is left. The planar Delaunay
  // property goes: on a terrain, a thin triangle in the plane may be a fine one on the
  // slope, and the other way round. Returns the number of flips.
  std::size_t improve_by_3d_flips(double bound) {
    std::vector<HalfEdge> stack;
    for (FaceId f = 0; f < mesh().face_capacity(); ++f) {
      if (!mesh().is_live(f) || tri_.is_ghost(f)) continue;
      const HalfEdge h = mesh().half_edge(f);
      for (const HalfEdge e : {h, mesh().next(h), mesh().prev(h)}) stack.push_back(e);
    }
    std::size_t flips = 0;
    // Each flip raises the pair's smallest angle, so the process ends; the budget only
    // bounds its time on a pathological grid.
    for (std::size_t budget = 10 * stack.size() + 16; !stack.empty() && budget > 0; --budget) {
      const HalfEdge h = stack.back();
      stack.pop_back();
      const HalfEdge t = mesh().twin(h);
      const FaceId f = mesh().face(h), g = mesh().face(t);
      if (!mesh().is_live(f) || !mesh().is_live(g) || tri_.is_ghost(f) || tri_.is_ghost(g)) continue;
      // abc and bad, the quadrilateral a d b c; the flip makes adc and dbc.
      const VertexId a = mesh().origin(h), b = mesh().dest(h), c = mesh().apex(h), d = mesh().apex(t);
      if (edge_function(index_of(a), index_of(d), index_of(c)) <= 0 ||
          edge_function(index_of(d), index_of(b), index_of(c)) <= 0)
        continue;  // not convex in the plane
      const double before = std::min(smallest_angle_3d(a, b, c), smallest_angle_3d(b, a, d));
      const double after = std::min(smallest_angle_3d(a, d, c), smallest_angle_3d(d, b, c));
      if (!(after > before * (1 + 1e-9))) continue;
      const double error_before = std::max(worst_[f].error, worst_[g].error);
      if (std::max(scan_worst(a, d, c).error, scan_worst(d, b, c).error) > std::max(bound, error_before)) continue;
      if (flips == 0) rec().phase_begin(replay::Phase::improve);
      rec().step_begin(mesh(), replay::StepKind::flip_3d, a, b);
      const HalfEdge n = tri_.flip(h, replay::FlipReason::angles_3d);
      ++flips;
      for (const HalfEdge e : {n, mesh().twin(n)}) {
        measure(mesh().face(e));
        stack.push_back(mesh().next(e));
        stack.push_back(mesh().prev(e));
      }
    }
    if (flips > 0) rec().phase_end(replay::Phase::improve);
    return flips;
  }

  // The improvement (TerrainOptions::improve): in rounds, vertex ids ascending, every vertex
  // off the border whose removal keeps every sample of the new triangles within `bound` and
  // does not lower the smallest 3D angle round it is removed (the hole filled with its
  // Delaunay triangulation in the plane, vertex_removal.hpp), until a round removes none or
  // after three. Border vertices are on the hull, which the remover leaves alone. Returns
  // how many went. On the corpus at 1% and 0.5% it takes lepp-surface from 1.04-1.14 times
  // greedy's triangles to 0.96-1.03, and its share under 20 degrees down by a third.
  std::size_t remove_vertices(double bound) {
    VertexRemover<Mesh, Rec> remover(tri_);
    removed_.assign(samples_.size(), false);
    std::size_t removed = 0;
    rec().phase_begin(replay::Phase::improve);
    for (int round = 0; round < 3; ++round) {
      const std::size_t before = removed;
      for (VertexId v = static_cast<VertexId>(hull_vertices_); v < samples_.size(); ++v) {
        if (removed_[v]) continue;
        const HalfEdge out = mesh().vertex_half_edge(v);
        if (out == kNone || !remover.plan(out) || !removal_keeps_the_bounds(remover, bound)) continue;
        made_.assign(remover.new_triangles().begin(), remover.new_triangles().end());
        rec().step_begin(mesh(), replay::StepKind::remove_vertex, v);
        remover.apply();
        removed_[v] = true;
        ++removed;
        for (const auto& t : made_)
          if (const HalfEdge f = tri_.find_edge(t[0], t[1]); f != kNone && mesh().apex(f) == t[2]) measure(mesh().face(f));
      }
      if (removed == before) break;
    }
    rec().phase_end(replay::Phase::improve);
    return removed;
  }

  // Whether the planned removal keeps every sample of its new triangles within `bound` and
  // the smallest 3D angle round the vertex where it was or higher.
  bool removal_keeps_the_bounds(VertexRemover<Mesh, Rec>& remover, double bound) {
    double old_smallest = 4.0, new_smallest = 4.0;  // radians
    for (const auto& t : remover.old_triangles()) old_smallest = std::min(old_smallest, smallest_angle_3d(t[0], t[1], t[2]));
    for (const auto& t : remover.new_triangles()) {
      new_smallest = std::min(new_smallest, smallest_angle_3d(t[0], t[1], t[2]));
      if (new_smallest < old_smallest) return false;
    }
    for (const auto& t : remover.new_triangles()) {
      VertexId a = t[0], b = t[1], c = t[2];
      while (a > b || a > c) std::tie(a, b, c) = std::tuple(b, c, a);  // as scan_worst measures
      if (scan_worst(a, b, c).error > bound) return false;
    }
    return true;
  }

  // The smallest angle of triangle abc in 3D, in radians: the one with the largest cosine.
  double smallest_angle_3d(VertexId a, VertexId b, VertexId c) const {
    const auto position = [&](VertexId v) {
      const Point p = metres(v);
      return std::array<double, 3>{p.x, p.y, static_cast<double>(heights_[v])};
    };
    const std::array<double, 3> p[3] = {position(a), position(b), position(c)};
    double largest_cos = -1.0;
    for (int k = 0; k < 3; ++k) {
      const auto &o = p[k], &u = p[(k + 1) % 3], &w = p[(k + 2) % 3];
      const double x[3] = {u[0] - o[0], u[1] - o[1], u[2] - o[2]}, y[3] = {w[0] - o[0], w[1] - o[1], w[2] - o[2]};
      const double dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
      const double norms = std::sqrt((x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) * (y[0] * y[0] + y[1] * y[1] + y[2] * y[2]));
      largest_cos = std::max(largest_cos, dot / norms);
    }
    return std::acos(std::clamp(largest_cos, -1.0, 1.0));
  }

  // Lepp-surface's sample for the worst triangle f. Its longest-edge propagating path
  // (edges measured in 3D) ends at a terminal edge, the longest of the one or two
  // triangles beside it: a point there splits long edges and leaves no sliver. If a
  // terminal triangle still misses the bound, its worst sample goes in (error-driven, as
  // greedy, but where the split keeps the shapes); else the sample nearest the terminal
  // point (shape-driven, as the paper). f's own worst sample when that one is already a
  // vertex or has no data.
  Choice lepp_sample(FaceId f, TerrainReport& report) {
    const HalfEdge e = terminal_edge(f);
    const FaceId near = mesh().face(e), far = mesh().face(mesh().twin(e));
    if constexpr (Rec::enabled) {
      lepp_vertices_.clear();
      for (const FaceId g : lepp_faces_) {
        const HalfEdge h = mesh().half_edge(g);
        lepp_vertices_.insert(lepp_vertices_.end(), {mesh().origin(h), mesh().dest(h), mesh().apex(h)});
      }
      rec().lepp_path(mesh().origin(e), mesh().dest(e), tri_.is_ghost(far) ? 1 : 2, lepp_vertices_);
    }
    const FaceWorst& worst =
        tri_.is_ghost(far) || worst_[near].error >= worst_[far].error ? worst_[near] : worst_[far];
    if (worst.error > options_.max_error) {
      ++report.terminal_worst;
      return {worst.sample, &worst == &worst_[near] ? near : far, replay::SampleChoice::terminal_worst};
    }
    const auto p = terminal_point(e);
    terminal_point_ = {p[0], p[1]};
    const double fi = std::round(p[0] / scale_.dx), fj = std::round(p[1] / scale_.dy);
    const std::size_t i = static_cast<std::size_t>(std::clamp(fi, 0.0, static_cast<double>(grid_.nx - 1)));
    const std::size_t j = static_cast<std::size_t>(std::clamp(fj, 0.0, static_cast<double>(grid_.ny - 1)));
    const std::uint32_t s = static_cast<std::uint32_t>(i + j * grid_.nx);
    if (used_[s] || !grid_.has_data(i, j) || !in_window(i, j)) return {worst_[f].sample, f, replay::SampleChoice::own_worst};
    ++report.terminal_points;
    return {s, near, replay::SampleChoice::terminal_point};
  }

  // The terminal edge of f's Lepp; recorded, the path's faces are kept in lepp_faces_.
  HalfEdge terminal_edge(FaceId f) {
    HalfEdge e = longest_edge(mesh().half_edge(f));
    if constexpr (Rec::enabled) lepp_faces_.assign(1, f);
    while (true) {
      const HalfEdge across = mesh().twin(e);
      const FaceId g = mesh().face(across);
      if (tri_.is_ghost(g)) return e;  // a border edge: one terminal triangle
      if constexpr (Rec::enabled) lepp_faces_.push_back(g);
      const HalfEdge longest = longest_edge(mesh().half_edge(g));
      if (longest == across) return e;  // the two share their longest edge
      e = longest;
    }
  }

  std::array<double, 2> terminal_point(HalfEdge e) const {
    const Point& a = tri_.point(mesh().origin(e));
    const Point& b = tri_.point(mesh().dest(e));
    if (options_.terminal_point == TerminalPoint::midpoint) return {(a.x + b.x) / 2, (a.y + b.y) / 2};
    const Point& c = tri_.point(mesh().apex(e));
    const HalfEdge t = mesh().twin(e);
    if (tri_.is_ghost(mesh().face(t))) return {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    // The centroid of the quadrilateral the two terminal triangles make: their centroids
    // weighted by their areas.
    const Point& d = tri_.point(mesh().apex(t));
    const double area_abc = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    const double area_bad = std::abs((a.x - b.x) * (d.y - b.y) - (a.y - b.y) * (d.x - b.x));
    const double total = area_abc + area_bad;
    return {(area_abc * (a.x + b.x + c.x) + area_bad * (b.x + a.x + d.x)) / (3 * total),
            (area_abc * (a.y + b.y + c.y) + area_bad * (b.y + a.y + d.y)) / (3 * total)};
  }

  // The longest edge of h's face in 3D; ties go to the edge with the smaller vertex ids, so
  // that both faces of an edge agree and a path cannot cycle.
  HalfEdge longest_edge(HalfEdge h) const {
    HalfEdge best = h;
    auto best_key = edge_key(h);
    for (HalfEdge e = mesh().next(h); e != h; e = mesh().next(e)) {
      const auto key = edge_key(e);
      if (key > best_key) {
        best = e;
        best_key = key;
      }
    }
    return best;
  }
  std::array<double, 3> edge_key(HalfEdge e) const {
    const VertexId u = mesh().origin(e), w = mesh().dest(e);
    const Point p = metres(u), q = metres(w);
    const double dz = static_cast<double>(heights_[u]) - heights_[w];
    const double length2 = (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + dz * dz;
    return {length2, -static_cast<double>(std::min(u, w)), -static_cast<double>(std::max(u, w))};
  }

  // The TIN, its vertices renumbered past those the improvement removed.
  Tin result() const {
    Tin tin;
    std::vector<std::uint32_t> renumber(samples_.size());
    for (std::size_t v = 0; v < samples_.size(); ++v) {
      if (!removed_.empty() && removed_[v]) continue;
      renumber[v] = static_cast<std::uint32_t>(tin.samples.size());
      tin.samples.push_back(samples_[v]);
      tin.heights.push_back(heights_[v]);
    }
    tin.triangles.reserve(mesh().face_count());
    for (FaceId f = 0; f < mesh().face_capacity(); ++f) {
      if (!mesh().is_live(f) || tri_.is_ghost(f)) continue;
      const HalfEdge h = mesh().half_edge(f);
      tin.triangles.push_back({renumber[mesh().origin(h)], renumber[mesh().dest(h)], renumber[mesh().apex(h)]});
    }
    return tin;
  }

  const HeightGrid& grid_;
  const TerrainOptions& options_;
  const BorderVertices* border_;         // null: the four corners start the TIN
  PlanarScale scale_;                    // the triangulation's coordinates: samples scaled exactly
  Triangulation<Mesh, Rec> tri_;
  std::vector<bool> used_;               // by sample: already a vertex
  std::vector<bool> removed_;            // by vertex: removed by the improvement (empty: none)
  std::vector<std::array<VertexId, 3>> made_;  // the triangles a removal makes
  SampleWindow window_;                  // the samples that may be searched and inserted
  std::size_t hull_vertices_;            // the vertices the TIN starts with, all on the hull
  std::vector<std::uint32_t> samples_;   // by vertex
  std::vector<float> heights_;           // by vertex (a corner without data borrows one)
  std::vector<FaceWorst> worst_;         // by face
  std::priority_queue<Worst> queue_;
  std::size_t border_vertices_ = 0;     // inserted on the grid's border (never with border_)
  // Recording only: the Lepp path's faces and their vertices, and the terminal point.
  std::vector<FaceId> lepp_faces_;
  std::vector<VertexId> lepp_vertices_;
  Point terminal_point_{0, 0};
};

}  // namespace meshstep::terrain::detail
