// Reading STL files, binary or ASCII.
//
// Binary: an 80-byte header, a uint32 triangle count, then 50 bytes per triangle (normal
// and 3 corners as float32, a 2-byte attribute), all little-endian. ASCII:
//   solid NAME / facet normal nx ny nz / outer loop / vertex x y z (3 times) / endloop /
//   endfacet / ... / endsolid NAME
// Many binary files also begin with "solid" (exporters copy the word into the header), so
// the size formula decides first: a file of exactly 84 + 50 * count bytes is binary.
//
// STL stores every triangle's corners by value; corners with exactly equal coordinates
// become one vertex, numbered in order of first appearance. Facet normals are ignored:
// they are redundant with the corners' order, and exporters often leave them 0 0 0.
#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "io/fields.hpp"
#include "io/record_reader.hpp"
#include "io/sections.hpp"
#include "io/surface_bytes.hpp"
#include "io/surface_readers.hpp"
#include "meshstep/io/mapped_file.hpp"
#include "meshstep/io/shortest_text.hpp"

namespace meshstep::io::detail {
namespace {

constexpr std::size_t kHeaderSize = 80;
constexpr std::size_t kCountEnd = kHeaderSize + 4;
constexpr std::size_t kRecordSize = 50;

// Welds corners into shared vertices: a map from coordinates to vertex number.
class Welder {
 public:
  explicit Welder(Surface& s) : s_(s) {}
  void reserve(std::size_t corners) { index_.reserve(corners / 2); }
  // False when the point would be one vertex too many for 32-bit indices.
  bool add(const Point3& p, std::uint32_t& vertex) {
    const auto next = static_cast<std::uint32_t>(s_.vertices.size());
    const auto [it, inserted] = index_.try_emplace(p, next);
    if (inserted) {
      if (s_.vertices.size() == kMaxItems) return false;
      s_.vertices.push_back(p);
    }
    vertex = it->second;
    return true;
  }

 private:
  // Equal coordinates must hash alike: -0.0 == 0.0, but their bits differ, and adding
  // +0.0 turns -0.0 into +0.0. (NaN never gets here: the readers refuse it.)
  struct Hash {
    std::size_t operator()(const Point3& p) const {
      const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v + 0.0); };
      std::uint64_t h = bits(p.x);
      h = (h ^ (h >> 29)) * 0x9E3779B97F4A7C15ull + bits(p.y);
      h = (h ^ (h >> 29)) * 0x9E3779B97F4A7C15ull + bits(p.z);
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  Surface& s_;
  std::unordered_map<Point3, std::uint32_t, Hash> index_;
};

// Bytes that never occur in a text file (control characters other than whitespace).
bool has_binary_bytes(const std::uint8_t* p, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t c = p[i];
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f') || c == 0x7F) {
      return true;
    }
  }
  return false;
}

bool starts_with_solid(const std::uint8_t* p, std::size_t n) {
  std::size_t i = 0;
  while (i < n && std::isspace(p[i])) ++i;
  if (n - i < 5) return false;
  for (std::size_t k = 0; k < 5; ++k) {
    if (std::tolower(p[i + k]) != "solid"[k]) return false;
  }
  return n - i == 5 || std::isspace(p[i + 5]);
}

Surface read_binary(const std::string& path, const std::uint8_t* data, std::uint32_t count) {
  Surface s;
  Welder welder(s);
  s.triangles.reserve(count);  // the size check bounds count by the file size
  welder.reserve(std::size_t{3} * count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::size_t record = kCountEnd + std::size_t{t} * kRecordSize;
    std::array<std::uint32_t, 3> triangle{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t at = record + 12 + 12 * k;  // after the normal
      double xyz[3];
      for (std::size_t c = 0; c < 3; ++c) {
        xyz[c] = load_float(data + at + 4 * c, false);
        if (!std::isfinite(xyz[c])) {
          fail_at_byte(path, at + 4 * c, "triangle " + std::to_string(t) +
                                             " has a coordinate that is not finite (" +
                                             shortest_text(xyz[c]) + ")");
        }
      }
      if (!welder.add({xyz[0], xyz[1], xyz[2]}, triangle[k])) {
        fail_at_byte(path, at, "too many distinct vertices");
      }
    }
    s.triangles.push_back(triangle);
  }
  return s;
}

bool is_keyword(const RecordReader& r, std::size_t field, std::string_view word) {
  const std::string_view f = r.field(field);
  if (f.size() != word.size()) return false;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(f[i])) != word[i]) return false;
  }
  return true;
}

