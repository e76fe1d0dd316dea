// Conversions between numpy arrays and the core's vectors: each array is converted once, in
// C++ (numpy casts the whole array to the type asked for; the loops here touch raw
// buffers), never element by element through Python. A wrong shape or a bad index is a
// ValueError naming the argument ("segments: expected an array of shape (M, 2), got (4, 3)").
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// `value` as a C-contiguous float64 array of shape (rows, columns): 2D with that many
// columns, or, when columns is 1, also 1D. Throws py::value_error naming `what`.
DoubleArray real_table(const py::handle& value, std::size_t columns, const std::string& what);

// Rows of (x, y).
std::vector<Point> points_from(const py::handle& value, const std::string& what);
// Any array of numbers as C-contiguous float64, whatever its shape.
DoubleArray as_reals(const py::handle& value, const std::string& what);

// Indices and markers are read as float64 too (exact to 2^53) and checked to be whole.
// Rows of (a, b) vertex indices, each checked to be in [0, vertex_count): a segment to a
// missing vertex names the row and the index.
std::vector<Segment> segments_from(const py::handle& value, std::size_t vertex_count, const std::string& what);
// Rows of three vertex indices, checked the same way.
std::vector<std::array<std::uint32_t, 3>> triangles_from(const py::handle& value, std::size_t vertex_count,
                                                         const std::string& what);
// One integer a row ((n,) or (n, 1)), `expected` rows.
std::vector<int> ints_from(const py::handle& value, std::size_t expected, const std::string& what);
// One real a row ((n,) or (n, 1)), `expected` rows.
std::vector<double> reals_from(const py::handle& value, std::size_t expected, const std::string& what);

// numpy arrays made from the core's vectors, one copy each.
py::array_t<double> points_array(const std::vector<Point>& points);
py::array_t<double> reals_array(const std::vector<double>& values, std::size_t columns);
py::array_t<std::int32_t> ints_array(const std::vector<int>& values, std::size_t columns);
py::array_t<std::int32_t> triangles_array(const std::vector<std::array<std::uint32_t, 3>>& triangles);
// kNoIndex becomes -1 (the triangle package's "no neighbour").
py::array_t<std::int32_t> neighbors_array(const std::vector<std::array<std::uint32_t, 3>>& neighbors);
py::array_t<std::int32_t> segments_array(const std::vector<Segment>& segments);
py::array_t<std::int32_t> segment_markers_array(const std::vector<Segment>& segments);

}  // namespace meshstep::python
