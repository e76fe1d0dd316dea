// meshstep.Log: a replay log (meshstep --record) read through the core's reader and replay
// cursor: its steps and phases, the mesh after step K as numpy arrays, its events one at a
// time, the explain panel's text of a step, and a picture of a moment: SVG, or RGB pixels
// drawn by the OpenGL renderer off screen (EGL or OSMesa, as `meshstep render` draws PNGs).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>

#include "bindings.hpp"
#include "meshstep/replay/describe.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/scene/build.hpp"
#include "meshstep/scene/camera.hpp"
#include "meshstep/scene/explain.hpp"
#include "meshstep/scene/image.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/scene/svg.hpp"
#include "numpy_arrays.hpp"
#include "render/painter.hpp"

namespace meshstep::python {
namespace {

class LogFile {
 public:
  explicit LogFile(const std::string& path)
      : reader_(std::make_unique<replay::LogReader>(path)), cursor_(std::make_unique<replay::Replay>(*reader_)) {}

  const replay::LogReader& reader() const { return *reader_; }

  // A step count from Python: 0 to step_count, or -1 for the end.
  std::uint64_t step_arg(long long k) const {
    const auto n = static_cast<long long>(reader_->step_count());
    if (k == -1) return static_cast<std::uint64_t>(n);
    if (k < 0 || k > n)
      throw py::index_error("step " + std::to_string(k) + " is out of range: the log has " + std::to_string(n) +
                            " steps (0: before the first, -1: the end)");
    return static_cast<std::uint64_t>(k);
  }

  // The mesh after K steps, as the run's own output writes it.
  py::dict mesh(long long k) {
    const std::uint64_t steps = step_arg(k);
    TriMesh m;
    {
      py::gil_scoped_release release;
      cursor_->seek_step(steps);
      m = cursor_->output_mesh();
    }
    py::dict out;
    out["vertices"] = points_array(m.points);
    out["triangles"] = triangles_array(m.triangles);
    out["segments"] = segments_array(m.segments);
    out["segment_markers"] = segment_markers_array(m.segments);
    out["vertex_markers"] = ints_array(m.vertex_markers, 1);
    out["triangle_attributes"] = reals_array(m.triangle_attributes, m.attributes_per_triangle);
    return out;
  }

  py::list steps() const {
    py::list out;
    for (std::uint64_t k = 0; k < reader_->step_count(); ++k) {
      py::dict s;
      s["step"] = k + 1;  // counted from 1, as the captions and explain() count them
      s["kind"] = replay::name(reader_->step_kind(k));
      s["first_event"] = reader_->step_start(k);
      s["end_event"] = reader_->step_start(k + 1);
      out.append(s);
    }
    return out;
  }

  py::list phases() const {
    py::list out;
    for (const replay::PhaseSpan& p : reader_->phases()) {
      py::dict d;
      d["phase"] = replay::name(p.phase);
      d["begin_event"] = p.begin;
      d["end_event"] = p.end == replay::kNoEnd ? py::object(py::none()) : py::object(py::int_(p.end));
      out.append(d);
    }
    return out;
  }

  // Event e as the JSON line of `meshstep log dump --jsonl` (parsed on the Python side).
  std::string event_json(long long e) const {
    if (e < 0 || static_cast<std::uint64_t>(e) >= reader_->event_count())
      throw py::index_error("event " + std::to_string(e) + " is out of range: the log has " +
                            std::to_string(reader_->event_count()) + " events");
    const auto index = static_cast<std::uint64_t>(e);
    const std::uint64_t step = reader_->step_of_event(index);
    return replay::to_json(reader_->event(index), index, step, step < reader_->step_count());
  }

  std::string describe_event(long long e) const {
    if (e < 0 || static_cast<std::uint64_t>(e) >= reader_->event_count())
      throw py::index_error("event " + std::to_string(e) + " is out of range");
    return replay::describe(reader_->event(static_cast<std::uint64_t>(e)));
  }

  // The explain panel's text for step K (the one that ends at mesh(K)): a heading, then a
  // line per thing the step did.
  std::pair<std::string, std::vector<std::string>> explain(long long k) {
    cursor_->seek_step(step_arg(k));
    scene::Explanation e = scene::explain_step(*cursor_);
    return {e.heading, e.lines};
  }

  // The moment after K steps drawn as `meshstep render --format svg` draws it (default
  // options), width x height pixels.
  std::string svg(long long k, int width, int height) {
    const scene::Scene s = moment(k, width, height);
    return scene::to_svg(s, scene::fit_scene(s, width, height));
  }

