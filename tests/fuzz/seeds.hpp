// The harnesses' seed corpora, made from the project's examples and small inputs of its own
// (the hardening campaign's reproducers among them): every file a valid input, so that the
// fuzzers start from the readers' and the pipeline's deep paths. Written by make_seeds for
// the fuzz build, and by the damaged-input test (tests/unit/test_damaged_inputs.cpp), which
// feeds the same files, and damaged copies of them, to the real commands.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "log_bytes.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/surface/surface_refine.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"

namespace meshstep::fuzz::seeds {

namespace fs = std::filesystem;

inline std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

inline const std::vector<std::pair<std::string, std::string>> kSmallPolys = {
    {"square_hole.poly", "8 2 0 1\n1 0 0 1\n2 4 0 1\n3 4 4 1\n4 0 4 1\n5 1 1 2\n6 3 1 2\n7 3 3 2\n8 1 3 2\n"
                         "8 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n1\n1 2 2\n"},
    {"regions.poly", "6 2 0 0\n1 0 0\n2 2 0\n3 4 0\n4 4 4\n5 2 4\n6 0 4\n7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n"
                     "6 6 1\n7 2 5\n0\n2\n1 1 2 1 0.5\n2 3 2 2 -1\n"},
    {"crossing_next_to_vertex.poly", "6 2 0 0\n0 0 0\n1 1 5\n2 1 0\n3 0 1\n4 0.15 0.75\n5 1 0\n3 0\n0 0 1\n1 2 3\n2 4 5\n0\n"},
    {"magnitudes_apart.poly", "5 2 0 0\n0 1.0 0.0\n1 0.0 1.0\n2 0.1 0.7\n3 0.0 9233720368545808.0\n4 2.0 0.0\n2 0\n0 1 4\n"
                              "1 3 2\n0\n"},
    {"collinear.poly", "5 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 3 0\n5 1.5 1e-30\n2 0\n1 1 4\n2 2 5\n0\n"},
    {"duplicates.poly", "5 2 0 0\n1 0 0\n2 1 0\n3 1 0\n4 0 1\n5 0 0\n3 0\n1 1 2\n2 3 4\n3 4 5\n0\n"},
};

// Stored raw, so that the fuzzer's mutations land in the events themselves.
inline void store_raw(const fs::path& log) {
  const std::string bytes = read(log);
  const std::vector<std::uint8_t> raw = with_raw_payloads({bytes.begin(), bytes.end()});
  write(log, std::string(raw.begin(), raw.end()));
}

inline fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() / ("make_seeds_" + std::to_string(::getpid()) + "_" + name);
}

// A terrain run (`meshstep terrain GRID --record`): elevation events, the grid in the header.
inline void write_terrain_log(const fs::path& log, const std::string& asc_text, const std::string& name) {
  const fs::path asc = scratch(name);
  write(asc, asc_text);
  const terrain::HeightGrid grid = terrain::read_height_grid(asc.string());
  fs::remove(asc);
  const auto [low, high] = grid.height_range();
  terrain::TerrainOptions options;
  options.max_error = 0.05 * (static_cast<double>(high) - low);
  options.improve = true;
  options.flips_3d = true;
  replay::LogHeader header;
  header.algorithm = "lepp-surface";
  header.parameters = "max_error=" + std::to_string(options.max_error) + " input_vertices=4 grid_columns=" +
                      std::to_string(grid.nx) + " grid_rows=" + std::to_string(grid.ny) + " dx=" +
                      std::to_string(grid.dx) + " dy=" + std::to_string(grid.dy) + " terminal=centroid improve=1 flips_3d=1";
  fs::create_directories(log.parent_path());
  replay::LogWriter writer(log.string(), header);
  options.record = &writer;
  (void)terrain::approximate(grid, options);
  writer.finish();
}

