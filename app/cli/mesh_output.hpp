// Where a command writes its 2D mesh (triangulate, refine, run, log mesh): `-o OUT.EXT`
// whose extension names a mesh writer in the format table (io/formats.hpp: .msh .vtu .obj
// .off .ply .stl) is that one file in that format; any other value is a PREFIX for
// Triangle's files, written exactly as before (box.1 -> box.1.node, .ele, .poly).
#pragma once

#include <string>

#include <stdexcept>

#include "refuse_overwrites.hpp"
#include "meshstep/check/mesh_check.hpp"
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

// The full checker (`meshstep check`: coverage of the input's segments and vertices, holes,
// overlaps, the constrained Delaunay property when `delaunay`) on a mesh about to be
// written, when it is small enough for the check to cost little beside the run (up to
// kFullCheckTriangles, about 70 ms at most); bigger meshes have the cheap checks only
// (delaunay/invariants.hpp, docs/cli.md). A failure is a bug in meshstep: std::logic_error,
// which the commands report as an internal error, writing nothing. `input`: the PSLG the
// mesh was made from (null: none to compare with, as for a mesh refined again).
inline constexpr std::size_t kFullCheckTriangles = 20000;
inline void check_before_writing(const TriMesh& mesh, const Pslg* input, bool delaunay) {
  if (mesh.triangles.size() > kFullCheckTriangles) return;
  CheckOptions options;
  options.delaunay = delaunay;
  options.max_problems = 1;
  const CheckReport report = check_mesh(mesh, input, options);
  if (!report.ok)
    throw std::logic_error("the mesh made fails its check (" + std::to_string(report.problem_count) +
                           " problems; the first: " + report.problems.front() + ")");
}

}  // namespace meshstep::app
