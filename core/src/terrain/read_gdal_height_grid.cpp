// GeoTIFF and every other raster GDAL reads, as a height grid (the first band), when
// meshstep is built with GDAL (MESHSTEP_HAVE_GDAL; core/CMakeLists.txt).
//
// Where the raster stands: its geotransform. A north-up raster (no rotation terms) is read;
// a rotated or sheared one is refused. Its cell size is in the units of its spatial
// reference: degrees for a geographic one (turned into metres at the raster's central
// latitude, on the sphere the ESRI reader uses: geographic.hpp), the projection's linear
// unit (times its metres per unit) for a projected one. Without a spatial reference the
// ESRI reader's guess decides, or HeightGridOptions::geographic. Heights are the band's
// values times its scale plus its offset; its NoData value, and NaN, are no data.
//
// GDAL is loaded the first time a grid needs it (dlopen of MESHSTEP_GDAL_SONAME), never
// linked: its hundred libraries would load with every meshstep process.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "io/grid_cells.hpp"
#include "meshstep/error.hpp"
#include "meshstep/huge_pages.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "terrain/geographic.hpp"
#include "terrain/height_grid_readers.hpp"

#ifdef MESHSTEP_HAVE_GDAL
#include <cpl_error.h>
#include <dlfcn.h>
#include <gdal.h>
#include <ogr_srs_api.h>
#endif

