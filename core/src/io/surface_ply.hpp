// The header of a PLY file, as the ASCII and binary body readers need it
// (read_surface_ply*.cpp).
//
// A PLY file is a header of text lines ("ply", "format ascii|binary_little_endian|
// binary_big_endian 1.0", then "element NAME COUNT" lines each followed by its
// "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME" lines, "end_header"),
// then the elements' instances in the order declared: one line each in ASCII, packed
// numbers in binary. A surface needs the vertex element's x, y, z and the face element's
// vertex_indices (or vertex_index) list; every other element and property is skipped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/record_reader.hpp"
#include "meshstep/io/surface_io.hpp"

namespace meshstep::io::detail {

struct PlyType {
  enum Kind : std::uint8_t { signed_integer, unsigned_integer, real };
  Kind kind = signed_integer;
  std::uint8_t size = 0;  // bytes in a binary file: 1, 2, 4 or 8
};

// What the reader does with a property.
enum class PlyRole : std::uint8_t { skip, x, y, z, corners };

struct PlyProperty {
  std::string name;
  PlyType type;  // of the value, or of a list's items
  bool is_list = false;
  PlyType count_type;  // of a list's length
  PlyRole role = PlyRole::skip;
  std::size_t line = 0;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::size_t line = 0;
  // Bytes an instance takes at least in a binary file (every list empty).
  std::uint64_t min_binary_size() const;
};

struct PlyHeader {
  enum class Encoding { ascii, binary_little_endian, binary_big_endian };
  Encoding encoding = Encoding::ascii;
  std::vector<PlyElement> elements;
  std::uint64_t vertex_count = 0;  // of the "vertex" element, which every surface has
  std::size_t end_line = 0;        // line of end_header
};

// Reads the header, the reader on its first line; on return the reader is on end_header.
// Fails unless the vertex element has x, y, z and any face element has its vertex list.
PlyHeader read_ply_header(RecordReader& r);

// The elements, the reader on end_header.
Surface read_ply_ascii_body(RecordReader& r, const PlyHeader& h);
// The elements, from `bytes` (the whole file) starting at `offset`, just after end_header.
Surface read_ply_binary_body(const std::string& path, const PlyHeader& h,
                             const std::uint8_t* bytes, std::size_t size, std::size_t offset);

}  // namespace meshstep::io::detail
