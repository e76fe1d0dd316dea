// numpy arrays in and out (numpy_arrays.hpp).
#include "numpy_arrays.hpp"

#include <cmath>
#include <cstring>

#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::python {
namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// The array's rows when it has the shape asked for; throws otherwise.
template <class Array>
std::size_t check_shape(const Array& a, std::size_t columns, const std::string& what) {
  const bool two_d = a.ndim() == 2 && static_cast<std::size_t>(a.shape(1)) == columns;
  const bool one_d = columns == 1 && a.ndim() == 1;
  // An empty list reads as shape (0,): no rows, whatever the columns.
  const bool empty = a.ndim() == 1 && a.shape(0) == 0;
  if (!two_d && !one_d && !empty)
    throw py::value_error(what + ": expected an array of shape (n, " + std::to_string(columns) + ")" +
                          (columns == 1 ? " or (n,)" : "") + ", got " + shape_text(a));
  return static_cast<std::size_t>(a.shape(0));
}

template <class Array>
Array as_array(const py::handle& value, const std::string& what, const char* kind) {
  // ensure() clears numpy's own error and returns an empty handle when it cannot convert.
  Array a = Array::ensure(value);
  if (!a) throw py::value_error(what + ": expected an array of " + kind + ", got " +
                                py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  return a;
}

std::size_t rows_of(const py::array& a) { return a.ndim() == 0 ? 0 : static_cast<std::size_t>(a.shape(0)); }

// A whole number read as a double (exact up to 2^53, far beyond any index): 1.5 or NaN is
// refused rather than cut.
std::int64_t whole(double r, const std::string& what, std::size_t row) {
  if (!(std::floor(r) == r) || std::fabs(r) > 9.0e15)
    throw py::value_error(what + ": row " + std::to_string(row) + ": expected a whole number, got " +
                          py::repr(py::float_(r)).cast<std::string>());
  return static_cast<std::int64_t>(r);
}

std::uint32_t vertex_index(double r, std::size_t vertex_count, const std::string& what, std::size_t row) {
  const std::int64_t v = whole(r, what, row);
  if (v < 0 || static_cast<std::uint64_t>(v) >= vertex_count)
    throw py::value_error(what + ": row " + std::to_string(row) + " names vertex " + std::to_string(v) + ", but there " +
                          (vertex_count == 1 ? "is 1 vertex" : "are " + std::to_string(vertex_count) + " vertices") +
                          " (indices start at 0)");
  return static_cast<std::uint32_t>(v);
}

}  // namespace

DoubleArray as_reals(const py::handle& value, const std::string& what) {
  return as_array<DoubleArray>(value, what, "numbers");
}

DoubleArray real_table(const py::handle& value, std::size_t columns, const std::string& what) {
  DoubleArray a = as_array<DoubleArray>(value, what, "numbers");
  check_shape(a, columns, what);
  return a;
}

std::vector<Point> points_from(const py::handle& value, const std::string& what) {
  const DoubleArray a = real_table(value, 2, what);
  std::vector<Point> points(rows_of(a));
  static_assert(sizeof(Point) == 2 * sizeof(double));
  if (!points.empty()) std::memcpy(static_cast<void*>(points.data()), a.data(), points.size() * sizeof(Point));
  return points;
}

std::vector<Segment> segments_from(const py::handle& value, std::size_t vertex_count, const std::string& what) {
  const DoubleArray a = real_table(value, 2, what);
  const std::size_t n = rows_of(a);
  const double* v = a.data();
  std::vector<Segment> segments(n);
  for (std::size_t i = 0; i < n; ++i) {
    segments[i].a = vertex_index(v[2 * i], vertex_count, what, i);
    segments[i].b = vertex_index(v[2 * i + 1], vertex_count, what, i);
  }
  return segments;
}

