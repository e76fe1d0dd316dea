// read_geojson (polygon_io.hpp): the polygons of a GeoJSON file (RFC 7946), as rings for
// pslg_from_rings. Each Polygon's first ring is its shell, the others its holes.
#include <string_view>

#include "io/json_value.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/mapped_file.hpp"
#include "meshstep/io/polygon_io.hpp"
#include "meshstep/pslg/polygon_rings.hpp"

namespace meshstep::io {
namespace {

using detail::JsonValue;

class GeoJsonReader {
 public:
  GeoJsonReader(const std::string& file, std::vector<std::string>* warnings) : file_(file), warnings_(warnings) {}

  // Any GeoJSON object: a geometry, a Feature or a FeatureCollection.
  void object(const JsonValue& v, std::size_t depth) {
    if (v.kind != JsonValue::Kind::object)
      fail(v, std::string("expected a GeoJSON object, found ") + detail::json_kind_name(v.kind));
    const std::string& type = string_member(v, "type");
    if (type == "FeatureCollection") {
      for (const JsonValue& f : items_of(array_member(v, "features"), "Features")) {
        if (f.kind != JsonValue::Kind::object || string_member(f, "type") != "Feature")
          fail(f, "each of a FeatureCollection's \"features\" must be a Feature");
        object(f, depth + 1);
      }
    } else if (type == "Feature") {
      const JsonValue* g = v.member("geometry");
      if (!g) fail(v, "a Feature needs a \"geometry\" member (null when it has none)");
      if (g->kind == JsonValue::Kind::null) warn(v, "a Feature without a geometry: skipped");
      else object(*g, depth + 1);
    } else if (type == "GeometryCollection") {
      if (depth > detail::kMaxJsonDepth) fail(v, "GeometryCollections nested too deep");
      for (const JsonValue& g : items_of(array_member(v, "geometries"), "geometries")) object(g, depth + 1);
    } else if (type == "Polygon") {
      polygon(array_member(v, "coordinates"));
    } else if (type == "MultiPolygon") {
      for (const JsonValue& p : items_of(array_member(v, "coordinates"), "polygons (arrays of rings)")) {
        if (p.kind != JsonValue::Kind::array)
          fail(p, std::string("a MultiPolygon's coordinates are polygons (arrays of rings), found ") +
                      detail::json_kind_name(p.kind));
        polygon(p);
      }
    } else if (type == "Point" || type == "MultiPoint" || type == "LineString" || type == "MultiLineString") {
      warn(v, "a " + type + " is not a polygon: skipped");
    } else {
      fail(v, "unknown GeoJSON type \"" + type + "\"");
    }
  }

  std::vector<PolygonRing> rings;

 private:
  [[noreturn]] void fail(const JsonValue& at, const std::string& message) const {
    throw InputError(file_, at.line, message);
  }
  void warn(const JsonValue& at, const std::string& message) {
    if (warnings_) warnings_->push_back(file_ + ":" + std::to_string(at.line) + ": " + message);
  }

  const std::string& string_member(const JsonValue& v, std::string_view key) const {
    const JsonValue* m = v.member(key);
    if (!m) fail(v, "this object has no \"" + std::string(key) + "\" member");
    if (m->kind != JsonValue::Kind::string)
      fail(*m, "\"" + std::string(key) + "\" must be a string, not " + detail::json_kind_name(m->kind));
    return m->text;
  }

  // An array's values, which must not be numbers (the parser keeps an array of numbers
  // apart, in JsonValue::numbers).
  const std::vector<JsonValue>& items_of(const JsonValue& array, const std::string& what) const {
    if (!array.numbers.empty()) fail(array, "expected an array of " + what + ", found an array of numbers");
    return array.items;
  }

  const JsonValue& array_member(const JsonValue& v, std::string_view key) const {
    const JsonValue* m = v.member(key);
    if (!m) fail(v, "this " + v.member("type")->text + " has no \"" + std::string(key) + "\" member");
    if (m->kind != JsonValue::Kind::array)
      fail(*m, "\"" + std::string(key) + "\" must be an array, not " + detail::json_kind_name(m->kind));
    return *m;
  }

  // [[x, y], ...] rings: the first the shell, the others holes. An empty polygon is allowed
  // (RFC 7946 allows empty coordinates) and skipped.
  void polygon(const JsonValue& coordinates) {
    bool first = true;
    for (const JsonValue& r : items_of(coordinates, "rings (arrays of positions)")) {
      if (r.kind != JsonValue::Kind::array)
        fail(r, std::string("a polygon's coordinates are rings (arrays of positions), found ") +
                    detail::json_kind_name(r.kind));
      PolygonRing ring;
      ring.hole = !first;
      ring.line = r.line;
      first = false;
      for (const JsonValue& p : items_of(r, "positions [x, y]")) {
        // The parser keeps an array of numbers only in p.numbers: any item left is not one.
        for (const JsonValue& c : p.items)
          if (c.kind != JsonValue::Kind::number)
            fail(c, std::string("a position's coordinates are numbers, found ") + detail::json_kind_name(c.kind));
        if (p.kind != JsonValue::Kind::array || p.numbers.size() < 2)
          fail(p, "a position is an array of two or more numbers [x, y]");
        ring.points.push_back({p.numbers[0], p.numbers[1]});
      }
      if (ring.points.size() >= 2 &&
          (ring.points.front().x != ring.points.back().x || ring.points.front().y != ring.points.back().y))
        warn(r, "this ring is not closed (its last position is not its first): closed with a segment");
      rings.push_back(std::move(ring));
    }
  }

  const std::string& file_;
  std::vector<std::string>* warnings_;
};

}  // namespace

Pslg read_geojson(const std::string& path, std::vector<std::string>* warnings) {
  GeoJsonReader reader(path, warnings);
  {  // The file and its tree go before the rings are meshed for their holes.
    const MappedFile bytes(path);
    const detail::JsonValue root =
        detail::parse_json(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    reader.object(root, 0);
  }
  if (reader.rings.empty()) throw InputError(path, 0, "no polygon in the file (meshstep reads Polygon and MultiPolygon)");
  return pslg_from_rings(path, reader.rings, warnings);
}

}  // namespace meshstep::io
