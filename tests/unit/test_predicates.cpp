// Exactness tests of the geometric predicates: orient2d, incircle, incircle_perturbed and
// strictly_between. Every sign is compared with an independent GMP evaluation
// (exact_reference.hpp) on inputs chosen so that plain double arithmetic gets it wrong;
// each test also asserts that its inputs really are hard (naive double evaluation fails
// on many of them, or many are exactly degenerate), so that a test passing cannot be an
// accident of easy data.
#include "meshstep/geometry/predicates.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "exact_reference.hpp"

namespace {

using meshstep::incircle;
using meshstep::incircle_perturbed;
using meshstep::orient2d;
using meshstep::Point;

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// Textbook double-precision determinants without any error filter (the project compiles
// with -ffp-contract=off, so these are evaluated exactly as written). Used only to show
// that the test inputs defeat floating point. Two forms each: translated to one of the
// points first (wrong on the near-degenerate scaled data), and expanded over the raw
// coordinates (wrong on the translated cluster, where the translated form is accurate
// because differences of nearby coordinates are exact).
double naive_orient(const Point& p, const Point& q, const Point& r) {
  return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);  // Kettner et al.'s form
}

double naive_orient_expanded(const Point& a, const Point& b, const Point& c) {
  return (b.x * c.y - b.y * c.x) - (a.x * c.y - a.y * c.x) + (a.x * b.y - a.y * b.x);
}

