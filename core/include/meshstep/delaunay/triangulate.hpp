// Front door of the triangulators: a PSLG in, a TriMesh out, with the data structure and
// the insertion strategy chosen at run time (each combination is its own instantiation,
// so the choice costs nothing inside the loops).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"
#include "meshstep/replay/event.hpp"
#include "meshstep/replay/event_sink.hpp"

namespace meshstep {

enum class DataStructure { tds, dcel };
enum class Insertion { flip, cavity };

struct TriangulateOptions {
  DataStructure data_structure = DataStructure::tds;
  Insertion insertion = Insertion::flip;
  // Keep every triangle of the convex hull (minus holes) instead of removing the ones
  // outside the segments (Triangle's -c).
  bool convex_hull = false;
  bool compute_neighbors = false;
  // false: the triangulation is built and checked but not converted to a TriMesh (the one
  // returned is empty; the report has its counts), for a caller that only measures it.
  // Ignored by refine(), whose output is checked as it is converted.
  bool keep_mesh = true;
  // Record every step into this sink (a replay::LogWriter); nullptr: no recording, and the
  // triangulators run the code they would run without a recorder.
  replay::EventSink* record = nullptr;
  // Tests: with `record`, called with every face slot at each step boundary and at the end.
  std::function<void(const std::vector<replay::FaceRecord>&)> observe_steps;
};

struct TriangulateReport {
  std::size_t duplicate_vertices = 0;   // merged with an earlier vertex at the same place
  std::size_t steiner_vertices = 0;     // added where segments cross
  std::size_t split_segments = 0;       // segments split by a vertex or a crossing
  std::size_t removed_triangles = 0;    // in holes or outside the segments
  std::size_t mesh_bytes = 0;           // memory held by the data structure at its largest
  std::size_t vertices = 0, triangles = 0, segments = 0;  // of the mesh made, kept or not
  std::vector<std::string> warnings;    // human-readable, one line each
};

// Delaunay triangulation of input.points when input has no segments, else the constrained
// Delaunay triangulation of the PSLG (holes and, unless convex_hull, the outside removed).
// Throws InputError for input with fewer than three non-collinear vertices or a segment
// that names a missing vertex. Deterministic: the same input gives the same mesh on every
// data structure and insertion strategy.
TriMesh triangulate(const Pslg& input, const TriangulateOptions& options = {},
                    TriangulateReport* report = nullptr);

// Same, consuming the input (no copy of its points: the large-input path).
TriMesh triangulate(Pslg&& input, const TriangulateOptions& options = {},
                    TriangulateReport* report = nullptr);

const char* to_string(DataStructure ds);
const char* to_string(Insertion insertion);

}  // namespace meshstep
