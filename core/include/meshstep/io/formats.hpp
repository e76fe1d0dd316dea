// The files meshstep knows, in one table: extension, what the file holds, whether meshstep
// reads and writes it, and for planar work the reader of an input PSLG and the writer of a
// 2D mesh it goes through. Every command that tells files apart by name, `-o OUT.EXT` on the
// commands that write a 2D mesh, the viewer's file dialog and `meshstep list` read it.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"

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

// An input PSLG from a file: problems are InputError("FILE:LINE: ..."); what loses nothing
// asked for goes to *warnings as "FILE:LINE: ..." lines.
using PslgReader = Pslg (*)(const std::string& path, std::vector<std::string>* warnings);
// A whole 2D mesh into one file, replaced atomically.
using MeshWriter = void (*)(const std::string& path, const TriMesh& mesh);

struct FileFormat {
  std::string_view extension;  // with its dot, lower case
  FileKind kind;
  bool read, write;  // meshstep reads it / writes it
  std::string_view description;
  // For planar work: what a written 2D mesh keeps (empty: no 2D mesh writer here).
  std::string_view carries = {};
  PslgReader read_pslg = nullptr;  // an input to triangulate or refine (null: none)
  MeshWriter write_mesh = nullptr; // `-o OUT.EXT` writes a 2D mesh with it (null: none)
};

std::span<const FileFormat> file_formats();

// The format a path's extension names (in any case), or null.
const FileFormat* format_of(std::string_view path);
const char* to_string(FileKind kind);

// The format whose MeshWriter `-o OUT` names by its extension (any case), or null: then OUT
// is a PREFIX for Triangle's files, as it always was (box.1 writes box.1.node, ...).
const FileFormat* mesh_writer_for(std::string_view path);

// A planar input to triangulate or refine: a .poly PSLG or a .node point set, or a polygon
// file (.geojson, .wkt).
bool is_planar_input(std::string_view path);
// A 3D triangle surface by its name (.off, .obj, .ply, .stl).
bool is_surface(std::string_view path);
// Triangle's mesh PREFIX stands for several files. `MeshPrefixFiles::written`: every file a
// mesh writer may leave (.node .ele .poly .area .edge .neigh); `read`: those a reader of the
// mesh may open (.node .ele .poly .area).
enum class MeshPrefixFiles { read, written };
std::vector<std::string> mesh_prefix_files(const std::string& prefix, MeshPrefixFiles which);
// A mesh PREFIX on disk: PREFIX.node and PREFIX.ele both exist.
bool is_mesh_prefix(const std::string& prefix);
// "mesh.1.node" and "mesh.1.ele" name the prefix "mesh.1"; any other path is returned as it is.
std::string mesh_prefix_of(const std::string& path);

// A replay log by its content (its magic bytes), whatever its name.
bool is_replay_log(const std::string& path);

}  // namespace meshstep::io
