// The part of the plane a refinement is limited to (RefineOptions::region): an axis-aligned
// box or a simple polygon. Only triangles whose centroid lies in the region are tested
// against the bounds; the algorithm may still put points outside it where its own rules
// require (docs/recipes.md, "Regions").
//
// A value type of its own, with no tie to the refinement loop, so that anything that runs
// an operation on part of a mesh can hold one.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "meshstep/geometry/point.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep {

class RefineRegion {
 public:
  enum class Kind { box, polygon };

  // The box [low.x, high.x] x [low.y, high.y]. Throws InputError for a coordinate that is
  // not finite or a box with no inside (low.x >= high.x or low.y >= high.y).
  static RefineRegion box(const Point& low, const Point& high);
  // "X0,Y0,X1,Y1" (the --region option's text), with the errors of box() and one for text
  // that is not four comma-separated numbers.
  static RefineRegion parse_box(std::string_view text);
  // A simple polygon through `vertices` in order, either way round (the last joins the
  // first). Throws InputError for fewer than 3 vertices, a coordinate that is not finite,
  // two edges that touch or cross other than neighbours at their shared end, or no area.
  static RefineRegion polygon(std::vector<Point> vertices);
  // The vertices of "X0,Y0,X1,Y1,X2,Y2,..." (the --region-polygon option's text), in the
  // order given, checked as polygon() checks them, each edge named with its ends ("edge 2
  // (1,0 to 0,1)"). Throws InputError for those errors and for text that is not an even
  // count, at least 6, of comma-separated numbers.
  static std::vector<Point> parse_polygon(std::string_view text);
  // The polygon a PSLG's segments make: they must form one closed simple polygon, every
  // vertex they use on exactly two of them. Throws InputError naming the first segment or
  // vertex (in the PSLG's own numbering, first_index) that breaks the rule.
  static RefineRegion polygon_of(const Pslg& pslg);

  Kind kind() const { return kind_; }
  // The box's corners, or the polygon's bounding box.
  const Point& low() const { return low_; }
  const Point& high() const { return high_; }
  // The polygon's vertices, counterclockwise; the box's four corners counterclockwise.
  const std::vector<Point>& vertices() const { return vertices_; }

  // Is p in the closed region (its border included)? Decided exactly: comparisons for the
  // box, exact orientation predicates for the polygon (a point on an edge, or at a vertex,
  // is inside).
  bool contains(const Point& p) const {
    if (p.x < low_.x || p.x > high_.x || p.y < low_.y || p.y > high_.y) return false;
    return kind_ == Kind::box || polygon_contains(p);
  }

  // The region as one word of text, exact (shortest round-trip numbers), for the log's
  // parameters: "box:X0,Y0,X1,Y1" or "polygon:X,Y;X,Y;..." (counterclockwise).
  std::string text() const;
  // The region from text() (the log header's region= field). Throws InputError for text
  // that is neither, with the errors of box() and polygon().
  static RefineRegion parse_text(std::string_view text);

 private:
  bool polygon_contains(const Point& p) const;

  Kind kind_ = Kind::box;
  Point low_, high_;
  std::vector<Point> vertices_;
};

}  // namespace meshstep