  // The same moment as pixels, as `meshstep render -o OUT.png` draws it: an (height, width,
  // 3) uint8 array, rows top to bottom. `backend` as --gl: "auto", "egl" or "osmesa".
  // Throws GlUnavailable (RuntimeError in Python) saying why when no OpenGL can be had.
  py::array_t<std::uint8_t> rgb(long long k, int width, int height, const std::string& backend) {
    const scene::Scene s = moment(k, width, height);
    scene::Image image;
    {
      py::gil_scoped_release release;
      // A context per picture: it is made current on the calling thread, whichever Python
      // thread that is, and nothing GL outlives the call (no context torn down at exit).
      render::Painter painter(backend);
      painter.paint(s, scene::fit_scene(s, width, height), 0, image);
    }
    py::array_t<std::uint8_t> out({py::ssize_t{image.height}, py::ssize_t{image.width}, py::ssize_t{3}});
    std::uint8_t* to = out.mutable_data();
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    for (std::size_t i = 0; i < pixels; ++i)
      to[3 * i] = image.rgba[4 * i], to[3 * i + 1] = image.rgba[4 * i + 1], to[3 * i + 2] = image.rgba[4 * i + 2];
    return out;
  }

  // An (height, width, 3) uint8 array as PNG bytes (Jupyter's _repr_png_).
  static py::bytes png(const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& rgb) {
    if (rgb.ndim() != 3 || rgb.shape(2) != 3 || rgb.shape(0) < 1 || rgb.shape(1) < 1)
      throw py::value_error("png: expected an RGB array of shape (height, width, 3)");
    scene::Image image;
    image.height = static_cast<int>(rgb.shape(0));
    image.width = static_cast<int>(rgb.shape(1));
    const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    image.rgba.resize(pixels * 4);
    const std::uint8_t* from = rgb.data();
    for (std::size_t i = 0; i < pixels; ++i) {
      for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = from[3 * i + c];
      image.rgba[4 * i + 3] = 255;
    }
    const std::vector<std::uint8_t> bytes = scene::encode_png(image);
    return py::bytes(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }

 private:
  // The scene of the moment after K steps, with the default drawing options.
  scene::Scene moment(long long k, int width, int height) {
    if (width < 16 || height < 16 || width > 16384 || height > 16384)
      throw py::value_error("size: width and height must be 16 to 16384 pixels");
    cursor_->seek_step(step_arg(k));
    scene::SceneOptions options;
    scene::FaceAges ages;
    ages.update(*cursor_);
    return scene::build_scene(*cursor_, options, &ages);
  }

  std::unique_ptr<replay::LogReader> reader_;
  std::unique_ptr<replay::Replay> cursor_;
};

}  // namespace

void bind_log(py::module_& m) {
  py::class_<LogFile>(m, "LogFile")
      .def(py::init<const std::string&>(), py::arg("path"))
      .def_property_readonly("path", [](const LogFile& l) { return l.reader().path(); })
      .def_property_readonly("algorithm", [](const LogFile& l) { return l.reader().header().algorithm; })
      .def_property_readonly("parameters", [](const LogFile& l) { return l.reader().header().parameters; })
      .def_property_readonly("input", [](const LogFile& l) { return l.reader().header().input; })
      .def_property_readonly("data_structure", [](const LogFile& l) { return l.reader().header().data_structure; })
      .def_property_readonly("complete", [](const LogFile& l) { return l.reader().complete(); })
      .def_property_readonly("event_count", [](const LogFile& l) { return l.reader().event_count(); })
      .def_property_readonly("step_count", [](const LogFile& l) { return l.reader().step_count(); })
      .def("steps", &LogFile::steps)
      .def("phases", &LogFile::phases)
      .def("mesh", &LogFile::mesh, py::arg("step"))
      .def("event_json", &LogFile::event_json, py::arg("event"))
      .def("describe_event", &LogFile::describe_event, py::arg("event"))
      .def("explain", &LogFile::explain, py::arg("step"))
      .def("svg", &LogFile::svg, py::arg("step"), py::arg("width"), py::arg("height"))
      .def("rgb", &LogFile::rgb, py::arg("step"), py::arg("width"), py::arg("height"), py::arg("backend"));
  m.def("png_bytes", &LogFile::png, py::arg("rgb"), "An (height, width, 3) uint8 array as the bytes of a PNG file.");
  py::register_exception<render::GlUnavailable>(m, "GlUnavailable", PyExc_RuntimeError);
}

}  // namespace meshstep::python
