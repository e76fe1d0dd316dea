// meshstep.refine(...): a run description (one operation, or a recipe's lines) on a PSLG
// given as numpy arrays. The Python side (meshstep/_refine.py) writes the keyword arguments
// as the command line's words, one list of words per operation; the core's parser reads
// them (parse_operation), so the names, ranges and messages are the command line's own.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "meshstep/check/quality.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/esri_grid.hpp"
#include "meshstep/refine/quality.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/run_header.hpp"
#include "numpy_arrays.hpp"
#include "triangle_dicts.hpp"

namespace meshstep::python {
namespace {

// One operation ready to run, as planar_refine.cpp prepares it for the command line.
RefineOptions options_of(const Operation& op, const std::string& origin) {
  std::function<double(const Point&)> grid_size;
  if (op.size && !size_length(op)) {
    auto grid = std::make_shared<io::EsriGrid>(io::read_esri_grid(*op.size));
    grid_size = [grid](const Point& p) { return grid->at(p, -1.0); };
  }
  RefineOptions options;
  try {
    options = refine_options(op, grid_size);
    options.region = region_of(op);
  } catch (const RunSpecError& e) {
    throw py::value_error(origin + e.what());
  } catch (const InputError& e) {
    throw py::value_error(origin + e.what());
  }
  return options;
}

// meshpy's refinement_func: a triangle is bad when is_bad(vertices, area) says so. It goes
// in as a per-triangle area bound below the triangle's own area when bad (none otherwise),
// the core's hook for a caller's bound, which every selection and the report honour.
void add_user_criterion(RefineCriteria& c, const py::object& is_bad) {
  c.max_area_for = [is_bad](const Point& a, const Point& b, const Point& p) {
    const double area = 0.5 * quality::twice_area(a, b, p);
    py::gil_scoped_acquire gil;
    py::array_t<double> corners({py::ssize_t{3}, py::ssize_t{2}});
    double* v = corners.mutable_data();
    v[0] = a.x, v[1] = a.y, v[2] = b.x, v[3] = b.y, v[4] = p.x, v[5] = p.y;
    const bool bad = py::bool_(is_bad(corners, area));
    return bad ? area * 0.5 : 0.0;
  };
}

// The statistics `meshstep refine --stats json` prints, with the same names and values
// (but for the file-related ones: input, ms.read, ms.write).
py::dict stats_of(const TriMesh& mesh, const RefineOptions& options, const RefineReport& report,
                  std::size_t input_vertices, std::size_t input_segments) {
  const AngleStats angles = angle_stats(mesh);
  py::dict s;
  s["algorithm"] = options.algorithm;
  s["selection"] = to_string(options.selection);
  s["order"] = to_string(options.order);
  s["encroachment"] = options.encroachment == Encroachment::lens ? "lens" : "circle";
  s["min_angle_bound"] = options.phases.empty() ? options.criteria.min_angle_deg
                                                : options.phases.back().criteria.min_angle_deg;
  s["vertices"] = mesh.points.size();
  s["triangles"] = mesh.triangles.size();
  s["segments"] = mesh.segments.size();
  s["input_vertices"] = input_vertices;
  s["input_segments"] = input_segments;
  s["steiner"] = report.steiner_vertices;
  s["removed_vertices"] = report.removed_vertices;
  s["segment_splits"] = report.segment_splits;
  s["triangles_split"] = report.triangles_split;
  s["rejected_points"] = report.rejected_points;
  s["skipped_small_angle"] = report.skipped_small_angle;
  s["unsplittable_segments"] = report.unsplittable_segments;
  s["split_segments"] = to_string(options.segment_splits);
  s["kept_segment_refusals"] = report.kept_segment_refusals;
  s["below_min_angle"] = report.below_min_angle;
  s["bad_triangles"] = report.bad_triangles;
  s["bad_near_small_input_angle"] = report.bad_near_small_input_angle;
  s["bounds_met"] = report.bounds_met;
  s["stopped_by_cap"] = report.stopped_by_cap;
  s["min_angle"] = angles.min_angle_deg;
  s["max_angle"] = angles.max_angle_deg;
  s["ds"] = to_string(options.triangulate.data_structure);
  s["insertion"] = insertion_name(options);
  py::dict ms, phases;
  ms["triangulate"] = report.triangulate_ms;
  ms["refine"] = report.refine_ms;
  for (const auto& [name, phase_ms] : report.phase_ms) phases[py::str(name)] = phase_ms;
  ms["phases"] = phases;
  s["ms"] = ms;
  return s;
}

py::dict refine_arrays(const py::object& vertices, const py::object& segments, const py::object& segment_markers,
                       const py::object& holes, const py::object& regions, const py::object& vertex_markers,
                       const std::vector<std::vector<std::string>>& lines, const std::vector<std::string>& origins,
                       const std::string& ds, const py::object& region_polygon, const std::string& record,
                       const py::object& is_bad) {
  py::dict tri;
  tri["vertices"] = vertices;
  tri["segments"] = segments;
  tri["segment_markers"] = segment_markers;
  tri["holes"] = holes;
  tri["regions"] = regions;
  tri["vertex_markers"] = vertex_markers;
  Pslg input = pslg_from_dict(tri, true);

  std::vector<Operation> ops;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string origin = i < origins.size() ? origins[i] : std::string();
    try {
      Operation op = parse_operation(lines[i]);
      if (op.kind != OperationKind::refine)
        throw RunSpecError("an operation of a refinement is 'refine ...', not '" + lines[i].front() + " ...'");
      if (op.flip_dihedral) throw RunSpecError("--flip-dihedral is for a 3D surface, not a planar mesh");
      set_option(op, "ds", ds);
      ops.push_back(std::move(op));
    } catch (const RunSpecError& e) {
      throw py::value_error(origin + e.what());
    }
  }
  if (ops.empty()) throw py::value_error("recipe: no operation (one 'refine ...' line at least)");
  std::vector<RefineOptions> options;
  for (std::size_t i = 0; i < ops.size(); ++i) options.push_back(options_of(ops[i], i < origins.size() ? origins[i] : ""));
  if (!region_polygon.is_none()) {
    if (ops.size() > 1) throw py::value_error("region: a polygon region applies to one operation, not a recipe");
    options[0].region = RefineRegion::polygon(points_from(region_polygon, "region"));
  }
  if (!is_bad.is_none()) {
    if (!PyCallable_Check(is_bad.ptr())) throw py::value_error("is_bad: expected a callable (vertices, area) -> bool");
    for (RefineOptions& o : options) {
      add_user_criterion(o.criteria, is_bad);
      for (RefinePhase& phase : o.phases) add_user_criterion(phase.criteria, is_bad);
    }
  }