// The record's fields as they read, for messages.
std::string record_text(const RecordReader& r) {
  std::string text;
  for (std::size_t i = 0; i < r.field_count(); ++i) {
    if (i > 0) text += ' ';
    text += r.field(i);
  }
  return quote(text);
}

// Moves to the next record, which must be exactly the words of `line` ("outer loop").
void expect_line(RecordReader& r, std::string_view line) {
  const std::string quoted = std::string("'").append(line).append("'");
  require_record(r, r.next(), quoted);
  std::size_t k = 0;
  bool same = true;
  for (std::size_t start = 0; start < line.size(); ++k) {
    const std::size_t end = std::min(line.find(' ', start), line.size());
    same = same && k < r.field_count() && is_keyword(r, k, line.substr(start, end - start));
    start = end + 1;
  }
  if (!same || k != r.field_count()) {
    r.fail("expected " + quoted + ", found " + record_text(r));
  }
}

// One facet, the reader on its "facet normal" line.
void read_facet(RecordReader& r, Welder& welder, Surface& s) {
  if (r.field_count() != 5 || !is_keyword(r, 1, "normal")) {
    r.fail("expected 'facet normal nx ny nz', found " + record_text(r));
  }
  expect_line(r, "outer loop");
  std::array<std::uint32_t, 3> triangle{};
  std::size_t corners = 0;
  for (;;) {
    require_record(r, r.next(), "'vertex' or 'endloop'");
    if (is_keyword(r, 0, "endloop")) break;
    if (!is_keyword(r, 0, "vertex")) {
      r.fail("expected 'vertex' or 'endloop', found " + quote(r.field(0)));
    }
    if (corners == 3) r.fail("a facet has more than 3 vertices; STL facets are triangles");
    expect_fields(r, 4, "vertex, x, y, z");
    const Point3 p{parse_real(r, 1, "x coordinate"), parse_real(r, 2, "y coordinate"),
                   parse_real(r, 3, "z coordinate")};
    if (!welder.add(p, triangle[corners])) r.fail("too many distinct vertices");
    ++corners;
  }
  if (corners < 3) {
    r.fail("a facet needs 3 vertices, found " + std::to_string(corners));
  }
  if (r.field_count() != 1) r.fail("'endloop' should be alone on its line");
  expect_line(r, "endfacet");
  s.triangles.push_back(triangle);
}

Surface read_ascii(const std::string& path) {
  RecordReader r(path);
  read_header(r, "solid NAME");
  Surface s;
  Welder welder(s);
  // A file may hold several solids one after the other: they make one surface.
  bool more = true;
  while (more) {
    if (!is_keyword(r, 0, "solid")) {
      r.fail("expected 'solid', found " + quote(r.field(0)));
    }
    for (;;) {
      require_record(r, r.next(), "'facet' or 'endsolid'");
      if (is_keyword(r, 0, "endsolid")) break;
      if (!is_keyword(r, 0, "facet")) {
        r.fail("expected 'facet' or 'endsolid', found " + quote(r.field(0)));
      }
      read_facet(r, welder, s);
    }
    more = r.next();
  }
  return s;
}

}  // namespace

Surface read_stl(const std::string& path) {
  const MappedFile file(path);
  const std::uint8_t* data = file.data();
  const std::size_t size = file.size();
  std::uint64_t binary_size = 0;
  std::uint32_t count = 0;
  if (size >= kCountEnd) {
    count = static_cast<std::uint32_t>(load_uint(data + kHeaderSize, 4, false));
    binary_size = kCountEnd + std::uint64_t{count} * kRecordSize;
    if (binary_size == size) return read_binary(path, data, count);
  }
  if (starts_with_solid(data, size) && !has_binary_bytes(data, size)) return read_ascii(path);
  if (size == 0) fail_at_byte(path, 0, "the file is empty");
  if (size < kCountEnd) {
    fail_at_byte(path, size,
                 "unexpected end of file: a binary STL file has at least " +
                     std::to_string(kCountEnd) + " bytes, this one " + std::to_string(size) +
                     ", and it is not an ASCII STL file either (which starts with 'solid')");
  }
  fail_at_byte(path, kHeaderSize,
               "the triangle count " + std::to_string(count) + " makes a binary STL file of " +
                   std::to_string(binary_size) + " bytes, but this one has " +
                   std::to_string(size) +
                   " (truncated file?); it is not an ASCII STL file either (text starting "
                   "with 'solid')");
}

}  // namespace meshstep::io::detail
