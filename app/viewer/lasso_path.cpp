#include "lasso_path.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace meshstep::viewer {

namespace {

double distance(const Point& a, const Point& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The distance from p to the segment ab.
double off_segment(const Point& a, const Point& b, const Point& p) {
  const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
  if (length2 == 0.0) return distance(a, p);
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0);
  return distance({a.x + t * dx, a.y + t * dy}, p);
}

}  // namespace

std::vector<Point> simplify_lasso(const std::vector<Point>& path, double step) {
  std::size_t n = path.size();
  while (n > 1 && distance(path[n - 1], path[0]) < step) --n;
  if (n < 3) return {path.begin(), path.begin() + static_cast<std::ptrdiff_t>(n)};
  // Douglas-Peucker on the two chains between the start and the point farthest from it
  // (the ring closed: index n stands for the start again), with a stack, not recursion: a
  // long path is thousands of points.
  std::size_t far = 1;
  for (std::size_t i = 2; i < n; ++i)
    if (distance(path[0], path[i]) > distance(path[0], path[far])) far = i;
  const auto at = [&](std::size_t i) -> const Point& { return path[i == n ? 0 : i]; };
  std::vector<bool> keep(n + 1, false);
  keep[0] = keep[far] = keep[n] = true;
  std::vector<std::pair<std::size_t, std::size_t>> chains{{0, far}, {far, n}};
  while (!chains.empty()) {
    const auto [first, last] = chains.back();
    chains.pop_back();
    std::size_t worst = first;
    double worst_off = step / 4.0;
    for (std::size_t i = first + 1; i < last; ++i)
      if (const double off = off_segment(at(first), at(last), at(i)); off > worst_off) {
        worst = i;
        worst_off = off;
      }
    if (worst == first) continue;
    keep[worst] = true;
    chains.push_back({first, worst});
    chains.push_back({worst, last});
  }
  std::vector<Point> ring;
  for (std::size_t i = 0; i < n; ++i)
    if (keep[i] && (ring.empty() || distance(ring.back(), path[i]) >= step)) ring.push_back(path[i]);
  while (ring.size() > 1 && distance(ring.back(), ring.front()) < step) ring.pop_back();
  // 10^k: for k < 0 a division by 10^-k (an exact integer), so that n / 1000 is the double
  // nearest n thousandths, whose shortest text is "0.832" (n * 0.001 is 0.8320000000000001).
  const double k = std::floor(std::log10(step / 40.0));
  if (!std::isfinite(k) || std::fabs(k) > 300) return ring;
  const double ten_k = std::pow(10.0, std::fabs(k));
  for (Point& p : ring) {
    if (k < 0) p = {std::round(p.x * ten_k) / ten_k, std::round(p.y * ten_k) / ten_k};
    else p = {std::round(p.x / ten_k) * ten_k, std::round(p.y / ten_k) * ten_k};
  }
  return ring;
}

}  // namespace meshstep::viewer