  const std::size_t input_vertices = input.points.size(), input_segments = input.segments.size();
  std::unique_ptr<replay::LogWriter> log;
  if (!record.empty()) {
    replay::LogHeader header;
    header.input = "<python arrays>";
    header.algorithm = options[0].algorithm;
    header.parameters = replay::refine_parameters(options[0], ops[0].size.value_or(""), input_vertices, 0) +
                        (options[0].region ? " region=" + options[0].region->text() : "");
    header.data_structure = to_string(options[0].triangulate.data_structure);
    header.insertion = to_string(options[0].triangulate.insertion);
    // One log for the whole recipe, naming its operations as `meshstep run` does.
    if (ops.size() > 1)
      for (const Operation& op : ops) header.operations += print_operation(op) + "\n";
    replay::describe_input(header, input);
    log = std::make_unique<replay::LogWriter>(record, header);
    options[0].triangulate.record = log.get();
  }
  for (RefineOptions& o : options) o.progress = signal_checking_progress();

  // Every operation on the one mesh in one run, as `meshstep run` does (refine.hpp:
  // refine_chain), so that a recipe gives the mesh and the report the command line gives.
  std::vector<RefineReport> reports(options.size());
  TriMesh mesh = without_gil([&] {
    TriMesh m = refine_chain(std::move(input), options, reports);
    if (log) log->finish();
    return m;
  });
  const RefineReport report = combined_report(reports);
  py::dict out;
  out["vertices"] = points_array(mesh.points);
  out["triangles"] = triangles_array(mesh.triangles);
  out["segments"] = segments_array(mesh.segments);
  out["segment_markers"] = segment_markers_array(mesh.segments);
  out["vertex_markers"] = ints_array(mesh.vertex_markers, 1);
  out["triangle_attributes"] = reals_array(mesh.triangle_attributes, mesh.attributes_per_triangle);
  out["stats"] = stats_of(mesh, options.back(), report, input_vertices, input_segments);
  return out;
}

}  // namespace

void bind_refine(py::module_& m) {
  m.def("refine", &refine_arrays, py::arg("vertices"), py::arg("segments"), py::arg("segment_markers"),
        py::arg("holes"), py::arg("regions"), py::arg("vertex_markers"), py::arg("operations"), py::arg("origins"),
        py::arg("ds"), py::arg("region_polygon"), py::arg("record"), py::arg("is_bad"),
        "Refine a PSLG by a run description's operation lines; see meshstep.refine.");
  m.def("algorithms", [] {
    std::vector<std::string> names;
    for (const AlgorithmInfo& a : algorithms()) names.emplace_back(a.name);
    return names;
  }, "The registered refinement algorithms' names.");
}

}  // namespace meshstep::python
