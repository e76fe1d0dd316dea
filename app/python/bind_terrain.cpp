// The pieces of meshstep.terrain_tiles (meshstep/_terrain.py), which maps the tiles of a
// height grid over a Dask cluster: the tile layout of a grid, one tile's TIN (what
// `meshstep terrain GRID --tile N --tile-index R,C` computes and writes), and the join of
// the tiles with its check (what `meshstep terrain-join` does).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/tile_join.hpp"
#include "meshstep/terrain/tiles.hpp"
#include "meshstep/terrain/tin.hpp"
#include "numpy_arrays.hpp"

namespace meshstep::python {
namespace {

py::array_t<double> vertices3(const io::Surface& s) {
  py::array_t<double> a({static_cast<py::ssize_t>(s.vertices.size()), py::ssize_t{3}});
  double* out = a.mutable_data();
  for (std::size_t i = 0; i < s.vertices.size(); ++i) {
    out[3 * i] = s.vertices[i].x;
    out[3 * i + 1] = s.vertices[i].y;
    out[3 * i + 2] = s.vertices[i].z;
  }
  return a;
}

py::dict surface_dict(const io::Surface& s) {
  py::dict d;
  d["vertices"] = vertices3(s);
  d["triangles"] = triangles_array(s.triangles);
  return d;
}

io::Surface surface_from(const py::handle& tile) {
  const py::dict d = py::reinterpret_borrow<py::dict>(tile);
  const DoubleArray v = real_table(d["vertices"], 3, "tile vertices");
  io::Surface s;
  const std::size_t n = v.ndim() == 0 ? 0 : static_cast<std::size_t>(v.shape(0));
  s.vertices.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.vertices[i] = {v.data()[3 * i], v.data()[3 * i + 1], v.data()[3 * i + 2]};
  s.triangles = triangles_from(d["triangles"], n, "tile triangles");
  return s;
}

// The options `meshstep terrain` gives approximate_tile() by default for `algorithm`.
terrain::TerrainOptions terrain_options(const std::string& algorithm, double max_error) {
  const terrain::TerrainAlgorithmInfo* info = terrain::find_terrain_algorithm(algorithm);
  if (!info) throw py::value_error("algorithm: no terrain algorithm '" + algorithm + "' (lepp-surface, greedy)");
  if (!(max_error > 0.0) || !std::isfinite(max_error))
    throw py::value_error("max_error: must be a positive number of height units");
  terrain::TerrainOptions options;
  options.algorithm = info->algorithm;
  options.max_error = max_error;
  // lepp-surface improves by default; greedy stays the Garland-Heckbert baseline.
  options.improve = info->algorithm == terrain::TerrainAlgorithm::lepp_surface;
  return options;
}

}  // namespace

void bind_terrain(py::module_& m) {
  m.def(
      "tile_layout",
      [](const std::string& grid, std::size_t size) {
        if (size < 2) throw py::value_error("tile: a tile needs at least 2 x 2 samples");
        terrain::HeightGrid header;
        {
          py::gil_scoped_release release;
          // Streamed, keeping no row: the grid may be bigger than memory.
          header = terrain::read_height_grid_rows(grid, {}, [](const terrain::HeightGrid&, std::size_t,
                                                               std::span<const float>) {});
        }
        const terrain::TileLayout layout{header.nx, header.ny, std::min(size, std::max(header.nx, header.ny))};
        return std::make_pair(layout.rows(), layout.columns());
      },
      py::arg("grid"), py::arg("size"), "(rows, columns) of tiles of `size` samples a side of the grid file.");
  m.def(
      "terrain_tile",
      [](const std::string& grid, std::size_t size, std::size_t row, std::size_t column, double max_error,
         const std::string& algorithm, const std::string& output, const std::string& staged) {
        const terrain::TerrainOptions options = terrain_options(algorithm, max_error);
        std::optional<io::SurfaceFormat> format;
        if (!output.empty()) {
          format = io::surface_format_for(output);
          if (!format || *format == io::SurfaceFormat::stl_ascii || *format == io::SurfaceFormat::stl_binary)
            throw py::value_error(output + ": tiles are written as .obj, .off or .ply");
        }
        io::Surface surface;
        double error = 0.0;
        without_gil([&] {
          terrain::cut_tiles(grid, {}, size, terrain::TileIndex{row, column}, [&](const terrain::Tile& tile) {
            terrain::TerrainReport report;
            const terrain::Tin tin = terrain::approximate_tile(tile, options, &report);
            const terrain::ErrorMeasure measure = terrain::measure_error(tile.grid, tin);
            if (measure.uncovered > 0 || measure.max > max_error)
              throw InputError(grid, 0, "internal: a tile misses its bound");
            error = measure.max;
            surface = terrain::tile_surface(tile, tin);
            if (format) io::write_surface(staged, surface, *format);
          });
        });
        py::dict d = surface_dict(surface);
        d["max_error"] = error;
        return d;
      },
      py::arg("grid"), py::arg("size"), py::arg("row"), py::arg("column"), py::arg("max_error"),
      py::arg("algorithm"), py::arg("output"), py::arg("staged"),
      "Tile (row, column)'s TIN within max_error, as `meshstep terrain --tile-index` makes it; written to "
      "`staged` in the format of `output`'s extension when output is given.");
  m.def(
      "join_tiles",
      [](const py::list& tiles) {
        std::vector<io::Surface> surfaces;
        for (const py::handle& t : tiles) surfaces.push_back(surface_from(t));
        terrain::SurfaceWelder welder;
        terrain::TileJoinCheck check;
        io::Surface joined;
        without_gil([&] {
          for (const io::Surface& s : surfaces) welder.add(s);
          joined = welder.take();
          check = terrain::check_joined_tiles(joined);
        });
        py::dict d = surface_dict(joined);
        d["check"] = terrain::describe(check);
        d["ok"] = check.ok();
        return d;
      },
      py::arg("tiles"), "The tiles welded into one surface, and the check of `meshstep terrain-join`.");
}

}  // namespace meshstep::python
