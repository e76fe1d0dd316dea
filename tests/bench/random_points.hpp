// Uniform random points in the unit square, shared by every benchmark program
// (bench_delaunay, cgal_compare, make_points) so that they all measure the same input.
//
// The doubles are built from the raw 64-bit output of std::mt19937_64, whose sequence is
// fixed by the C++ standard, rather than through std::uniform_real_distribution, whose
// algorithm is left to the library: the same seed gives bit-identical points with any
// compiler and standard library.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep::bench {

inline constexpr std::uint64_t kDefaultSeed = 20260101;

// A double in [0, 1): the top 53 bits of one engine output, scaled by 2^-53.
inline double unit_double(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// n points with x and y independent and uniform in [0, 1), drawn x then y.
inline std::vector<Point> uniform_points(std::size_t n, std::uint64_t seed = kDefaultSeed) {
  std::mt19937_64 engine(seed);
  std::vector<Point> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = unit_double(engine);
    const double y = unit_double(engine);
    points.push_back(Point{x, y});
  }
  return points;
}

}  // namespace meshstep::bench
