// Reading Wavefront OBJ files: "v x y z" vertices and "f" faces whose corners are 1-based
// vertex numbers, or negative ones counting back from the latest vertex (-1 is the one just
// before the face), each possibly followed by /texture/normal numbers, which are ignored.
// Every other record (vt, vn, g, o, s, usemtl, mtllib, l, ...) says nothing about the shape
// and is ignored too.
#include <charconv>
#include <system_error>

#include "io/fields.hpp"
#include "io/record_reader.hpp"
#include "io/sections.hpp"
#include "io/surface_readers.hpp"
#include "meshstep/error.hpp"

namespace meshstep::io::detail {
namespace {

// The vertex number of a face corner "v", "v/vt", "v//vn" or "v/vt/vn": never 0.
std::int64_t corner_number(const RecordReader& r, std::size_t field) {
  const std::string_view token = r.field(field);
  const std::string_view number = token.substr(0, token.find('/'));
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
  if (ec == std::errc::result_out_of_range) {
    r.fail("vertex index " + quote(number) + " is out of range");
  }
  if (ec != std::errc() || ptr != number.data() + number.size()) {
    r.fail("a face corner should be a vertex index (then optionally /texture/normal), found " +
           quote(token));
  }
  if (v == 0) r.fail("vertex index 0 is out of range: OBJ numbers vertices from 1");
  return v;
}

// A positive vertex number may refer to a vertex later in the file, so it can only be
// checked at the end; the largest is enough, with its line for the message.
struct ForwardReference {
  std::int64_t number = 0;
  std::size_t line = 0;
};

}  // namespace

Surface read_obj(const std::string& path) {
  RecordReader r(path);
  Surface s;
  std::vector<std::uint32_t> corners;
  ForwardReference largest;
  while (r.next()) {
    const std::string_view keyword = r.field(0);
    if (keyword == "v") {
      if (r.field_count() < 4) {
        r.fail("expected 3 coordinates after 'v', found " + std::to_string(r.field_count() - 1));
      }
      if (s.vertices.size() == kMaxItems) {
        r.fail("more than " + std::to_string(kMaxItems) + " vertices are not supported");
      }
      s.vertices.push_back({parse_real(r, 1, "x coordinate"), parse_real(r, 2, "y coordinate"),
                            parse_real(r, 3, "z coordinate")});
      // Some writers add a weight w, or a colour r g b: numbers that do not move the vertex.
      for (std::size_t k = 4; k < r.field_count(); ++k) parse_real(r, k, "vertex weight or colour");
    } else if (keyword == "f") {
      if (r.field_count() < 4) {
        r.fail("a face needs at least 3 vertices, found " + std::to_string(r.field_count() - 1));
      }
      corners.clear();
      for (std::size_t k = 1; k < r.field_count(); ++k) {
        const std::int64_t v = corner_number(r, k);
        const auto so_far = static_cast<std::int64_t>(s.vertices.size());
        if (v < 0 && so_far + v < 0) {
          r.fail("vertex index " + std::to_string(v) +
                 " is out of range (it counts back from the latest vertex, and there are " +
                 std::to_string(so_far) + " so far)");
        }
        if (v > largest.number) largest = {v, r.line()};
        // A number past 2^32 wraps here, but it is then also past the vertex count, which
        // fails below.
        corners.push_back(static_cast<std::uint32_t>(v < 0 ? so_far + v : v - 1));
      }
      add_fan(s.triangles, corners);
    }
  }
  if (largest.number > static_cast<std::int64_t>(s.vertices.size())) {
    const std::string range = s.vertices.empty()
                                  ? "there are no vertices"
                                  : "vertices are numbered 1.." + std::to_string(s.vertices.size());
    throw InputError(path, largest.line,
                     "vertex index " + std::to_string(largest.number) + " is out of range (" +
                         range + ")");
  }
  return s;
}

}  // namespace meshstep::io::detail
