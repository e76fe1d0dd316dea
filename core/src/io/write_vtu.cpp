// write_vtu (mesh_formats.hpp): VTK's XML UnstructuredGrid (as VTK's "VTK File Formats"
// document describes it), its arrays in binary: the XML names each array and its offset,
// then one <AppendedData encoding="raw"> section holds them, each as a UInt64 byte count and
// its values in the machine's byte order (which the header names). Binary keeps every double
// exact as the ASCII form's shortest round-trip text did, at half the size and a third of
// the time (docs/formats.md, Costs); ParaView and meshio read it.
#include <bit>
#include <cstdint>
#include <functional>
#include <vector>

#include "io/atomic_writer.hpp"
#include "io/planar_mesh_check.hpp"
#include "meshstep/io/mesh_formats.hpp"
#include "meshstep/refine/quality.hpp"

namespace meshstep::io {
namespace {

constexpr std::uint8_t kVtkTriangle = 5;

// One array of the file: its XML attributes, how many bytes it holds, and the function that
// writes those bytes.
struct VtuArray {
  const char* type;  // VTK's name: Float64, Int64, Int32, UInt8
  const char* name;
  int components;
  std::uint64_t bytes;
  std::function<void(detail::AtomicWriter&)> write;
};

// The values of `count` items (each(i, put) puts item i's), through a buffer written a block
// at a time.
template <class T, class Each>
void write_values(detail::AtomicWriter& w, std::size_t count, Each each) {
  constexpr std::size_t kBlock = 4096;
  T block[kBlock];
  std::size_t used = 0;
  for (std::size_t i = 0; i < count; ++i) {
    each(i, [&](T v) {
      block[used++] = v;
      if (used == kBlock) {
        w.bytes(block, sizeof block);
        used = 0;
      }
    });
  }
  w.bytes(block, used * sizeof(T));
}

template <class T, class Each>
VtuArray array(const char* type, const char* name, int components, std::size_t count, Each each) {
  return {type, name, components, static_cast<std::uint64_t>(count) * components * sizeof(T),
          [count, each](detail::AtomicWriter& w) { write_values<T>(w, count, each); }};
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

  const std::vector<VtuArray> points{array<double>("Float64", "points", 3, n, [&](std::size_t i, auto put) {
    put(mesh.points[i].x);
    put(mesh.points[i].y);
    put(0.0);
  })};
  const std::vector<VtuArray> cell_arrays{
      array<std::int64_t>("Int64", "connectivity", 1, 3 * cells,
                          [&](std::size_t k, auto put) { put(mesh.triangles[k / 3][k % 3]); }),
      array<std::int64_t>("Int64", "offsets", 1, cells,
                          [](std::size_t t, auto put) { put(3 * static_cast<std::int64_t>(t + 1)); }),
      array<std::uint8_t>("UInt8", "types", 1, cells, [](std::size_t, auto put) { put(kVtkTriangle); })};
  const std::vector<VtuArray> cell_data{
      array<double>("Float64", "region", 1, cells, [&](std::size_t t, auto put) { put(detail::region_of(mesh, t)); }),
      array<double>("Float64", "min_angle", 1, cells, [&](std::size_t t, auto put) { put(min_angle[t]); }),
      array<double>("Float64", "quality", 1, cells, [&](std::size_t t, auto put) { put(min_angle[t] / 60.0); })};
  const std::vector<VtuArray> point_data{array<std::int32_t>("Int32", "marker", 1, n, [&](std::size_t i, auto put) {
    put(mesh.vertex_markers.empty() ? 0 : mesh.vertex_markers[i]);
  })};

  detail::AtomicWriter w(path);
  std::uint64_t offset = 0;  // of the next array in the appended data, past its '_'
  const auto declare = [&](const std::vector<VtuArray>& arrays) {
    for (const VtuArray& a : arrays) {
      w.text("        <DataArray type=\"");
      w.text(a.type);
      w.text("\" Name=\"");
      w.text(a.name);
      w.text("\"");
      if (a.components > 1) {
        w.text(" NumberOfComponents=\"");
        w.integer(a.components);
        w.text("\"");
      }
      w.text(" format=\"appended\" offset=\"");
      w.integer(static_cast<std::int64_t>(offset));
      w.text("\"/>\n");
      offset += sizeof(std::uint64_t) + a.bytes;
    }
  };
  w.text("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"");
  w.text(std::endian::native == std::endian::big ? "BigEndian" : "LittleEndian");
  w.text("\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"");
  w.integer(static_cast<std::int64_t>(n));
  w.text("\" NumberOfCells=\"");
  w.integer(static_cast<std::int64_t>(cells));
  w.text("\">\n      <Points>\n");
  declare(points);
  w.text("      </Points>\n      <Cells>\n");
  declare(cell_arrays);
  w.text("      </Cells>\n      <CellData Scalars=\"quality\">\n");
  declare(cell_data);
  w.text("      </CellData>\n      <PointData Scalars=\"marker\">\n");
  declare(point_data);
  w.text("      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _");
  for (const auto* arrays : {&points, &cell_arrays, &cell_data, &point_data})
    for (const VtuArray& a : *arrays) {
      w.bytes(&a.bytes, sizeof a.bytes);
      a.write(w);
    }
  w.text("\n  </AppendedData>\n</VTKFile>\n");
  w.commit();
}

}  // namespace meshstep::io
