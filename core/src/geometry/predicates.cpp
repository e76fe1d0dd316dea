// Filtered exact predicates: a double-precision evaluation certified by Shewchuk's
// stage-A error bound, and an exact expansion evaluation when the bound cannot decide.
#include "meshstep/geometry/predicates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "expansion.hpp"

namespace meshstep {
namespace {

constexpr double kEpsilon = 0x1p-53;  // half an ulp of 1.0: the unit roundoff
constexpr double kOrientErrBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kInCircleErrBound = (10.0 + 96.0 * kEpsilon) * kEpsilon;

// Kept out of line: the filter succeeds almost always and should stay small enough to inline.
[[gnu::noinline]] double orient2d_exact(const Point& a, const Point& b, const Point& c) {
  using namespace exact;
  const auto acx = difference(a.x, c.x), acy = difference(a.y, c.y);
  const auto bcx = difference(b.x, c.x), bcy = difference(b.y, c.y);
  return (acx * bcy - acy * bcx).sign();
}

[[gnu::noinline]] double incircle_exact(const Point& a, const Point& b, const Point& c,
                                        const Point& d) {
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

int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

}  // namespace

double orient2d(const Point& a, const Point& b, const Point& c) {
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  // Terms of opposite sign cannot cancel: the rounded difference has the right sign.
  if ((detleft > 0.0 && detright <= 0.0) || (detleft < 0.0 && detright >= 0.0)) return det;
  const double bound = kOrientErrBound * std::fabs(detleft + detright);
  if (det > bound || -det > bound) return det;
  if (detleft == 0.0 && detright == 0.0) return 0.0;
  return orient2d_exact(a, b, c);
}

double incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) +
                     clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double bound = kInCircleErrBound * permanent;
  if (det > bound || -det > bound) return det;
  return incircle_exact(a, b, c, d);
}

int incircle_perturbed(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int s = sign_of(incircle(a, b, c, d));
  if (s != 0) return s;
  // incircle(a,b,c,d) is the 4x4 determinant with rows (x, y, x²+y², 1). Raising the lift
  // of one row by an infinitesimal changes it by that row's cofactor; the point with the
  // largest infinitesimal (lexicographically smallest) whose cofactor is nonzero decides.
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

bool strictly_between(const Point& a, const Point& b, const Point& c) {
  if (a.x != b.x) return (a.x < c.x && c.x < b.x) || (b.x < c.x && c.x < a.x);
  return (a.y < c.y && c.y < b.y) || (b.y < c.y && c.y < a.y);
}

}  // namespace meshstep
