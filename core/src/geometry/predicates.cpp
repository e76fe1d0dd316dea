// Exact fallbacks of the predicates (their filters are inline in predicates.hpp): exact
// expansion arithmetic, and the symbolic perturbation that breaks cocircular ties.
#include "meshstep/geometry/predicates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "expansion.hpp"

namespace meshstep::detail {
namespace {

int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

}  // namespace

double orient2d_exact(const Point& a, const Point& b, const Point& c) {
  using namespace exact;
  const auto acx = difference(a.x, c.x), acy = difference(a.y, c.y);
  const auto bcx = difference(b.x, c.x), bcy = difference(b.y, c.y);
  return (acx * bcy - acy * bcx).sign();
}

double incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  using namespace exact;
  const auto adx = difference(a.x, d.x), ady = difference(a.y, d.y);
  const auto bdx = difference(b.x, d.x), bdy = difference(b.y, d.y);
  const auto cdx = difference(c.x, d.x), cdy = difference(c.y, d.y);
  const auto alift = adx * adx + ady * ady;
  const auto blift = bdx * bdx + bdy * bdy;
  const auto clift = cdx * cdx + cdy * cdy;
  const auto bc = bdx * cdy - cdx * bdy;
  const auto ca = cdx * ady - adx * cdy;
  const auto ab = adx * bdy - bdx * ady;
  return (alift * bc + blift * ca + clift * ab).sign();
}

// Called when incircle(a, b, c, d) is exactly 0. incircle is the 4x4 determinant with rows
// (x, y, x²+y², 1); raising the lift of one row by an infinitesimal changes it by that
// row's cofactor. The point with the largest infinitesimal (lexicographically smallest)
// whose cofactor is nonzero decides.
int incircle_tie_break(const Point& a, const Point& b, const Point& c, const Point& d) {
  struct Term {
    const Point* p;
    int cofactor_sign;
  };
  std::array<Term, 4> terms{{{&a, sign_of(orient2d(b, c, d))},
                             {&b, -sign_of(orient2d(a, c, d))},
                             {&c, sign_of(orient2d(a, b, d))},
                             {&d, -sign_of(orient2d(a, b, c))}}};
  std::sort(terms.begin(), terms.end(),
            [](const Term& s, const Term& t) { return lex_less(*s.p, *t.p); });
  for (const Term& t : terms)
    if (t.cofactor_sign != 0) return t.cofactor_sign;
  return 0;
}

}  // namespace meshstep::detail

namespace meshstep {

double orient2d_value(const Point& a, const Point& b, const Point& c) {
  using namespace exact;
  const auto acx = difference(a.x, c.x), acy = difference(a.y, c.y);
  const auto bcx = difference(b.x, c.x), bcy = difference(b.y, c.y);
  return (acx * bcy - acy * bcx).estimate();
}

}  // namespace meshstep
