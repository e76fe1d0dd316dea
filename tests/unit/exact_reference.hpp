// Exact reference predicates in GMP arithmetic, for checking meshstep's predicates.
//
// Written independently of core/src/geometry/expansion.hpp: each predicate is the plain
// textbook determinant evaluated in rationals (mpq_class) or, for the symbolically
// perturbed incircle, in integers (mpz_class) after an exact power-of-two rescaling.
// Every finite double is a dyadic rational, and mpq_set_d converts it without rounding,
// so these functions give the true sign for any finite input.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>

#include "meshstep/geometry/point.hpp"

namespace exact_ref {

using meshstep::Point;

inline mpq_class rational(double v) { return mpq_class(v); }  // exact (mpq_set_d)

template <class T>
int sign(const T& v) {
  return sgn(v);
}

// Determinant of a 4x4 matrix straight from the Leibniz formula, sum over permutations s
// of sign(s) * m[s(0)][0] * m[s(1)][1] * m[s(2)][2] * m[s(3)][3], so that it is obviously
// the definition and shares nothing with the cofactor formulas the library uses. (Taken
// column by column, so that the lift column, the one with the big entries, is multiplied
// in last.)
template <class T>
T det4_leibniz(const std::array<std::array<T, 4>, 4>& m) {
  std::array<int, 4> perm{0, 1, 2, 3};
  T total = 0;
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
    T term = m[perm[0]][0];
    term *= m[perm[1]][1];
    term *= m[perm[3]][3];
    term *= m[perm[2]][2];
    if (inversions % 2 == 0)
      total += term;
    else
      total -= term;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return total;
}

// Sign of | ax ay 1 ; bx by 1 ; cx cy 1 |, expanded along the column of ones (not the
// translated form the library evaluates).
inline int orient_sign(const Point& a, const Point& b, const Point& c) {
  const mpq_class ax = rational(a.x), ay = rational(a.y);
  const mpq_class bx = rational(b.x), by = rational(b.y);
  const mpq_class cx = rational(c.x), cy = rational(c.y);
  const mpq_class det = (bx * cy - by * cx) - (ax * cy - ay * cx) + (ax * by - ay * bx);
  return sign(det);
}

// Sign of the incircle determinant, in the d-translated 3x3 form
// | adx ady adx²+ady² ; bdx bdy ... ; cdx cdy ... | (equal to the 4x4 lifted determinant
// below; a test checks the two forms against each other). This form is the cheaper one
// and is used for the bulk of the random cases.
inline int incircle_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  const mpq_class dx = rational(d.x), dy = rational(d.y);
  const mpq_class adx = rational(a.x) - dx, ady = rational(a.y) - dy;
  const mpq_class bdx = rational(b.x) - dx, bdy = rational(b.y) - dy;
  const mpq_class cdx = rational(c.x) - dx, cdy = rational(c.y) - dy;
  const mpq_class alift = adx * adx + ady * ady;
  const mpq_class blift = bdx * bdx + bdy * bdy;
  const mpq_class clift = cdx * cdx + cdy * cdy;
  const mpq_class det = adx * (bdy * clift - blift * cdy) - ady * (bdx * clift - blift * cdx) +
                        alift * (bdx * cdy - bdy * cdx);
  return sign(det);
}

// Sign of the 4x4 lifted determinant | x y x²+y² 1 | over the rows a, b, c, d.
inline int incircle_sign_4x4(const Point& a, const Point& b, const Point& c, const Point& d) {
  std::array<std::array<mpq_class, 4>, 4> m;
  const std::array<Point, 4> pts{a, b, c, d};
  for (std::size_t i = 0; i < 4; ++i) {
    const mpq_class x = rational(pts[i].x), y = rational(pts[i].y);
    m[i] = {x, y, x * x + y * y, mpq_class(1)};
  }
  return sign(det4_leibniz(m));
}

// Scales of the perturbed reference below (see the proof there).
inline constexpr int kGridBits = 200;     // coordinates must be multiples of 2^-200 ...
inline constexpr int kMagnitudeBits = 100;  // ... of magnitude below 2^100
inline constexpr int kEpsBits = 1100;       // eps = 2^-1100