namespace meshstep::terrain::detail {

bool gdal_available() {
#ifdef MESHSTEP_HAVE_GDAL
  return true;
#else
  return false;
#endif
}

#ifndef MESHSTEP_HAVE_GDAL

HeightGrid read_gdal_height_rows(const std::string& path, const HeightGridOptions&, const HeightRowVisitor&) {
  throw InputError(path, 0,
                   "this meshstep was built without GDAL, which reads GeoTIFF and other rasters: install "
                   "libgdal-dev and build again (or convert the grid to .asc: gdal_translate -of AAIGrid)");
}

HeightGrid read_gdal_height_grid(const std::string& path, const HeightGridOptions& options) {
  return read_gdal_height_rows(path, options, nullptr);
}

#else

namespace {

// The GDAL functions this reader calls, looked up in the library once it is loaded; each
// pointer has the type the header declares.
struct GdalApi {
#define MESHSTEP_GDAL_FUNCTIONS(X)                                                                          \
  X(GDALAllRegister) X(CPLPushErrorHandler) X(CPLPopErrorHandler) X(CPLQuietErrorHandler) X(CPLErrorReset)   \
  X(CPLGetLastErrorMsg) X(GDALOpen) X(GDALClose) X(GDALGetRasterXSize) X(GDALGetRasterYSize)                 \
  X(GDALGetGeoTransform) X(GDALGetSpatialRef) X(OSRIsGeographic) X(OSRIsProjected) X(OSRGetLinearUnits)      \
  X(GDALGetRasterCount) X(GDALGetRasterBand) X(GDALGetRasterNoDataValue) X(GDALGetRasterScale)               \
  X(GDALGetRasterOffset) X(GDALRasterIO)
#define MESHSTEP_GDAL_POINTER(name) decltype(&::name) name = nullptr;
  MESHSTEP_GDAL_FUNCTIONS(MESHSTEP_GDAL_POINTER)
#undef MESHSTEP_GDAL_POINTER
  std::string failure;  // why GDAL could not be loaded ("" when it was)
};

// Loaded on first use, once for the process (thread-safe: a static's initialisation).
const GdalApi& gdal(const std::string& path) {
  static const GdalApi api = [] {
    GdalApi a;
    void* library = ::dlopen(MESHSTEP_GDAL_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
      const char* why = ::dlerror();
      a.failure = std::string("GDAL (" MESHSTEP_GDAL_SONAME ") cannot be loaded: ") + (why ? why : "no reason given") +
                  " (install libgdal32, or convert the grid to .asc: gdal_translate -of AAIGrid)";
      return a;
    }
#define MESHSTEP_GDAL_LOOKUP(name)                                                   \
  a.name = reinterpret_cast<decltype(&::name)>(::dlsym(library, #name));              \
  if (!a.name && a.failure.empty()) a.failure = "GDAL (" MESHSTEP_GDAL_SONAME ") has no " #name;
    MESHSTEP_GDAL_FUNCTIONS(MESHSTEP_GDAL_LOOKUP)
#undef MESHSTEP_GDAL_LOOKUP
    if (a.failure.empty()) a.GDALAllRegister();
    return a;
  }();
  if (!api.failure.empty()) throw InputError(path, 0, api.failure);
  return api;
}

// GDAL's messages go to the exceptions this reader throws, not to standard error.
class QuietGdal {
 public:
  explicit QuietGdal(const GdalApi& api) : api_(api) {
    api_.CPLPushErrorHandler(api_.CPLQuietErrorHandler);
    api_.CPLErrorReset();
  }
  ~QuietGdal() { api_.CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;

 private:
  const GdalApi& api_;
};

std::string gdal_says(const GdalApi& api, const char* fallback) {
  const char* message = api.CPLGetLastErrorMsg();
  return message && *message ? message : fallback;
}

class Dataset {
 public:
  Dataset(const GdalApi& api, const std::string& path) : api_(api), handle_(api.GDALOpen(path.c_str(), GA_ReadOnly)) {
    if (!handle_) throw InputError(path, 0, "GDAL cannot read it: " + gdal_says(api, "not a raster it knows"));
  }
  ~Dataset() { api_.GDALClose(handle_); }
  Dataset(const Dataset&) = delete;
  Dataset& operator=(const Dataset&) = delete;
  GDALDatasetH get() const { return handle_; }

 private:
  const GdalApi& api_;
  GDALDatasetH handle_;
};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

// The grid's sizes, spacing in metres and units, from the raster's geotransform and spatial
// reference. Sets north_up: whether the raster's first row is its northernmost.
HeightGrid layout_of(const GdalApi& api, const std::string& path, GDALDatasetH dataset,
                     const HeightGridOptions& options, bool& north_up) {
  HeightGrid grid;
  const int columns = api.GDALGetRasterXSize(dataset), rows = api.GDALGetRasterYSize(dataset);
  grid.nx = static_cast<std::size_t>(std::max(columns, 0));
  grid.ny = static_cast<std::size_t>(std::max(rows, 0));
  if (grid.nx < 2 || grid.ny < 2) throw InputError(path, 0, too_few_samples(grid.nx, grid.ny));
  // The file's bytes say nothing of a compressed raster's size: only the product is checked.
  io::detail::checked_grid_cells(path, 0, grid.nx, grid.ny, std::nullopt);

  double t[6] = {0.0, 1.0, 0.0, 0.0, 0.0, -1.0};
  const bool georeferenced = api.GDALGetGeoTransform(dataset, t) == CE_None;
  if (t[2] != 0.0 || t[4] != 0.0)
    throw InputError(path, 0,
                     "the raster is rotated or sheared (geotransform terms " + number(t[2]) + " and " + number(t[4]) +
                         "): warp it north-up first (gdalwarp)");
  if (!(t[1] > 0.0) || t[5] == 0.0 || !std::isfinite(t[1]) || !std::isfinite(t[5]))
    throw InputError(path, 0, "the raster's cells are " + number(t[1]) + " x " + number(t[5]) + ": not a grid");
  north_up = t[5] < 0.0;
  const double cell_x = t[1], cell_y = std::fabs(t[5]);
  const double west = t[0], south = north_up ? t[3] + t[5] * static_cast<double>(grid.ny) : t[3];
  grid.x0 = west + cell_x / 2.0;
  grid.y0 = south + cell_y / 2.0;

  const OGRSpatialReferenceH srs = api.GDALGetSpatialRef(dataset);
  GridExtent extent{west, south, std::max(cell_x, cell_y), grid.nx, grid.ny};
  bool degrees = false;
  double metres_per_unit = 1.0;
  if (options.geographic) {
    degrees = *options.geographic;
  } else if (srs) {
    degrees = api.OSRIsGeographic(srs) != 0;
  } else {
    degrees = georeferenced && looks_geographic(extent);
  }
  if (!degrees && srs && api.OSRIsProjected(srs)) metres_per_unit = api.OSRGetLinearUnits(srs, nullptr);

  if (degrees) {
    if (!latitudes_valid(extent))
      throw InputError(path, 0, "the raster's latitudes run from " + number(extent.south) + " to " +
                                    number(extent.north()) + ": not degrees (say --geographic no)");
    const double latitude = (south + south + cell_y * static_cast<double>(grid.ny)) / 2.0;
    grid.dx = degree_cells_in_metres(cell_x, latitude).dx;
    grid.dy = degree_cells_in_metres(cell_y, latitude).dy;
    grid.geographic = true;
    grid.units_note = geographic_note(cell_y, latitude, {grid.dx, grid.dy});
    if (cell_x != cell_y) grid.units_note += " (cells " + number(cell_x * 3600.0) + " arc-seconds east-west)";
  } else {
    grid.dx = cell_x * metres_per_unit;
    grid.dy = cell_y * metres_per_unit;
    if (!georeferenced) grid.units_note = "the raster has no georeferencing: 1 m cells";
    else if (metres_per_unit != 1.0)
      grid.units_note = "the raster's unit is " + number(metres_per_unit) + " m: cells of " + number(grid.dx) + " m x " +
                        number(grid.dy) + " m";
  }
  return grid;
}

}  // namespace

HeightGrid read_gdal_height_rows(const std::string& path, const HeightGridOptions& options,
                                 const HeightRowVisitor& visit) {
  const GdalApi& api = gdal(path);
  const QuietGdal quiet(api);
  const Dataset dataset(api, path);
  if (api.GDALGetRasterCount(dataset.get()) < 1) throw InputError(path, 0, "the raster has no band of heights");
  bool north_up = true;
  HeightGrid grid = layout_of(api, path, dataset.get(), options, north_up);
  const GDALRasterBandH band = api.GDALGetRasterBand(dataset.get(), 1);
  int has_nodata = 0, has_scale = 0, has_offset = 0;
  const double nodata = api.GDALGetRasterNoDataValue(band, &has_nodata);
  const double scale = api.GDALGetRasterScale(band, &has_scale), offset = api.GDALGetRasterOffset(band, &has_offset);

  std::vector<double> raw(grid.nx);
  std::vector<float> heights(grid.nx);
  std::size_t with_data = 0;
  // Northernmost row first, as HeightRowVisitor promises (and an ESRI grid stores them).
  for (std::size_t k = 0; k < grid.ny; ++k) {
    const std::size_t j = grid.ny - 1 - k;                  // the grid's row, 0 southernmost
    const std::size_t row = north_up ? k : j;               // the raster's row
    if (api.GDALRasterIO(band, GF_Read, 0, static_cast<int>(row), static_cast<int>(grid.nx), 1, raw.data(),
                     static_cast<int>(grid.nx), 1, GDT_Float64, 0, 0) != CE_None)
      throw InputError(path, 0, "GDAL cannot read row " + std::to_string(row) + ": " + gdal_says(api, "a read error"));
    for (std::size_t i = 0; i < grid.nx; ++i) {
      const double v = raw[i];
      if (std::isnan(v) || (has_nodata && v == nodata)) {
        heights[i] = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const double z = v * (has_scale ? scale : 1.0) + (has_offset ? offset : 0.0);
      if (!(std::fabs(z) <= FLT_MAX))
        throw InputError(path, 0, "row " + std::to_string(row) + ", column " + std::to_string(i) + ": height " +
                                      number(z) + " is not a finite float");
      heights[i] = static_cast<float>(z);
      ++with_data;
    }
    if (visit) visit(grid, j, heights);
  }
  if (with_data == 0) throw InputError(path, 0, "every sample is NoData: the grid has no data");
  return grid;
}

HeightGrid read_gdal_height_grid(const std::string& path, const HeightGridOptions& options) {
  std::vector<float> z;
  HeightGrid grid = read_gdal_height_rows(path, options, [&](const HeightGrid& header, std::size_t j,
                                                             std::span<const float> heights) {
    if (j == header.ny - 1) reserve_huge(z, header.nx * header.ny);
    z.insert(z.end(), heights.begin(), heights.end());
  });
  grid.z = std::move(z);
  flip_rows(grid);
  return grid;
}

#endif

}  // namespace meshstep::terrain::detail
