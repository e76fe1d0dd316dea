// An input (a Pslg) being edited by hand: the viewer's workbench edits through it, and its
// scripts and tests drive it directly. No GL, no ImGui.
//
// Every command is one edit that undo() takes back whole, and redo() makes again; there is
// no limit on how many are kept. An edit is kept as the few primitive changes it made to
// the arrays (a vertex inserted at i, a segment erased at j, a point set from p to q), each
// with the values it replaced, so that undoing restores the exact bits of every coordinate
// and an edit of a big input costs memory for what changed only.
//
// Commands that make no sense (a vertex that does not exist, a segment from a vertex to
// itself or one that is there already, a coordinate that is not finite) are refused with
// an EditRefused that says why, and change nothing. What the core refuses or warns of when
// the input is triangulated (two vertices at one place, coordinates outside the range rule)
// is allowed here: it is the triangulator's to say, and the workbench shows its words.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep {

class EditRefused : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The kinds of element a person points at.
enum class InputElement { none, vertex, segment, hole, region };
const char* to_string(InputElement kind);

struct ElementRef {
  InputElement kind = InputElement::none;
  std::uint32_t index = 0;
  bool operator==(const ElementRef&) const = default;
};

class PslgEditor {
 public:
  // Starts from `input` (its vertex markers and attributes are kept for the vertices it has;
  // new vertices get marker 0 and attributes 0). No edit to undo.
  explicit PslgEditor(Pslg input = {});

  const Pslg& input() const { return input_; }
  // Goes up with every change, undo and redo included: what the workbench compares to know
  // that the mesh it shows is stale.
  std::uint64_t revision() const { return revision_; }

  // --- Commands: each one edit (one undo step). EditRefused when it makes no sense.
  // A new, empty input (Ctrl+N); undoable like any edit.
  void clear();
  std::uint32_t add_vertex(Point p);
  void move_vertex(std::uint32_t v, Point to);
  // Deletes the vertex and every segment that ends at it; later vertices are renumbered
  // (one less), as a .poly file written after it numbers them.
  void delete_vertex(std::uint32_t v);
  std::uint32_t add_segment(std::uint32_t a, std::uint32_t b);
  // A segment between two points, each end snapped to the nearest vertex within
  // `tolerance` or made a new vertex there. One edit, whatever it made.
  std::uint32_t add_segment(Point a, Point b, double tolerance);
  void delete_segment(std::uint32_t s);
  // Closes a polyline: a segment from its last vertex back to its first.
  std::uint32_t close_polygon(std::uint32_t first, std::uint32_t last) { return add_segment(last, first); }
  std::uint32_t add_hole(Point p);
  void move_hole(std::uint32_t h, Point to);
  void delete_hole(std::uint32_t h);
  std::uint32_t add_region(const Region& r);
  // A region point's values (attribute, max area, and where it is) as a form edits them.
  void set_region(std::uint32_t r, const Region& values);
  void delete_region(std::uint32_t r);
  // Moves whatever `at` names (a segment cannot be moved: refused).
  void move(ElementRef at, Point to);
  // Deletes whatever `at` names.
  void erase(ElementRef at);

  bool can_undo() const { return !done_.empty(); }
  bool can_redo() const { return !undone_.empty(); }
  bool undo();  // false when there is nothing to undo
  bool redo();
  std::size_t undo_depth() const { return done_.size(); }

  // --- Finding what is where (a click, a script's X Y).
  // The nearest vertex within `tolerance` (Euclidean) of p.
  std::optional<std::uint32_t> vertex_near(Point p, double tolerance) const;
  std::optional<std::uint32_t> hole_near(Point p, double tolerance) const;
  std::optional<std::uint32_t> region_near(Point p, double tolerance) const;
  std::optional<std::uint32_t> segment_near(Point p, double tolerance) const;
  // A vertex, else a hole point, else a region point, else a segment: the order a click
  // picks in (points lie on segments; the point is what is meant).
  ElementRef element_near(Point p, double tolerance) const;
  // Where an element is drawn and its message is put: a point, or a segment's midpoint.
  Point position(ElementRef at) const;

  // The largest |coordinate| span (width or height of the bounding box of every point), 0
  // for an empty input: what a script's tolerance is measured against.
  double extent() const;

 private:
  // One primitive change to the arrays, with what it replaced: applied forward to redo,
  // backward (its inverse) to undo.
  enum class Op : std::uint8_t { insert, erase, set };
  enum class Array : std::uint8_t { vertex, segment, hole, region };
  struct VertexValue {
    Point p;
    int marker = 0;
    std::vector<double> attributes;
  };
  struct Change {
    Op op;
    Array array;
    std::uint32_t index;
    VertexValue vertex_before, vertex_after;  // vertex
    Segment segment_before{}, segment_after{};  // segment
    Region region_before{}, region_after{};     // hole (its point) and region
  };
  using Edit = std::vector<Change>;

  void apply(const Change& c, bool forward);
  void commit(Edit edit);  // applies nothing: the edit's changes are applied as made
  void change(Edit& edit, Change c);
  VertexValue vertex_value(std::uint32_t v) const;
  void insert_vertex(std::uint32_t at, const VertexValue& value);
  void erase_vertex(std::uint32_t at);
  void check_vertex(std::uint32_t v, const char* what) const;
  static void check_finite(Point p, const char* what);

  Pslg input_;
  std::vector<Edit> done_, undone_;
  std::uint64_t revision_ = 0;
};

}  // namespace meshstep