// A surface refinement (`meshstep refine SURFACE --record`): the loading, then bisections.
inline void write_surface_log(const fs::path& log, const std::string& obj_text, double max_edge) {
  const fs::path obj = scratch("surface.obj");
  write(obj, obj_text);
  const io::Surface in = io::read_surface(obj.string());
  fs::remove(obj);
  surface::BisectionOptions options;
  options.max_edge = max_edge;
  options.max_triangles = 200;
  options.flip_dihedral_deg = 10;
  replay::LogHeader header;
  header.algorithm = "lepp-bisection";
  header.parameters = "surface=1 insertion=bisection size=" + std::to_string(max_edge) +
                      " input_vertices=" + std::to_string(in.vertices.size()) + " max_triangles=200 flip_dihedral=10";
  fs::create_directories(log.parent_path());
  replay::LogWriter writer(log.string(), header);
  options.record = &writer;
  (void)surface::bisect_surface(in, options);
  writer.finish();
}

inline const std::string kHillGrid = "ncols 5\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 10\n1 2 3 2 1\n2 4 6 4 2\n2 5 9 5 2\n1 2 3 2 1\n";
inline const std::string kHolesGrid =
    "ncols 4\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -1\n-1 2 3 4\n5 -1 7 8\n9 10 11 -1\n";
inline const std::string kTetraObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";

