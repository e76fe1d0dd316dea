// Reading PLY files: the header, and read_ply, which hands the body to the ASCII or the
// binary reader as the header says (surface_ply.hpp describes the format).
#include <algorithm>

#include "io/fields.hpp"
#include "io/sections.hpp"
#include "io/surface_ply.hpp"
#include "io/surface_readers.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/mapped_file.hpp"

namespace meshstep::io::detail {
namespace {

// Header lines hold words, which expect_fields would call numbers.
void expect_words(const RecordReader& r, std::size_t n, std::string_view names) {
  if (r.field_count() == n) return;
  r.fail("expected " + std::to_string(n) + " words (" + std::string(names) + "), found " +
         std::to_string(r.field_count()));
}

std::optional<PlyType> type_named(std::string_view name) {
  using K = PlyType::Kind;
  if (name == "char" || name == "int8") return PlyType{K::signed_integer, 1};
  if (name == "uchar" || name == "uint8") return PlyType{K::unsigned_integer, 1};
  if (name == "short" || name == "int16") return PlyType{K::signed_integer, 2};
  if (name == "ushort" || name == "uint16") return PlyType{K::unsigned_integer, 2};
  if (name == "int" || name == "int32") return PlyType{K::signed_integer, 4};
  if (name == "uint" || name == "uint32") return PlyType{K::unsigned_integer, 4};
  if (name == "float" || name == "float32") return PlyType{K::real, 4};
  if (name == "double" || name == "float64") return PlyType{K::real, 8};
  return std::nullopt;
}

PlyType parse_type(const RecordReader& r, std::size_t field) {
  const std::optional<PlyType> t = type_named(r.field(field));
  if (!t) {
    r.fail("unknown property type " + quote(r.field(field)) +
           " (expected char, uchar, short, ushort, int, uint, float, double or a sized name "
           "such as uint8 or float32)");
  }
  return *t;
}

PlyHeader::Encoding parse_format(const RecordReader& r) {
  if (r.field(0) != "format") {
    r.fail("the second line should be 'format ascii 1.0' (or binary_little_endian or "
           "binary_big_endian), found " + quote(r.field(0)));
  }
  expect_words(r, 3, "format, encoding, version");
  if (r.field(2) != "1.0") {
    r.fail("unsupported PLY version " + quote(r.field(2)) + " (expected 1.0)");
  }
  const std::string_view e = r.field(1);
  if (e == "ascii") return PlyHeader::Encoding::ascii;
  if (e == "binary_little_endian") return PlyHeader::Encoding::binary_little_endian;
  if (e == "binary_big_endian") return PlyHeader::Encoding::binary_big_endian;
  r.fail("unknown PLY format " + quote(e) +
         " (expected ascii, binary_little_endian or binary_big_endian)");
}

void add_element(RecordReader& r, PlyHeader& h) {
  expect_words(r, 3, "element, name, count");
  PlyElement e;
  e.name = std::string(r.field(1));
  e.count = parse_count(r, 2, "element count");
  e.line = r.line();
  h.elements.push_back(std::move(e));
}

void add_property(RecordReader& r, PlyHeader& h) {
  if (h.elements.empty()) r.fail("a property before any element");
  PlyProperty p;
  p.line = r.line();
  if (r.field_count() >= 2 && r.field(1) == "list") {
    expect_words(r, 5, "property, list, count type, item type, name");
    p.is_list = true;
    p.count_type = parse_type(r, 2);
    p.type = parse_type(r, 3);
    p.name = std::string(r.field(4));
    if (p.count_type.kind == PlyType::real) {
      r.fail("a list's length cannot be a " + std::string(r.field(2)));
    }
  } else {
    expect_words(r, 3, "property, type, name");
    p.type = parse_type(r, 1);
    p.name = std::string(r.field(2));
  }
  h.elements.back().properties.push_back(std::move(p));
}

[[noreturn]] void fail_at_line(const RecordReader& r, std::size_t line, const std::string& m) {
  throw InputError(r.path(), line, m);
}

// Fails when two of `items` (elements, or one element's properties) have the same name.
// Sorted rather than compared pairwise, so that a hostile header of a million property
// lines takes no quadratic time.
template <class Item>
void check_unique_names(const RecordReader& r, const std::vector<Item>& items,
                        const std::string& what) {
  std::vector<std::pair<std::string_view, std::size_t>> names;  // name, line
  names.reserve(items.size());
  for (const Item& item : items) names.emplace_back(item.name, item.line);
  std::sort(names.begin(), names.end());
  for (std::size_t k = 1; k < names.size(); ++k) {
    if (names[k].first == names[k - 1].first) {
      fail_at_line(r, names[k].second,
                   what + " '" + std::string(names[k].first) +
                       "' is declared twice (first on line " +
                       std::to_string(names[k - 1].second) + ")");
    }
  }
}

// Gives the properties a surface needs their roles, and checks they are usable.
void assign_roles(const RecordReader& r, PlyHeader& h) {
  check_unique_names(r, h.elements, "element");
  bool have_vertices = false;
  for (PlyElement& e : h.elements) {
    check_unique_names(r, e.properties, "property");
    if (e.count > 0 && e.properties.empty()) {
      // Instances without properties take no room: a count of them means nothing.
      fail_at_line(r, e.line, "element '" + e.name + "' has no properties");
    }
    if (e.name == "vertex") {
      have_vertices = true;
      if (e.count > kMaxItems) {
        fail_at_line(r, e.line, "declares " + std::to_string(e.count) + " vertices; at most " +
                                    std::to_string(kMaxItems) + " are supported");
      }
      h.vertex_count = e.count;
      const char* names[] = {"x", "y", "z"};
      const PlyRole roles[] = {PlyRole::x, PlyRole::y, PlyRole::z};
      for (int k = 0; k < 3; ++k) {
        const auto p = std::find_if(e.properties.begin(), e.properties.end(),
                                    [&](const PlyProperty& q) { return q.name == names[k]; });
        if (p == e.properties.end()) {
          fail_at_line(r, e.line, std::string("the vertex element has no property '") +
                                      names[k] + "'");
        }
        if (p->is_list || p->type.kind != PlyType::real) {
          fail_at_line(r, p->line, std::string("property '") + names[k] +
                                       "' should be a float or a double");
        }
        p->role = roles[k];
      }
    } else if (e.name == "face") {
      PlyProperty* corners = nullptr;
      for (PlyProperty& p : e.properties) {
        if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
        if (corners) {
          fail_at_line(r, p.line, "the face element has both vertex_indices and vertex_index");
        }
        if (!p.is_list || p.type.kind == PlyType::real) {
          fail_at_line(r, p.line, "property '" + p.name + "' should be a list of integers");
        }
        corners = &p;
      }
      if (!corners) fail_at_line(r, e.line, "the face element has no property 'vertex_indices'");
      corners->role = PlyRole::corners;
    }
  }
  if (!have_vertices) r.fail("the header declares no vertex element");
}

}  // namespace

std::uint64_t PlyElement::min_binary_size() const {
  std::uint64_t size = 0;
  for (const PlyProperty& p : properties) size += p.is_list ? p.count_type.size : p.type.size;
  return size;
}

PlyHeader read_ply_header(RecordReader& r) {
  read_header(r, "ply");
  if (r.field_count() != 1 || r.field(0) != "ply") {
    r.fail("not a PLY file: the first line should be 'ply', found " + quote(r.field(0)));
  }
  require_record(r, r.next(), "the format line ('format ascii 1.0' or a binary one)");
  PlyHeader h;
  h.encoding = parse_format(r);
  for (;;) {
    require_record(r, r.next(), "more of the header, up to 'end_header'");
    const std::string_view keyword = r.field(0);
    if (keyword == "end_header") break;
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "element") {
      add_element(r, h);
    } else if (keyword == "property") {
      add_property(r, h);
    } else {
      r.fail("unknown header line " + quote(keyword) +
             " (expected element, property, comment or end_header)");
    }
  }
  if (r.field_count() != 1) r.fail("'end_header' should be alone on its line");
  h.end_line = r.line();
  assign_roles(r, h);
  return h;
}

Surface read_ply(const std::string& path) {
  RecordReader r(path);
  const PlyHeader h = read_ply_header(r);
  if (h.encoding == PlyHeader::Encoding::ascii) return read_ply_ascii_body(r, h);
  // The binary body starts right after the end_header line: where the text reader stopped.
  const std::optional<std::uint64_t> remaining = r.remaining_bytes();
  if (!remaining) r.fail("a binary PLY file can only be read from a regular file");
  const MappedFile file(path);
  if (file.size() < *remaining) fail_at_byte(path, 0, "the file changed while being read");
  const std::size_t offset = file.size() - static_cast<std::size_t>(*remaining);
  return read_ply_binary_body(path, h, file.data(), file.size(), offset);
}

}  // namespace meshstep::io::detail
