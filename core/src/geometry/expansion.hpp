// Exact floating-point expansion arithmetic (Priest; Shewchuk 1997, section 2).
//
// An expansion is a sum of doubles of increasing magnitude that do not overlap; its value
// is the exact sum. Capacities are compile-time template parameters, so the exact
// fallbacks of the predicates never touch the heap; zero components are dropped as they
// appear, which keeps the live length short in practice.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace meshstep::exact {

// x + y == a + b exactly, x = fl(a + b).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

// x + y == a - b exactly.
inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  y = (a - a_virtual) + (b_virtual - b);
}

// Veltkamp split: a == hi + lo, each with at most 26 significant bits.
inline void split(double a, double& hi, double& lo) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

// x + y == a * b exactly (Dekker), without relying on a hardware FMA.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}

template <std::size_t N>
struct Expansion {
  std::array<double, N> c;
  std::size_t n = 0;

  void push_nonzero(double v) {
    if (v != 0.0) c[n++] = v;
  }
  // The sign of an expansion is the sign of its largest (last) component.
  int sign() const { return n == 0 ? 0 : (c[n - 1] > 0.0 ? 1 : -1); }
  // The value rounded to a double, within a few ulps of it: the components summed from the
  // smallest up (they do not overlap, so no sum cancels what a later one needs).
  double estimate() const {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += c[i];
    return sum;
  }
};

inline Expansion<2> difference(double a, double b) {
  Expansion<2> e;
  double x, y;
  two_diff(a, b, x, y);
  e.push_nonzero(y);
  e.push_nonzero(x);
  return e;
}

// h = e + f exactly: merge by magnitude, then carry with two_sum (Shewchuk's
// FAST-EXPANSION-SUM, using the unconditional two_sum). h needs room for en + fn
// components and must not alias e or f. Returns the length of h.
inline std::size_t sum_into(const double* e, std::size_t en, const double* f, std::size_t fn,
                            double* merged, double* h) {
  std::size_t i = 0, j = 0, m = 0;
  while (i < en && j < fn) merged[m++] = std::fabs(e[i]) < std::fabs(f[j]) ? e[i++] : f[j++];
  while (i < en) merged[m++] = e[i++];
  while (j < fn) merged[m++] = f[j++];
  if (m == 0) return 0;
  std::size_t hn = 0;
  double q = merged[0];
  for (std::size_t k = 1; k < m; ++k) {
    double sum, err;
    two_sum(q, merged[k], sum, err);
    if (err != 0.0) h[hn++] = err;
    q = sum;
  }
  if (q != 0.0) h[hn++] = q;
  return hn;
}

template <std::size_t A, std::size_t B>
Expansion<A + B> operator+(const Expansion<A>& e, const Expansion<B>& f) {
  std::array<double, A + B> merged;
  Expansion<A + B> h;
  h.n = sum_into(e.c.data(), e.n, f.c.data(), f.n, merged.data(), h.c.data());
  return h;
}

template <std::size_t A>
Expansion<A> operator-(const Expansion<A>& e) {
  Expansion<A> r = e;
  for (std::size_t k = 0; k < r.n; ++k) r.c[k] = -r.c[k];
  return r;
}

template <std::size_t A, std::size_t B>
Expansion<A + B> operator-(const Expansion<A>& e, const Expansion<B>& f) {
  return e + (-f);
}

// Expansion times one double (Shewchuk's SCALE-EXPANSION with zero elimination).
template <std::size_t A>
Expansion<2 * A> scale(const Expansion<A>& e, double b) {
  Expansion<2 * A> h;
  if (e.n == 0 || b == 0.0) return h;
  double q, err;
  two_product(e.c[0], b, q, err);
  h.push_nonzero(err);
  for (std::size_t k = 1; k < e.n; ++k) {
    double p1, p0, sum;
    two_product(e.c[k], b, p1, p0);
    two_sum(q, p0, sum, err);
    h.push_nonzero(err);
    two_sum(p1, sum, q, err);
    h.push_nonzero(err);
  }
  h.push_nonzero(q);
  return h;
}

// Product of two expansions: the sum of e scaled by each component of f. After k terms
// the running sum has at most 2*A*k components, so 2*A*B bounds every step.
template <std::size_t A, std::size_t B>
Expansion<2 * A * B> operator*(const Expansion<A>& e, const Expansion<B>& f) {
  Expansion<2 * A * B> total;
  std::array<double, 2 * A * B> merged, next;
  for (std::size_t k = 0; k < f.n; ++k) {
    const Expansion<2 * A> term = scale(e, f.c[k]);
    const std::size_t n = sum_into(total.c.data(), total.n, term.c.data(), term.n,
                                   merged.data(), next.data());
    std::copy_n(next.data(), n, total.c.data());
    total.n = n;
  }
  return total;
}

}  // namespace meshstep::exact
