#include "meshstep/pslg/pslg_editor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "meshstep/io/shortest_text.hpp"

namespace meshstep {

const char* to_string(InputElement kind) {
  switch (kind) {
    case InputElement::none: return "none";
    case InputElement::vertex: return "vertex";
    case InputElement::segment: return "segment";
    case InputElement::hole: return "hole";
    case InputElement::region: return "region";
  }
  return "none";
}

namespace {

double distance_to_segment(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

template <class Points>
std::optional<std::uint32_t> nearest(const Points& points, Point p, double tolerance, auto point_of) {
  std::optional<std::uint32_t> best;
  double best_d = tolerance;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point q = point_of(points[i]);
    const double d = std::hypot(q.x - p.x, q.y - p.y);
    if (d <= best_d) {
      best_d = d;
      best = static_cast<std::uint32_t>(i);
    }
  }
  return best;
}

}  // namespace

PslgEditor::PslgEditor(Pslg input) : input_(std::move(input)) {
  if (input_.has_vertex_markers) input_.vertex_markers.resize(input_.points.size(), 0);
  else input_.vertex_markers.clear();
  input_.vertex_attributes.resize(input_.points.size() * input_.attributes_per_vertex, 0.0);
}

void PslgEditor::check_finite(Point p, const char* what) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y))
    throw EditRefused(std::string(what) + ": a coordinate (" + io::shortest_text(p.x) + ", " + io::shortest_text(p.y) +
                      ") is not a finite number");
}

void PslgEditor::check_vertex(std::uint32_t v, const char* what) const {
  if (v >= input_.points.size())
    throw EditRefused(std::string(what) + ": there is no vertex " + std::to_string(v + input_.first_index) +
                      " (the input has " + std::to_string(input_.points.size()) + ")");
}

PslgEditor::VertexValue PslgEditor::vertex_value(std::uint32_t v) const {
  VertexValue value;
  value.p = input_.points[v];
  if (input_.has_vertex_markers) value.marker = input_.vertex_markers[v];
  const std::size_t k = input_.attributes_per_vertex;
  value.attributes.assign(input_.vertex_attributes.begin() + static_cast<std::ptrdiff_t>(v * k),
                          input_.vertex_attributes.begin() + static_cast<std::ptrdiff_t>((v + 1) * k));
  return value;
}

// Inserting a vertex at `at` moves every later one up by one, and the segments' ends with
// them; erasing moves them down (no segment may end at the vertex erased).
void PslgEditor::insert_vertex(std::uint32_t at, const VertexValue& value) {
  input_.points.insert(input_.points.begin() + at, value.p);
  if (input_.has_vertex_markers) input_.vertex_markers.insert(input_.vertex_markers.begin() + at, value.marker);
  const std::size_t k = input_.attributes_per_vertex;
  std::vector<double> row = value.attributes;
  row.resize(k, 0.0);
  input_.vertex_attributes.insert(input_.vertex_attributes.begin() + static_cast<std::ptrdiff_t>(at * k), row.begin(),
                                  row.end());
  for (Segment& s : input_.segments) {
    if (s.a >= at) ++s.a;
    if (s.b >= at) ++s.b;
  }
}

void PslgEditor::erase_vertex(std::uint32_t at) {
  input_.points.erase(input_.points.begin() + at);
  if (input_.has_vertex_markers) input_.vertex_markers.erase(input_.vertex_markers.begin() + at);
  const std::size_t k = input_.attributes_per_vertex;
  input_.vertex_attributes.erase(input_.vertex_attributes.begin() + static_cast<std::ptrdiff_t>(at * k),
                                 input_.vertex_attributes.begin() + static_cast<std::ptrdiff_t>((at + 1) * k));
  for (Segment& s : input_.segments) {
    if (s.a > at) --s.a;
    if (s.b > at) --s.b;
  }
}

