// Reading OFF files (Geomview's Object File Format): a line "OFF", a line of counts
// "vertices faces edges" (the counts may also follow "OFF" on its line), one "x y z" line
// per vertex, then one "n i1 ... in [colour]" line per face, vertices numbered from 0.
// '#' starts a comment.
#include "io/fields.hpp"
#include "io/record_reader.hpp"
#include "io/sections.hpp"
#include "io/surface_readers.hpp"

namespace meshstep::io::detail {
namespace {

constexpr std::string_view kCountNames = "number of vertices, number of faces, number of edges";

// A face line: its corners, 0-based, into `corners`.
void read_face(const RecordReader& r, std::uint64_t vertex_count,
               std::vector<std::uint32_t>& corners) {
  const std::uint64_t n = parse_count(r, 0, "number of face vertices");
  if (n < 3) r.fail("a face needs at least 3 vertices, found " + std::to_string(n));
  const std::size_t listed = r.field_count() - 1;
  if (n > listed) {
    r.fail("the face has " + std::to_string(n) + " vertices, but the line lists only " +
           std::to_string(listed) + " indices");
  }
  // What follows the indices is the face's colour: an index into a colour map, or RGB, or
  // RGBA. Anything else means the vertex count is wrong.
  const std::size_t colour = listed - static_cast<std::size_t>(n);
  if (colour == 2 || colour > 4) {
    r.fail("the face has " + std::to_string(n) + " vertices, but the line lists " +
           std::to_string(listed) + " numbers after the count (a colour takes 1, 3 or 4)");
  }
  corners.clear();
  for (std::size_t k = 1; k <= n; ++k) {
    corners.push_back(parse_index(r, k, "vertex index", vertex_count, 0, "vertices"));
  }
  for (std::size_t k = 1 + n; k < r.field_count(); ++k) parse_real(r, k, "face colour");
}

}  // namespace

Surface read_off(const std::string& path) {
  RecordReader r(path);
  read_header(r, "OFF");
  if (r.field(0) != "OFF") {
    r.fail("not an OFF file: the first line should be 'OFF', found " + quote(r.field(0)));
  }
  std::size_t first = 1;  // field of the vertex count
  if (r.field_count() == 1) {
    require_record(r, r.next(), "the counts (" + std::string(kCountNames) + ")");
    first = 0;
  }
  if (r.field_count() - first != 3) {
    r.fail("expected 3 numbers (" + std::string(kCountNames) + "), found " +
           std::to_string(r.field_count() - first));
  }
  const std::uint64_t vertex_count = parse_count(r, first, "number of vertices");
  const std::uint64_t face_count = parse_count(r, first + 1, "number of faces");
  parse_count(r, first + 2, "number of edges");  // unused, as by every OFF reader
  const std::size_t header_line = r.line();

  Surface s;
  s.vertices.reserve(check_count(r, vertex_count, 3, "vertices", kMaxItems));
  s.triangles.reserve(check_count(r, face_count, 4, "faces", kMaxItems));
  for (std::uint64_t i = 0; i < vertex_count; ++i) {
    if (!r.next()) fail_truncated(r, i, vertex_count, "vertices", header_line);
    expect_fields(r, 3, "x, y, z");
    s.vertices.push_back({parse_real(r, 0, "x coordinate"), parse_real(r, 1, "y coordinate"),
                          parse_real(r, 2, "z coordinate")});
  }
  std::vector<std::uint32_t> corners;
  for (std::uint64_t i = 0; i < face_count; ++i) {
    if (!r.next()) fail_truncated(r, i, face_count, "faces", header_line);
    read_face(r, vertex_count, corners);
    add_fan(s.triangles, corners);
  }
  if (r.next()) {
    r.fail("more data after the " + std::to_string(face_count) + " faces declared on line " +
           std::to_string(header_line) + " (is a count wrong?)");
  }
  return s;
}

}  // namespace meshstep::io::detail
