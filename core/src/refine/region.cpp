// RefineRegion: building a box or a simple polygon, refusing what is neither, and the exact
// point-in-region test.
#include "meshstep/refine/region.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <string>
#include <utility>

#include "meshstep/error.hpp"
#include "meshstep/geometry/predicates.hpp"

namespace meshstep {
namespace {

// The shortest text that reads back to the same double.
std::string shortest(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

int sign(double v) { return (v > 0.0) - (v < 0.0); }

// Given p on the line through a and b: is it on the closed segment ab?
bool within(const Point& a, const Point& b, const Point& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Do the closed segments pq and rs share a point? Exact.
bool segments_meet(const Point& p, const Point& q, const Point& r, const Point& s) {
  const int d1 = sign(orient2d(r, s, p)), d2 = sign(orient2d(r, s, q));
  const int d3 = sign(orient2d(p, q, r)), d4 = sign(orient2d(p, q, s));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && within(r, s, p)) || (d2 == 0 && within(r, s, q)) || (d3 == 0 && within(p, q, r)) ||
         (d4 == 0 && within(p, q, s));
}

// Checks that the ring `v` is a simple polygon with an inside; `edge_name(i)` names edge i
// (from v[i] to v[i + 1]) in the messages.
template <class Name>
void check_simple(const std::vector<Point>& v, Name edge_name) {
  const std::size_t n = v.size();
  if (n < 3) throw InputError("a region polygon needs at least 3 vertices, not " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(v[i].x) || !std::isfinite(v[i].y))
      throw InputError("a region polygon's coordinates must be finite numbers: " + edge_name(i) + " starts at (" +
                       shortest(v[i].x) + ", " + shortest(v[i].y) + ")");
  const auto at = [&](std::size_t i) -> const Point& { return v[i % n]; };
  // Neighbours share an end and nothing more: no edge of length zero, no edge that folds
  // back along the one before it.
  for (std::size_t i = 0; i < n; ++i) {
    const Point &a = at(i + n - 1), &b = at(i), &c = at(i + 1);
    if (b == c) throw InputError("a region polygon's " + edge_name(i) + " has length zero");
    if (orient2d(a, b, c) == 0.0 && (a.x - b.x) * (c.x - b.x) + (a.y - b.y) * (c.y - b.y) > 0.0)
      throw InputError("a region polygon's " + edge_name((i + n - 1) % n) + " and " + edge_name(i) +
                       " overlap: the polygon is not simple");
  }
  // Other pairs share no point. Edges sorted by their smallest x: a pair can meet only while
  // the second starts before the first ends.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto lo_x = [&](std::size_t i) { return std::min(at(i).x, at(i + 1).x); };
  const auto hi_x = [&](std::size_t i) { return std::max(at(i).x, at(i + 1).x); };
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return lo_x(i) < lo_x(j) || (lo_x(i) == lo_x(j) && i < j); });
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    for (std::size_t m = k + 1; m < n && lo_x(order[m]) <= hi_x(i); ++m) {
      const std::size_t j = order[m];
      if ((i + 1) % n == j || (j + 1) % n == i) continue;  // neighbours: checked above
      if (segments_meet(at(i), at(i + 1), at(j), at(j + 1)))
        throw InputError("a region polygon's " + edge_name(std::min(i, j)) + " and " + edge_name(std::max(i, j)) +
                         " touch or cross: the polygon is not simple");
    }
  }
}

}  // namespace

RefineRegion RefineRegion::box(const Point& low, const Point& high) {
  if (!std::isfinite(low.x) || !std::isfinite(low.y) || !std::isfinite(high.x) || !std::isfinite(high.y))
    throw InputError("a region box's coordinates must be finite numbers");
  if (!(low.x < high.x) || !(low.y < high.y))
    throw InputError("the region box " + shortest(low.x) + "," + shortest(low.y) + "," + shortest(high.x) + "," +
                     shortest(high.y) + " is empty: X0 must be below X1 and Y0 below Y1");
  RefineRegion r;
  r.kind_ = Kind::box;
  r.low_ = low;
  r.high_ = high;
  r.vertices_ = {low, {high.x, low.y}, high, {low.x, high.y}};
  return r;
}

