// A Pslg as a self-contained .poly file (triangle_io.hpp: write_pslg): what the viewer's
// workbench saves.
#include <cmath>

#include "io/atomic_writer.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/write_pslg.hpp"

namespace meshstep::io {
namespace {

[[noreturn]] void bad_input(const std::string& path, const std::string& message) {
  throw InputError(path, 0, "cannot write this input: " + message);
}

void number(detail::AtomicWriter& w, double v, const char* what, std::size_t index) {
  if (!std::isfinite(v)) bad_input(w.path(), std::string(what) + " " + std::to_string(index) + " is not finite");
  w.ch(' ');
  w.real(v);
}

}  // namespace

void write_pslg(const std::string& path, const Pslg& input) {
  if (input.first_index != 0 && input.first_index != 1)
    bad_input(path, "first_index must be 0 or 1, not " + std::to_string(input.first_index));
  const std::size_t n = input.points.size(), k = input.attributes_per_vertex;
  if (input.vertex_attributes.size() != n * k)
    bad_input(path, "vertex_attributes has " + std::to_string(input.vertex_attributes.size()) + " values, expected " +
                        std::to_string(n * k));
  if (input.has_vertex_markers && input.vertex_markers.size() != n)
    bad_input(path, "vertex_markers has " + std::to_string(input.vertex_markers.size()) + " values for " +
                        std::to_string(n) + " vertices");
  const std::int64_t base = input.first_index;
  detail::AtomicWriter w(path);
  w.integer(static_cast<std::int64_t>(n));
  w.text(" 2 ");
  w.integer(static_cast<std::int64_t>(k));
  w.text(input.has_vertex_markers ? " 1\n" : " 0\n");
  for (std::size_t i = 0; i < n; ++i) {
    w.integer(static_cast<std::int64_t>(i) + base);
    number(w, input.points[i].x, "x coordinate of vertex", i + base);
    number(w, input.points[i].y, "y coordinate of vertex", i + base);
    for (std::size_t a = 0; a < k; ++a) number(w, input.vertex_attributes[i * k + a], "attribute of vertex", i + base);
    if (input.has_vertex_markers) {
      w.ch(' ');
      w.integer(input.vertex_markers[i]);
    }
    w.ch('\n');
  }
  w.integer(static_cast<std::int64_t>(input.segments.size()));
  w.text(input.has_segment_markers ? " 1\n" : " 0\n");
  for (std::size_t i = 0; i < input.segments.size(); ++i) {
    const Segment& s = input.segments[i];
    if (s.a >= n || s.b >= n)
      bad_input(path, "segment " + std::to_string(i + base) + " names a vertex past the last (" + std::to_string(n) + ")");
    w.integer(static_cast<std::int64_t>(i) + base);
    w.ch(' ');
    w.integer(s.a + base);
    w.ch(' ');
    w.integer(s.b + base);
    if (input.has_segment_markers) {
      w.ch(' ');
      w.integer(s.marker);
    }
    w.ch('\n');
  }
  w.integer(static_cast<std::int64_t>(input.holes.size()));
  w.ch('\n');
  for (std::size_t i = 0; i < input.holes.size(); ++i) {
    w.integer(static_cast<std::int64_t>(i) + base);
    number(w, input.holes[i].x, "x coordinate of hole", i + base);
    number(w, input.holes[i].y, "y coordinate of hole", i + base);
    w.ch('\n');
  }
  w.integer(static_cast<std::int64_t>(input.regions.size()));
  w.ch('\n');
  for (std::size_t i = 0; i < input.regions.size(); ++i) {
    const Region& r = input.regions[i];
    w.integer(static_cast<std::int64_t>(i) + base);
    number(w, r.point.x, "x coordinate of region", i + base);
    number(w, r.point.y, "y coordinate of region", i + base);
    number(w, r.attribute, "attribute of region", i + base);
    number(w, r.max_area, "maximum area of region", i + base);
    w.ch('\n');
  }
  w.commit();
}

}  // namespace meshstep::io