void PslgEditor::apply(const Change& c, bool forward) {
  // Undoing an insert erases, undoing an erase inserts, undoing a set sets the old value.
  Op op = c.op;
  if (!forward && op != Op::set) op = op == Op::insert ? Op::erase : Op::insert;
  const bool after = forward;  // which value a set or an insert puts in
  const auto at = static_cast<std::ptrdiff_t>(c.index);
  switch (c.array) {
    case Array::vertex:
      if (op == Op::insert) insert_vertex(c.index, c.op == Op::insert ? c.vertex_after : c.vertex_before);
      else if (op == Op::erase) erase_vertex(c.index);
      else {
        const VertexValue& v = after ? c.vertex_after : c.vertex_before;
        input_.points[c.index] = v.p;
        if (input_.has_vertex_markers) input_.vertex_markers[c.index] = v.marker;
      }
      break;
    case Array::segment:
      if (op == Op::insert)
        input_.segments.insert(input_.segments.begin() + at, c.op == Op::insert ? c.segment_after : c.segment_before);
      else if (op == Op::erase) input_.segments.erase(input_.segments.begin() + at);
      else input_.segments[c.index] = after ? c.segment_after : c.segment_before;
      break;
    case Array::hole:
      if (op == Op::insert)
        input_.holes.insert(input_.holes.begin() + at, (c.op == Op::insert ? c.region_after : c.region_before).point);
      else if (op == Op::erase) input_.holes.erase(input_.holes.begin() + at);
      else input_.holes[c.index] = (after ? c.region_after : c.region_before).point;
      break;
    case Array::region:
      if (op == Op::insert)
        input_.regions.insert(input_.regions.begin() + at, c.op == Op::insert ? c.region_after : c.region_before);
      else if (op == Op::erase) input_.regions.erase(input_.regions.begin() + at);
      else input_.regions[c.index] = after ? c.region_after : c.region_before;
      break;
  }
}

void PslgEditor::change(Edit& edit, Change c) {
  apply(c, true);
  edit.push_back(std::move(c));
}

void PslgEditor::commit(Edit edit) {
  if (edit.empty()) return;
  done_.push_back(std::move(edit));
  undone_.clear();
  ++revision_;
}

bool PslgEditor::undo() {
  if (done_.empty()) return false;
  Edit edit = std::move(done_.back());
  done_.pop_back();
  for (auto c = edit.rbegin(); c != edit.rend(); ++c) apply(*c, false);
  undone_.push_back(std::move(edit));
  ++revision_;
  return true;
}

bool PslgEditor::redo() {
  if (undone_.empty()) return false;
  Edit edit = std::move(undone_.back());
  undone_.pop_back();
  for (const Change& c : edit) apply(c, true);
  done_.push_back(std::move(edit));
  ++revision_;
  return true;
}

void PslgEditor::clear() {
  Edit edit;
  // From the end, so that each erase leaves the indices of those still to erase as they are.
  for (std::size_t r = input_.regions.size(); r-- > 0;)
    change(edit, {Op::erase, Array::region, static_cast<std::uint32_t>(r), {}, {}, {}, {}, input_.regions[r], {}});
  for (std::size_t h = input_.holes.size(); h-- > 0;)
    change(edit, {Op::erase, Array::hole, static_cast<std::uint32_t>(h), {}, {}, {}, {}, Region{input_.holes[h]}, {}});
  for (std::size_t s = input_.segments.size(); s-- > 0;)
    change(edit, {Op::erase, Array::segment, static_cast<std::uint32_t>(s), {}, {}, input_.segments[s], {}, {}, {}});
  for (std::size_t v = input_.points.size(); v-- > 0;)
    change(edit, {Op::erase, Array::vertex, static_cast<std::uint32_t>(v), vertex_value(static_cast<std::uint32_t>(v)),
                  {}, {}, {}, {}, {}});
  commit(std::move(edit));
}

std::uint32_t PslgEditor::add_vertex(Point p) {
  check_finite(p, "add vertex");
  VertexValue value;
  value.p = p;
  value.attributes.assign(input_.attributes_per_vertex, 0.0);
  const auto at = static_cast<std::uint32_t>(input_.points.size());
  Edit edit;
  change(edit, {Op::insert, Array::vertex, at, {}, value, {}, {}, {}, {}});
  commit(std::move(edit));
  return at;
}

void PslgEditor::move_vertex(std::uint32_t v, Point to) {
  check_vertex(v, "move vertex");
  check_finite(to, "move vertex");
  VertexValue before = vertex_value(v), after = before;
  after.p = to;
  Edit edit;
  change(edit, {Op::set, Array::vertex, v, std::move(before), std::move(after), {}, {}, {}, {}});
  commit(std::move(edit));
}

void PslgEditor::delete_vertex(std::uint32_t v) {
  check_vertex(v, "delete vertex");
  Edit edit;
  for (std::size_t s = input_.segments.size(); s-- > 0;) {
    const Segment seg = input_.segments[s];
    if (seg.a == v || seg.b == v)
      change(edit, {Op::erase, Array::segment, static_cast<std::uint32_t>(s), {}, {}, seg, {}, {}, {}});
  }
  change(edit, {Op::erase, Array::vertex, v, vertex_value(v), {}, {}, {}, {}, {}});
  commit(std::move(edit));
}

