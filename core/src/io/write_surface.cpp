// write_surface (io/surface_io.hpp): checks the surface, then the writer of the format;
// and the OFF and OBJ writers, text with coordinates in their shortest exact form.
#include <cmath>

#include "io/atomic_writer.hpp"
#include "io/sections.hpp"
#include "io/surface_writers.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/shortest_text.hpp"

namespace meshstep::io {
namespace detail {
namespace {

// What no reader would accept back is refused before the target is touched.
void check_surface(const std::string& path, const Surface& s) {
  if (s.vertices.size() > kMaxItems) {
    refuse_surface(path, std::to_string(s.vertices.size()) + " vertices; at most " +
                             std::to_string(kMaxItems) + " are supported");
  }
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    const Point3& p = s.vertices[i];
    for (const double v : {p.x, p.y, p.z}) {
      if (!std::isfinite(v)) {
        refuse_surface(path, "vertex " + std::to_string(i) +
                                 " has a coordinate that is not finite (" + shortest_text(v) +
                                 ")");
      }
    }
  }
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    for (const std::uint32_t v : s.triangles[t]) {
      if (v >= s.vertices.size()) {
        refuse_surface(path, "triangle " + std::to_string(t) + " uses vertex " +
                                 std::to_string(v) + ", but there are only " +
                                 std::to_string(s.vertices.size()) + " vertices");
      }
    }
  }
}

void write_point(AtomicWriter& w, const Point3& p) {
  w.real(p.x);
  w.ch(' ');
  w.real(p.y);
  w.ch(' ');
  w.real(p.z);
}

}  // namespace

void write_vertex_and_face_lines(AtomicWriter& w, const Surface& s) {
  for (const Point3& p : s.vertices) {
    write_point(w, p);
    w.ch('\n');
  }
  for (const auto& t : s.triangles) {
    w.ch('3');
    for (const std::uint32_t v : t) {
      w.ch(' ');
      w.integer(v);
    }
    w.ch('\n');
  }
}

void refuse_surface(const std::string& path, const std::string& message) {
  throw InputError(path, 0, "cannot write this surface: " + message);
}

void write_off(const std::string& path, const Surface& s) {
  AtomicWriter w(path);
  w.text("OFF\n");
  w.integer(static_cast<std::int64_t>(s.vertices.size()));
  w.ch(' ');
  w.integer(static_cast<std::int64_t>(s.triangles.size()));
  w.text(" 0\n");
  write_vertex_and_face_lines(w, s);
  w.commit();
}

void write_obj(const std::string& path, const Surface& s) {
  AtomicWriter w(path);
  w.text("# written by meshstep\n");
  for (const Point3& p : s.vertices) {
    w.text("v ");
    write_point(w, p);
    w.ch('\n');
  }
  for (const auto& t : s.triangles) {
    w.ch('f');
    for (const std::uint32_t v : t) {
      w.ch(' ');
      w.integer(std::int64_t{v} + 1);  // OBJ numbers vertices from 1
    }
    w.ch('\n');
  }
  w.commit();
}

}  // namespace detail

void write_surface(const std::string& path, const Surface& s, SurfaceFormat f) {
  detail::check_surface(path, s);
  switch (f) {
    case SurfaceFormat::off: return detail::write_off(path, s);
    case SurfaceFormat::obj: return detail::write_obj(path, s);
    case SurfaceFormat::ply_ascii: return detail::write_ply(path, s, false);
    case SurfaceFormat::ply_binary: return detail::write_ply(path, s, true);
    case SurfaceFormat::stl_ascii: return detail::write_stl(path, s, false);
    case SurfaceFormat::stl_binary: return detail::write_stl(path, s, true);
  }
  detail::refuse_surface(path, "unknown format");
}

}  // namespace meshstep::io
