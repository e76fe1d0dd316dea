// The refine() front door: checks the criteria, triangulates, refines, converts.
#include "meshstep/refine/refine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>

#include "../delaunay/builder.hpp"
#include "meshstep/error.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
#include "meshstep/geometry/triangle_field.hpp"
#include "meshstep/refine/registry.hpp"
#include "lepp_bisection.hpp"
#include "refiner.hpp"

namespace meshstep {
namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

void check(const RefineCriteria& c) {
  if (const std::string problem = criteria_problem(c); !problem.empty()) throw InputError(problem);
}

// The criteria in the triangulation's scaled coordinates.
detail::ScaledCriteria scaled(const RefineCriteria& c, int exponent, const TriangleField& regions,
                              const std::optional<RefineRegion>& region) {
  detail::ScaledCriteria s;
  s.region = region ? &*region : nullptr;
  s.unscale = std::ldexp(1.0, -exponent);
  const double sin_min = std::sin(quality::radians(c.min_angle_deg));
  s.sin2_min_angle = sin_min * sin_min;
  s.cos_max_angle = c.max_angle_deg >= 180.0 ? -1.0 : std::cos(quality::radians(c.max_angle_deg));
  s.max_aspect = c.max_aspect;
  s.max_area = c.max_area > 0.0 ? std::ldexp(c.max_area, 2 * exponent) : 0.0;
  if (c.size) {
    s.size = [size = c.size, exponent](const Point& p) {
      return std::ldexp(size({std::ldexp(p.x, -exponent), std::ldexp(p.y, -exponent)}), exponent);
    };
  }
  // Off-centers aim at the radius-edge ratio of the angle bound (Ungor), or of 20.7 degrees
  // when only size bounds are set.
  const double angle = c.min_angle_deg > 0.0 ? c.min_angle_deg : 20.7;
  s.offcenter_beta = 0.5 / std::sin(quality::radians(angle));
  const double lens_cos = std::cos(quality::radians(lens_angle_deg(c)));
  s.lens_cos2 = lens_cos * lens_cos;
  // The smaller of the regions' bound and the caller's, where either is set.
  const bool own = !regions.empty();
  if (own || c.max_area_for) {
    s.max_area_for = [own, &regions, theirs = c.max_area_for, exponent](const Point& a, const Point& b, const Point& p) {
      double bound = own ? regions.min_positive_over(a, b, p, -1.0) : -1.0;
      if (theirs) {
        const auto user = [exponent](const Point& q) { return Point{std::ldexp(q.x, -exponent), std::ldexp(q.y, -exponent)}; };
        const double t = std::ldexp(theirs(user(a), user(b), user(p)), 2 * exponent);
        if (t > 0.0) bound = bound > 0.0 ? std::min(bound, t) : t;
      }
      return bound;
    };
  }
  s.max_triangles = c.max_triangles;
  s.max_steiner = c.max_steiner;
  return s;
}

template <class Rec>
void record_empty_phase(Rec& rec, replay::Phase phase) {
  rec.phase_begin(phase);
  rec.phase_end(phase);
}

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

template <TriangleMesh Mesh, class Rec>
TriMesh refine_with(Pslg& input, std::span<const RefineOptions> operations, std::span<RefineReport> reports,
                    const std::function<void(std::size_t)>& before, Rec rec) {
  const RefineOptions& first = operations.front();
  const auto start = std::chrono::steady_clock::now();
  detail::Builder<Mesh, Rec> builder(input, first.triangulate, reports.front().triangulation, std::move(rec));
  builder.build();
  reports.front().triangulate_ms = ms_since(start);
  TriangleField regions;  // the regions' own area bounds, on the starting mesh
  if (first.regional_max_area) builder.region_area_field(regions);
  const TriangleField no_regions;
  const auto steiner_so_far = [&] {
    return builder.triangulation().points().size() - builder.input_count() -
           builder.triangulation().removed_vertices().size();
  };
  for (std::size_t i = 0; i < operations.size(); ++i) {
    const RefineOptions& options = operations[i];
    RefineReport& report = reports[i];
    if (before) before(i);
    const auto refine_start = std::chrono::steady_clock::now();
    // The first operation counts the triangulation's own Steiner vertices (segment crossings).
    const std::size_t steiner_before = i == 0 ? 0 : steiner_so_far();
    const std::vector<RefinePhase> phases =
        options.phases.empty() ? std::vector<RefinePhase>{{"refine", options.criteria}} : options.phases;
    // One algorithm object for every phase of an operation: what it knows of the boundary
    // (which segment each split vertex lies on, the small input angles) carries over. The
    // next operation starts from the boundary this one left, each subsegment a segment.
    const auto refine_by = [&]<class Algorithm>(std::type_identity<Algorithm>) {
      Algorithm algorithm(builder.triangulation(), builder.boundary_segments(), builder.input_count(), options);
      for (const RefinePhase& phase : phases) {
        if (report.stopped_by_cap) {
          // The phases a cap cut off are recorded empty, so that a log's phases follow
          // from its operations alone (replay/run_header.hpp).
          record_empty_phase(builder.triangulation().recorder(), replay::Phase::refine);
          if (options.improve) record_empty_phase(builder.triangulation().recorder(), replay::Phase::improve);
          continue;
        }
        const auto phase_start = std::chrono::steady_clock::now();
        algorithm.set_criteria(
            scaled(phase.criteria, builder.exponent(), options.regional_max_area ? regions : no_regions, options.region));
        algorithm.run(report);
        report.phase_ms.emplace_back(phase.name, ms_since(phase_start));
      }
      builder.set_boundary_segments(algorithm.boundary());
    };
    if (options.insertion == RefineInsertion::bisection)
      refine_by(std::type_identity<detail::LeppBisector<Mesh, Rec>>{});
    else
      refine_by(std::type_identity<detail::Refiner<Mesh, Rec>>{});
    // What this operation added, net of what it removed again.
    report.steiner_vertices = steiner_so_far() - steiner_before;
    report.refine_ms = ms_since(refine_start);
  }
  builder.reassign_regions();
  const auto finish_start = std::chrono::steady_clock::now();
  TriMesh out = builder.finish();
  reports.back().refine_ms += ms_since(finish_start);
  return out;
}

template <TriangleMesh Mesh>
TriMesh run(Pslg& input, std::span<const RefineOptions> operations, std::span<RefineReport> reports,
            const std::function<void(std::size_t)>& before) {
  const TriangulateOptions& t = operations.front().triangulate;
  if (!t.record) return refine_with<Mesh>(input, operations, reports, before, replay::NullRecorder{});
  replay::Recorder recorder(*t.record);
  if (t.observe_steps) recorder.observe_steps(t.observe_steps);
  return refine_with<Mesh>(input, operations, reports, before, std::move(recorder));
}

// Every set of criteria a run will use: its phases', or its one.
std::vector<const RefineCriteria*> criteria_of(const RefineOptions& o) {
  if (o.phases.empty()) return {&o.criteria};
  std::vector<const RefineCriteria*> all;
  for (const RefinePhase& p : o.phases) all.push_back(&p.criteria);
  return all;
}

// Bisection keeps shapes and only makes triangles smaller: it takes size criteria (a global
// or per-triangle area, a size function, or the input's regional areas).
void check_bisection(const RefineOptions& o, const RefineCriteria& c, const Pslg& input) {
  const std::string who = "longest-edge bisection (" + o.algorithm + ")";
  if (c.min_angle_deg > 0.0 || c.max_angle_deg < 180.0 || c.max_aspect > 0.0)
    throw InputError(who + " cannot improve angles or aspect ratios: give it --max-area or --size only");
  const bool regional = o.regional_max_area && has_regional_area_bounds(input);
  if (c.max_area <= 0.0 && !c.size && !c.max_area_for && !regional)
    throw InputError(who + " needs a size bound: --max-area or --size");
}

}  // namespace

