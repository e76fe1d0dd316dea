// The sections of Triangle's .node and .poly files, shared by read_node, read_poly and
// read_mesh (which reads a .poly against the vertices of a .node it already has).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/fields.hpp"
#include "io/record_reader.hpp"
#include "meshstep/pslg/pslg.hpp"

namespace meshstep::io::detail {

// Vertex indices are 32-bit and 0xFFFFFFFF means "none".
inline constexpr std::uint64_t kMaxItems = 0xFFFFFFFEu;

// Appends "FILE:LINE: message" for the reader's current line, when warnings are wanted.
void warn(const RecordReader& r, std::vector<std::string>* warnings, const std::string& msg);

// Advances to the first record; a file with none is empty whatever its comments say.
void read_header(RecordReader& r, std::string_view header_names);

// "unexpected end of file: found 2 of the 3 vertices declared on line 1".
[[noreturn]] void fail_truncated(const RecordReader& r, std::uint64_t found,
                                 std::uint64_t declared, std::string_view plural,
                                 std::size_t header_line);

// Triangle ignores whatever follows the last section; so do we, with a warning, since it
// usually means a count is too small.
void warn_if_trailing(RecordReader& r, std::string_view last_section, std::size_t header_line,
                      std::vector<std::string>* warnings);

struct VertexHeader {
  std::uint64_t count = 0;
  std::size_t attributes = 0;
  bool markers = false;
  std::size_t line = 0;
};

// The header line of a vertex section, the reader positioned on it.
VertexHeader read_vertex_header(const RecordReader& r);

// The records announced by `header` into out.points, vertex attributes and markers.
void read_vertex_records(RecordReader& r, const VertexHeader& header, Numbering& numbering,
                         Pslg& out);

// Segments, holes and the optional regions of a .poly file, then the end of the file.
// Segment endpoints must lie in base..base+vertex_count-1.
void read_poly_tail(RecordReader& r, Numbering& numbering, std::uint64_t vertex_count,
                    Pslg& out, std::vector<std::string>* warnings);

// Everything of a .node file, from a reader opened on it.
Pslg read_node_file(RecordReader& r, std::vector<std::string>* warnings);

// PATH with its extension replaced by `ext` (".node"), or `ext` appended when it has none.
std::string replace_extension(const std::string& path, std::string_view ext);

// A .poly file. When `known` is given (read_mesh: the vertices of the .node beside it),
// segments refer to those vertices, a non-empty vertex section must agree with them in
// number, and the result holds no vertices (the caller has them). Otherwise an empty vertex
// section means reading the .node file beside the .poly.
Pslg read_poly_file(const std::string& path, const Pslg* known,
                    std::vector<std::string>* warnings);

}  // namespace meshstep::io::detail
