// PLY writers: vertices as doubles (so coordinates come back exactly, in ASCII as the
// shortest text that reads back to the same double), faces as lists of uchar length 3 and
// uint indices. Binary files are little-endian, the byte order of nearly every machine.
#include "io/atomic_writer.hpp"
#include "io/surface_bytes.hpp"
#include "io/surface_writers.hpp"

namespace meshstep::io::detail {
namespace {

void write_header(AtomicWriter& w, const Surface& s, bool binary) {
  w.text(binary ? "ply\nformat binary_little_endian 1.0\n" : "ply\nformat ascii 1.0\n");
  w.text("comment written by meshstep\nelement vertex ");
  w.integer(static_cast<std::int64_t>(s.vertices.size()));
  w.text("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  w.integer(static_cast<std::int64_t>(s.triangles.size()));
  w.text("\nproperty list uchar uint vertex_indices\nend_header\n");
}

void write_binary_body(AtomicWriter& w, const Surface& s) {
  char record[24];
  for (const Point3& p : s.vertices) {
    store_little_endian(record, std::bit_cast<std::uint64_t>(p.x), 8);
    store_little_endian(record + 8, std::bit_cast<std::uint64_t>(p.y), 8);
    store_little_endian(record + 16, std::bit_cast<std::uint64_t>(p.z), 8);
    w.bytes(record, 24);
  }
  for (const auto& t : s.triangles) {
    record[0] = 3;
    for (std::size_t k = 0; k < 3; ++k) store_little_endian(record + 1 + 4 * k, t[k], 4);
    w.bytes(record, 13);
  }
}

}  // namespace

void write_ply(const std::string& path, const Surface& s, bool binary) {
  AtomicWriter w(path);
  write_header(w, s, binary);
  if (binary) {
    write_binary_body(w, s);
  } else {
    write_vertex_and_face_lines(w, s);
  }
  w.commit();
}

}  // namespace meshstep::io::detail
