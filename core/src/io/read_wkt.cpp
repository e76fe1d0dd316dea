// read_wkt (polygon_io.hpp): POLYGON and MULTIPOLYGON in well-known text (OGC simple
// features), as rings for pslg_from_rings. Other geometries are skipped with a warning;
// GEOMETRYCOLLECTIONs are looked into.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "meshstep/error.hpp"
#include "meshstep/io/mapped_file.hpp"
#include "meshstep/io/polygon_io.hpp"
#include "meshstep/pslg/polygon_rings.hpp"

namespace meshstep::io {
namespace {

constexpr std::size_t kMaxDepth = 64;  // GEOMETRYCOLLECTIONs in GEOMETRYCOLLECTIONs

class WktReader {
 public:
  WktReader(const std::string& file, std::string_view text, std::vector<std::string>* warnings)
      : file_(file), text_(text), warnings_(warnings) {}

  // Geometries one after another, separated by white space (or ';').
  std::vector<PolygonRing> read() {
    while (true) {
      skip_space();
      while (pos_ < text_.size() && text_[pos_] == ';') {
        ++pos_;
        skip_space();
      }
      if (pos_ >= text_.size()) break;
      geometry(0);
    }
    return std::move(rings_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw InputError(file_, line_, message); }

  std::string here() const {
    if (pos_ >= text_.size()) return "end of file";
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    if (c >= 0x21 && c < 0x7F) {
      std::size_t end = pos_ + 1;
      if (std::isalnum(c) || c == '-' || c == '+' || c == '.')
        while (end < text_.size() && end - pos_ < 24 &&
               (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '.' || text_[end] == '-' ||
                text_[end] == '+'))
          ++end;
      return "'" + std::string(text_.substr(pos_, end - pos_)) + "'";
    }
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "byte 0x%02X", c);
    return buffer;
  }

  void skip_space() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') ++line_;
      else if (c != ' ' && c != '\t' && c != '\r') return;
      ++pos_;
    }
  }

  bool take(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c, const char* what) {
    if (!take(c)) fail("unexpected " + here() + ": expected " + what);
  }

  // A word in upper case ("" when none starts here).
  std::string word() {
    skip_space();
    std::string w;
    while (pos_ < text_.size() && (std::isalpha(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      w += static_cast<char>(std::toupper(static_cast<unsigned char>(text_[pos_++])));
    return w;
  }

  double number() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.' ||
                                   text_[pos_] == '-' || text_[pos_] == '+'))
      ++pos_;
    const std::string_view token = text_.substr(start, pos_ - start);
    double v = 0.0;
    const char* first = token.data();
    if (!token.empty() && token[0] == '+') ++first;  // from_chars takes no '+'
    const auto [end, ec] = std::from_chars(first, token.data() + token.size(), v);
    if (token.empty() || ec != std::errc() || end != token.data() + token.size() || !std::isfinite(v)) {
      pos_ = start;
      fail("unexpected " + here() + ": expected a finite number");
    }
    return v;
  }

  void geometry(std::size_t depth) {
    if (depth > kMaxDepth) fail("GEOMETRYCOLLECTIONs nested deeper than " + std::to_string(kMaxDepth) + " levels");
    std::string type = word();
    if (type == "SRID") {  // EWKT: SRID=4326;POLYGON(...)
      expect('=', "'=' after SRID");
      number();
      expect(';', "';' after SRID=N");
      type = word();
    }
    if (type.empty()) fail("unexpected " + here() + ": expected a geometry such as POLYGON or MULTIPOLYGON");
    const std::size_t line = line_;
    std::string modifier = word();  // Z, M, ZM, or the EMPTY after them
    if (modifier == "Z" || modifier == "M" || modifier == "ZM") modifier = word();
    if (modifier == "EMPTY") return;
    if (!modifier.empty()) fail("unexpected '" + modifier + "' after " + type + ": expected '(' or EMPTY");
    if (type == "POLYGON") {
      polygon();
    } else if (type == "MULTIPOLYGON") {
      expect('(', "'(' to open the MULTIPOLYGON");
      do {
        skip_space();
        if (word() == "EMPTY") continue;
        polygon();
      } while (take(','));
      expect(')', "',' or ')' in the MULTIPOLYGON");
    } else if (type == "GEOMETRYCOLLECTION") {
      expect('(', "'(' to open the GEOMETRYCOLLECTION");
      do geometry(depth + 1);
      while (take(','));
      expect(')', "',' or ')' in the GEOMETRYCOLLECTION");
    } else if (type == "POINT" || type == "MULTIPOINT" || type == "LINESTRING" || type == "MULTILINESTRING" ||
               type == "TRIANGLE" || type == "TIN" || type == "POLYHEDRALSURFACE") {
      if (warnings_)
        warnings_->push_back(file_ + ":" + std::to_string(line) + ": a " + type + " is not a polygon: skipped");
      skip_parentheses();
    } else {
      fail("unknown geometry " + type + ": meshstep reads POLYGON and MULTIPOLYGON");
    }
  }

  // The balanced parentheses of a geometry skipped (checked only for balance).
  void skip_parentheses() {
    expect('(', "'('");
    std::size_t open = 1;
    while (open) {
      if (pos_ >= text_.size()) fail("unexpected end of file: a '(' is never closed");
      const char c = text_[pos_++];
      if (c == '\n') ++line_;
      else if (c == '(') ++open;
      else if (c == ')') --open;
    }
  }

  // "((x y, ...), (x y, ...))": the shell, then holes.
  void polygon() {
    expect('(', "'(' to open a polygon");
    bool first = true;
    do {
      PolygonRing ring;
      ring.hole = !first;
      first = false;
      skip_space();
      ring.line = line_;
      expect('(', "'(' to open a ring");
      do {
        const double x = number(), y = number();
        // A third and fourth coordinate (Z, M) are read and dropped.
        for (int extra = 0; extra < 2; ++extra) {
          skip_space();
          if (pos_ >= text_.size() || text_[pos_] == ',' || text_[pos_] == ')') break;
          number();
        }
        ring.points.push_back({x, y});
      } while (take(','));
      expect(')', "',' or ')' in a ring (a point is 'x y')");
      if (ring.points.front().x != ring.points.back().x || ring.points.front().y != ring.points.back().y) {
        if (warnings_)
          warnings_->push_back(file_ + ":" + std::to_string(ring.line) +
                               ": this ring is not closed (its last point is not its first): closed with a segment");
      }
      rings_.push_back(std::move(ring));
    } while (take(','));
    expect(')', "',' or ')' in a polygon");
  }

  const std::string& file_;
  std::string_view text_;
  std::vector<std::string>* warnings_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::vector<PolygonRing> rings_;
};

}  // namespace

Pslg read_wkt(const std::string& path, std::vector<std::string>* warnings) {
  std::vector<PolygonRing> rings;
  {  // The file goes before the rings are meshed for their holes.
    const MappedFile bytes(path);
    rings = WktReader(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), warnings).read();
  }
  if (rings.empty()) throw InputError(path, 0, "no polygon in the file (meshstep reads POLYGON and MULTIPOLYGON)");
  return pslg_from_rings(path, rings, warnings);
}

}  // namespace meshstep::io