std::uint32_t PslgEditor::add_segment(std::uint32_t a, std::uint32_t b) {
  check_vertex(a, "add segment");
  check_vertex(b, "add segment");
  const auto number = [&](std::uint32_t v) { return std::to_string(v + input_.first_index); };
  if (a == b) throw EditRefused("add segment: both ends are vertex " + number(a));
  for (std::size_t s = 0; s < input_.segments.size(); ++s) {
    const Segment& seg = input_.segments[s];
    if ((seg.a == a && seg.b == b) || (seg.a == b && seg.b == a))
      throw EditRefused("add segment: vertices " + number(a) + " and " + number(b) + " are joined already (segment " +
                        std::to_string(s + input_.first_index) + ")");
  }
  const auto at = static_cast<std::uint32_t>(input_.segments.size());
  Edit edit;
  change(edit, {Op::insert, Array::segment, at, {}, {}, {}, Segment{a, b, 0}, {}, {}});
  commit(std::move(edit));
  return at;
}

std::uint32_t PslgEditor::add_segment(Point a, Point b, double tolerance) {
  check_finite(a, "add segment");
  check_finite(b, "add segment");
  std::optional<std::uint32_t> va = vertex_near(a, tolerance), vb = vertex_near(b, tolerance);
  if (va && vb && *va == *vb)
    throw EditRefused("add segment: both ends snap to vertex " + std::to_string(*va + input_.first_index));
  if (va && vb) return add_segment(*va, *vb);  // (refuses a segment that is there already)
  // One edit: the new ends and the segment, undone together.
  Edit edit;
  const auto new_vertex = [&](Point p) {
    VertexValue value;
    value.p = p;
    value.attributes.assign(input_.attributes_per_vertex, 0.0);
    const auto at = static_cast<std::uint32_t>(input_.points.size());
    change(edit, {Op::insert, Array::vertex, at, {}, value, {}, {}, {}, {}});
    return at;
  };
  if (!va) va = new_vertex(a);
  if (!vb) {
    if (a.x == b.x && a.y == b.y) {
      for (auto c = edit.rbegin(); c != edit.rend(); ++c) apply(*c, false);
      throw EditRefused("add segment: its two ends are the same point");
    }
    vb = new_vertex(b);
  }
  const auto at = static_cast<std::uint32_t>(input_.segments.size());
  change(edit, {Op::insert, Array::segment, at, {}, {}, {}, Segment{*va, *vb, 0}, {}, {}});
  commit(std::move(edit));
  return at;
}

void PslgEditor::delete_segment(std::uint32_t s) {
  if (s >= input_.segments.size())
    throw EditRefused("delete segment: there is no segment " + std::to_string(s + input_.first_index));
  Edit edit;
  change(edit, {Op::erase, Array::segment, s, {}, {}, input_.segments[s], {}, {}, {}});
  commit(std::move(edit));
}

std::uint32_t PslgEditor::add_hole(Point p) {
  check_finite(p, "add hole");
  const auto at = static_cast<std::uint32_t>(input_.holes.size());
  Edit edit;
  change(edit, {Op::insert, Array::hole, at, {}, {}, {}, {}, {}, Region{p}});
  commit(std::move(edit));
  return at;
}

void PslgEditor::move_hole(std::uint32_t h, Point to) {
  if (h >= input_.holes.size()) throw EditRefused("move hole: there is no hole point " + std::to_string(h + input_.first_index));
  check_finite(to, "move hole");
  Edit edit;
  change(edit, {Op::set, Array::hole, h, {}, {}, {}, {}, Region{input_.holes[h]}, Region{to}});
  commit(std::move(edit));
}

void PslgEditor::delete_hole(std::uint32_t h) {
  if (h >= input_.holes.size())
    throw EditRefused("delete hole: there is no hole point " + std::to_string(h + input_.first_index));
  Edit edit;
  change(edit, {Op::erase, Array::hole, h, {}, {}, {}, {}, Region{input_.holes[h]}, {}});
  commit(std::move(edit));
}

namespace {
void check_region_values(const Region& r, const char* what) {
  if (!std::isfinite(r.point.x) || !std::isfinite(r.point.y) || !std::isfinite(r.attribute) ||
      !std::isfinite(r.max_area))
    throw EditRefused(std::string(what) + ": a region point's coordinates, attribute and maximum area must be finite numbers");
}
}  // namespace

std::uint32_t PslgEditor::add_region(const Region& r) {
  check_region_values(r, "add region");
  const auto at = static_cast<std::uint32_t>(input_.regions.size());
  Edit edit;
  change(edit, {Op::insert, Array::region, at, {}, {}, {}, {}, {}, r});
  commit(std::move(edit));
  return at;
}