RefineRegion RefineRegion::parse_box(std::string_view text) {
  double values[4];
  std::size_t count = 0;
  const std::string whole(text);
  const auto malformed = [&] {
    return InputError("a region box is X0,Y0,X1,Y1 (four numbers separated by commas), not '" + whole + "'");
  };
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    const std::string part = trimmed(text.substr(start, comma == std::string_view::npos ? text.npos : comma - start));
    if (count == 4 || part.empty()) throw malformed();
    char* end = nullptr;
    values[count++] = std::strtod(part.c_str(), &end);
    if (end != part.c_str() + part.size()) throw malformed();
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (count != 4) throw malformed();
  for (const double v : values)
    if (!std::isfinite(v))
      throw InputError("a region box's coordinates must be finite numbers, not '" + whole + "'");
  return box({values[0], values[1]}, {values[2], values[3]});
}

std::vector<Point> RefineRegion::parse_polygon(std::string_view text) {
  const std::string whole(text);
  const auto malformed = [&](const std::string& why) {
    return InputError("a region polygon is X0,Y0,X1,Y1,X2,Y2,... (" + why + "), not '" + whole + "'");
  };
  std::vector<double> values;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    const std::string part = trimmed(text.substr(start, comma == std::string_view::npos ? text.npos : comma - start));
    char* end = nullptr;
    const double v = part.empty() ? 0.0 : std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size())
      throw malformed("numbers separated by commas, two for each vertex");
    if (!std::isfinite(v)) throw InputError("a region polygon's coordinates must be finite numbers, not '" + part + "'");
    values.push_back(v);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (values.size() % 2 != 0) throw malformed("an odd count of numbers: every vertex is two");
  if (values.size() < 6) throw malformed("at least 3 vertices");
  std::vector<Point> vertices(values.size() / 2);
  for (std::size_t i = 0; i < vertices.size(); ++i) vertices[i] = {values[2 * i], values[2 * i + 1]};
  // The edges named by their ends as given: a person finds "edge 2 (1,0 to 0,1)" in the text.
  check_simple(vertices, [&](std::size_t i) {
    const Point &a = vertices[i], &b = vertices[(i + 1) % vertices.size()];
    return "edge " + std::to_string(i + 1) + " (" + shortest(a.x) + "," + shortest(a.y) + " to " + shortest(b.x) +
           "," + shortest(b.y) + ")";
  });
  return vertices;
}

RefineRegion RefineRegion::polygon(std::vector<Point> vertices) {
  check_simple(vertices, [](std::size_t i) { return "edge " + std::to_string(i + 1); });
  RefineRegion r;
  r.kind_ = Kind::polygon;
  // Counterclockwise: the lexicographically smallest vertex is convex, and its turn is never
  // zero in a simple polygon (its neighbours would overlap).
  const std::size_t n = vertices.size();
  const std::size_t m = std::min_element(vertices.begin(), vertices.end(), lex_less) - vertices.begin();
  if (orient2d(vertices[(m + n - 1) % n], vertices[m], vertices[(m + 1) % n]) < 0.0)
    std::reverse(vertices.begin(), vertices.end());
  BBox box;
  for (const Point& p : vertices) box.add(p);
  r.low_ = box.lo;
  r.high_ = box.hi;
  r.vertices_ = std::move(vertices);
  return r;
}

