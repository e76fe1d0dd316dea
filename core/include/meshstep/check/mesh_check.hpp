// An independent checker for triangle meshes. It recomputes everything from the plain arrays
// of a TriMesh with exact predicates and trusts nothing the triangulator may have cached, so
// the tests of every triangulator and the `meshstep check` command can rely on it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep {

struct CheckOptions {
  // Check the constrained Delaunay property: every edge shared by two triangles and not
  // listed in mesh.segments is locally Delaunay (exact incircle; cocircular is accepted).
  bool delaunay = true;
  // Only the first max_problems descriptions are kept; problem_count still counts them all.
  std::size_t max_problems = 20;
};

struct CheckReport {
  bool ok = true;
  // Human readable, one per problem. Triangle and vertex numbers are 0-based indices plus
  // mesh.first_index (as in the .ele/.node files); input segments use input.first_index.
  std::vector<std::string> problems;
  std::size_t problem_count = 0;
};

// Checks, in order: indices and duplicates, strict counterclockwise orientation, edge
// manifoldness, no overlap (winding around interior vertices, no vertex inside a triangle
// or on the interior of its edges), constrained Delaunay (if options.delaunay), neighbors
// (if present) and, when input is given: input vertices kept first and bit for bit; input
// segments covered by chains of mesh edges (listed in mesh.segments when it is not empty),
// except where a segment lies outside the meshed domain and passes through no triangle;
// no hole point inside a remaining triangle. Later stages skip triangles that failed the
// basic ones so that one defect is not reported many times over.
CheckReport check_mesh(const TriMesh& mesh, const Pslg* input = nullptr,
                       const CheckOptions& options = {});

}  // namespace meshstep
