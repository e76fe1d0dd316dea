// The log header's fields that describe the input beyond what the events hold (LogHeader):
// text, one record a line, every number the shortest text that reads back to the same value.
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include "meshstep/io/shortest_text.hpp"
#include "meshstep/replay/log_writer.hpp"

namespace meshstep::replay {

namespace {

void append_number(std::string& out, double v) { out += io::shortest_text(v); }

// Reads the text's lines of numbers. Each line must hold `per_line` numbers (0: any
// number of them, at least one); `what` names a line in messages ("region 3").
class NumberLines {
 public:
  NumberLines(const std::string& text, std::string what) : p_(text.data()), end_(p_ + text.size()), what_(std::move(what)) {}

  bool more() const { return p_ < end_; }

  template <class T>
  std::vector<T> line(std::size_t per_line) {
    ++line_;  // the line being read, and after it the line read last: what fail() names
    std::vector<T> values;
    for (;;) {
      while (p_ < end_ && *p_ == ' ') ++p_;
      if (p_ == end_ || *p_ == '\n') break;
      if (per_line != 0 && values.size() == per_line)
        fail("more than " + std::to_string(per_line) + " numbers");
      T v{};
      const auto [next, ec] = std::from_chars(p_, end_, v);
      if (ec != std::errc()) fail(ec == std::errc::result_out_of_range ? "a number out of range" : "not a number");
      if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(v)) fail("a number that is not finite");
      values.push_back(v);
      p_ = next;
    }
    if (values.empty() || (per_line != 0 && values.size() != per_line))
      fail("expected " + (per_line != 0 ? std::to_string(per_line) : std::string("some")) + " numbers");
    if (p_ < end_) ++p_;  // the newline
    return values;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument(what_ + " " + std::to_string(line_) + ": " + what);
  }

 private:
  const char* p_;
  const char* end_;
  std::string what_;
  std::size_t line_ = 0;
};

}  // namespace

std::string regions_field(const std::vector<Region>& regions) {
  std::string out;
  for (const Region& r : regions) {
    for (const double v : {r.point.x, r.point.y, r.attribute, r.max_area}) {
      append_number(out, v);
      out += ' ';
    }
    out.back() = '\n';
  }
  return out;
}

std::vector<Region> parse_regions_field(const std::string& text) {
  std::vector<Region> regions;
  NumberLines lines(text, "region");
  while (lines.more()) {
    const std::vector<double> v = lines.line<double>(4);
    regions.push_back({{v[0], v[1]}, v[2], v[3]});
  }
  return regions;
}

std::string holes_field(const std::vector<Point>& holes) {
  std::string out;
  for (const Point& h : holes) {
    append_number(out, h.x);
    out += ' ';
    append_number(out, h.y);
    out += '\n';
  }
  return out;
}

std::vector<Point> parse_holes_field(const std::string& text) {
  std::vector<Point> holes;
  NumberLines lines(text, "hole");
  while (lines.more()) {
    const std::vector<double> v = lines.line<double>(2);
    holes.push_back({v[0], v[1]});
  }
  return holes;
}

std::string segments_field(const std::vector<Segment>& segments) {
  std::string out;
  for (const Segment& s : segments) out += std::to_string(s.a) + ' ' + std::to_string(s.b) + '\n';
  return out;
}

std::vector<Segment> parse_segments_field(const std::string& text, std::size_t vertex_count) {
  std::vector<Segment> segments;
  NumberLines lines(text, "segment");
  while (lines.more()) {
    const std::vector<std::uint64_t> v = lines.line<std::uint64_t>(2);
    if (v[0] >= vertex_count || v[1] >= vertex_count)
      lines.fail("a vertex index beyond the input's " + std::to_string(vertex_count) + " vertices");
    segments.push_back({static_cast<std::uint32_t>(v[0]), static_cast<std::uint32_t>(v[1]), 0});
  }
  return segments;
}

// Runs of equal markers, "marker count" a line: a boundary marked 1 among interior 0s
// takes a few lines, not one number a vertex.
std::string vertex_markers_field(const std::vector<int>& markers) {
  std::string out;
  for (std::size_t i = 0; i < markers.size();) {
    std::size_t j = i;
    while (j < markers.size() && markers[j] == markers[i]) ++j;
    out += std::to_string(markers[i]) + ' ' + std::to_string(j - i) + '\n';
    i = j;
  }
  return out;
}

std::vector<int> parse_vertex_markers_field(const std::string& text, std::size_t vertex_limit) {
  std::vector<int> markers;
  NumberLines lines(text, "vertex marker run");
  while (lines.more()) {
    const std::vector<std::int64_t> v = lines.line<std::int64_t>(2);
    if (v[0] < INT32_MIN || v[0] > INT32_MAX) lines.fail("a marker out of range");
    if (v[1] <= 0 || static_cast<std::uint64_t>(v[1]) > vertex_limit - markers.size())
      lines.fail("a run of " + std::to_string(v[1]) + " markers where the input has " +
                 std::to_string(vertex_limit) + " vertices");
    markers.insert(markers.end(), static_cast<std::size_t>(v[1]), static_cast<int>(v[0]));
  }
  return markers;
}

// The count per vertex on the first line, then one vertex's attributes a line.
std::string vertex_attributes_field(std::size_t per_vertex, const std::vector<double>& values) {
  std::string out = std::to_string(per_vertex) + '\n';
  for (std::size_t i = 0; i < values.size(); ++i) {
    append_number(out, values[i]);
    out += (i + 1) % per_vertex == 0 ? '\n' : ' ';
  }
  return out;
}

std::pair<std::size_t, std::vector<double>> parse_vertex_attributes_field(const std::string& text,
                                                                          std::size_t vertex_limit) {
  NumberLines lines(text, "vertex attributes line");
  const std::vector<std::uint32_t> count = lines.line<std::uint32_t>(1);
  if (count[0] == 0 || count[0] > 1000) lines.fail("a count of attributes of 1 to 1000 expected");
  std::vector<double> values;
  std::size_t vertices = 0;
  while (lines.more()) {
    if (++vertices > vertex_limit)
      lines.fail("more vertices than the input's " + std::to_string(vertex_limit));
    const std::vector<double> v = lines.line<double>(count[0]);
    values.insert(values.end(), v.begin(), v.end());
  }
  return {count[0], std::move(values)};
}

void describe_input(LogHeader& header, const Pslg& in) {
  header.regions = in.regions;
  header.holes = in.holes;
  if (in.has_vertex_markers) header.vertex_markers = in.vertex_markers;
  header.attributes_per_vertex = in.attributes_per_vertex;
  header.vertex_attributes = in.vertex_attributes;
  header.has_segment_markers = in.has_segment_markers;
  header.segments = in.segments;
}

}  // namespace meshstep::replay