RefineRegion RefineRegion::polygon_of(const Pslg& pslg) {
  const auto vertex_name = [&](std::uint32_t v) { return "vertex " + std::to_string(v + pslg.first_index); };
  const auto segment_name = [&](std::size_t s) { return "segment " + std::to_string(s + pslg.first_index); };
  if (pslg.segments.size() < 3)
    throw InputError("a region polygon needs at least 3 segments forming a closed polygon, not " +
                     std::to_string(pslg.segments.size()));
  // The segments at each vertex: exactly two wherever a segment ends.
  std::vector<std::vector<std::size_t>> at(pslg.points.size());
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    const Segment& seg = pslg.segments[s];
    for (const std::uint32_t v : {seg.a, seg.b}) {
      if (v >= at.size()) throw InputError(segment_name(s) + " names " + vertex_name(v) + ", which does not exist");
      at[v].push_back(s);
      if (at[v].size() == 3)
        throw InputError(vertex_name(v) + " ends " + segment_name(at[v][0]) + ", " + segment_name(at[v][1]) + " and " +
                         segment_name(s) + ": a region's segments must form one closed polygon, two at each vertex");
    }
  }
  for (std::uint32_t v = 0; v < at.size(); ++v)
    if (at[v].size() == 1)
      throw InputError(vertex_name(v) + " ends " + segment_name(at[v][0]) +
                       " only: a region's segments must form one closed polygon, two at each vertex");
  // Round the loop from segment 0's first vertex.
  std::vector<Point> ring;
  std::vector<std::size_t> segment_of_edge;
  std::uint32_t v = pslg.segments[0].a;
  std::size_t s = 0;
  do {
    ring.push_back(pslg.points[v]);
    segment_of_edge.push_back(s);
    const Segment& seg = pslg.segments[s];
    v = seg.a == v ? seg.b : seg.a;
    s = at[v][0] == s ? at[v][1] : at[v][0];
  } while (v != pslg.segments[0].a);
  if (ring.size() != pslg.segments.size())
    throw InputError("a region's segments form more than one closed polygon: " + segment_name(0) + "'s has " +
                     std::to_string(ring.size()) + " of the " + std::to_string(pslg.segments.size()) + " segments");
  check_simple(ring, [&](std::size_t i) { return segment_name(segment_of_edge[i]); });
  return polygon(std::move(ring));
}

RefineRegion RefineRegion::parse_text(std::string_view text) {
  if (text.starts_with("box:")) return parse_box(text.substr(4));
  if (!text.starts_with("polygon:"))
    throw InputError("a region is box:X0,Y0,X1,Y1 or polygon:X,Y;X,Y;..., not '" + std::string(text) + "'");
  std::vector<Point> vertices;
  std::string_view rest = text.substr(8);
  for (std::size_t start = 0; start <= rest.size();) {
    const std::size_t semicolon = std::min(rest.find(';', start), rest.size());
    const std::string pair(rest.substr(start, semicolon - start));
    const std::size_t comma = pair.find(',');
    char* end_x = nullptr;
    char* end_y = nullptr;
    const double x = std::strtod(pair.c_str(), &end_x);
    const double y = comma == std::string::npos ? 0.0 : std::strtod(pair.c_str() + comma + 1, &end_y);
    if (comma == std::string::npos || end_x != pair.c_str() + comma || end_y != pair.c_str() + pair.size() ||
        comma == 0 || comma + 1 == pair.size())
      throw InputError("a region polygon's vertex is X,Y, not '" + pair + "'");
    vertices.push_back({x, y});
    start = semicolon + 1;
  }
  return polygon(std::move(vertices));
}

std::string RefineRegion::text() const {
  if (kind_ == Kind::box)
    return "box:" + shortest(low_.x) + "," + shortest(low_.y) + "," + shortest(high_.x) + "," + shortest(high_.y);
  std::string out = "polygon:";
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    if (i) out += ';';
    out += shortest(vertices_[i].x);
    out += ',';
    out += shortest(vertices_[i].y);
  }
  return out;
}

// The winding number round p, with every edge through p counting p in. Upward edges that
// cross the horizontal line through p (their lower end on or below it, their upper end above)
// with p to their left add one, downward ones with p to their right take one away: exact,
// since it compares coordinates and signs of orient2d only.
bool RefineRegion::polygon_contains(const Point& p) const {
  const std::size_t n = vertices_.size();
  int winding = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point &a = vertices_[i], &b = vertices_[i + 1 == n ? 0 : i + 1];
    if (std::max(a.y, b.y) < p.y || std::min(a.y, b.y) > p.y) continue;  // cannot cross or hold p
    const double o = orient2d(a, b, p);
    if (o == 0.0 && within(a, b, p)) return true;  // on the border
    if (a.y <= p.y && b.y > p.y && o > 0.0) ++winding;
    else if (b.y <= p.y && a.y > p.y && o < 0.0) --winding;
  }
  return winding != 0;
}

}  // namespace meshstep