std::string criteria_problem(const RefineCriteria& c) {
  if (!(c.min_angle_deg >= 0.0 && c.min_angle_deg < 60.0))
    return "minimum angle " + number(c.min_angle_deg) + " is out of range (0 to below 60 degrees)";
  if (!(c.max_angle_deg > 60.0 && c.max_angle_deg <= 180.0))
    return "maximum angle " + number(c.max_angle_deg) + " is out of range (above 60 to 180 degrees)";
  if (!(c.max_aspect == 0.0 || c.max_aspect >= 2.0 / std::sqrt(3.0)))
    return "maximum aspect ratio " + number(c.max_aspect) +
           " is below the equilateral triangle's 1.1547 (longest edge over shortest altitude)";
  if (!(c.max_area >= 0.0) || !std::isfinite(c.max_area))
    return "maximum area " + number(c.max_area) + " must be a positive number";
  return "";
}

TriMesh refine_chain(Pslg input, std::span<const RefineOptions> operations, std::span<RefineReport> reports,
                     const std::function<void(std::size_t)>& before) {
  if (operations.empty()) throw InputError("a refinement needs at least one operation");
  if (reports.size() != operations.size()) throw std::invalid_argument("refine_chain: one report per operation");
  for (const RefineOptions& options : operations) {
    // Bisection cuts a triangle across the terminal edge its path reaches, whatever it is:
    // a segment it may not cut would leave the triangles on the path unrefinable.
    if (options.insertion == RefineInsertion::bisection && options.segment_splits != SegmentSplits::all)
      throw InputError("longest-edge bisection (" + options.algorithm + ") splits whatever terminal edge it reaches, " +
                       "segments included: it cannot keep segments whole (split segments " +
                       to_string(options.segment_splits) + "); use a Delaunay algorithm");
    for (const RefineCriteria* c : criteria_of(options)) {
      check(*c);
      if (options.insertion == RefineInsertion::bisection) check_bisection(options, *c, input);
    }
  }
  detail::validate(input);
  for (RefineReport& r : reports) r = RefineReport{};  // a caller's report may hold an earlier run's
  switch (operations.front().triangulate.data_structure) {
    case DataStructure::tds: return run<Tds>(input, operations, reports, before);
    case DataStructure::dcel: return run<Dcel>(input, operations, reports, before);
  }
  throw std::logic_error("unknown data structure");
}