void PslgEditor::set_region(std::uint32_t r, const Region& values) {
  if (r >= input_.regions.size())
    throw EditRefused("edit region: there is no region point " + std::to_string(r + input_.first_index));
  check_region_values(values, "edit region");
  Edit edit;
  change(edit, {Op::set, Array::region, r, {}, {}, {}, {}, input_.regions[r], values});
  commit(std::move(edit));
}

void PslgEditor::delete_region(std::uint32_t r) {
  if (r >= input_.regions.size())
    throw EditRefused("delete region: there is no region point " + std::to_string(r + input_.first_index));
  Edit edit;
  change(edit, {Op::erase, Array::region, r, {}, {}, {}, {}, input_.regions[r], {}});
  commit(std::move(edit));
}

void PslgEditor::move(ElementRef at, Point to) {
  switch (at.kind) {
    case InputElement::vertex: return move_vertex(at.index, to);
    case InputElement::hole: return move_hole(at.index, to);
    case InputElement::region: {
      if (at.index >= input_.regions.size()) break;
      Region r = input_.regions[at.index];
      r.point = to;
      return set_region(at.index, r);
    }
    case InputElement::segment: throw EditRefused("move: a segment moves with its vertices (move them)");
    case InputElement::none: break;
  }
  throw EditRefused("move: nothing there to move");
}

void PslgEditor::erase(ElementRef at) {
  switch (at.kind) {
    case InputElement::vertex: return delete_vertex(at.index);
    case InputElement::segment: return delete_segment(at.index);
    case InputElement::hole: return delete_hole(at.index);
    case InputElement::region: return delete_region(at.index);
    case InputElement::none: break;
  }
  throw EditRefused("delete: nothing there to delete");
}

std::optional<std::uint32_t> PslgEditor::vertex_near(Point p, double tolerance) const {
  return nearest(input_.points, p, tolerance, [](const Point& q) { return q; });
}
std::optional<std::uint32_t> PslgEditor::hole_near(Point p, double tolerance) const {
  return nearest(input_.holes, p, tolerance, [](const Point& q) { return q; });
}
std::optional<std::uint32_t> PslgEditor::region_near(Point p, double tolerance) const {
  return nearest(input_.regions, p, tolerance, [](const Region& r) { return r.point; });
}

std::optional<std::uint32_t> PslgEditor::segment_near(Point p, double tolerance) const {
  std::optional<std::uint32_t> best;
  double best_d = tolerance;
  for (std::size_t s = 0; s < input_.segments.size(); ++s) {
    const Segment& seg = input_.segments[s];
    const double d = distance_to_segment(p, input_.points[seg.a], input_.points[seg.b]);
    if (d <= best_d) {
      best_d = d;
      best = static_cast<std::uint32_t>(s);
    }
  }
  return best;
}

ElementRef PslgEditor::element_near(Point p, double tolerance) const {
  if (const auto v = vertex_near(p, tolerance)) return {InputElement::vertex, *v};
  if (const auto h = hole_near(p, tolerance)) return {InputElement::hole, *h};
  if (const auto r = region_near(p, tolerance)) return {InputElement::region, *r};
  if (const auto s = segment_near(p, tolerance)) return {InputElement::segment, *s};
  return {};
}

Point PslgEditor::position(ElementRef at) const {
  switch (at.kind) {
    case InputElement::vertex:
      if (at.index < input_.points.size()) return input_.points[at.index];
      break;
    case InputElement::hole:
      if (at.index < input_.holes.size()) return input_.holes[at.index];
      break;
    case InputElement::region:
      if (at.index < input_.regions.size()) return input_.regions[at.index].point;
      break;
    case InputElement::segment:
      if (at.index < input_.segments.size()) {
        const Point a = input_.points[input_.segments[at.index].a], b = input_.points[input_.segments[at.index].b];
        return {a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
      }
      break;
    case InputElement::none: break;
  }
  return {};
}

double PslgEditor::extent() const {
  if (input_.points.empty() && input_.holes.empty() && input_.regions.empty()) return 0.0;
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x, hi_x = -lo_x, hi_y = -lo_x;
  const auto grow = [&](Point q) {
    lo_x = std::min(lo_x, q.x);
    lo_y = std::min(lo_y, q.y);
    hi_x = std::max(hi_x, q.x);
    hi_y = std::max(hi_y, q.y);
  };
  for (const Point& q : input_.points) grow(q);
  for (const Point& q : input_.holes) grow(q);
  for (const Region& r : input_.regions) grow(r.point);
  return std::max(hi_x - lo_x, hi_y - lo_y);
}

}  // namespace meshstep
