// read_wkt (polygon_io.hpp): POLYGON and MULTIPOLYGON in well-known text (OGC simple
// features), as rings for pslg_from_rings. Other geometries are skipped with a warning;
// GEOMETRYCOLLECTIONs are looked into.
#include <cctype>
#include <string_view>

#include "io/text_scanner.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/mapped_file.hpp"
#include "meshstep/io/polygon_io.hpp"
#include "meshstep/pslg/polygon_rings.hpp"

namespace meshstep::io {
namespace {

constexpr std::size_t kMaxDepth = 64;  // GEOMETRYCOLLECTIONs in GEOMETRYCOLLECTIONs

class WktReader : detail::TextScanner {
 public:
  WktReader(const std::string& file, std::string_view text, std::vector<std::string>* warnings)
      : TextScanner(file, text), warnings_(warnings) {}

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
  void expect(char c, const char* what) {
    if (!take(c)) fail("unexpected " + describe_here(true) + ": expected " + what);
  }

  // A word in upper case ("" when none starts here).
  std::string word() {
    skip_space();
    std::string w;
    while (pos_ < text_.size() && (std::isalpha(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      w += static_cast<char>(std::toupper(static_cast<unsigned char>(text_[pos_++])));
    return w;
  }

  double number() { return decimal_token(); }

  void geometry(std::size_t depth) {
    if (depth > kMaxDepth) fail("GEOMETRYCOLLECTIONs nested deeper than " + std::to_string(kMaxDepth) + " levels");
    std::string type = word();
    if (type == "SRID") {  // EWKT: SRID=4326;POLYGON(...)
      expect('=', "'=' after SRID");
      number();
      expect(';', "';' after SRID=N");
      type = word();
    }
    if (type.empty()) fail("unexpected " + describe_here(true) + ": expected a geometry such as POLYGON or MULTIPOLYGON");
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

  std::vector<std::string>* warnings_;
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
