// Where a command writes its 2D mesh (triangulate, refine, run, log mesh): `-o OUT.EXT`
// whose extension names a mesh writer in the format table (io/formats.hpp: .msh .vtu .obj
// .off .ply .stl) is that one file in that format; any other value is a PREFIX for
// Triangle's files, written exactly as before (box.1 -> box.1.node, .ele, .poly).
#pragma once

#include <string>

#include "refuse_overwrites.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::app {

struct MeshOutput {
  std::string path;                        // the file, or Triangle's PREFIX
  const io::FileFormat* format = nullptr;  // null: Triangle's files under the PREFIX

  static MeshOutput named(const std::string& value) { return {value, io::mesh_writer_for(value)}; }

  bool single_file() const { return format != nullptr; }

  // What the command writes, for the overwrite check (nothing when `path` is empty).
  void add_to(FileRoles& files, const std::string& option) const {
    if (single_file()) files.writes(option, path, "output file");
    else files.writes_mesh(option, path);
  }

  // "box.1.node/.ele/.poly" or "lake.msh", for progress lines.
  std::string files() const { return single_file() ? path : path + ".node/.ele/.poly"; }

  // Throws InputError as the writers do.
  void write(const TriMesh& mesh, const io::WriteOptions& options = {}) const {
    if (single_file()) format->write_mesh(path, mesh);
    else io::write_mesh(path, mesh, options);
  }
};

}  // namespace meshstep::app
