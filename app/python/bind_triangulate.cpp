// meshstep.triangulate(tri, opts): the `triangle` package's call, run by the core's run
// description. The switches become an Operation through the registry's own option setter
// (set_option: the same names, ranges and messages as the command line), so that
// triangulate(tri, 'pq30') runs exactly what `meshstep refine IN.poly --min-angle 30` runs.
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "triangle_dicts.hpp"
#include "triangle_switches.hpp"

namespace meshstep::python {
namespace {

// One option of the run description from a switch, its errors in the switch's words.
void set_from_switch(Operation& op, char letter, std::string_view name, const std::string& text) {
  try {
    set_option(op, name, text);
  } catch (const RunSpecError& e) {
    throw py::value_error("switch '" + std::string(1, letter) + "': " + e.what());
  }
}

py::dict triangulate_dict(const py::object& given, const std::string& opts) {
  const py::dict tri(given);
  TriangleSwitches s;
  try {
    s = parse_triangle_switches(opts);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  // S or S0: no Steiner point at all, so no refinement (crossing segments still meet at
  // their crossing: the CDT needs that vertex).
  const bool no_steiner = s.max_steiner && s.max_steiner->find_first_not_of('0') == std::string::npos;
  const bool refines = !no_steiner && (s.quality || !s.max_area.empty() || s.regional_area || s.conforming ||
                                       s.refine_mesh || (s.max_steiner && !no_steiner));

  Operation op;
  op.kind = OperationKind::refine;
  // Without q there is no angle bound (the registry's default would give one).
  set_from_switch(op, 'q', "min-angle", s.quality ? (s.min_angle.empty() ? "20" : s.min_angle) : "0");
  if (!s.max_area.empty()) set_from_switch(op, 'a', "max-area", s.max_area);
  if (s.conforming) set_from_switch(op, 'D', "encroachment", "circle");
  if (s.convex_hull) set_from_switch(op, 'c', "convex-hull", "");
  if (s.max_steiner && !no_steiner) set_from_switch(op, 'S', "max-steiner", *s.max_steiner);
  if (s.keep_segments) set_from_switch(op, 'Y', "split-segments", s.keep_segments == 1 ? "interior" : "none");
  RefineOptions options;
  try {
    options = refine_options(op);
  } catch (const RunSpecError& e) {
    throw py::value_error(std::string("opts '") + opts + "': " + e.what());
  }
  options.regional_max_area = s.regional_area;
  options.triangulate.compute_neighbors = s.neighbors;
  options.progress = signal_checking_progress();

  TriMesh mesh;
  if (s.refine_mesh) {
    TriMesh old = mesh_from_dict(tri, s.regional_area);
    mesh = without_gil([&] { return refine_mesh(old, options); });
  } else {
    Pslg in = pslg_from_dict(tri, s.pslg);
    if (refines) {
      mesh = without_gil([&] { return refine(std::move(in), options); });
    } else {
      TriangulateOptions t = options.triangulate;
      mesh = without_gil([&] { return triangulate(std::move(in), t); });
    }
  }
  return mesh_to_dict(mesh, {.edges = s.edges, .neighbors = s.neighbors, .triangle_attributes = s.attributes});
}

}  // namespace

void bind_triangulate(py::module_& m) {
  m.def("triangulate", &triangulate_dict, py::arg("tri"), py::arg("opts") = "",
        "Triangulate or refine a PSLG given as the `triangle` package's dict; see meshstep.triangulate.");
  m.def(
      "read_poly",
      [](const std::string& path) {
        Pslg in = io::read_pslg(path);
        TriMesh as_mesh;
        as_mesh.points = std::move(in.points);
        as_mesh.vertex_markers = std::move(in.vertex_markers);
        as_mesh.attributes_per_vertex = in.attributes_per_vertex;
        as_mesh.vertex_attributes = std::move(in.vertex_attributes);
        as_mesh.segments = std::move(in.segments);
        as_mesh.holes = std::move(in.holes);
        as_mesh.regions = std::move(in.regions);
        py::dict out = mesh_to_dict(as_mesh, {});
        out.attr("pop")("triangles");
        if (!in.has_segment_markers && out.contains("segment_markers")) out.attr("pop")("segment_markers");
        return out;
      },
      py::arg("path"), "A .poly or .node file as the triangle package's dict (indices from 0).");
}

}  // namespace meshstep::python