double naive_incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
         (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
         (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

// | px py px²+py² ; qx qy .. ; rx ry .. | in double.
double naive_lifted3(const Point& p, const Point& q, const Point& r) {
  const double pl = p.x * p.x + p.y * p.y, ql = q.x * q.x + q.y * q.y;
  const double rl = r.x * r.x + r.y * r.y;
  return p.x * (q.y * rl - ql * r.y) - p.y * (q.x * rl - ql * r.x) + pl * (q.x * r.y - q.y * r.x);
}

// The 4x4 lifted determinant expanded along its column of ones.
double naive_incircle_expanded(const Point& a, const Point& b, const Point& c, const Point& d) {
  return -naive_lifted3(b, c, d) + naive_lifted3(a, c, d) - naive_lifted3(a, b, d) +
         naive_lifted3(a, b, c);
}

// Points in hexadecimal floating point, so that a reported failure can be replayed exactly.
std::string describe(const Point& p) {
  std::ostringstream s;
  s << std::hexfloat << '(' << p.x << ", " << p.y << ')';
  return s.str();
}

template <std::size_t N>
std::string describe(const std::array<Point, N>& pts) {
  std::ostringstream s;
  for (const Point& p : pts) s << describe(p) << ' ';
  return s.str();
}

// Portable deterministic randomness: std::uniform_*_distribution differ between standard
// libraries, so the doubles are built from the raw 64-bit output.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double unit() { return static_cast<double>(gen_() >> 11) * 0x1p-53; }  // [0, 1)
  double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
  int integer(int lo, int hi) {  // [lo, hi]
    return lo + static_cast<int>(gen_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool coin() { return (gen_() >> 63) != 0; }

 private:
  std::mt19937_64 gen_;
};

// v moved by |ulps| representable doubles towards +inf (ulps > 0) or -inf (ulps < 0).
// Zero is left alone: its neighbours are subnormal, and the predicates are documented to
// be exact only when no intermediate product underflows.
double nudge(double v, int ulps) {
  if (v == 0.0) return v;
  const double target = ulps > 0 ? INFINITY : -INFINITY;
  for (int i = 0; i < std::abs(ulps); ++i) v = std::nextafter(v, target);
  return v;
}

// Moves one nonzero coordinate of p (chosen at random) by one ulp; false if p is (0, 0).
bool nudge_one_coordinate(Point& p, Rng& rng) {
  const bool x_first = rng.coin();
  double& first = x_first ? p.x : p.y;
  double& second = x_first ? p.y : p.x;
  double& coord = first != 0.0 ? first : second;
  if (coord == 0.0) return false;
  coord = nudge(coord, rng.coin() ? 1 : -1);
  return true;
}

// Where the configurations are placed. A configuration is generated in "unit"
// coordinates (mostly within [-1, 1]²) and mapped by p -> offset + p * 2^exponent. The
// scalings are exact. The translated frame puts a cluster about 1e-6 wide at 1e6, where
// all coordinates share their leading bits; it maps exactly the lattice families, whose
// unit coordinates are multiples of 2^-13 or coarser (1e6 + k 2^-33 fits in 53 bits).
struct Frame {
  const char* name;
  double offset;
  int exponent;
  Point map(const Point& u) const {
    return {offset + std::ldexp(u.x, exponent), offset + std::ldexp(u.y, exponent)};
  }
  double length(double l) const { return std::ldexp(l, exponent); }
};

constexpr std::array<Frame, 4> kFrames{{{"scale 2^-60", 0.0, -60},
                                        {"scale 1", 0.0, 0},
                                        {"scale 2^60", 0.0, 60},
                                        {"offset 1e6, size 1e-6", 1e6, -20}}};

// All orderings of N indices with the parity of each (odd orderings flip a determinant).
template <std::size_t N>
std::vector<std::pair<std::array<int, N>, bool>> orderings() {
  std::vector<std::pair<std::array<int, N>, bool>> out;
  std::array<int, N> perm;
  for (std::size_t i = 0; i < N; ++i) perm[i] = static_cast<int>(i);
  do {
    int inversions = 0;
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = i + 1; j < N; ++j) inversions += perm[i] > perm[j];
    out.emplace_back(perm, inversions % 2 != 0);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

// Counts for one family of cases, and the first few mismatches as readable failures.
struct Tally {
  long cases = 0;        // configurations generated (each checked in several orders)
  long calls = 0;        // predicate calls compared with the exact sign
  long zeros = 0;        // configurations whose exact sign is 0
  long naive_wrong = 0;  // configurations where a naive double sign is wrong (see below)
  long failures = 0;     // predicate calls with a wrong sign

  void fail(const std::string& what) {
    if (++failures <= 10) ADD_FAILURE() << what;
  }
};

// orient2d on all six orderings of (a, b, c) against the exact sign.
void check_orient(const Point& a, const Point& b, const Point& c, Tally& t) {
  static const auto kOrders = orderings<3>();
  const std::array<Point, 3> p{a, b, c};
  const int exact = exact_ref::orient_sign(a, b, c);
  for (const auto& [o, odd] : kOrders) {
    const int expected = odd ? -exact : exact;
    const int got = sign_of(orient2d(p[o[0]], p[o[1]], p[o[2]]));
    ++t.calls;
    if (got != expected)
      t.fail("orient2d" + describe(std::array<Point, 3>{p[o[0]], p[o[1]], p[o[2]]}) +
             "sign " + std::to_string(got) + ", exact " + std::to_string(expected));
  }
  ++t.cases;
  t.zeros += exact == 0;
  t.naive_wrong += sign_of(naive_orient(a, b, c)) != exact ||
                   sign_of(naive_orient_expanded(a, b, c)) != exact;
}

// incircle against the exact sign on several orderings of (a, b, c, d): the pivot d of
// the library's translated form changes with the ordering, and so do its rounding
// errors. With all_orders, every one of the 24 orderings; otherwise 4, one per pivot.
void check_incircle(const Point& a, const Point& b, const Point& c, const Point& d, Tally& t,
                    bool all_orders) {
  static const auto kAll = orderings<4>();
  static const auto kOnePerPivot = [] {
    std::vector<std::pair<std::array<int, 4>, bool>> some;
    for (const auto& order : kAll)
      if (order.first[0] < order.first[1] && order.first[1] < order.first[2])
        some.push_back(order);  // (a,b,c,d), (a,b,d,c), (a,c,d,b), (b,c,d,a)
    return some;
  }();
  const std::array<Point, 4> p{a, b, c, d};
  const int exact = exact_ref::incircle_sign(a, b, c, d);
  for (const auto& [o, odd] : all_orders ? kAll : kOnePerPivot) {
    const int expected = odd ? -exact : exact;
    const std::array<Point, 4> q{p[o[0]], p[o[1]], p[o[2]], p[o[3]]};
    const int got = sign_of(incircle(q[0], q[1], q[2], q[3]));
    ++t.calls;
    if (got != expected)
      t.fail("incircle" + describe(q) + "sign " + std::to_string(got) + ", exact " +
             std::to_string(expected));
  }
  ++t.cases;
  t.zeros += exact == 0;
  t.naive_wrong += sign_of(naive_incircle(a, b, c, d)) != exact ||
                   sign_of(naive_incircle_expanded(a, b, c, d)) != exact;
}

void report(const char* family, const Frame& f, const Tally& t) {
  std::printf("[ stats    ] %-27s %-22s cases %6ld  calls %7ld  exact zeros %6ld  naive wrong %6ld\n",
              family, f.name, t.cases, t.calls, t.zeros, t.naive_wrong);
}

// Integer points (x, y) with x² + y² = r².
std::vector<Point> lattice_circle(int r) {
  std::vector<Point> pts;
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      if (x * x + y * y == r * r) pts.push_back({double(x), double(y)});
  return pts;
}

// k distinct random indices below n, in random order.
template <std::size_t K>
std::array<int, K> distinct_indices(Rng& rng, int n) {
  std::array<int, K> idx;
  for (std::size_t i = 0; i < K; ++i) {
    bool fresh;
    do {
      idx[i] = rng.integer(0, n - 1);
      fresh = std::find(idx.begin(), idx.begin() + i, idx[i]) == idx.begin() + i;
    } while (!fresh);
  }
  return idx;
}

// Near-degenerate and degenerate quadruples for the incircle_perturbed tests, with
// distinct points, drawn from lattice circles, a small grid (many collinear and
// cocircular subsets) and rounded circles, in every frame.
std::vector<std::array<Point, 4>> perturbed_cases() {
  std::vector<std::array<Point, 4>> cases;
  // Every ordered quadruple of the 12 points of x² + y² = 25: cocircular, all orders.
  const std::vector<Point> c5 = lattice_circle(5);
  for (const Point& a : c5)
    for (const Point& b : c5)
      for (const Point& c : c5)
        for (const Point& d : c5)
          if (!(a == b || a == c || a == d || b == c || b == d || c == d))
            cases.push_back({a, b, c, d});
  Rng rng(0x5eed'0003);
  const std::vector<Point> c65 = lattice_circle(65);
  std::vector<Point> grid;
  for (int x = 0; x < 5; ++x)
    for (int y = 0; y < 5; ++y) grid.push_back({double(x), double(y)});
  for (const Frame& f : kFrames) {
    for (int i = 0; i < 3000; ++i) {  // lattice circle r = 65 around a random centre
      const Point centre{double(rng.integer(-64, 64)), double(rng.integer(-64, 64))};
      const auto idx = distinct_indices<4>(rng, int(c65.size()));
      std::array<Point, 4> q;
      for (int k = 0; k < 4; ++k)
        q[k] = f.map({(centre.x + c65[idx[k]].x) / 256, (centre.y + c65[idx[k]].y) / 256});
      cases.push_back(q);
    }
    for (int i = 0; i < 3000; ++i) {  // 5x5 grid: collinear quadruples, squares, ...
      const auto idx = distinct_indices<4>(rng, int(grid.size()));
      std::array<Point, 4> q;
      for (int k = 0; k < 4; ++k) q[k] = f.map({grid[idx[k]].x / 8, grid[idx[k]].y / 8});
      cases.push_back(q);
    }
    for (int i = 0; i < 500; ++i) {  // four distinct collinear lattice points
      const Point a{double(rng.integer(-64, 64)), double(rng.integer(-64, 64))};
      Point d{0, 0};
      while (d == Point{0, 0}) d = {double(rng.integer(-8, 8)), double(rng.integer(-8, 8))};
      const auto m = distinct_indices<4>(rng, 9);
      std::array<Point, 4> q;
      for (int k = 0; k < 4; ++k)
        q[k] = f.map({(a.x + (m[k] - 4) * d.x) / 128, (a.y + (m[k] - 4) * d.y) / 128});
      cases.push_back(q);
    }
    for (int i = 0; i < 1500; ++i) {  // rounded points of a circle
      const Point centre = f.map({rng.range(-0.5, 0.5), rng.range(-0.5, 0.5)});
      const double r = f.length(rng.range(0.01, 0.5));
      std::array<Point, 4> q;
      for (Point& p : q) {
        const double t = rng.range(0.0, 2 * std::numbers::pi);
        p = {centre.x + r * std::cos(t), centre.y + r * std::sin(t)};
      }
      if (q[0] == q[1] || q[0] == q[2] || q[0] == q[3] || q[1] == q[2] || q[1] == q[3] ||
          q[2] == q[3])
        continue;
      cases.push_back(q);
    }
  }
  return cases;
}

const std::vector<std::array<Point, 4>>& perturbed_case_set() {
  static const std::vector<std::array<Point, 4>> cases = perturbed_cases();
  return cases;
}

// ---------------------------------------------------------------------------------------
// orient2d
// ---------------------------------------------------------------------------------------

// Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems in
// geometric computations" (CGTA 2008): p = (0.5 + X u, 0.5 + Y u), u = 2^-53, X, Y in
// [0, 256), against q = (12, 12), r = (24, 24). The true orientation changes along the
// diagonal of the grid; naive evaluation paints a noisy band around it. Catches a filter
// that certifies a wrong sign (e.g. a too-small error bound) or a broken exact fallback,
// in each of the three argument rotations (each puts a different point at the pivot).
TEST(Orient2d, KettnerGridMatchesExactSign) {
  const Point q{12.0, 12.0}, r{24.0, 24.0};
  struct Order {
    const char* name;
    std::array<int, 3> idx;  // indices into {p, q, r}
  };
  for (const Order& order : {Order{"(p,q,r)", {0, 1, 2}}, Order{"(q,r,p)", {1, 2, 0}},
                             Order{"(r,p,q)", {2, 0, 1}}}) {
    SCOPED_TRACE(order.name);
    long wrong = 0, naive_wrong = 0, positive = 0, negative = 0, zero = 0;
    for (int X = 0; X < 256; ++X) {
      for (int Y = 0; Y < 256; ++Y) {
        const Point p{0.5 + std::ldexp(X, -53), 0.5 + std::ldexp(Y, -53)};
        const std::array<Point, 3> pts{p, q, r};
        const Point& a = pts[order.idx[0]];
        const Point& b = pts[order.idx[1]];
        const Point& c = pts[order.idx[2]];
        const int exact = exact_ref::orient_sign(a, b, c);
        (exact > 0 ? positive : exact < 0 ? negative : zero) += 1;
        const int got = sign_of(orient2d(a, b, c));
        if (got != exact && ++wrong <= 10)
          ADD_FAILURE() << "orient2d" << describe(std::array<Point, 3>{a, b, c}) << "(X=" << X
                        << ", Y=" << Y << ") sign " << got << ", exact " << exact;
        naive_wrong += sign_of(naive_orient(a, b, c)) != exact;
      }
    }
    std::printf("[ stats    ] Kettner grid %s: naive wrong in %ld of 65536 cells\n", order.name,
                naive_wrong);
    EXPECT_EQ(wrong, 0);
    // The grid straddles the line y = x: both signs and exact zeros (the 256 diagonal
    // cells) occur. A rotation changes no orientation, so these counts are order-free.
    EXPECT_EQ(zero, 256);
    EXPECT_EQ(positive, negative);
    // The grid is a real test: plain double arithmetic fails on thousands of cells.
    EXPECT_GT(naive_wrong, 1000);
  }
}

// Points nearly on a line: a, b random; c = a + t (b - a) rounded to double, then each
// coordinate moved by up to 3 ulps. The true orientation is decided by a few ulps, far
// below the filter's error bound, so the exact fallback must get it right. Catches a wrong
// filter bound, a wrong early return, and exact-arithmetic bugs, in every frame.
TEST(Orient2d, NearlyCollinearMatchesExactSign) {
  Rng rng(0x5eed'0001);
  for (const Frame& f : kFrames) {
    SCOPED_TRACE(f.name);
    Tally t;
    for (int i = 0; i < 25000; ++i) {
      const Point a = f.map({rng.range(-1, 1), rng.range(-1, 1)});
      const Point b = f.map({rng.range(-1, 1), rng.range(-1, 1)});
      const double s = rng.range(-0.5, 1.5);
      Point c{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
      c.x = nudge(c.x, rng.integer(-3, 3));
      c.y = nudge(c.y, rng.integer(-3, 3));
      check_orient(a, b, c, t);
    }
    report("orient nearly collinear", f, t);
    EXPECT_EQ(t.failures, 0);
    EXPECT_GT(t.naive_wrong, t.cases / 50);  // the cases are hard for plain doubles
  }
}

// Exactly collinear dyadic lattice points a, a + m d, a + n d (coordinates k / 1024),
// half of them with one nonzero coordinate then moved by one ulp: exact zeros must come out as 0
// (not a rounding-noise sign), and a one-ulp departure must get its true sign.
TEST(Orient2d, ExactlyCollinearLatticeMatchesExactSign) {
  Rng rng(0x5eed'0002);
  for (const Frame& f : kFrames) {
    SCOPED_TRACE(f.name);
    Tally t;
    for (int i = 0; i < 25000; ++i) {
      const int ax = rng.integer(-512, 512), ay = rng.integer(-512, 512);
      const int dx = rng.integer(-16, 16), dy = rng.integer(-16, 16);
      const int m = rng.integer(-8, 8), n = rng.integer(-8, 8);
      const Point a = f.map({ax / 1024.0, ay / 1024.0});
      const Point b = f.map({(ax + m * dx) / 1024.0, (ay + m * dy) / 1024.0});
      Point c = f.map({(ax + n * dx) / 1024.0, (ay + n * dy) / 1024.0});
      if (rng.coin()) nudge_one_coordinate(c, rng);
      check_orient(a, b, c, t);
    }
    report("orient exactly collinear", f, t);
    EXPECT_EQ(t.failures, 0);
    EXPECT_GT(t.zeros, t.cases / 4);  // many cases are exactly degenerate
  }
}

// ---------------------------------------------------------------------------------------
// incircle
// ---------------------------------------------------------------------------------------

// Rounded points of a circle (cos/sin), the fourth sometimes moved by an ulp: the true
// incircle sign is decided by rounding-level distances from the circle. Catches a wrong
// filter bound or permanent and exact-arithmetic bugs, in every frame and argument order.
TEST(Incircle, NearlyCocircularMatchesExactSign) {
  Rng rng(0x5eed'0004);
  for (const Frame& f : kFrames) {
    SCOPED_TRACE(f.name);
    Tally t;
    for (int i = 0; i < 12500; ++i) {
      const Point centre = f.map({rng.range(-0.5, 0.5), rng.range(-0.5, 0.5)});
      const double r = f.length(rng.range(0.001, 0.5));
      std::array<Point, 4> p;
      for (Point& q : p) {
        const double angle = rng.range(0.0, 2 * std::numbers::pi);
        q = {centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)};
      }
      if (rng.coin()) p[3].x = nudge(p[3].x, rng.integer(-2, 2));
      if (rng.coin()) p[3].y = nudge(p[3].y, rng.integer(-2, 2));
      check_incircle(p[0], p[1], p[2], p[3], t, i % 8 == 0);
    }
    report("incircle nearly cocircular", f, t);
    EXPECT_EQ(t.failures, 0);
    EXPECT_GT(t.naive_wrong, t.cases / 50);
  }
}

// Exactly cocircular lattice points of x² + y² = r² for r = 5, 25, 65, 325 around a
// random integer centre, as integers or divided by 512 (dyadic), a third of them with a
// nonzero coordinate of the fourth point then moved by one ulp. Exact zeros must be 0, and one-ulp departures from
// the circle must get their true sign.
TEST(Incircle, ExactlyCocircularLatticeMatchesExactSign) {
  Rng rng(0x5eed'0005);
  std::vector<std::vector<Point>> circles;
  for (int r : {5, 25, 65, 325}) circles.push_back(lattice_circle(r));
  ASSERT_EQ(circles[0].size(), 12u);  // (±5, 0), (0, ±5), (±3, ±4), (±4, ±3)
  for (const Frame& f : kFrames) {
    SCOPED_TRACE(f.name);
    Tally t;
    for (int i = 0; i < 12500; ++i) {
      const std::vector<Point>& circle = circles[rng.integer(0, 3)];
      const Point centre{double(rng.integer(-64, 64)), double(rng.integer(-64, 64))};
      // Integer lattice (|coordinates| <= 389), or the same divided by 512; both map
      // exactly into every frame.
      const double unit = rng.coin() ? 1.0 : 1.0 / 512;
      const auto idx = distinct_indices<4>(rng, int(circle.size()));
      std::array<Point, 4> p;
      for (int k = 0; k < 4; ++k)
        p[k] = f.map({(centre.x + circle[idx[k]].x) * unit, (centre.y + circle[idx[k]].y) * unit});
      if (rng.integer(0, 2) == 0) nudge_one_coordinate(p[3], rng);
      check_incircle(p[0], p[1], p[2], p[3], t, i % 8 == 0);
    }
    report("incircle exactly cocircular", f, t);
    EXPECT_EQ(t.failures, 0);
    EXPECT_GT(t.zeros, t.cases / 2);           // the lattice circles are exact ...
    EXPECT_GT(t.cases - t.zeros, t.cases / 5);  // ... and the ulp moves are not
  }
}

// ---------------------------------------------------------------------------------------
// incircle_perturbed
// ---------------------------------------------------------------------------------------

// The perturbation is infinitesimal: whenever the exact incircle sign is nonzero,
// incircle_perturbed must return it. Catches a perturbation applied when it should not be.
TEST(IncirclePerturbed, EqualsExactSignWhenNonzero) {
  long nonzero = 0, failures = 0;
  for (const auto& p : perturbed_case_set()) {
    const int exact = exact_ref::incircle_sign(p[0], p[1], p[2], p[3]);
    if (exact == 0) continue;
    ++nonzero;
    const int got = incircle_perturbed(p[0], p[1], p[2], p[3]);
    if (got != exact && ++failures <= 10)
      ADD_FAILURE() << "incircle_perturbed" << describe(p) << "= " << got << ", exact " << exact;
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(nonzero, 10000);
}

// The result is 0 only when all four points are collinear: in particular never for a
// counterclockwise (or any non-degenerate) triangle abc, whatever d is, including d on
// the circle. Catches a missing or skipped tie-break that lets the unperturbed 0 through.
// (For distinct points with incircle 0, the cofactor of any one point is nonzero unless
// all four are collinear, so dropping a single cofactor term cannot produce a 0; the
// definition test below catches that.)
TEST(IncirclePerturbed, NonzeroUnlessAllFourCollinear) {
  long ccw = 0, cocircular_ccw = 0, failures = 0;
  for (const auto& p : perturbed_case_set()) {
    const int abc = exact_ref::orient_sign(p[0], p[1], p[2]);
    const bool all_collinear = abc == 0 && exact_ref::orient_sign(p[0], p[1], p[3]) == 0 &&
                               exact_ref::orient_sign(p[0], p[2], p[3]) == 0 &&
                               exact_ref::orient_sign(p[1], p[2], p[3]) == 0;
    const int got = incircle_perturbed(p[0], p[1], p[2], p[3]);
    if (abc > 0) {
      ++ccw;
      cocircular_ccw += exact_ref::incircle_sign(p[0], p[1], p[2], p[3]) == 0;
    }
    if ((got == 0) != all_collinear && ++failures <= 10)
      ADD_FAILURE() << "incircle_perturbed" << describe(p) << "= " << got
                    << (all_collinear ? ", all four collinear" : ", not all collinear");
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(ccw, 10000);
  EXPECT_GT(cocircular_ccw, 3000);  // the hard part: d exactly on the circle
}

// Rotating the triangle (a, b, c) -> (b, c, a) is an even permutation of the rows: the
// perturbed determinant, and so the result, must not change. Catches a tie-break that
// depends on argument positions rather than on the points (e.g. a wrong cofactor sign
// for a, b or c, or ranks taken from positions instead of lexicographic order).
TEST(IncirclePerturbed, InvariantUnderRotationOfTriangle) {
  long failures = 0, degenerate = 0;
  for (const auto& p : perturbed_case_set()) {
    const auto& [a, b, c, d] = p;
    const int abc = incircle_perturbed(a, b, c, d);
    const int bca = incircle_perturbed(b, c, a, d);
    const int cab = incircle_perturbed(c, a, b, d);
    degenerate += exact_ref::incircle_sign(a, b, c, d) == 0;
    if ((abc != bca || abc != cab) && ++failures <= 10)
      ADD_FAILURE() << "incircle_perturbed" << describe(p) << "rotations give " << abc << ", "
                    << bca << ", " << cab;
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(degenerate, 10000);  // mostly decided by the perturbation, not the filter
}

// Four cocircular points a, b, c, d in counterclockwise order on a circle form a convex
// quadrilateral, and exactly one of its diagonals must be locally Delaunay after the
// perturbation: the test for diagonal ac agrees from both of its triangles,
// incircle_perturbed(a,b,c,d) == incircle_perturbed(c,d,a,b), the test for diagonal bd
// likewise, and the two disagree. Otherwise a flip algorithm could flip forever (both
// illegal) or two algorithms could stop at different meshes (both legal).
TEST(IncirclePerturbed, CocircularQuadrilateralHasExactlyOneDelaunayDiagonal) {
  Rng rng(0x5eed'0006);
  long quads = 0, failures = 0, ac_legal = 0;
  for (int r : {25, 65}) {
    std::vector<Point> circle = lattice_circle(r);
    std::sort(circle.begin(), circle.end(), [](const Point& s, const Point& t) {
      return std::atan2(s.y, s.x) < std::atan2(t.y, t.x);  // counterclockwise
    });
    const int n = int(circle.size());
    for (const Frame& f : kFrames) {
      const Point centre{double(rng.integer(-64, 64)), double(rng.integer(-64, 64))};
      auto at = [&](int k) {
        return f.map({(centre.x + circle[k].x) / 512, (centre.y + circle[k].y) / 512});
      };
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
          for (int k = j + 1; k < n; ++k)
            for (int l = k + 1; l < n; ++l) {
              if (r == 65 && rng.integer(0, 9) != 0) continue;  // sample the larger circle
              const Point a = at(i), b = at(j), c = at(k), d = at(l);
              ASSERT_EQ(exact_ref::orient_sign(a, b, c), 1);
              ASSERT_EQ(exact_ref::orient_sign(a, c, d), 1);
              ASSERT_EQ(exact_ref::incircle_sign(a, b, c, d), 0);
              ++quads;
              const int ac1 = incircle_perturbed(a, b, c, d);  // d against circle abc
              const int ac2 = incircle_perturbed(c, d, a, b);  // b against circle cda
              const int bd1 = incircle_perturbed(b, c, d, a);  // a against circle bcd
              const int bd2 = incircle_perturbed(d, a, b, c);  // c against circle dab
              ac_legal += ac1 < 0;
              if ((ac1 != ac2 || bd1 != bd2 || ac1 == bd1 || ac1 == 0 || bd1 == 0) &&
                  ++failures <= 10)
                ADD_FAILURE() << "quadrilateral " << describe(std::array<Point, 4>{a, b, c, d})
                              << "in " << f.name << ": ac " << ac1 << "/" << ac2 << ", bd "
                              << bd1 << "/" << bd2;
            }
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(quads, 20000);
  // Both diagonals are chosen in some quadrilaterals (the rule is not "always ac").
  EXPECT_GT(ac_legal, quads / 10);
  EXPECT_LT(ac_legal, quads - quads / 10);
}

// The implementation (sort by lexicographic order, first nonzero cofactor) against the
// definition: the 4x4 lifted determinant in which the lift of the k-th smallest point is
// raised by eps^k, evaluated exactly with the concrete eps = 2^-1100 (proof that this eps
// is small enough in exact_reference.hpp). Catches a reversed order (smaller points must
// get the larger infinitesimal), a wrong cofactor sign, and a wrong tie direction. Also
// checks the two exact incircle references (3x3 translated, 4x4 lifted) against each other.
TEST(IncirclePerturbed, MatchesLiftedDeterminantWithInfinitesimals) {
  long failures = 0, decided_by_perturbation = 0, all_collinear = 0;
  std::size_t index = 0;
  for (const auto& p : perturbed_case_set()) {
    const int exact = exact_ref::incircle_sign(p[0], p[1], p[2], p[3]);
    if (index++ % 4 == 0) {  // the slow rational 4x4 form on a quarter of the cases
      ASSERT_EQ(exact, exact_ref::incircle_sign_4x4(p[0], p[1], p[2], p[3])) << describe(p);
    }
    const int expected = exact_ref::incircle_perturbed_sign(p[0], p[1], p[2], p[3]);
    const int got = incircle_perturbed(p[0], p[1], p[2], p[3]);
    decided_by_perturbation += exact == 0 && expected != 0;
    all_collinear += expected == 0;
    if (got != expected && ++failures <= 10)
      ADD_FAILURE() << "incircle_perturbed" << describe(p) << "= " << got << ", definition "
                    << expected << " (unperturbed " << exact << ")";
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(decided_by_perturbation, 10000);
  EXPECT_GT(all_collinear, 100);  // where the definition itself gives 0
}

// ---------------------------------------------------------------------------------------
// strictly_between
// ---------------------------------------------------------------------------------------

// Expected results for c on the line through a and b, checked with (a, b) in both orders.
void expect_between(const Point& a, const Point& b, const Point& c, bool expected) {
  EXPECT_EQ(meshstep::strictly_between(a, b, c), expected)
      << "a=" << describe(a) << " b=" << describe(b) << " c=" << describe(c);
  EXPECT_EQ(meshstep::strictly_between(b, a, c), expected)
      << "a=" << describe(b) << " b=" << describe(a) << " c=" << describe(c);
}

// Horizontal segment: interior points (including the doubles adjacent to the endpoints)
// are between, the endpoints and points beyond them are not.
TEST(StrictlyBetween, Horizontal) {
  const Point a{1.0, 3.0}, b{9.0, 3.0};
  expect_between(a, b, {5.0, 3.0}, true);
  expect_between(a, b, {std::nextafter(1.0, 2.0), 3.0}, true);
  expect_between(a, b, {std::nextafter(9.0, 0.0), 3.0}, true);
  expect_between(a, b, a, false);
  expect_between(a, b, b, false);
  expect_between(a, b, {std::nextafter(1.0, 0.0), 3.0}, false);
  expect_between(a, b, {std::nextafter(9.0, 10.0), 3.0}, false);
  expect_between(a, b, {-4.0, 3.0}, false);
  expect_between(a, b, {12.0, 3.0}, false);
}

// Vertical segment: x is equal for all three points, so only y can decide. Catches an
// implementation that looks at x alone.
TEST(StrictlyBetween, Vertical) {
  const Point a{2.0, -1.0}, b{2.0, 7.0};
  expect_between(a, b, {2.0, 0.0}, true);
  expect_between(a, b, {2.0, std::nextafter(-1.0, 0.0)}, true);
  expect_between(a, b, {2.0, std::nextafter(7.0, 0.0)}, true);
  expect_between(a, b, a, false);
  expect_between(a, b, b, false);
  expect_between(a, b, {2.0, std::nextafter(-1.0, -2.0)}, false);
  expect_between(a, b, {2.0, std::nextafter(7.0, 8.0)}, false);
  expect_between(a, b, {2.0, -5.0}, false);
  expect_between(a, b, {2.0, 9.0}, false);
}

// Sloped segments, rising, falling and nearly vertical.
TEST(StrictlyBetween, Sloped) {
  expect_between({0, 0}, {4, 2}, {2, 1}, true);
  expect_between({0, 0}, {4, 2}, {0, 0}, false);
  expect_between({0, 0}, {4, 2}, {4, 2}, false);
  expect_between({0, 0}, {4, 2}, {6, 3}, false);
  expect_between({0, 0}, {4, 2}, {-2, -1}, false);
  expect_between({0, 4}, {4, 0}, {1, 3}, true);
  expect_between({0, 4}, {4, 0}, {5, -1}, false);
  expect_between({0, 4}, {4, 0}, {4, 0}, false);
  // Steep: x differs by one unit over 2^40 in y.
  expect_between({0, 0}, {1, 0x1p40}, {0.5, 0x1p39}, true);
  expect_between({0, 0}, {1, 0x1p40}, {2, 0x1p41}, false);
  expect_between({0, 0}, {1, 0x1p40}, {1, 0x1p40}, false);
}

// Every triple of collinear lattice points a + i d, i in [-3, 5], for horizontal,
// vertical, rising, falling and steep directions, in every frame (including the
// translated cluster, where neighbours differ only in the last bits), against the exact
// criterion (c - a) . (b - c) > 0. Also covers a == b, where nothing is between.
TEST(StrictlyBetween, CollinearLatticeMatchesExact) {
  const std::array<Point, 7> directions{
      {{1, 0}, {0, 1}, {-1, 0}, {3, 2}, {2, -3}, {1, 64}, {-64, 1}}};
  long checked = 0, between = 0, failures = 0;
  for (const Frame& f : kFrames)
    for (const Point& d : directions)
      for (int i = -3; i <= 5; ++i)
        for (int j = -3; j <= 5; ++j)
          for (int k = -3; k <= 5; ++k) {
            auto at = [&](int m) { return f.map({(0.25 + m * d.x) / 512, (-0.5 + m * d.y) / 512}); };
            const Point a = at(i), b = at(j), c = at(k);
            const bool expected = exact_ref::strictly_between(a, b, c);
            const bool got = meshstep::strictly_between(a, b, c);
            ++checked;
            between += expected;
            if (got != expected && ++failures <= 10)
              ADD_FAILURE() << "strictly_between(" << describe(a) << ", " << describe(b)
                            << ", " << describe(c) << ") = " << got << " in " << f.name;
          }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(between, checked / 5);
  EXPECT_LT(between, checked - checked / 5);
}

}  // namespace
