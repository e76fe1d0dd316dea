// Text and JSON renderings of events.
#include "meshstep/replay/describe.hpp"

#include <cstdio>

namespace meshstep::replay {
namespace {

std::string number(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  return buf;
}

std::string id_text(IdKind kind, std::uint32_t v) {
  if (kind == IdKind::marker) return std::to_string(static_cast<std::int32_t>(v));
  if (v == kNone) return "none";
  if (v == kInfiniteVertex && kind == IdKind::vertex) return "inf";
  return std::to_string(v);
}

std::string id_json(IdKind kind, std::uint32_t v) {
  if (kind == IdKind::marker) return std::to_string(static_cast<std::int32_t>(v));
  if (v == kNone) return "null";
  if (v == kInfiniteVertex && kind == IdKind::vertex) return "-1";
  return std::to_string(v);
}

std::string face_text(const FaceRecord& r) {
  if (r.dead()) return "-";
  // Here and below, literals are appended piece by piece: GCC 12 at -O3 warns falsely
  // (-Wrestrict) on `"(" + std::string`.
  std::string s = "(";
  for (int i = 0; i < 3; ++i) {
    s += id_text(IdKind::vertex, r.v[i]);
    s += i < 2 ? ' ' : ')';
  }
  if (r.constrained) s += 'c' + std::to_string(r.constrained);
  return s;
}

std::string face_json(const FaceRecord& r) {
  if (r.dead()) return "null";
  return "{\"v\":[" + id_json(IdKind::vertex, r.v[0]) + "," + id_json(IdKind::vertex, r.v[1]) + "," +
         id_json(IdKind::vertex, r.v[2]) + "],\"constrained\":" + std::to_string(r.constrained) + "}";
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

std::string describe(const Event& e) {
  const EventSchema& s = schema(e.type);
  std::string out = s.name;
  if (has_code(e.type)) {
    out += ' ';
    out += code_name(e.type, e.code);
  }
  for (int i = 0; i < s.id_count; ++i)
    if (e.ids[i] != kNone) out += std::string(" ") + s.id_names[i] + "=" + id_text(s.id_kinds[i], e.ids[i]);
  if (s.has_point) out += " at (" + number(e.point.x) + ", " + number(e.point.y) + ")";
  if (s.has_value) out += " value=" + number(e.value);
  if (s.has_list && !e.list.empty()) {
    out += " list=[";
    for (std::size_t i = 0; i < e.list.size(); ++i) {
      if (i) out += ' ';
      out += id_text(IdKind::vertex, e.list[i]);
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
    out += (i ? "; slot " : "; slot ") + std::to_string(w.slot) + " " + face_text(w.before) + " -> " +
           face_text(w.after);
  }
  return out;
}

std::string to_json(const Event& e, std::uint64_t index, std::uint64_t step, bool in_step) {
  const EventSchema& s = schema(e.type);
  std::string out = "{\"event\":" + std::to_string(index) +
                    ",\"step\":" + (in_step ? std::to_string(step) : std::string("null")) +
                    ",\"type\":\"" + s.name + "\"";
  if (has_code(e.type)) out += ",\"code\":\"" + code_name(e.type, e.code) + "\"";
  for (int i = 0; i < s.id_count; ++i)
    out += std::string(",\"") + s.id_names[i] + "\":" + id_json(s.id_kinds[i], e.ids[i]);
  if (s.has_point) out += ",\"point\":[" + number(e.point.x) + "," + number(e.point.y) + "]";
  if (s.has_value) out += ",\"value\":" + number(e.value);
  if (s.has_list) {
    out += ",\"list\":[";
    for (std::size_t i = 0; i < e.list.size(); ++i) {
      if (i) out += ',';
      out += id_json(IdKind::vertex, e.list[i]);
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
             ",\"before\":" + face_json(w.before) + ",\"after\":" + face_json(w.after) + "}";
    }
    out += "]";
  }
  return out + "}";
}

}  // namespace meshstep::replay
