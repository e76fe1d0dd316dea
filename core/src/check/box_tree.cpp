#include "check/box_tree.hpp"

#include "meshstep/geometry/predicates.hpp"

namespace meshstep::check_detail {

bool box_right_of(const BBox& box, const Point& p, const Point& q) {
  // orient2d(p, q, r) is affine in r with gradient (p.y - q.y, q.x - p.x), so over the box
  // it is largest at the corner picked by those signs (signs of differences of doubles
  // are exact). If even that corner is strictly right of the line, the whole box is.
  const Point best{q.y < p.y ? box.hi.x : box.lo.x, q.x > p.x ? box.hi.y : box.lo.y};
  return orient2d(p, q, best) < 0.0;
}

}  // namespace meshstep::check_detail