// Writes every harness's seeds into OUT/<harness>/; returns the number of logs written.
inline int write_seeds(const fs::path& assets, const fs::path& out) {
  std::vector<std::pair<std::string, std::string>> polys = kSmallPolys;
  for (const char* name : {"plate.poly", "lesson.poly"}) polys.emplace_back(name, read(assets / name));
  const std::string node = read(assets / "cocircular.node");

  // Triangle's formats: the first byte picks the reader.
  write(out / "triangle_io" / "cocircular.node", std::string(1, '\0') + node);
  for (const auto& [name, text] : polys) write(out / "triangle_io" / name, std::string(1, '\1') + text);
  {
    const fs::path tmp = fs::temp_directory_path() / ("make_seeds_" + std::to_string(::getpid()));
    fs::create_directories(tmp);
    io::write_mesh((tmp / "plate").string(), triangulate(io::read_poly((assets / "plate.poly").string())));
    write(out / "triangle_io" / "plate_mesh", std::string(1, '\2') + read(tmp / "plate.node") + '\0' + read(tmp / "plate.ele"));
    fs::remove_all(tmp);
  }

  // ESRI grids.
  write(out / "esri_grid" / "small.asc", "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1.5\n1 2 3\n4 5 6\n");
  write(out / "esri_grid" / "nodata.asc",
        "ncols 2\nnrows 2\nxllcenter 10\nyllcenter -5\ncellsize 0.25\nNODATA_value -9999\n-9999 2\n3.5e2 4\n");

  // Surfaces: the first byte picks the reader (0 .off, 1 .obj, 2 .ply, 3 .stl) and the
  // dihedral bound, the next two the refinement's bounds (fuzz_surface.cpp).
  const std::string area_bound("\0\x40", 2), edge_bound("\1\x60", 2), both_capped("\6\x20", 2);
  write(out / "surface" / "square.off", std::string(1, '\0') + area_bound + "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 1\n3 0 1 2\n3 0 2 3\n");
  write(out / "surface" / "tetra.obj", std::string(1, '\1') + edge_bound + kTetraObj);
  write(out / "surface" / "quad.ply", std::string(1, '\2') + both_capped +
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  write(out / "surface" / "one.stl", std::string(1, '\3') + area_bound +
        "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n");
  write(out / "surface" / "flat_grid.off", std::string("\0\2\x30", 3) +
        "OFF\n9 8 0\n0.09 0.17 0\n1.21 0.31 0\n2.17 0.3 0\n-0.33 0.98 0\n1.31 1.1 0\n2.28 0.73 0\n-0.02 1.82 0\n"
        "1.03 2.05 0\n1.66 1.8 0\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n3 4 5 8\n3 4 8 7\n");

  // Polygons: the first byte picks the reader (0 GeoJSON, 1 WKT), the rest is the file.
  write(out / "polygons" / "lake.geojson",
        std::string(1, '\0') + R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
 "geometry": {"type": "Polygon", "coordinates": [[[0,0],[4,0],[4,4],[0,4],[0,0]],
  [[1,1],[3,1],[3,1.5],[1.5,1.5],[1.5,2.5],[3,2.5],[3,3],[1,3],[1,1]]]}}]})");
  write(out / "polygons" / "island.geojson",
        std::string(1, '\0') + R"({"type": "MultiPolygon", "coordinates": [
 [[[0,0],[10,0],[10,10],[0,10],[0,0]], [[2,2],[8,2],[8,8],[2,8],[2,2]]],
 [[[4,4],[6,4],[6,6],[4,6],[4,4]]]]})");
  write(out / "polygons" / "lake.wkt",
        std::string(1, '\1') + "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1))\n");
  write(out / "polygons" / "collection.wkt",
        std::string(1, '\1') + "SRID=4326;GEOMETRYCOLLECTION (POINT (9 9), MULTIPOLYGON (((0 0, 2 0, 2 2, 0 0)), "
                                "((3 0, 5 0, 5 2 7, 3 0))))\n");

  // Terrains: small height grids, one with a hole of no data and a corner without any.
  write(out / "terrain" / "hill.asc", kHillGrid);
  write(out / "terrain" / "holes.asc", kHolesGrid);

  // The pipeline: a byte of choices, then the .poly.
  for (const auto& [name, text] : polys)
    for (const char choice : {'\0', '\7', '\x19'}) write(out / "pipeline" / (name + "_" + std::to_string(int(choice))), choice + text);

  // Refinement under options: eight bytes of choices (fuzz_refine_options.cpp), then the
  // .poly; every algorithm of the registry, with and without area and size bounds.
  const std::size_t algorithm_count = algorithms().size();
  for (const auto& [name, text] : polys)
    for (std::size_t a = 0; a < algorithm_count; ++a) {
      // algorithm, flags, order, min angle (about 25), max angle, bounds, Steiner cap, triangle cap
      const std::string options = {char(a), char(a * 37), char(a), char(106), char(a % 2 ? 200 : 0),
                                   char(a % 3 == 0 ? 0 : a % 3 == 1 ? 0x03 : 0x20), char(60), char(0)};
      write(out / "refine_options" / (name + "_" + std::to_string(a)), options + text);
    }

  // Replay logs: a triangulation and refinements, recorded.
  int n = 0;
  for (const auto& [name, text] : polys) {
    if (name == "plate.poly" || name == "magnitudes_apart.poly") continue;
    const fs::path poly = fs::temp_directory_path() / ("make_seeds_" + std::to_string(::getpid()) + ".poly");
    write(poly, text);
    const Pslg in = io::read_poly(poly.string());
    for (const char* algorithm : {"triangulate", "offcenter", "lepp-centroid"}) {
      const fs::path log = out / "replay_log" / (name + "_" + algorithm + ".mslog");
      fs::create_directories(log.parent_path());
      replay::LogHeader header;
      header.algorithm = algorithm;
      header.parameters = "input_vertices=" + std::to_string(in.points.size()) + " min_angle=25";
      replay::describe_input(header, in);
      replay::LogWriter writer(log.string(), header);
      if (std::string(algorithm) == "triangulate") {
        TriangulateOptions o;
        o.record = &writer;
        triangulate(in, o);
      } else {
        RefineOptions o = options_for(*find_algorithm(algorithm));
        o.criteria.min_angle_deg = 25;
        o.criteria.max_steiner = 100;
        o.triangulate.record = &writer;
        refine(in, o);
      }
      writer.finish();
      store_raw(log);
      ++n;
    }
    fs::remove(poly);
  }
  // A terrain run and surface refinements: elevation events, and steps of their own kinds.
  for (const auto& [name, grid] : {std::pair{"hill", kHillGrid}, std::pair{"holes", kHolesGrid}}) {
    const fs::path log = out / "replay_log" / (std::string(name) + "_terrain.mslog");
    write_terrain_log(log, grid, std::string(name) + ".asc");
    store_raw(log);
    ++n;
  }
  for (const double max_edge : {0.5, 0.3}) {
    const fs::path log = out / "replay_log" / ("tetra_surface_" + std::to_string(max_edge).substr(0, 3) + ".mslog");
    write_surface_log(log, kTetraObj, max_edge);
    store_raw(log);
    ++n;
  }
  return n;
}

}  // namespace meshstep::fuzz::seeds
