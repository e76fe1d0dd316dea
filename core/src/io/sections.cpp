#include "io/sections.hpp"

#include <memory>
#include <unordered_map>

#include "meshstep/error.hpp"
#include "meshstep/huge_pages.hpp"

namespace meshstep::io::detail {
namespace {

std::string vertex_record_names(std::size_t attributes, bool markers) {
  std::string names = "vertex number, x, y";
  if (attributes == 1) names += ", attribute";
  if (attributes > 1) names += ", " + std::to_string(attributes) + " attributes";
  if (markers) names += ", marker";
  return names;
}

void read_segments(RecordReader& r, Numbering& numbering, std::uint64_t vertex_count,
                   Pslg& out, std::vector<std::string>* warnings) {
  require_record(r, r.next(),
                 "the segment header line (number of segments, number of boundary markers)");
  expect_fields(r, 2, "number of segments, number of boundary markers");
  const std::uint64_t count = parse_count(r, 0, "number of segments");
  const bool markers = parse_marker_flag(r, 1, "number of segment boundary markers");
  const std::size_t header_line = r.line();
  const std::size_t fields = markers ? 4 : 3;
  const std::size_t reserve = check_count(r, count, fields, "segments", kMaxItems);
  out.has_segment_markers = markers;
  out.segments.reserve(reserve);
  const char* names = markers ? "segment number, endpoint, endpoint, marker"
                              : "segment number, endpoint, endpoint";

  // Segment number (as written in the file) of each undirected vertex pair seen so far.
  std::unordered_map<std::uint64_t, std::int64_t> seen;
  seen.reserve(reserve);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.next()) fail_truncated(r, i, count, "segments", header_line);
    expect_fields(r, fields, names);
    check_record_number(r, numbering, i, "segment");
    Segment s;
    s.a = parse_index(r, 1, "segment endpoint", vertex_count, numbering.base, "vertices");
    s.b = parse_index(r, 2, "segment endpoint", vertex_count, numbering.base, "vertices");
    if (markers) s.marker = parse_marker(r, 3, "segment boundary marker");
    const std::int64_t number = numbering.base + static_cast<std::int64_t>(i);
    const std::int64_t first_vertex = numbering.base;
    if (s.a == s.b) {
      warn(r, warnings,
           "segment " + std::to_string(number) + " joins vertex " +
               std::to_string(first_vertex + s.a) + " to itself; dropped");
      continue;
    }
    const std::uint64_t key = s.a < s.b ? (std::uint64_t{s.a} << 32) | s.b
                                        : (std::uint64_t{s.b} << 32) | s.a;
    const auto [it, inserted] = seen.emplace(key, number);
    if (!inserted) {
      warn(r, warnings,
           "segment " + std::to_string(number) + " duplicates segment " +
               std::to_string(it->second) + " (vertices " + std::to_string(first_vertex + s.a) +
               " and " + std::to_string(first_vertex + s.b) + "); dropped");
      continue;
    }
    out.segments.push_back(s);
  }
}

void read_holes(RecordReader& r, Numbering& numbering, Pslg& out) {
  require_record(r, r.next(), "the hole header line (number of holes)");
  expect_fields(r, 1, "number of holes");
  const std::uint64_t count = parse_count(r, 0, "number of holes");
  const std::size_t header_line = r.line();
  out.holes.reserve(check_count(r, count, 3, "holes", kMaxItems));
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.next()) fail_truncated(r, i, count, "holes", header_line);
    expect_fields(r, 3, "hole number, x, y");
    check_record_number(r, numbering, i, "hole");
    out.holes.push_back({parse_real(r, 1, "hole x coordinate"),
                         parse_real(r, 2, "hole y coordinate")});
  }
}

// The region section is optional: the file may end after the holes.
void read_regions(RecordReader& r, Numbering& numbering, Pslg& out,
                  std::vector<std::string>* warnings) {
  if (!r.next()) return;
  expect_fields(r, 1, "number of regions");
  const std::uint64_t count = parse_count(r, 0, "number of regions");
  const std::size_t header_line = r.line();
  out.regions.reserve(check_count(r, count, 4, "regions", kMaxItems));
  bool warned_short = false;
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.next()) fail_truncated(r, i, count, "regions", header_line);
    if (r.field_count() != 4) expect_fields(r, 5, "region number, x, y, attribute, maximum area");
    check_record_number(r, numbering, i, "region");
    Region region;
    region.point = {parse_real(r, 1, "region x coordinate"),
                    parse_real(r, 2, "region y coordinate")};
    region.attribute = parse_real(r, 3, "region attribute");
    if (r.field_count() == 5) {
      region.max_area = parse_real(r, 4, "region maximum area");
    } else {
      // Triangle reads a lone fourth number as both the attribute and the area bound
      // (which of the two it uses depends on its -A and -a switches); so do we.
      region.max_area = region.attribute;
      if (!warned_short) {
        warn(r, warnings,
             "region has one number after x and y; as Triangle does, it is used both as "
             "the regional attribute and as the maximum area");
        warned_short = true;
      }
    }
    out.regions.push_back(region);
  }
  warn_if_trailing(r, "regions", header_line, warnings);
}

}  // namespace

void warn(const RecordReader& r, std::vector<std::string>* warnings, const std::string& msg) {
  if (warnings) warnings->push_back(r.path() + ":" + std::to_string(r.line()) + ": " + msg);
}

void read_header(RecordReader& r, std::string_view header_names) {
  if (!r.next()) {
    r.fail("no data: the file is empty or holds only comments; expected a header line (" +
           std::string(header_names) + ")");
  }
}

