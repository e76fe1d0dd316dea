// The lasso's path: the points a press-drag-release leaves on the canvas, made into the few
// vertices of a region polygon before they go into the recipe (a recipe line of thousands
// of coordinates helps nobody, and a person's hand shakes). GL-free, so that the tests call
// it directly.
#pragma once

#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep::viewer {

// The lasso's vertices are at least this many pixels apart; the path drawn stays within a
// quarter of it of the polygon made.
inline constexpr double kLassoStepPixels = 4.0;

// The lasso's ring from the path drawn, `step` the world length of kLassoStepPixels:
//  1. the end goes while it is closer than `step` to the start (the ring closes by itself);
//  2. Douglas-Peucker round the ring, split at the start and the point farthest from it:
//     every point drawn stays within step / 4 of the ring, and straight strokes keep their
//     ends alone (the corners of a square drawn are its four vertices);
//  3. a vertex closer than `step` to the one kept before it goes (a shaking hand's knots;
//     the path there then strays from the ring by up to about `step`);
//  4. each coordinate is rounded to a multiple of the power of ten at most step / 40 (a
//     tenth of a pixel): the recipe's line reads 5.1342, not 5.134228187919463.
// Fewer than 3 points back: nothing to close. The ring may still cross itself (the person
// drew a figure eight): RefineRegion::polygon() says so.
std::vector<Point> simplify_lasso(const std::vector<Point>& path, double step);

}  // namespace meshstep::viewer