TriMesh refine(Pslg input, const RefineOptions& options, RefineReport* report) {
  RefineReport local;
  return refine_chain(std::move(input), std::span<const RefineOptions>(&options, 1),
                      std::span<RefineReport>(report ? report : &local, 1));
}

// Its record's name (refine/registry.hpp), which is a literal: the pointer stays valid.
const char* to_string(Selection s) { return selection_info(s).name.data(); }
const char* to_string(SegmentSplits s) {
  return s == SegmentSplits::all ? "all" : s == SegmentSplits::interior ? "interior" : "none";
}
const char* to_string(RefineInsertion i) { return i == RefineInsertion::bisection ? "bisection" : "delaunay"; }

double lens_angle_deg(const RefineCriteria& c) {
  // Without an angle bound nothing caps how flat a triangle by a segment may be: the circle.
  double angle = c.min_angle_deg > 0.0 ? 180.0 - 2.0 * c.min_angle_deg : 90.0;
  // A point that sees a segment at more than the largest angle allowed would only make a
  // triangle that has to go again (and another, and another: a 130-degree lens under a
  // 120-degree bound never ended); an aspect bound R allows at most 2 atan(R / 2) there.
  if (c.max_angle_deg < 180.0) angle = std::min(angle, c.max_angle_deg);
  if (c.max_aspect > 0.0) angle = std::min(angle, 2.0 * quality::degrees(std::atan(c.max_aspect / 2.0)));
  return std::max(90.0, angle);
}

const char* to_string(RefineOrder o) {
  return o == RefineOrder::smallest_first ? "smallest" : o == RefineOrder::worst_first ? "worst" : "fifo";
}

}  // namespace meshstep