void fail_truncated(const RecordReader& r, std::uint64_t found, std::uint64_t declared,
                    std::string_view plural, std::size_t header_line) {
  r.fail("unexpected end of file: found " + std::to_string(found) + " of the " +
         std::to_string(declared) + " " + std::string(plural) + " declared on line " +
         std::to_string(header_line) + " (truncated file?)");
}

void warn_if_trailing(RecordReader& r, std::string_view last_section, std::size_t header_line,
                      std::vector<std::string>* warnings) {
  if (!r.next()) return;
  warn(r, warnings,
       "ignoring data after the " + std::string(last_section) + " declared on line " +
           std::to_string(header_line) + " (is that count too small?)");
}

VertexHeader read_vertex_header(const RecordReader& r) {
  expect_fields(r, 4,
                "number of vertices, dimension, number of attributes, number of boundary "
                "markers");
  VertexHeader h;
  h.line = r.line();
  h.count = parse_count(r, 0, "number of vertices");
  const std::int64_t dimension = parse_integer(r, 1, "dimension");
  if (dimension != 2) r.fail("dimension must be 2, found " + std::to_string(dimension));
  const std::uint64_t attributes = parse_count(r, 2, "number of attributes");
  // Bounded so that 3 + attributes + 1 fields fit on one line (and no product overflows).
  if (attributes > kMaxFields - 4) {
    r.fail("declares " + std::to_string(attributes) +
           " attributes per vertex, more than a line can hold");
  }
  h.attributes = static_cast<std::size_t>(attributes);
  h.markers = parse_marker_flag(r, 3, "number of boundary markers");
  return h;
}

void read_vertex_records(RecordReader& r, const VertexHeader& h, Numbering& numbering,
                         Pslg& out) {
  const std::size_t fields = 3 + h.attributes + (h.markers ? 1 : 0);
  const std::size_t reserve = check_count(r, h.count, fields, "vertices", kMaxItems);
  out.attributes_per_vertex = h.attributes;
  out.has_vertex_markers = h.markers;
  reserve_huge(out.points, reserve);
  out.vertex_attributes.reserve(reserve * h.attributes);
  if (h.markers) out.vertex_markers.reserve(reserve);
  const std::string names = vertex_record_names(h.attributes, h.markers);
  for (std::uint64_t i = 0; i < h.count; ++i) {
    if (!r.next()) fail_truncated(r, i, h.count, "vertices", h.line);
    expect_fields(r, fields, names);
    check_record_number(r, numbering, i, "vertex");
    out.points.push_back({parse_real(r, 1, "x coordinate"), parse_real(r, 2, "y coordinate")});
    for (std::size_t k = 0; k < h.attributes; ++k) {
      out.vertex_attributes.push_back(parse_real(r, 3 + k, "vertex attribute"));
    }
    if (h.markers) out.vertex_markers.push_back(parse_marker(r, fields - 1, "boundary marker"));
  }
}

void read_poly_tail(RecordReader& r, Numbering& numbering, std::uint64_t vertex_count,
                    Pslg& out, std::vector<std::string>* warnings) {
  read_segments(r, numbering, vertex_count, out, warnings);
  read_holes(r, numbering, out);
  // Anything after the holes is the optional region section, which checks for trailing data.
  read_regions(r, numbering, out, warnings);
}

Pslg read_node_file(RecordReader& r, std::vector<std::string>* warnings) {
  read_header(r, "number of vertices, dimension, number of attributes, number of markers");
  const VertexHeader header = read_vertex_header(r);
  Numbering numbering;
  Pslg out;
  read_vertex_records(r, header, numbering, out);
  out.first_index = numbering.base < 0 ? 0 : numbering.base;
  warn_if_trailing(r, "vertices", header.line, warnings);
  return out;
}

std::string replace_extension(const std::string& path, std::string_view ext) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? path.substr(0, dot) : path) + std::string(ext);
}

Pslg read_poly_file(const std::string& path, const Pslg* known,
                    std::vector<std::string>* warnings) {
  RecordReader r(path);
  read_header(r, "number of vertices, dimension, number of attributes, number of markers");
  const VertexHeader header = read_vertex_header(r);
  Numbering numbering;
  Pslg out;
  std::uint64_t vertex_count = 0;
  if (known) {
    if (header.count != 0 && header.count != known->points.size()) {
      r.fail("lists " + std::to_string(header.count) + " vertices, but the .node file of " +
             "this mesh has " + std::to_string(known->points.size()));
    }
    // The .node decided the numbering of the whole set of files.
    if (!known->points.empty()) numbering.base = known->first_index;
    if (header.count != 0) {
      read_vertex_records(r, header, numbering, out);
      out = Pslg{};  // read only to check them; the .node's vertices are the ones used
    }
    vertex_count = known->points.size();
  } else if (header.count != 0) {
    read_vertex_records(r, header, numbering, out);
    vertex_count = out.points.size();
  } else {
    const std::string node_path = replace_extension(path, ".node");
    std::unique_ptr<RecordReader> node;
    try {
      node = std::make_unique<RecordReader>(node_path);
    } catch (const InputError& e) {
      r.fail("declares 0 vertices, so they should be in " + node_path +
             ", which cannot be read (" + e.message() + ")");
    }
    out = read_node_file(*node, warnings);
    if (!out.points.empty()) numbering.base = out.first_index;
    vertex_count = out.points.size();
  }
  read_poly_tail(r, numbering, vertex_count, out, warnings);
  out.first_index = numbering.base < 0 ? 0 : numbering.base;
  return out;
}

}  // namespace meshstep::io::detail
