// A command's full check of a small mesh before it writes it (app/cli/mesh_output.hpp): a
// mesh the checker rejects is a bug, refused as std::logic_error (an internal error, nothing
// written); a valid one passes; the input's segments are held against the mesh.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "mesh_output.hpp"

namespace meshstep {
namespace {

// The unit square as two triangles, split along (0,0)-(1,1).
TriMesh square() {
  TriMesh m;
  m.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(CheckBeforeWriting, AValidMeshPasses) {
  EXPECT_NO_THROW(app::check_before_writing(square(), nullptr, true));
}

TEST(CheckBeforeWriting, AVertexLeftInsideATriangleIsAnInternalError) {
  TriMesh m = square();
  m.points.push_back({0.75, 0.25});  // inside triangle 0, a corner of none
  Pslg input;
  input.points = m.points;
  try {
    app::check_before_writing(m, &input, true);
    FAIL() << "no error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("fails its check"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("inside triangle"), std::string::npos) << e.what();
  }
}

TEST(CheckBeforeWriting, AnInputSegmentNotCoveredIsAnInternalError) {
  Pslg input;
  input.points = square().points;
  input.segments = {{1, 3, 0}};  // the other diagonal
  EXPECT_THROW(app::check_before_writing(square(), &input, true), std::logic_error);
  EXPECT_NO_THROW(app::check_before_writing(square(), nullptr, true));  // without the input, valid
}

TEST(CheckBeforeWriting, TheDelaunayPropertyIsCheckedOnlyWhenAsked) {
  TriMesh m;  // a kite split along its long diagonal: the edge (0,2) is not locally Delaunay
  m.points = {{0, 0}, {1, -0.2}, {2, 0}, {1, 0.2}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_THROW(app::check_before_writing(m, nullptr, true), std::logic_error);
  EXPECT_NO_THROW(app::check_before_writing(m, nullptr, false));  // a bisection run's mesh
}

}  // namespace
}  // namespace meshstep