std::vector<std::array<std::uint32_t, 3>> triangles_from(const py::handle& value, std::size_t vertex_count,
                                                         const std::string& what) {
  const DoubleArray a = real_table(value, 3, what);
  const std::size_t n = rows_of(a);
  const double* v = a.data();
  std::vector<std::array<std::uint32_t, 3>> triangles(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) triangles[i][k] = vertex_index(v[3 * i + k], vertex_count, what, i);
  return triangles;
}

std::vector<int> ints_from(const py::handle& value, std::size_t expected, const std::string& what) {
  const DoubleArray a = real_table(value, 1, what);
  const std::size_t n = rows_of(a);
  if (n != expected)
    throw py::value_error(what + ": expected " + std::to_string(expected) + " rows, one for each, got " + std::to_string(n));
  std::vector<int> out(n);
  const double* r = a.data();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t v = whole(r[i], what, i);
    if (v < INT32_MIN || v > INT32_MAX)
      throw py::value_error(what + ": row " + std::to_string(i) + " is out of the range of a 32-bit integer");
    out[i] = static_cast<int>(v);
  }
  return out;
}

std::vector<double> reals_from(const py::handle& value, std::size_t expected, const std::string& what) {
  const DoubleArray a = real_table(value, 1, what);
  const std::size_t n = rows_of(a);
  if (n != expected)
    throw py::value_error(what + ": expected " + std::to_string(expected) + " rows, one for each, got " + std::to_string(n));
  return std::vector<double>(a.data(), a.data() + n);
}

py::array_t<double> points_array(const std::vector<Point>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  if (!points.empty()) std::memcpy(a.mutable_data(), points.data(), points.size() * sizeof(Point));
  return a;
}

py::array_t<double> reals_array(const std::vector<double>& values, std::size_t columns) {
  const std::size_t rows = columns ? values.size() / columns : 0;
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
  if (rows) std::memcpy(a.mutable_data(), values.data(), rows * columns * sizeof(double));
  return a;
}

py::array_t<std::int32_t> ints_array(const std::vector<int>& values, std::size_t columns) {
  const std::size_t rows = columns ? values.size() / columns : 0;
  py::array_t<std::int32_t> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
  std::int32_t* out = a.mutable_data();
  for (std::size_t i = 0; i < rows * columns; ++i) out[i] = values[i];
  return a;
}

py::array_t<std::int32_t> triangles_array(const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  py::array_t<std::int32_t> a({static_cast<py::ssize_t>(triangles.size()), py::ssize_t{3}});
  std::int32_t* out = a.mutable_data();
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) out[3 * t + k] = static_cast<std::int32_t>(triangles[t][k]);
  return a;
}

py::array_t<std::int32_t> neighbors_array(const std::vector<std::array<std::uint32_t, 3>>& neighbors) {
  py::array_t<std::int32_t> a({static_cast<py::ssize_t>(neighbors.size()), py::ssize_t{3}});
  std::int32_t* out = a.mutable_data();
  for (std::size_t t = 0; t < neighbors.size(); ++t)
    for (int k = 0; k < 3; ++k)
      out[3 * t + k] = neighbors[t][k] == kNoIndex ? -1 : static_cast<std::int32_t>(neighbors[t][k]);
  return a;
}

py::array_t<std::int32_t> segments_array(const std::vector<Segment>& segments) {
  py::array_t<std::int32_t> a({static_cast<py::ssize_t>(segments.size()), py::ssize_t{2}});
  std::int32_t* out = a.mutable_data();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    out[2 * i] = static_cast<std::int32_t>(segments[i].a);
    out[2 * i + 1] = static_cast<std::int32_t>(segments[i].b);
  }
  return a;
}

py::array_t<std::int32_t> segment_markers_array(const std::vector<Segment>& segments) {
  py::array_t<std::int32_t> a({static_cast<py::ssize_t>(segments.size()), py::ssize_t{1}});
  std::int32_t* out = a.mutable_data();
  for (std::size_t i = 0; i < segments.size(); ++i) out[i] = segments[i].marker;
  return a;
}

}  // namespace meshstep::python
