// The caption: one line that says where the run is and what the step did, for people.
// "refine · step 57 of 124 · off-center of a 21.3° triangle inserted; 4 flips"
//
// Steps are numbered as every command numbers them (replay/step_numbers.hpp): "step 124 of
// 124" is the last, and the mesh after it is `meshstep log mesh --step 124`. Vertices are
// named by their number in the output's .node (LogReader::vertex_name).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <vector>

#include "meshstep/refine/quality.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "parts.hpp"

namespace meshstep::scene::detail {

namespace {

using replay::StepKind;

constexpr const char* kDot = " \u00B7 ";

std::string degrees_text(double deg) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f\u00B0", deg);
  return buf;
}

// "a 21.3° triangle", "an 11.8° triangle": the article as the number is read aloud (eight,
// eleven, eighteen, eighty begin with a vowel sound).
std::string with_article(const std::string& number) {
  const bool vowel =
      number.starts_with("8") || ((number.starts_with("11") || number.starts_with("18")) &&
                                  (number.size() == 2 || !std::isdigit(static_cast<unsigned char>(number[2]))));
  return (vowel ? "an " : "a ") + number;
}

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}


// The phase a step belongs to, from its kind: a phase's first step begins right after its
// phase_begin, so the kind tells it without searching the log backward.
const char* phase_of(StepKind kind) {
  switch (kind) {
    case StepKind::start:
    case StepKind::insert_vertex: return "insert vertices";
    case StepKind::recover_segment: return "recover segments";
    case StepKind::carve: return "carve";
    case StepKind::refine:
    case StepKind::split_segment:
    case StepKind::bisect: return "refine";
    case StepKind::remove_vertex:
    case StepKind::flip_3d: return "improve";
    default: return "run";
  }
}

class CaptionWriter {
 public:
  CaptionWriter(const StepStory& story, const replay::LogReader& log) : story_(story), log_(log) {}

  std::string write() const {
    const std::string steps = std::to_string(story_.step_count);
    if (story_.position == 0) return "before the run" + std::string(kDot) + plural(story_.step_count, "step", "steps");
    if (!story_.in_step) return "start" + std::string(kDot) + "before the first of " + steps + " steps";
    std::string out = phase_of(story_.kind);
    out += kDot;
    out += "step " + std::to_string(replay::step_at(log_, story_.position).step) + " of " + steps;
    out += kDot;
    out += story_.next_triangle ? next_triangle() : what_happened();
    return out;
  }

 private:
  // Vertices by their number in the output's .node, as every text names them (log_reader.hpp).
  std::string vertex_name(VertexId v) const { return log_.vertex_name(v); }
  std::string edge_name(VertexId a, VertexId b) const { return vertex_name(a) + "-" + vertex_name(b); }

  double smallest_angle(const Triple& t) const {
    const auto& v = log_.vertices();
    for (const VertexId id : t)
      if (id >= v.size()) return NAN;
    return quality::shape(v[t[0]].point, v[t[1]].point, v[t[2]].point).min_angle_deg();
  }

  std::string flips_text() const {
    std::size_t n = 0;
    for (const StepStory::Flip& f : story_.flips) n += f.reason != replay::FlipReason::segment_recovery;
    return n ? "; " + plural(n, "flip", "flips") : "";
  }

  std::string lepp_text() const {
    return story_.lepp ? " (Lepp of " + plural(story_.lepp->path.size(), "triangle", "triangles") + ")" : "";
  }

  // The bound the step's triangle missed: "11.8° < 30°" (and how many more it missed).
  std::string failed_text() const {
    if (story_.failed.empty()) return "";
    std::string out = criterion_text(story_.failed.front(), log_);
    if (story_.failed.size() > 1) out += " and " + std::to_string(story_.failed.size() - 1) + " more";
    return out;
  }

  std::string next_triangle() const {
    const StepStory::Lepp& l = *story_.lepp;
    return "next: Lepp path of " + plural(l.path.size(), "triangle", "triangles") + " to edge " + edge_name(l.a, l.b);
  }

  std::string what_happened() const {
    switch (story_.kind) {
      case StepKind::start:
        return story_.first_triangle ? "the first triangle, on vertices " + vertex_name(story_.init[0]) + ", " +
                                           vertex_name(story_.init[1]) + ", " + vertex_name(story_.init[2])
                                     : "starting";
      case StepKind::insert_vertex: return insert_vertex();
      case StepKind::recover_segment: return recover_segment();
      case StepKind::carve: return carve();
      case StepKind::refine: return refine();
      case StepKind::split_segment: return split_segment();
      case StepKind::bisect: return bisect();
      case StepKind::remove_vertex: return remove_vertex();
      case StepKind::flip_3d: return flip_3d();
      default: return "";
    }
  }

  std::string insert_vertex() const {
    const VertexId v = story_.subject[0];
    if (story_.duplicate != kNone)
      return "vertex " + vertex_name(story_.duplicate) + " duplicates vertex " + vertex_name(story_.duplicate_of) +
             ": left out";
    if (story_.inserted.empty())
      return story_.located ? "vertex " + vertex_name(v) + " located" : "inserting vertex " + vertex_name(v);
    const bool on_edge = !story_.splits.empty();
    return "vertex " + vertex_name(v) + " inserted " + (on_edge ? "on an edge" : "in a triangle") + insertion_text();
  }

