// The inspector's words for the selection: a triangle's measures and its life, a vertex's
// origin, a segment's input segment, pieces and splits (the panel shows them, scripts'
// `state` reads them).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "viewer.hpp"

namespace meshstep::viewer {

namespace {

std::string step_name(const replay::LogReader& log, std::uint64_t step) {
  std::string kind = replay::name(log.step_kind(step));
  std::replace(kind.begin(), kind.end(), '_', ' ');
  return std::string("step ").append(std::to_string(step + 1)).append(" (").append(kind).append(")");
}

// "step 45 (refine), a flip": the step of event e and what the event was.
std::string event_name(const replay::LogReader& log, std::uint64_t e) {
  const std::uint64_t step = log.step_of_event(e);
  std::string what = replay::name(log.event(e).type);
  std::replace(what.begin(), what.end(), '_', ' ');
  if (step >= log.step_count()) return "event " + std::to_string(e + 1) + " (" + what + ")";
  return step_name(log, step).append(" by ").append(what);
}

// A vertex as every text names it: its number in the run's output .node (input vertices
// keep their input file's numbers), "r3" for one the run removes (LogReader::vertex_name);
// a mesh without a log numbers its own.
std::string vertex_name(const replay::LogReader* log, VertexId v) {
  return log ? log->vertex_name(v) : std::to_string(v);
}

std::string length_text(const scene::MeshLayer& mesh, VertexId a, VertexId b) {
  if (a >= mesh.points.size() || b >= mesh.points.size()) return "?";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", std::hypot(mesh.points[a].x - mesh.points[b].x, mesh.points[a].y - mesh.points[b].y));
  return buf;
}

// Where a split put its vertex, in words.
const char* split_words(const SegmentStory::Split& split) {
  const std::string_view place = split_place(split);
  if (place == "midpoint") return "at the midpoint";
  if (place == "shell") return "on a concentric shell";
  if (place == "crossing") return "where another segment crosses";
  if (place == "insert") return "a vertex inserted on it";
  return "bisected";
}

}  // namespace

std::string Viewer::selection_text() {
  const scene::Scene& s = session_->scene();
  const replay::LogReader* log = session_->log();
  const SelectionStory& story = selection_story();
  const bool indexed = log && history_.ready();
  char buf[256];
  if (selected_.kind == Picked::Kind::triangle) {
    const TriangleFacts f = triangle_facts(s.mesh, selected_.index);
    std::snprintf(buf, sizeof buf, ": angles %.1f %.1f %.1f, area %.4g", f.angles[0], f.angles[1], f.angles[2], f.area);
    std::string out = "triangle " + vertex_name(log, f.vertices[0]) + " " + vertex_name(log, f.vertices[1]) + " " +
                      vertex_name(log, f.vertices[2]) + buf;
    if (angle_bound_ > 0) {
      std::snprintf(buf, sizeof buf, ", smallest angle %.1f %s %.4g (the bound)", f.min_angle,
                    f.min_angle < angle_bound_ ? "<" : ">=", angle_bound_);
      out += buf;
    }
    if (selected_.index < s.mesh.region.size()) {
      std::snprintf(buf, sizeof buf, ", region %g", s.mesh.region[selected_.index]);
      out += buf;
    }
    out += "; Lepp path of " + std::to_string(lepp_.triangles.size()) + " to edge " + vertex_name(log, lepp_.a) + "-" +
           vertex_name(log, lepp_.b) + (lepp_.boundary ? " (on the boundary)" : "");
    const TriangleStory& t = story.triangle;
    if (indexed && t.created != kNoEvent) {
      out.append("; made by ").append(event_name(*log, t.created));
      if (const std::size_t n = t.reflagged.size(); n > 0)
        out.append(", its edges' constraints changed ").append(n == 1 ? "once" : std::to_string(n) + " times");
      out.append(t.removed != kNoEvent ? "; replaced by " + event_name(*log, t.removed) : "; it lasts to the end of the run");
    }
    return out;
  }
  if (selected_.kind == Picked::Kind::vertex) {
    const std::uint32_t v = selected_.index;
    const Point& p = s.mesh.points[v];
    std::snprintf(buf, sizeof buf, " at (%.6g, %.6g)", p.x, p.y);
    std::string out = "vertex " + vertex_name(log, v) + buf;
    if (log && log->has_elevation() && v < log->vertices().size()) {
      std::snprintf(buf, sizeof buf, ", height %.6g", log->vertices()[v].z);
      out += buf;
    }
    if (!log || v >= log->vertices().size()) return out + (log ? "" : ", of the mesh");
    const replay::VertexInfo& info = log->vertices()[v];
    const std::uint64_t inputs = log->run().input_vertices;
    const std::uint64_t step = log->step_of_event(info.event);
    out += info.input_index < inputs ? ": from the input" : ": Steiner";
    if (info.removed != UINT64_MAX) out += ", removed again by the run (no number in the output)";
    if (step < log->step_count()) out.append(", inserted by ").append(step_name(*log, step));
    return out;
  }
  if (selected_.kind == Picked::Kind::segment) {
    const VertexId a = selected_.index, b = selected_.other;
    std::string out = "segment " + vertex_name(log, a) + "-" + vertex_name(log, b) + " (length " +
                      length_text(s.mesh, a, b) + ")";
    if (!log) return out;
    if (!indexed) return out + "; indexing the run's history...";
    const SegmentStory& g = story.segment;
    if (g.segment == kNone) return out + ": a constrained edge the log does not trace to an input segment";
    const bool now = std::any_of(g.pieces.begin(), g.pieces.end(), [&](const auto& p) {
      return (p.first == a && p.second == b) || (p.first == b && p.second == a);
    });
    out.append(now ? ": a piece of input segment " : ", not a piece at this moment, of input segment ");
    out.append(vertex_name(log, g.a)).append("-").append(vertex_name(log, g.b));
    out.append("; ").append(std::to_string(g.pieces.size())).append(g.pieces.size() == 1 ? " piece" : " pieces");
    out.append(" at this moment, lengths");
    constexpr std::size_t kLengths = 8;
    for (std::size_t i = 0; i < std::min(g.pieces.size(), kLengths); ++i)
      out.append(i ? ", " : " ").append(length_text(s.mesh, g.pieces[i].first, g.pieces[i].second));
    if (g.pieces.size() > kLengths) out.append(", ...");
    if (g.splits.empty()) return out + "; never split";
    // The splits of the whole run, and how many of them the moment shown has seen.
    const std::uint64_t position = session_->shown_position();
    const auto done = std::count_if(g.splits.begin(), g.splits.end(), [&](const auto& x) { return x.event < position; });
    out.append("; split ").append(std::to_string(g.splits.size())).append(g.splits.size() == 1 ? " time" : " times");
    out.append(" in the run (").append(std::to_string(done)).append(" by this moment)");
    constexpr std::size_t kSplits = 6;
    for (std::size_t i = 0; i < std::min(g.splits.size(), kSplits); ++i) {
      const SegmentStory::Split& x = g.splits[i];
      const std::uint64_t step = log->step_of_event(x.event);
      out.append(i ? "; " : ": ").append("step ").append(std::to_string(step + 1)).append(" at vertex ");
      out.append(vertex_name(log, x.vertex)).append(", ").append(split_words(x));
    }
    return out + (g.splits.size() > kSplits ? "; ..." : "");
  }
  return "";
}

}  // namespace meshstep::viewer
