// The files meshstep knows, in one table: extension, what the file holds, whether meshstep
// reads and writes it. Every command that tells files apart by name, the viewer's file
// dialog and `meshstep list` read it.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace meshstep::io {

enum class FileKind {
  pslg,     // a planar straight-line graph to mesh (.poly)
  points,   // a point set, or the vertices of a mesh prefix (.node)
  mesh,     // a part of a mesh PREFIX (.ele, .edge, .neigh)
  area,     // per-triangle area bounds of a mesh PREFIX (.area)
  grid,     // a height or size grid (.asc, .png, .tif)
  surface,  // a 3D triangle surface (.off, .obj, .ply, .stl)
  log,      // a replay log (.mslog)
};

struct FileFormat {
  std::string_view extension;  // with its dot, lower case
  FileKind kind;
  bool read, write;  // meshstep reads it / writes it
  std::string_view description;
};

std::span<const FileFormat> file_formats();

// The format a path's extension names (in any case), or null.
const FileFormat* format_of(std::string_view path);
const char* to_string(FileKind kind);

// A planar input to triangulate or refine: a .poly PSLG or a .node point set.
bool is_planar_input(std::string_view path);
// A 3D triangle surface by its name (.off, .obj, .ply, .stl).
bool is_surface(std::string_view path);
// A replay log by its content (its magic bytes), whatever its name.
bool is_replay_log(const std::string& path);

}  // namespace meshstep::io