  // How the new vertex went in: its cavity, or the flips after the split.
  std::string insertion_text() const {
    if (!story_.cavities.empty()) {
      std::size_t removed = 0;
      for (const StepStory::Cavity& c : story_.cavities) removed += c.removed.size();
      return " by a cavity of " + plural(removed, "triangle", "triangles");
    }
    return flips_text();
  }

  std::string recover_segment() const {
    std::string out = "segment " + edge_name(story_.subject[0], story_.subject[1]);
    std::size_t recovery_flips = 0;
    for (const StepStory::Flip& f : story_.flips) recovery_flips += f.reason == replay::FlipReason::segment_recovery;
    std::size_t crossings = 0;
    for (const StepStory::Split& s : story_.splits) crossings += s.reason == replay::SplitReason::crossing;
    if (crossings)
      out += " split at " + plural(crossings, "crossing", "crossings");
    else if (recovery_flips)
      out += " recovered by " + plural(recovery_flips, "flip", "flips");
    else
      out += story_.constrained ? " is an edge already" : "";
    if (story_.constrained) out += (crossings || recovery_flips) ? "; constrained" : ": constrained";
    return out + flips_text();
  }

  // "removed 18 ghost, 16 hole and 1 outside triangles", the kinds that occur only.
  std::string carve() const {
    static constexpr const char* kKinds[] = {"ghost", "hole", "outside"};
    std::vector<std::string> parts;
    std::size_t total = 0;
    for (std::size_t i = 0; i < 3; ++i)
      if (const std::size_t n = story_.faces_removed[i]) {
        parts.push_back(std::to_string(n) + " " + kKinds[i]);
        total += n;
      }
    if (parts.empty()) return "carving";
    std::string out = "removed ";
    for (std::size_t i = 0; i < parts.size(); ++i)
      out += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    return out + (total == 1 ? " triangle" : " triangles");
  }

  std::string refine() const {
    if (!story_.selected) return (story_.failed.empty() ? "refining" : "bad triangle: " + failed_text()) + lepp_text();
    const StepStory::Selected& s = *story_.selected;
    const double angle = smallest_angle(s.bad);
    const std::string name = chosen_point_name(s, story_.lepp);
    // A terrain's triangle is bad by its vertical error, not by its shape.
    const bool terrain = s.strategy >= replay::kFirstSampleChoice;
    const std::string of = terrain && !story_.failed.empty() ? ": " + failed_text()
                           : !terrain && std::isfinite(angle) ? " of " + with_article(degrees_text(angle)) + " triangle"
                                                              : "";
    const bool inserted = !story_.inserted.empty();
    if (terrain) return name + (inserted ? " inserted" : " selected") + of + lepp_text() + (inserted ? insertion_text() : "");
    return name + of + (inserted ? " inserted" : " selected") + lepp_text() + (inserted ? insertion_text() : "");
  }

  std::string flip_3d() const {
    return "edge " + edge_name(story_.subject[0], story_.subject[1]) +
           " flipped: the smallest 3D angle of its two triangles goes up";
  }

  std::string split_segment() const {
    if (!story_.encroached) return "splitting segment " + edge_name(story_.subject[0], story_.subject[1]);
    const StepStory::Encroachment& e = *story_.encroached;
    std::string out = "segment " + edge_name(e.a, e.b) + " encroached by " +
                      (e.by != kNone ? "vertex " + vertex_name(e.by) : std::string("a rejected point"));
    if (e.split == kNone) return out;
    const auto& v = log_.vertices();
    if (std::max({e.a, e.b, e.split}) >= v.size()) return out;
    const Point &a = v[e.a].point, &b = v[e.b].point, &p = v[e.split].point;
    const bool middle = p == Point{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
    return out + (middle ? ": split at its midpoint" : ": split on a concentric shell") + flips_text();
  }

  std::string bisect() const {
    std::size_t bisections = 0;
    for (const StepStory::Split& s : story_.splits) bisections += s.reason == replay::SplitReason::bisection;
    // The cause first: "area 2.13 > 0.5: edge 11-1 bisected (Lepp of 2 triangles)".
    const std::string cause = story_.failed.empty() ? "" : failed_text() + ": ";
    if (!bisections) return cause + "bisecting" + lepp_text();
    if (bisections == 1)
      for (const StepStory::Split& s : story_.splits)
        if (s.reason == replay::SplitReason::bisection)
          return cause + "edge " + edge_name(s.a, s.b) + " bisected" + lepp_text();
    return cause + plural(bisections, "edge", "edges") + " bisected" + lepp_text();
  }

  std::string remove_vertex() const {
    const VertexId v = story_.subject[0];
    std::size_t n = 0;
    for (const StepStory::Flip& f : story_.flips) n += f.reason == replay::FlipReason::vertex_removal;
    const std::string flips = n ? " after " + plural(n, "flip", "flips") : "";
    if (story_.removed) return "vertex " + vertex_name(v) + " removed" + flips;
    return "removing vertex " + vertex_name(v) + (n ? ": " + plural(n, "flip", "flips") : "");
  }

  const StepStory& story_;
  const replay::LogReader& log_;
};

}  // namespace

std::string step_caption(const StepStory& story, const replay::LogReader& log) {
  return CaptionWriter(story, log).write();
}

}  // namespace meshstep::scene::detail
