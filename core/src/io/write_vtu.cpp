// write_vtu (mesh_formats.hpp): VTK's XML UnstructuredGrid, ASCII (as VTK's "VTK File
// Formats" document describes it): points, then cells as connectivity, offsets and types,
// then the cell and point data. ASCII keeps the coordinates exact and the file readable;
// ParaView and meshio read it as they read the binary form.
#include <cmath>

#include "io/atomic_writer.hpp"
#include "io/planar_mesh_check.hpp"
#include "meshstep/io/mesh_formats.hpp"
#include "meshstep/refine/quality.hpp"

namespace meshstep::io {
namespace {

constexpr int kVtkTriangle = 5;

// Values a line each, inside a <DataArray>.
template <class Each>
void data_array(detail::AtomicWriter& w, const char* type, const char* name, int components, std::size_t count,
                Each each) {
  w.text("        <DataArray type=\"");
  w.text(type);
  w.text("\" Name=\"");
  w.text(name);
  w.text("\"");
  if (components > 1) {
    w.text(" NumberOfComponents=\"");
    w.integer(components);
    w.text("\"");
  }
  w.text(" format=\"ascii\">\n");
  for (std::size_t i = 0; i < count; ++i) {
    each(i);
    w.ch('\n');
  }
  w.text("        </DataArray>\n");
}

}  // namespace

void write_vtu(const std::string& path, const TriMesh& mesh) {
  detail::check_planar_mesh(path, mesh);
  const std::size_t n = mesh.points.size(), cells = mesh.triangles.size();
  // The smallest angle of each triangle, in degrees (0 for a degenerate one).
  std::vector<double> min_angle(cells);
  for (std::size_t t = 0; t < cells; ++t) {
    const auto& tri = mesh.triangles[t];
    const quality::Shape s = quality::shape(mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]);
    min_angle[t] = s.area != 0.0 ? s.min_angle_deg() : 0.0;
  }

  detail::AtomicWriter w(path);
  w.text("<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
         "    <Piece NumberOfPoints=\"");
  w.integer(static_cast<std::int64_t>(n));
  w.text("\" NumberOfCells=\"");
  w.integer(static_cast<std::int64_t>(cells));
  w.text("\">\n      <Points>\n");
  data_array(w, "Float64", "points", 3, n, [&](std::size_t i) {
    w.real(mesh.points[i].x);
    w.ch(' ');
    w.real(mesh.points[i].y);
    w.text(" 0");
  });
  w.text("      </Points>\n      <Cells>\n");
  data_array(w, "Int64", "connectivity", 1, cells, [&](std::size_t t) {
    const auto& tri = mesh.triangles[t];
    w.integer(tri[0]);
    w.ch(' ');
    w.integer(tri[1]);
    w.ch(' ');
    w.integer(tri[2]);
  });
  data_array(w, "Int64", "offsets", 1, cells, [&](std::size_t t) { w.integer(3 * static_cast<std::int64_t>(t + 1)); });
  data_array(w, "UInt8", "types", 1, cells, [&](std::size_t) { w.integer(kVtkTriangle); });
  w.text("      </Cells>\n      <CellData Scalars=\"quality\">\n");
  data_array(w, "Float64", "region", 1, cells, [&](std::size_t t) { w.real(detail::region_of(mesh, t)); });
  data_array(w, "Float64", "min_angle", 1, cells, [&](std::size_t t) { w.real(min_angle[t]); });
  data_array(w, "Float64", "quality", 1, cells, [&](std::size_t t) { w.real(min_angle[t] / 60.0); });
  w.text("      </CellData>\n      <PointData Scalars=\"marker\">\n");
  data_array(w, "Int32", "marker", 1, n,
             [&](std::size_t i) { w.integer(mesh.vertex_markers.empty() ? 0 : mesh.vertex_markers[i]); });
  w.text("      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  w.commit();
}

}  // namespace meshstep::io
