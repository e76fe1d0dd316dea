// The SVG writer's output: a growing UTF-8 string with the few kinds of token an SVG file
// is made of (numbers rounded to 0.01, colours, escaped text), written without iostreams,
// and a path-data writer that keeps paths short.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

#include "meshstep/geometry/point.hpp"
#include "meshstep/scene/scene.hpp"

namespace meshstep::scene::detail {

// A coordinate in hundredths of a pixel: what the file says, exactly.
std::int64_t to_hundredths(double v);

class SvgText {
 public:
  SvgText() { out_.resize(std::size_t{1} << 16); }
  // Room for about n characters (growing later costs copies and page faults).
  void reserve(std::size_t n) {
    if (n > out_.size()) out_.resize(n);
  }

  void raw(std::string_view s) {
    char* p = room(s.size());
    s.copy(p, s.size());
    used_ += s.size();
  }
  void ch(char c) {
    *room(1) = c;
    ++used_;
  }
  // v / 100 with at most 2 decimals, no trailing zeros ("12", "-3.5", "0.25").
  void hundredths(std::int64_t v);
  // A finite value rounded to 0.01 (coordinates, radii).
  void number(double v) { hundredths(to_hundredths(v)); }
  // A finite value rounded to 0.001 (opacities, widths, font sizes, offsets).
  void fine_number(double v);
  // "#rrggbb" (the alpha goes into a separate opacity attribute).
  void color(Rgba c);
  // Text content or attribute value: &, <, >, " and ' escaped; bytes that are not valid
  // UTF-8 and characters XML does not allow become U+FFFD.
  void escaped(std::string_view text);

  // ` name="value"`: the attribute forms the writer uses.
  void attr(std::string_view name, std::string_view value);
  void attr_escaped(std::string_view name, std::string_view value);
  void attr_number(std::string_view name, double v);
  void attr_fine(std::string_view name, double v);
  void attr_color(std::string_view name, Rgba c);
  // ` NAME="#rrggbb"` and, when the colour is translucent, ` NAME-opacity="a"`;
  // ` NAME="none"` when fully transparent.
  void paint(std::string_view name, Rgba c);

  std::size_t size() const { return used_; }
  // Takes back what was written after size() was `size` (an element that turned out empty).
  void truncate(std::size_t size) { used_ = size; }
  std::string take() {
    out_.resize(used_);
    used_ = 0;
    return std::move(out_);
  }

 private:
  // Space for n more characters at the end. The string is kept larger than what is used
  // and written through a pointer: appending a number is a few stores, not a library call.
  char* room(std::size_t n) {
    if (out_.size() - used_ < n) out_.resize(std::max(2 * out_.size(), used_ + n));
    return out_.data() + used_;
  }
  // Appends [begin, end) of a number formatted on the stack.
  void append(const char* begin, const char* end) {
    const std::size_t n = static_cast<std::size_t>(end - begin);
    char* p = room(n);
    for (std::size_t i = 0; i < n; ++i) p[i] = begin[i];
    used_ += n;
  }

  std::string out_;
  std::size_t used_ = 0;
};

// Path data ("d") in relative commands: each step is a small difference, so a path of many
// small triangles costs a few bytes per point. Coordinates are rounded to 0.01 first and
// the differences are taken between rounded values, so no error accumulates.
class PathData {
 public:
  explicit PathData(SvgText& out) : out_(out) {}

  void move_to(Point p);
  void line_to(Point p);
  void close();
  // A whole circle as a subpath (two half-circle arcs), starting and ending at its left.
  void circle(Point center, double radius);
  bool empty() const { return empty_; }

 private:
  void command(char c);
  void value(std::int64_t v);
  void pair(std::int64_t x, std::int64_t y);

  SvgText& out_;
  std::int64_t x_ = 0, y_ = 0;            // the current point
  std::int64_t start_x_ = 0, start_y_ = 0;  // where the subpath started ('z' returns there)
  char last_ = 0;                          // the last command written
  bool after_command_ = true;              // no separator needed before the next number
  bool empty_ = true;
};

}  // namespace meshstep::scene::detail
