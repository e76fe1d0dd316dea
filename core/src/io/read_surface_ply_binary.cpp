// The body of a binary PLY file: each element instance's properties packed one after the
// other in the order the header declares them (a list: its length, then its items), in
// the byte order the header names.
#include <cmath>

#include "io/surface_bytes.hpp"
#include "io/surface_ply.hpp"
#include "io/surface_readers.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/shortest_text.hpp"

namespace meshstep::io::detail {
namespace {

// Reads numbers off the body, every failure naming the byte offset and the instance being
// read ("'face' element 3": instances count from 0, like PLY's vertex indices).
class BodyReader {
 public:
  BodyReader(const std::string& path, const std::uint8_t* data, std::size_t size,
             std::size_t offset, bool big_endian)
      : path_(path), data_(data), size_(size), pos_(offset), big_endian_(big_endian) {}

  std::size_t offset() const { return pos_; }
  std::size_t remaining() const { return size_ - pos_; }
  void at(const PlyElement& e, std::uint64_t index) {
    element_ = &e;
    index_ = index;
  }

  const std::uint8_t* take(std::size_t n) {
    if (n > remaining()) fail(pos_, "unexpected end of file (truncated file?)");
    const std::uint8_t* p = data_ + pos_;
    pos_ += n;
    return p;
  }
  double real(PlyType t) {
    const std::uint8_t* p = take(t.size);
    return t.size == 4 ? load_float(p, big_endian_) : load_double(p, big_endian_);
  }
  std::int64_t integer(PlyType t) {
    std::uint64_t v = load_uint(take(t.size), t.size, big_endian_);
    const unsigned bits = 8u * t.size;
    // Sign extension of the narrower signed types.
    if (t.kind == PlyType::signed_integer && bits < 64 && ((v >> (bits - 1)) & 1) != 0) {
      v |= ~std::uint64_t{0} << bits;
    }
    return static_cast<std::int64_t>(v);
  }
  // The length of a list whose items take `item_size` bytes each: they must fit in the
  // rest of the file, which also bounds any allocation made for them.
  std::size_t list_length(const PlyProperty& p) {
    const std::size_t at = pos_;
    const std::int64_t n = integer(p.count_type);
    if (n < 0) fail(at, "list '" + p.name + "' has a negative length (" + std::to_string(n) + ")");
    if (static_cast<std::uint64_t>(n) > remaining() / p.type.size) {
      fail(at, "list '" + p.name + "' of " + std::to_string(n) +
                   " items runs past the end of the file (truncated file?)");
    }
    return static_cast<std::size_t>(n);
  }

  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    const std::string where =
        element_ ? "'" + element_->name + "' element " + std::to_string(index_) + ": " : "";
    fail_at_byte(path_, offset, where + message);
  }

 private:
  const std::string& path_;
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_;
  bool big_endian_;
  const PlyElement* element_ = nullptr;
  std::uint64_t index_ = 0;
};

// Every instance takes at least its element's min_binary_size(): the counts must fit in
// the bytes after the header, checked before anything is reserved for them.
void check_counts(const std::string& path, const PlyHeader& h, std::uint64_t body,
                  std::size_t offset) {
  std::uint64_t needed = 0;
  for (const PlyElement& e : h.elements) {
    const std::uint64_t size = e.min_binary_size();  // > 0 when e.count > 0 (read_ply_header)
    if (e.count == 0) continue;
    if (e.count > (body - needed) / size) {
      throw InputError(path, e.line,
                       "declares " + std::to_string(e.count) + " '" + e.name +
                           "' elements of at least " + std::to_string(size) +
                           " bytes each, but only " + std::to_string(body) +
                           " bytes follow the header (from byte offset " +
                           std::to_string(offset) +
                           "): the count is wrong or the file is truncated");
    }
    needed += e.count * size;
  }
}

double coordinate(BodyReader& in, const PlyProperty& p) {
  const std::size_t at = in.offset();
  const double v = in.real(p.type);
  if (!std::isfinite(v)) {
    in.fail(at, p.name + " coordinate is not finite (" + shortest_text(v) + ")");
  }
  return v;
}

void read_corners(BodyReader& in, const PlyProperty& p, std::uint64_t vertex_count,
                  std::vector<std::uint32_t>& corners) {
  const std::size_t at = in.offset();
  const std::size_t n = in.list_length(p);
  if (n < 3) in.fail(at, "a face needs at least 3 vertices, found " + std::to_string(n));
  corners.clear();
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t index_at = in.offset();
    const std::int64_t v = in.integer(p.type);
    if (v < 0 || static_cast<std::uint64_t>(v) >= vertex_count) {
      const std::string range = vertex_count == 0 ? "there are no vertices"
                                                  : "vertices are numbered 0.." +
                                                        std::to_string(vertex_count - 1);
      in.fail(index_at, "vertex index " + std::to_string(v) + " is out of range (" + range + ")");
    }
    corners.push_back(static_cast<std::uint32_t>(v));
  }
}

}  // namespace

Surface read_ply_binary_body(const std::string& path, const PlyHeader& h,
                             const std::uint8_t* bytes, std::size_t size, std::size_t offset) {
  check_counts(path, h, size - offset, offset);
  BodyReader in(path, bytes, size, offset,
                h.encoding == PlyHeader::Encoding::binary_big_endian);
  Surface s;
  std::vector<std::uint32_t> corners;
  for (const PlyElement& e : h.elements) {
    const bool vertices = e.name == "vertex";
    if (vertices) s.vertices.reserve(static_cast<std::size_t>(e.count));
    if (e.name == "face") s.triangles.reserve(static_cast<std::size_t>(e.count));
    for (std::uint64_t i = 0; i < e.count; ++i) {
      in.at(e, i);
      Point3 point;
      for (const PlyProperty& p : e.properties) {
        switch (p.role) {
          case PlyRole::x: point.x = coordinate(in, p); break;
          case PlyRole::y: point.y = coordinate(in, p); break;
          case PlyRole::z: point.z = coordinate(in, p); break;
          case PlyRole::corners:
            read_corners(in, p, h.vertex_count, corners);
            add_fan(s.triangles, corners);
            break;
          case PlyRole::skip:
            in.take(p.is_list ? in.list_length(p) * p.type.size : p.type.size);
            break;
        }
      }
      if (vertices) s.vertices.push_back(point);
    }
  }
  if (in.remaining() != 0) {
    fail_at_byte(path, in.offset(),
                 std::to_string(in.remaining()) +
                     " bytes after the last element declared in the header (is a count wrong?)");
  }
  return s;
}

}  // namespace meshstep::io::detail
