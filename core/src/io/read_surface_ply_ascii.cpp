// The body of an ASCII PLY file: one line per element instance, its properties' values in
// the order the header declares them (a list: its length, then its items).
#include "io/fields.hpp"
#include "io/sections.hpp"
#include "io/surface_ply.hpp"
#include "io/surface_readers.hpp"
#include "meshstep/error.hpp"

namespace meshstep::io::detail {
namespace {

// How many instances of `e` it is safe to reserve room for: each takes a line of at least
// one value per property, so the rest of the file bounds the count.
std::size_t bounded_count(const RecordReader& r, const PlyElement& e) {
  try {
    return check_count(r, e.count, e.properties.size(), "'" + e.name + "' elements", kMaxItems);
  } catch (const InputError& error) {
    throw InputError(r.path(), e.line, error.message());  // the count is on the element's line
  }
}

// A value the surface does not need must still be a number of its type.
void check_value(const RecordReader& r, std::size_t field, const PlyProperty& p) {
  const std::string what = "value of property '" + p.name + "'";
  if (p.type.kind == PlyType::real) {
    parse_real(r, field, what);
  } else {
    parse_integer(r, field, what);
  }
}

// The current line, one instance of `e`: its corners go to `s` (a face), its point to
// `point` (a vertex).
void read_instance(const RecordReader& r, const PlyHeader& h, const PlyElement& e, Surface& s,
                   Point3& point, std::vector<std::uint32_t>& corners) {
  std::size_t k = 0;  // the next field
  for (const PlyProperty& p : e.properties) {
    if (k == r.field_count()) {
      r.fail("too few values for a '" + e.name + "' element: none for property '" + p.name + "'");
    }
    if (!p.is_list) {
      switch (p.role) {
        case PlyRole::x: point.x = parse_real(r, k, "x coordinate"); break;
        case PlyRole::y: point.y = parse_real(r, k, "y coordinate"); break;
        case PlyRole::z: point.z = parse_real(r, k, "z coordinate"); break;
        default: check_value(r, k, p); break;
      }
      ++k;
      continue;
    }
    const std::uint64_t n = parse_count(r, k, "length of list '" + p.name + "'");
    ++k;
    if (n > r.field_count() - k) {
      r.fail("list '" + p.name + "' has " + std::to_string(n) +
             " items, but the line holds only " + std::to_string(r.field_count() - k) +
             " more values");
    }
    if (p.role == PlyRole::corners) {
      if (n < 3) r.fail("a face needs at least 3 vertices, found " + std::to_string(n));
      corners.clear();
      for (std::size_t j = 0; j < n; ++j) {
        corners.push_back(parse_index(r, k + j, "vertex index", h.vertex_count, 0, "vertices"));
      }
      add_fan(s.triangles, corners);
    } else {
      for (std::size_t j = 0; j < n; ++j) check_value(r, k + j, p);
    }
    k += static_cast<std::size_t>(n);
  }
  if (k != r.field_count()) {
    r.fail("too many values for a '" + e.name + "' element: its properties take " +
           std::to_string(k) + ", the line has " + std::to_string(r.field_count()));
  }
}

}  // namespace

Surface read_ply_ascii_body(RecordReader& r, const PlyHeader& h) {
  Surface s;
  for (const PlyElement& e : h.elements) {
    const std::size_t reserve = bounded_count(r, e);
    if (e.name == "vertex") s.vertices.reserve(reserve);
    if (e.name == "face") s.triangles.reserve(reserve);
  }
  std::vector<std::uint32_t> corners;
  for (const PlyElement& e : h.elements) {
    const bool vertices = e.name == "vertex";
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (!r.next()) fail_truncated(r, i, e.count, "'" + e.name + "' elements", e.line);
      Point3 point;
      read_instance(r, h, e, s, point, corners);
      if (vertices) s.vertices.push_back(point);
    }
  }
  if (r.next()) {
    r.fail("more data after the last element declared in the header (is a count wrong?)");
  }
  return s;
}

}  // namespace meshstep::io::detail
