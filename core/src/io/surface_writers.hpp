// The writers behind write_surface (io/surface_io.hpp), one file per format family. Each
// gets a surface write_surface has checked: indices in range, coordinates finite.
#pragma once

#include <string>

#include "meshstep/io/surface_io.hpp"

namespace meshstep::io::detail {

void write_off(const std::string& path, const Surface& s);
void write_obj(const std::string& path, const Surface& s);
void write_ply(const std::string& path, const Surface& s, bool binary);
void write_stl(const std::string& path, const Surface& s, bool binary);

class AtomicWriter;

// The body OFF and ASCII PLY share: a line "x y z" a vertex (shortest exact doubles), then
// a line "3 a b c" a triangle.
void write_vertex_and_face_lines(AtomicWriter& w, const Surface& s);

// "cannot write this surface: message", as InputError(path, 0, ...).
[[noreturn]] void refuse_surface(const std::string& path, const std::string& message);

}  // namespace meshstep::io::detail
