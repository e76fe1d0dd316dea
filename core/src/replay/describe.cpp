// Text and JSON renderings of events.
#include "meshstep/replay/describe.hpp"

#include <cctype>
#include <cstdio>

namespace meshstep::replay {
namespace {

std::string number(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  return buf;
}

// Vertices are named as every text names them (LogReader::vertex_name) when a log is given
// as `names`, else by the log's own ids (for a log too damaged to number).
std::string id_text(IdKind kind, std::uint32_t v, const LogReader* names) {
  if (kind == IdKind::marker) return std::to_string(static_cast<std::int32_t>(v));
  if (v == kNone) return "none";
  if (v == kInfiniteVertex && kind == IdKind::vertex) return "inf";
  if (kind == IdKind::vertex && names) return names->vertex_name(v);
  // An input index counted as the input file counts it, as the names are; a Steiner
  // vertex's (its own id in the log) is no input index.
  if (kind == IdKind::input && names)
    return v < names->run().input_vertices ? std::to_string(static_cast<std::int64_t>(v) + names->run().first_index)
                                           : std::string("steiner");
  return std::to_string(v);
}

std::string id_json(IdKind kind, std::uint32_t v, const LogReader* names) {
  if (kind == IdKind::marker) return std::to_string(static_cast<std::int32_t>(v));
  if (v == kNone) return "null";
  if (v == kInfiniteVertex && kind == IdKind::vertex) return "-1";
  if (kind == IdKind::vertex && names) {
    const std::string name = names->vertex_name(v);  // a removed vertex's "r3" is a string
    return std::isdigit(static_cast<unsigned char>(name[0])) ? name : "\"" + name + "\"";
  }
  if (kind == IdKind::input && names)
    return v < names->run().input_vertices ? std::to_string(static_cast<std::int64_t>(v) + names->run().first_index)
                                           : std::string("null");
  return std::to_string(v);
}

std::string face_text(const FaceRecord& r, const LogReader* names) {
  if (r.dead()) return "-";
  // Here and below, literals are appended piece by piece: GCC 12 at -O3 warns falsely
  // (-Wrestrict) on `"(" + std::string`.
  std::string s = "(";
  for (int i = 0; i < 3; ++i) {
    s += id_text(IdKind::vertex, r.v[i], names);
    s += i < 2 ? ' ' : ')';
  }
  if (r.constrained) s += 'c' + std::to_string(r.constrained);
  return s;
}

std::string face_json(const FaceRecord& r, const LogReader* names) {
  if (r.dead()) return "null";
  return "{\"v\":[" + id_json(IdKind::vertex, r.v[0], names) + "," + id_json(IdKind::vertex, r.v[1], names) + "," +
         id_json(IdKind::vertex, r.v[2], names) + "],\"constrained\":" + std::to_string(r.constrained) + "}";
}

bool has_code(EventType t) {
  switch (t) {
    case EventType::step_begin: case EventType::phase_begin: case EventType::phase_end:
    case EventType::locate: case EventType::split_edge: case EventType::flip:
    case EventType::constrain: case EventType::remove_face: case EventType::criterion_test:
    case EventType::point_selected:
      return true;
    default: return false;
  }
}

}  // namespace

std::string describe(const Event& e, const LogReader* names) {
  const EventSchema& s = schema(e.type);
  std::string out = s.name;
  if (has_code(e.type)) {
    out += ' ';
    out += code_name(e.type, e.code);
  }
  for (int i = 0; i < s.id_count; ++i)
    if (e.ids[i] != kNone) out += std::string(" ") + s.id_names[i] + "=" + id_text(s.id_kinds[i], e.ids[i], names);
  if (s.has_point) out += " at (" + number(e.point.x) + ", " + number(e.point.y) + ")";
  if (s.has_value) out += " value=" + number(e.value);
  if (s.has_list && !e.list.empty()) {
    out += " list=[";
    for (std::size_t i = 0; i < e.list.size(); ++i) {
      if (i) out += ' ';
      out += id_text(IdKind::vertex, e.list[i], names);
    }
    out += "]";
  }
  if (s.has_points && !e.points.empty()) {
    out += " points=[";
    for (std::size_t i = 0; i < e.points.size(); ++i)
      out += (i ? " (" : "(") + number(e.points[i].x) + ", " + number(e.points[i].y) + ")";
    out += "]";
  }
  for (std::size_t i = 0; i < e.writes.size(); ++i) {
    const SlotWrite& w = e.writes[i];
    out += (i ? "; slot " : "; slot ") + std::to_string(w.slot) + " " + face_text(w.before, names) + " -> " +
           face_text(w.after, names);
  }
  return out;
}

std::string to_json(const Event& e, std::uint64_t index, std::uint64_t step, bool in_step, const LogReader* names) {
  const EventSchema& s = schema(e.type);
  std::string out = "{\"event\":" + std::to_string(index) +
                    ",\"step\":" + (in_step ? std::to_string(step) : std::string("null")) +
                    ",\"type\":\"" + s.name + "\"";
  if (has_code(e.type)) out += ",\"code\":\"" + code_name(e.type, e.code) + "\"";
  for (int i = 0; i < s.id_count; ++i)
    out += std::string(",\"") + s.id_names[i] + "\":" + id_json(s.id_kinds[i], e.ids[i], names);
  if (s.has_point) out += ",\"point\":[" + number(e.point.x) + "," + number(e.point.y) + "]";
  if (s.has_value) out += ",\"value\":" + number(e.value);
  if (s.has_list) {
    out += ",\"list\":[";
    for (std::size_t i = 0; i < e.list.size(); ++i) {
      if (i) out += ',';
      out += id_json(IdKind::vertex, e.list[i], names);
    }
    out += "]";
  }
  if (s.has_points) {
    out += ",\"points\":[";
    for (std::size_t i = 0; i < e.points.size(); ++i)
      out += std::string(i ? "," : "") + "[" + number(e.points[i].x) + "," + number(e.points[i].y) + "]";
    out += "]";
  }
  if (s.has_writes) {
    out += ",\"writes\":[";
    for (std::size_t i = 0; i < e.writes.size(); ++i) {
      const SlotWrite& w = e.writes[i];
      out += std::string(i ? "," : "") + "{\"slot\":" + std::to_string(w.slot) +
             ",\"before\":" + face_json(w.before, names) + ",\"after\":" + face_json(w.after, names) + "}";
    }
    out += "]";
  }
  return out + "}";
}

}  // namespace meshstep::replay
