// check_mesh: runs the stages in order. Stages that index by vertex or by edge only run
// once the indices are known to be safe for them.
#include "meshstep/check/mesh_check.hpp"

#include "check/stages.hpp"

namespace meshstep {

CheckReport check_mesh(const TriMesh& mesh, const Pslg* input, const CheckOptions& options) {
  using namespace check_detail;
  ProblemLog log(options.max_problems);
  if (mesh.triangles.size() > EdgeTable::kMaxTriangles ||
      mesh.points.size() >= static_cast<std::size_t>(kNoIndex)) {
    log.add([&] {
      return "the mesh is too large for the checker (" + std::to_string(mesh.points.size()) +
             " vertices, " + std::to_string(mesh.triangles.size()) + " triangles)";
    });
    return std::move(log).take();
  }
  MeshFacts facts{mesh, log, {}, {}, std::nullopt, {}, std::nullopt};
  check_indices(facts);
  check_orientation(facts);
  std::vector<std::uint8_t> usable(mesh.triangles.size());
  for (std::size_t t = 0; t < usable.size(); ++t) usable[t] = facts.usable(t);
  facts.edges.emplace(mesh, usable);
  usable = {};
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

}  // namespace meshstep
