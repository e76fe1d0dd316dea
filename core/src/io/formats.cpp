// The table of file formats (formats.hpp).
#include "meshstep/io/formats.hpp"

#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "meshstep/io/mesh_formats.hpp"
#include "meshstep/io/polygon_io.hpp"
#include "meshstep/io/triangle_io.hpp"

namespace meshstep::io {
namespace {

constexpr std::string_view kSurfaceCarries = "triangles at z = 0 (no segments, markers or regions)";

constexpr std::array kFormats = {
    FileFormat{".poly", FileKind::pslg, true, true, "Triangle's PSLG: vertices, segments, holes, regions",
               {}, read_poly},
    FileFormat{".node", FileKind::points, true, true, "Triangle's vertices: a point set, or a mesh PREFIX's vertices",
               {}, read_node},
    FileFormat{".ele", FileKind::mesh, true, true,
               "Triangle's triangles (with .node, a mesh PREFIX to check, view or refine again)"},
    FileFormat{".area", FileKind::area, true, true, "Triangle's per-triangle maximum areas (with a mesh PREFIX)"},
    FileFormat{".edge", FileKind::mesh, false, true, "Triangle's edges (-e)"},
    FileFormat{".neigh", FileKind::mesh, false, true, "Triangle's neighbours (-n)"},
    FileFormat{".geojson", FileKind::pslg, true, false,
               "GeoJSON polygons (Polygon, MultiPolygon, Feature, FeatureCollection; holes as holes) as a PSLG",
               {}, read_geojson},
    FileFormat{".wkt", FileKind::pslg, true, false, "WKT polygons (POLYGON, MULTIPOLYGON; holes as holes) as a PSLG",
               {}, read_wkt},
    FileFormat{".msh", FileKind::mesh, false, true, "gmsh mesh, format 4.1 ASCII",
               "triangles; segments as line elements; physical groups from segment markers and region attributes",
               nullptr, write_gmsh},
    FileFormat{".vtu", FileKind::mesh, false, true, "VTK XML unstructured grid (ParaView)",
               "triangles; cell data region, min_angle, quality (min angle / 60); point data marker",
               nullptr, write_vtu},
    FileFormat{".asc", FileKind::grid, true, false,
               "ESRI ASCII grid (refine --size GRID.asc; terrain heights, NODATA kept out)"},
    FileFormat{".png", FileKind::grid, true, true, "8/16-bit greyscale heightmap (terrain); also pictures (render, export)"},
    FileFormat{".tif", FileKind::grid, true, false, "GeoTIFF height grid (terrain, read through GDAL when present)"},
    FileFormat{".tiff", FileKind::grid, true, false, "GeoTIFF height grid, as .tif"},
    FileFormat{".off", FileKind::surface, true, true, "3D triangle surface (terrain output; refine input)",
               kSurfaceCarries, nullptr, write_mesh_off},
    FileFormat{".obj", FileKind::surface, true, true, "3D triangle surface, Wavefront (terrain output; refine input)",
               kSurfaceCarries, nullptr, write_mesh_obj},
    FileFormat{".ply", FileKind::surface, true, true, "3D triangle surface, PLY ASCII or binary (writes binary)",
               kSurfaceCarries, nullptr, write_mesh_ply},
    FileFormat{".stl", FileKind::surface, true, true,
               "3D triangle surface, STL ASCII or binary (writes binary: float32 coordinates)", kSurfaceCarries,
               nullptr, write_mesh_stl},
    FileFormat{".mslog", FileKind::log, true, true, "meshstep replay log (--record; read by meshstep log, render, view)"},
};

}  // namespace

std::span<const FileFormat> file_formats() { return kFormats; }

const FileFormat* format_of(std::string_view path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) return nullptr;
  std::string extension(path.substr(dot));
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const FileFormat& f : kFormats)
    if (f.extension == extension) return &f;
  return nullptr;
}

const FileFormat* mesh_writer_for(std::string_view path) {
  const FileFormat* f = format_of(path);
  return f && f->write_mesh ? f : nullptr;
}

const char* to_string(FileKind kind) {
  switch (kind) {
    case FileKind::pslg: return "pslg";
    case FileKind::points: return "points";
    case FileKind::mesh: return "mesh";
    case FileKind::area: return "area";
    case FileKind::grid: return "grid";
    case FileKind::surface: return "surface";
    case FileKind::log: return "log";
  }
  return "?";
}

// Case matters here as it always has for Triangle's files: "x.POLY" is no .poly input.
bool is_planar_input(std::string_view path) {
  for (const FileFormat& f : kFormats)
    if ((f.kind == FileKind::pslg || f.kind == FileKind::points) && path.ends_with(f.extension)) return true;
  return false;
}

bool is_surface(std::string_view path) {
  const FileFormat* f = format_of(path);
  return f && f->kind == FileKind::surface;
}

std::vector<std::string> mesh_prefix_files(const std::string& prefix, MeshPrefixFiles which) {
  // Triangle's files (.msh and .vtu are meshes too, but whole in one file). The table says
  // which are read: .edge and .neigh are written on request and never read.
  std::vector<std::string> files;
  for (const std::string_view ext : {".node", ".ele", ".poly", ".area", ".edge", ".neigh"})
    if (which == MeshPrefixFiles::written || format_of(ext)->read) files.push_back(prefix + std::string(ext));
  return files;
}

bool is_mesh_prefix(const std::string& prefix) {
  std::error_code ec;
  return std::filesystem::exists(prefix + ".node", ec) && std::filesystem::exists(prefix + ".ele", ec);
}

std::string mesh_prefix_of(const std::string& path) {
  for (const std::string_view ext : {std::string_view(".node"), std::string_view(".ele")})
    if (path.size() > ext.size() && path.ends_with(ext)) return path.substr(0, path.size() - ext.size());
  return path;
}

bool is_replay_log(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[8] = {};
  return in.read(magic, sizeof magic) && std::memcmp(magic, "MSTEPLOG", sizeof magic) == 0;
}

}  // namespace meshstep::io
