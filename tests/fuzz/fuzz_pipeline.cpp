// The whole pipeline on a .poly: read, triangulate (the first byte picks the data
// structure, the insertion and whether the convex hull is kept), check with the full
// checker; then refine with a small cap and check again. A refusal is an answer; an
// internal error or a mesh the checker rejects is a finding.
#include "fuzz_support.hpp"
#include "meshstep/check/mesh_check.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"

using namespace meshstep;

namespace {

void expect_valid(const TriMesh& mesh, const Pslg& input, const char* what) {
  const CheckReport check = check_mesh(mesh, &input);
  if (!check.ok) fuzz::finding(std::string(what) + " wrote an invalid mesh: " + check.problems.front());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::uint8_t choice = data[0];
  ++data, --size;
  Pslg input;
  try {
    input = io::read_poly(fuzz::write_input(data, size, ".poly"));
  } catch (const InputError&) {
    return 0;
  }
  if (input.points.size() > 300 || input.segments.size() > 300) return 0;  // keep each run short
  fuzz::refusals_allowed([&] {
    TriangulateOptions t;
    t.data_structure = choice & 1 ? DataStructure::dcel : DataStructure::tds;
    t.insertion = choice & 2 ? Insertion::cavity : Insertion::flip;
    t.convex_hull = (choice & 4) != 0;
    expect_valid(triangulate(input, t), input, "triangulate");

    static const char* const kAlgorithms[] = {"circumcenter", "offcenter", "lepp-centroid", "lepp-bisection"};
    RefineOptions r = options_for(*find_algorithm(kAlgorithms[(choice >> 3) % 4]));
    r.triangulate = t;
    r.criteria.min_angle_deg = 25.0;
    r.criteria.max_area = 0.0;
    r.criteria.max_steiner = 200;
    expect_valid(refine(input, r), input, "refine");
  });
  return 0;
}
