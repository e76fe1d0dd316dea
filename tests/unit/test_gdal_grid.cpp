// GeoTIFF height grids through GDAL (an optional dependency): rasters written here with
// GDAL's own API, read back as grids. North-up and south-up rows, NoData and NaN, scale
// and offset, metres, feet and degrees (converted as the ESRI reader converts them), and
// refusals: a rotated raster, a broken file, no data. Without GDAL, a .tif is refused with
// what to install, and the other tests skip.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/terrain/height_grid.hpp"
#include "meshstep/terrain/tin.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

#ifdef MESHSTEP_HAVE_GDAL
#include <gdal.h>
#include <ogr_srs_api.h>
#endif

namespace meshstep {
namespace {

using terrain::HeightGrid;
using terrain::read_height_grid;

std::string refusal(const std::string& path) {
  try {
    read_height_grid(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

#ifndef MESHSTEP_HAVE_GDAL

TEST(GdalGrid, WithoutGdalATifIsRefusedSayingWhatToInstall) {
  testing::TempDir dir("meshstep_gdal_");
  const std::string path = dir.write("dem.tif", "not read");
  const std::string message = refusal(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("libgdal-dev"), std::string::npos) << message;
}

#else

struct Raster {
  int nx = 4, ny = 3;
  std::vector<double> values;                        // row 0 first, as the file stores them
  std::array<double, 6> transform{1000, 10, 0, 2000, 0, -10};  // north-up, 10 m cells
  int epsg = 0;                                      // 0: no spatial reference
  std::string wkt;                                   // instead of an EPSG code
  std::optional<double> nodata, scale, offset;
  GDALDataType type = GDT_Float32;
};

void write_tif(const std::string& path, const Raster& r) {
  GDALAllRegister();
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  ASSERT_NE(driver, nullptr);
  GDALDatasetH ds = GDALCreate(driver, path.c_str(), r.nx, r.ny, 1, r.type, nullptr);
  ASSERT_NE(ds, nullptr);
  double t[6];
  std::copy(r.transform.begin(), r.transform.end(), t);
  GDALSetGeoTransform(ds, t);
  if (r.epsg || !r.wkt.empty()) {
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    if (r.epsg) OSRImportFromEPSG(srs, r.epsg);
    else {
      char* text = const_cast<char*>(r.wkt.c_str());
      OSRImportFromWkt(srs, &text);
    }
    OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
  }
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (r.nodata) GDALSetRasterNoDataValue(band, *r.nodata);
  if (r.scale) GDALSetRasterScale(band, *r.scale);
  if (r.offset) GDALSetRasterOffset(band, *r.offset);
  std::vector<double> v = r.values;
  ASSERT_EQ(GDALRasterIO(band, GF_Write, 0, 0, r.nx, r.ny, v.data(), r.nx, r.ny, GDT_Float64, 0, 0), CE_None);
  GDALClose(ds);
}

Raster ramp() {
  Raster r;
  for (int row = 0; row < r.ny; ++row)
    for (int i = 0; i < r.nx; ++i) r.values.push_back(100.0 * row + i);  // row 0: the north
  return r;
}

TEST(GdalGrid, NorthUpRowsBecomeSouthFirstWithTheirSpacing) {
  testing::TempDir dir("meshstep_gdal_");
  const std::string path = dir.file("ramp.tif");
  Raster r = ramp();
  r.epsg = 32633;  // UTM 33N: metres
  write_tif(path, r);
  const HeightGrid g = read_height_grid(path);
  ASSERT_EQ(g.nx, 4u);
  ASSERT_EQ(g.ny, 3u);
  EXPECT_EQ(g.dx, 10.0);
  EXPECT_EQ(g.dy, 10.0);
  EXPECT_FALSE(g.geographic);
  for (std::size_t j = 0; j < 3; ++j)
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(g.at(i, j), 100.0f * (2 - j) + i) << i << "," << j;
  EXPECT_EQ(g.x0, 1005.0);
  EXPECT_EQ(g.y0, 1975.0);  // the southern edge is 2000 - 3 x 10, the first centre 5 m up

  // South-up (a positive row step): the file's first row is the south.
  r.transform = {1000, 10, 0, 1970, 0, 10};
  write_tif(path, r);
  const HeightGrid up = read_height_grid(path);
  for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(up.at(1, j), 100.0f * j + 1) << j;
}

TEST(GdalGrid, NoDataNanScaleAndOffset) {
  testing::TempDir dir("meshstep_gdal_");
  const std::string path = dir.file("holes.tif");
  Raster r = ramp();
  r.values[1] = -9999;
  r.values[2] = std::numeric_limits<double>::quiet_NaN();
  r.nodata = -9999;
  r.scale = 0.5;
  r.offset = 10;
  write_tif(path, r);
  const HeightGrid g = read_height_grid(path);
  EXPECT_TRUE(std::isnan(g.at(1, 2)));  // row 0 of the file is the grid's northernmost, j = 2
  EXPECT_TRUE(std::isnan(g.at(2, 2)));
  EXPECT_EQ(g.at(3, 2), 0.5f * 3 + 10);
  EXPECT_EQ(g.at(0, 0), 0.5f * 200 + 10);
  EXPECT_EQ(g.data_count(), 10u);
}

TEST(GdalGrid, DegreesAndFeetBecomeMetres) {
  testing::TempDir dir("meshstep_gdal_");
  // 3 arc-second cells either side of 60 N, in WGS 84: as the ESRI reader converts them.
  Raster geo = ramp();
  const double cell = 3.0 / 3600.0;
  geo.transform = {10.0, cell, 0, 60.0 + 1.5 * cell, 0, -cell};
  geo.epsg = 4326;
  write_tif(dir.file("geo.tif"), geo);
  const HeightGrid g = read_height_grid(dir.file("geo.tif"));
  EXPECT_TRUE(g.geographic);
  const double along_meridian = terrain::kEarthMeanRadius * cell * std::numbers::pi / 180.0;
  EXPECT_DOUBLE_EQ(g.dy, along_meridian);
  EXPECT_NEAR(g.dx / g.dy, 0.5, 1e-9);
  EXPECT_NE(g.units_note.find("3 arc-second cells at 60.0 N"), std::string::npos) << g.units_note;
  // Told otherwise, the cells stay in their units.
  terrain::HeightGridOptions metres;
  metres.geographic = false;
  EXPECT_EQ(read_height_grid(dir.file("geo.tif"), metres).dy, cell);

  // A projection in US survey feet: cells of 10 ft are 3.048006 m.
  Raster feet = ramp();
  feet.epsg = 2263;  // NAD83 / New York Long Island (ftUS)
  write_tif(dir.file("feet.tif"), feet);
  const HeightGrid f = read_height_grid(dir.file("feet.tif"));
  EXPECT_NEAR(f.dx, 10.0 * 1200.0 / 3937.0, 1e-9);
  EXPECT_NE(f.units_note.find("m"), std::string::npos);
}

TEST(GdalGrid, RefusesARotatedRasterABrokenFileAndNoData) {
  testing::TempDir dir("meshstep_gdal_");
  Raster rotated = ramp();
  rotated.transform = {0, 10, 2, 0, 2, -10};
  write_tif(dir.file("rotated.tif"), rotated);
  EXPECT_NE(refusal(dir.file("rotated.tif")).find("rotated"), std::string::npos) << refusal(dir.file("rotated.tif"));

  const std::string broken = dir.write("broken.tif", "II*\0garbage");
  const std::string message = refusal(broken);
  EXPECT_NE(message.find(broken), std::string::npos) << message;
  EXPECT_NE(message.find("GDAL cannot read it"), std::string::npos) << message;

  Raster empty = ramp();
  empty.nodata = 5;
  for (double& v : empty.values) v = 5;
  write_tif(dir.file("empty.tif"), empty);
  EXPECT_NE(refusal(dir.file("empty.tif")).find("no data"), std::string::npos) << refusal(dir.file("empty.tif"));

  Raster thin = ramp();
  thin.ny = 1;
  thin.values.resize(4);
  write_tif(dir.file("thin.tif"), thin);
  EXPECT_NE(refusal(dir.file("thin.tif")).find("2 x 2"), std::string::npos) << refusal(dir.file("thin.tif"));
}

// The whole way: `meshstep terrain dem.tif` gives the TIN the same grid gives as .asc, and
// tiles stream the GeoTIFF row by row.
TEST(GdalGrid, TerrainReadsAGeoTiffAsItReadsTheSameAsc) {
  testing::TempDir dir("meshstep_gdal_");
  Raster hills;
  hills.nx = 40;
  hills.ny = 30;
  hills.transform = {0, 5, 0, 150, 0, -5};
  hills.epsg = 32633;
  std::string asc = "ncols 40\nnrows 30\nxllcorner 0\nyllcorner 0\ncellsize 5\n";
  for (int row = 0; row < 30; ++row) {
    for (int i = 0; i < 40; ++i) {
      const float z = static_cast<float>(50 + 10 * std::sin(i * 0.3) * std::cos(row * 0.2));
      hills.values.push_back(z);
      asc += std::to_string(z) + " ";
    }
    asc += "\n";
  }
  write_tif(dir.file("hills.tif"), hills);
  const std::string asc_path = dir.write("hills.asc", asc);
  const HeightGrid from_tif = read_height_grid(dir.file("hills.tif")), from_asc = read_height_grid(asc_path);
  EXPECT_EQ(from_tif.z, from_asc.z);
  EXPECT_EQ(from_tif.dx, from_asc.dx);

  const auto run = [&](const std::string& args) { return testing::run_meshstep(args, dir.path()); };
  const auto tif = run("terrain " + dir.file("hills.tif") + " --max-error 0.5 --stats json -q");
  const auto esri = run("terrain " + asc_path + " --max-error 0.5 --stats json -q");
  ASSERT_EQ(tif.status, 0) << tif.err;
  ASSERT_EQ(esri.status, 0) << esri.err;
  EXPECT_EQ(testing::json_field(testing::stats_line(tif.out), "triangles"),
            testing::json_field(testing::stats_line(esri.out), "triangles"));
  const auto tiles = run("terrain " + dir.file("hills.tif") + " --max-error 0.5 --tile 16 -o " + dir.file("t.obj") + " -q");
  EXPECT_EQ(tiles.status, 0) << tiles.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("t.r0-c0.obj")));
}

#endif

}  // namespace
}  // namespace meshstep
