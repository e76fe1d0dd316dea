// check_mesh: runs the stages in order. Stages that index by vertex or by edge only run
// once the indices are known to be safe for them.
#include "meshstep/check/mesh_check.hpp"

#include <cmath>

#include "check/stages.hpp"
#include "meshstep/geometry/magnitudes.hpp"
#include "meshstep/release.hpp"

namespace meshstep {

namespace {

CheckReport run_stages(const TriMesh& mesh, const Pslg* input, const CheckOptions& options) {
  using namespace check_detail;
  ProblemLog log(options.max_problems);
  MeshFacts facts{mesh, log, {}, {}, std::nullopt, {}, std::nullopt};
  check_indices(facts);
  check_orientation(facts);
  std::vector<std::uint8_t> usable(mesh.triangles.size());
  for (std::size_t t = 0; t < usable.size(); ++t) usable[t] = facts.usable(t);
  facts.edges.emplace(mesh, usable);
  release(usable);
  facts.mark_listed_edges();
  check_edge_use(facts);
  check_winding(facts);
  check_vertices_in_triangles(facts);
  if (options.delaunay) check_delaunay(facts);
  check_neighbors(facts);
  if (input != nullptr) {
    check_input_vertices(facts, *input);
    check_input_segments(facts, *input);
    check_input_holes(facts, *input);
  }
  return std::move(log).take();
}

void scale(std::vector<Point>& points, int e) {
  for (Point& p : points) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
}

}  // namespace

CheckReport check_mesh(const TriMesh& mesh, const Pslg* input, const CheckOptions& options) {
  using namespace check_detail;
  if (mesh.triangles.size() > EdgeTable::kMaxTriangles ||
      mesh.points.size() >= static_cast<std::size_t>(kNoIndex)) {
    ProblemLog log(options.max_problems);
    log.add([&] {
      return "the mesh is too large for the checker (" + std::to_string(mesh.points.size()) +
             " vertices, " + std::to_string(mesh.triangles.size()) + " triangles)";
    });
    return std::move(log).take();
  }
  // The predicates are exact within a window of magnitudes (geometry/magnitudes.hpp): a mesh
  // outside it is checked scaled into it by a power of two, which changes no decision.
  std::vector<Point> all(mesh.points);
  if (input) {
    all.insert(all.end(), input->points.begin(), input->points.end());
    all.insert(all.end(), input->holes.begin(), input->holes.end());
  }
  const Magnitudes m = magnitudes(all);
  release(all);
  if (!m.within_span()) {
    ProblemLog log(options.max_problems);
    log.add([&] {
      return "its nonzero coordinates span more than 2^" + std::to_string(kSpanExponent) +
             " in magnitude: too wide to be checked exactly (meshstep refuses such inputs)";
    });
    return std::move(log).take();
  }
  const int e = m.scale_exponent();
  if (e == 0) return run_stages(mesh, input, options);
  TriMesh scaled = mesh;
  scale(scaled.points, e);
  if (!input) return run_stages(scaled, nullptr, options);
  Pslg scaled_input = *input;
  scale(scaled_input.points, e);
  scale(scaled_input.holes, e);
  return run_stages(scaled, &scaled_input, options);
}

}  // namespace meshstep
