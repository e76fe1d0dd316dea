// Spatially coherent insertion order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep {

// The indices of `points` in the order of a Hilbert curve over their bounding box, so that
// consecutive points are close and walking point location takes few steps. Points that
// share a cell of the 2^16 x 2^16 grid are ordered again inside their own, smaller box, so
// tight clusters far from the rest are ordered as well as uniform data. Ties (identical
// points) keep index order: the result is deterministic.
std::vector<std::uint32_t> hilbert_order(std::span<const Point> points);

// Biased randomized insertion order (Amenta, Choi, Rote 2003) with Hilbert-sorted rounds:
// a reproducible shuffle is cut into rounds of doubling size, and each round is sorted along
// the Hilbert curve. Early rounds give a coarse triangulation of the whole domain, so each
// later point lands among triangles of its own scale (about three flips per insertion,
// against more for a plain Hilbert order), while walks inside a round stay short.
std::vector<std::uint32_t> brio_order(std::span<const Point> points);

}  // namespace meshstep
