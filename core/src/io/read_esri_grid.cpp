// Reading ESRI ASCII grids (io/esri_grid.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "io/fields.hpp"
#include "io/grid_cells.hpp"
#include "io/record_reader.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/esri_grid.hpp"

namespace meshstep::io {
using detail::checked_grid_cells;
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// The most values the file holds from the current record on: that record's fields, then
// (each value a character and a separator, but the last) half the bytes after it.
std::optional<std::uint64_t> room_for_values(const detail::RecordReader& r, bool have_record) {
  if (!have_record) return 0;
  const std::optional<std::uint64_t> rest = r.remaining_bytes();
  if (!rest) return std::nullopt;  // a pipe: the values are counted as they arrive
  return r.field_count() + (*rest + 1) / 2;
}

}  // namespace

double EsriGrid::at(const Point& p, double outside) const {
  const double fx = (p.x - x0) / cellsize, fy = (p.y - y0) / cellsize;
  if (!(fx >= 0.0 && fy >= 0.0 && fx <= static_cast<double>(ncols) && fy <= static_cast<double>(nrows))) return outside;
  const auto column = std::min(static_cast<std::size_t>(fx), ncols - 1);
  const auto row_from_south = std::min(static_cast<std::size_t>(fy), nrows - 1);
  const double v = values[(nrows - 1 - row_from_south) * ncols + column];
  return has_nodata && v == nodata ? outside : v;
}

EsriGrid read_esri_grid_rows(const std::string& path, const EsriRowVisitor& visit) {
  detail::RecordReader r(path);
  EsriGrid g;
  std::size_t* const key_lines[6] = {&g.lines.ncols, &g.lines.nrows,    &g.lines.x0,
                                     &g.lines.y0,    &g.lines.cellsize, &g.lines.nodata};
  bool x_center = false, y_center = false;
  const auto header_key = [](const std::string& key) -> int {
    if (key == "ncols") return 0;
    if (key == "nrows") return 1;
    if (key == "xllcorner" || key == "xllcenter") return 2;
    if (key == "yllcorner" || key == "yllcenter") return 3;
    if (key == "cellsize") return 4;
    if (key == "nodata_value") return 5;
    return -1;
  };
  bool have_record = r.next();
  for (; have_record; have_record = r.next()) {
    const std::string key = lower(r.field(0));
    const int k = header_key(key);
    if (k < 0) break;  // the values begin
    detail::expect_fields(r, 2, "key, value");
    if (*key_lines[k] != 0) r.fail("'" + key + "' appears twice");
    *key_lines[k] = r.line();
    // What a number means is checked at its own line, not where the values begin.
    switch (k) {
      case 0:
        g.ncols = detail::parse_count(r, 1, "ncols");
        if (g.ncols == 0) r.fail("ncols must be positive");
        break;
      case 1:
        g.nrows = detail::parse_count(r, 1, "nrows");
        if (g.nrows == 0) r.fail("nrows must be positive");
        break;
      case 2: g.x0 = detail::parse_real(r, 1, key); x_center = key == "xllcenter"; break;
      case 3: g.y0 = detail::parse_real(r, 1, key); y_center = key == "yllcenter"; break;
      case 4:
        g.cellsize = detail::parse_real(r, 1, "cellsize");
        if (!(g.cellsize > 0.0)) r.fail("cellsize must be positive");
        break;
      case 5: g.nodata = detail::parse_real(r, 1, "NODATA_value"); g.has_nodata = true; break;
    }
  }
  const char* names[] = {"ncols", "nrows", "xllcorner or xllcenter", "yllcorner or yllcenter", "cellsize"};
  for (int k = 0; k < 5; ++k)
    if (*key_lines[k] == 0) r.fail(std::string("the header has no ") + names[k]);
  if (x_center) g.x0 -= g.cellsize / 2.0;
  if (y_center) g.y0 -= g.cellsize / 2.0;
  // The header's size against what the file can hold, before any value is read or any
  // room made for them, named at the later of the two counts' lines.
  const std::uint64_t count =
      checked_grid_cells(path, std::max(g.lines.ncols, g.lines.nrows), g.ncols, g.nrows, room_for_values(r, have_record));
  // One row at a time: it grows with the values that arrive (the file may be short).
  std::vector<double> row;
  std::size_t rows_done = 0;
  for (; have_record; have_record = r.next())
    for (std::size_t i = 0; i < r.field_count(); ++i) {
      if (rows_done == g.nrows) r.fail("more values than ncols x nrows = " + std::to_string(count));
      row.push_back(detail::parse_real(r, i, "grid value"));
      if (row.size() == g.ncols) {
        visit(g, rows_done++, row, r.line());
        row.clear();
      }
    }
  const std::uint64_t found = static_cast<std::uint64_t>(rows_done) * g.ncols + row.size();
  if (found != count)
    r.fail("the grid has " + std::to_string(found) + " values; ncols x nrows = " + std::to_string(count) +
           " (the file is truncated, or the header's counts are wrong)");
  return g;
}

EsriGrid read_esri_grid(const std::string& path) {
  std::vector<double> values;
  EsriGrid g = read_esri_grid_rows(path, [&](const EsriGrid& header, std::size_t row, std::span<const double> v,
                                             std::size_t) {
    if (row == 0) values.reserve(std::min<std::size_t>(header.cell_count(), std::size_t{1} << 24));
    values.insert(values.end(), v.begin(), v.end());
  });
  g.values = std::move(values);
  return g;
}

}  // namespace meshstep::io
