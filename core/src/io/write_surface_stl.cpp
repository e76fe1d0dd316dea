// STL writers. STL has no shared vertices: each triangle carries its three corners, and a
// unit normal (computed here; readers, ours included, mostly ignore it).
//
// Binary STL stores float32: coordinates are rounded to the nearest float, and one beyond
// float's range is refused. The ASCII writer writes each double in its shortest exact form,
// so an ASCII file reads back exactly (most other programs read it as float).
#include <cfloat>
#include <cmath>
#include <limits>

#include "io/atomic_writer.hpp"
#include "io/surface_bytes.hpp"
#include "io/surface_writers.hpp"

namespace meshstep::io::detail {
namespace {

Point3 unit_normal(const Surface& s, const std::array<std::uint32_t, 3>& t) {
  const Point3& a = s.vertices[t[0]];
  const Point3& b = s.vertices[t[1]];
  const Point3& c = s.vertices[t[2]];
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const Point3 n{uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  // Degenerate (or overflowing) triangles get the "no normal" 0 0 0 that exporters write.
  if (!(length > 0.0) || !std::isfinite(length)) return {};
  return {n.x / length, n.y / length, n.z / length};
}

void write_ascii_point(AtomicWriter& w, const char* keyword, const Point3& p) {
  w.text(keyword);
  w.real(p.x);
  w.ch(' ');
  w.real(p.y);
  w.ch(' ');
  w.real(p.z);
  w.ch('\n');
}

void write_ascii(const std::string& path, const Surface& s) {
  AtomicWriter w(path);
  w.text("solid meshstep\n");
  for (const auto& t : s.triangles) {
    write_ascii_point(w, "  facet normal ", unit_normal(s, t));
    w.text("    outer loop\n");
    for (const std::uint32_t v : t) write_ascii_point(w, "      vertex ", s.vertices[v]);
    w.text("    endloop\n  endfacet\n");
  }
  w.text("endsolid meshstep\n");
  w.commit();
}

// Converting a double beyond float's range to float is undefined behaviour: check first.
void check_fits_float(const std::string& path, const Surface& s) {
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const Point3& p = s.vertices[i];
    for (const double v : {p.x, p.y, p.z}) {
      if (std::fabs(v) > FLT_MAX) {
        refuse_surface(path, "vertex " + std::to_string(i) +
                                 " has a coordinate beyond the range of float, which binary "
                                 "STL stores");
      }
    }
  }
}

void store_float(char* out, double v) {
  store_little_endian(out, std::bit_cast<std::uint32_t>(static_cast<float>(v)), 4);
}

void write_binary(const std::string& path, const Surface& s) {
  check_fits_float(path, s);
  if (s.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
    refuse_surface(path, std::to_string(s.triangles.size()) +
                             " triangles; a binary STL file holds at most 2^32 - 1");
  }
  AtomicWriter w(path);
  // The header is free text, but must not begin with "solid": some readers would take the
  // file for ASCII.
  char header[80] = "binary STL written by meshstep";
  w.bytes(header, sizeof header);
  char count[4];
  store_little_endian(count, s.triangles.size(), 4);
  w.bytes(count, 4);
  char record[50] = {};  // the last 2 bytes, the "attribute byte count", stay 0
  for (const auto& t : s.triangles) {
    const Point3 n = unit_normal(s, t);
    store_float(record, n.x);
    store_float(record + 4, n.y);
    store_float(record + 8, n.z);
    for (std::size_t k = 0; k < 3; ++k) {
      const Point3& p = s.vertices[t[k]];
      store_float(record + 12 + 12 * k, p.x);
      store_float(record + 16 + 12 * k, p.y);
      store_float(record + 20 + 12 * k, p.z);
    }
    w.bytes(record, sizeof record);
  }
  w.commit();
}

}  // namespace

void write_stl(const std::string& path, const Surface& s, bool binary) {
  if (binary) {
    write_binary(path, s);
  } else {
    write_ascii(path, s);
  }
}

}  // namespace meshstep::io::detail