// x * 2^200 as an integer; throws if x is not a multiple of 2^-200 or |x| >= 2^100, the
// range in which eps = 2^-1100 is provably "infinitesimal enough".
inline mpz_class to_grid_integer(double v) {
  mpq_class scaled = rational(v);
  mpq_mul_2exp(scaled.get_mpq_t(), scaled.get_mpq_t(), kGridBits);
  if (scaled.get_den() != 1)
    throw std::domain_error("exact_ref: coordinate is not a multiple of 2^-200");
  if (mpz_sizeinbase(scaled.get_num_mpz_t(), 2) > kGridBits + kMagnitudeBits)
    throw std::domain_error("exact_ref: coordinate magnitude is not below 2^100");
  return scaled.get_num();
}

inline mpz_class shifted(const mpz_class& v, unsigned long e) {  // v * 2^e
  mpz_class r;
  mpz_mul_2exp(r.get_mpz_t(), v.get_mpz_t(), e);
  return r;
}

// Sign of the symbolically perturbed incircle determinant, from its definition: the 4x4
// determinant with rows (x, y, x²+y² + eps^k, 1), where k is the point's rank in
// lexicographic (x, then y) order, 1 for the smallest, and eps = 2^-1100 is a concrete
// rational. The four points must be distinct.
//
// Why eps = 2^-1100 behaves like an infinitesimal: the determinant is linear in the lift
// column, so it equals D + C1 eps + C2 eps² + C3 eps³ + C4 eps⁴, with D the unperturbed
// determinant and Ck ± a 3x3 orientation determinant. With coordinates multiples of
// 2^-200 and below 2^100 in magnitude, a nonzero D is a multiple of 2^-800, a nonzero Ck a
// multiple of 2^-400, and every |Ck| < 6 * 2^200 < 2^203. So the first nonzero coefficient
// c_j exceeds the sum of all later terms: 4 * 2^203 * eps = 2^-895 < 2^-800 <= |D| when
// j = 0, and 3 * 2^203 * eps^(j+1) < 2^-400 eps^j <= |Cj| eps^j when j >= 1. The sign at
// eps is therefore the sign of the first nonzero coefficient, i.e. the limit eps -> 0+.
//
// For speed the matrix is made integral by positive power-of-two column scalings, which
// do not change the sign: x and y columns by 2^200, the lift column by 2^4800.
inline int incircle_perturbed_sign(const Point& a, const Point& b, const Point& c,
                                   const Point& d) {
  const std::array<Point, 4> pts{a, b, c, d};
  std::array<std::array<mpz_class, 4>, 4> m;
  for (std::size_t i = 0; i < 4; ++i) {
    int rank = 1;
    for (std::size_t j = 0; j < 4; ++j) {
      if (j == i) continue;
      if (pts[j].x == pts[i].x && pts[j].y == pts[i].y)
        throw std::invalid_argument("exact_ref: perturbed incircle needs distinct points");
      const bool smaller =
          pts[j].x < pts[i].x || (pts[j].x == pts[i].x && pts[j].y < pts[i].y);
      rank += smaller;
    }
    const mpz_class x = to_grid_integer(pts[i].x), y = to_grid_integer(pts[i].y);
    // (x²+y²) * 2^-400 + 2^(-1100 rank), times 2^4800.
    const mpz_class lift = shifted(x * x + y * y, 4 * kEpsBits) +
                           shifted(1, 4 * kEpsBits + 2 * kGridBits - kEpsBits * rank);
    m[i] = {x, y, lift, mpz_class(1)};
  }
  return sign(det4_leibniz(m));
}

// For collinear a, b, c: is c strictly inside the segment ab? True exactly when c - a and
// b - c point the same way, i.e. their dot product is positive.
inline bool strictly_between(const Point& a, const Point& b, const Point& c) {
  const mpq_class cax = rational(c.x) - rational(a.x), cay = rational(c.y) - rational(a.y);
  const mpq_class bcx = rational(b.x) - rational(c.x), bcy = rational(b.y) - rational(c.y);
  return sgn(cax * bcx + cay * bcy) > 0;
}

}  // namespace exact_ref
