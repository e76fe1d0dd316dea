#include "step_story.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"

namespace meshstep::scene::detail {

namespace {

using replay::Event;
using replay::EventType;

// How far back the tail of the previous step is searched for the Lepp path it ended with:
// the tail holds a few decision events, never many.
constexpr std::uint64_t kTailLimit = 256;
constexpr std::uint64_t kNoEvent = UINT64_MAX;

std::string printed(const char* format, double value) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

bool changes_mesh(EventType t) { return replay::schema(t).changes_mesh(); }

bool holds(const FaceRecord& f, VertexId v) { return !f.dead() && std::find(f.v.begin(), f.v.end(), v) != f.v.end(); }

// The first event of the explanation of the step s at position p (see read_step).
std::uint64_t explanation_start(const replay::LogReader& log, std::uint64_t s, std::uint64_t p, bool& next_triangle) {
  const std::uint64_t begin = log.step_start(s);
  // A Lepp path after this step's mesh changes: the next triangle's.
  std::uint64_t last_lepp = kNoEvent, last_change = kNoEvent;
  for (std::uint64_t e = begin; e < p; ++e) {
    const EventType t = log.event(e).type;
    if (changes_mesh(t)) last_change = e;
    if (t == EventType::lepp_path && last_change != kNoEvent) last_lepp = e;
  }
  if (last_lepp != kNoEvent) {
    next_triangle = true;
    return last_lepp;
  }
  // The Lepp path in the previous step's tail, after its last mesh change.
  if (s == 0) return begin;
  const std::uint64_t previous = log.step_start(s - 1);
  for (std::uint64_t e = begin; e > previous + 1 && begin - e < kTailLimit;) {
    --e;
    const EventType t = log.event(e).type;
    if (t == EventType::lepp_path) return e;
    if (changes_mesh(t) || t == EventType::step_begin) break;
  }
  return begin;
}

std::vector<FaceRecord> live_records(std::span<const replay::SlotWrite> writes, bool after) {
  std::vector<FaceRecord> out;
  for (const replay::SlotWrite& w : writes) {
    const FaceRecord& r = after ? w.after : w.before;
    if (!r.dead()) out.push_back(r);
  }
  return out;
}

std::vector<Triple> triples(std::span<const std::uint32_t> list) {
  std::vector<Triple> out;
  for (std::size_t i = 0; i + 3 <= list.size(); i += 3) out.push_back({list[i], list[i + 1], list[i + 2]});
  return out;
}

// Every face round v at the start of [first, end): for each slot, the record its first write
// in the range replaced, when that holds v. A removal step writes a few dozen slots at most,
// so the slots seen are searched linearly.
std::vector<FaceRecord> star_at_start(const replay::LogReader& log, std::uint64_t first, std::uint64_t end,
                                      VertexId v) {
  std::vector<FaceId> seen;
  std::vector<FaceRecord> star;
  for (std::uint64_t e = first; e < end; ++e)
    for (const replay::SlotWrite& w : log.writes(e)) {
      if (std::find(seen.begin(), seen.end(), w.slot) != seen.end()) continue;
      seen.push_back(w.slot);
      if (holds(w.before, v)) star.push_back(w.before);
    }
  return star;
}

// Of the chosen point and the alternatives, is the chosen one the circumcenter of the bad
// triangle: the one most nearly equidistant from its corners? (The refiner records the
// point it did not take beside the one it took; the circumcenter may be either.)
bool is_circumcenter_of(const replay::LogReader& log, const Triple& bad, const Point& chosen,
                        std::span<const Point> alternatives) {
  if (alternatives.empty()) return true;
  const auto& vertices = log.vertices();
  for (const VertexId v : bad)
    if (v >= vertices.size()) return false;
  const Point &a = vertices[bad[0]].point, &b = vertices[bad[1]].point, &c = vertices[bad[2]].point;
  const auto unevenness = [&](const Point& p) {
    const double da = std::hypot(p.x - a.x, p.y - a.y), db = std::hypot(p.x - b.x, p.y - b.y),
                 dc = std::hypot(p.x - c.x, p.y - c.y);
    return std::max({da, db, dc}) - std::min({da, db, dc});
  };
  return unevenness(chosen) < unevenness(alternatives[0]);
}

}  // namespace

StepStory read_step(const replay::Replay& cursor) {
  const replay::LogReader& log = cursor.log();
  StepStory story;
  story.position = cursor.position();
  story.step_count = log.step_count();
  if (story.position == 0) return story;

  const std::uint64_t p = story.position;
  story.step = log.step_of_event(p - 1);
  story.in_step = story.step < log.step_count();
  if (story.in_step) {
    const Event begin = log.event(log.step_start(story.step));
    story.kind = static_cast<replay::StepKind>(begin.code);
    story.subject = {begin.ids[0], begin.ids[1]};
    story.first_event = explanation_start(log, story.step, p, story.next_triangle);
  }

  FaceId located_slot = kNone;
  bool located_captured = false;
  for (std::uint64_t e = story.first_event; e < p; ++e) {
    const Event ev = log.event(e);
    switch (ev.type) {
      case EventType::locate:
        story.located = StepStory::Located{ev.ids[0], static_cast<replay::LocateResult>(ev.code), {}, triples(ev.list)};
        located_slot = ev.ids[2];
        located_captured = false;
        break;
      case EventType::duplicate:
        story.duplicate = ev.ids[0];
        story.duplicate_of = ev.ids[1];
        break;
      case EventType::init:
        story.first_triangle = true;
        story.init = {ev.ids[0], ev.ids[1], ev.ids[2]};
        break;
      case EventType::split_face: story.inserted.push_back(ev.ids[0]); break;
      case EventType::split_edge: {
        const auto reason = static_cast<replay::SplitReason>(ev.code);
        story.splits.push_back({reason, ev.ids[0], ev.ids[1], ev.ids[2], {}});
        for (const FaceRecord& r : live_records(ev.writes, true))
          if (holds(r, ev.ids[0])) story.splits.back().made.push_back(r);
        story.inserted.push_back(ev.ids[0]);
        if (story.encroached && story.encroached->split == kNone && reason == replay::SplitReason::encroached)
          story.encroached->split = ev.ids[0];
        break;
      }
      case EventType::flip:
        story.flips.push_back({{ev.ids[0], ev.ids[1], ev.ids[2], ev.ids[3]}, static_cast<replay::FlipReason>(ev.code)});
        break;
      case EventType::cavity:
        story.cavities.push_back({ev.ids[0], live_records(ev.writes, false), live_records(ev.writes, true)});
        story.inserted.push_back(ev.ids[0]);
        break;
      case EventType::constrain: story.constrained += ev.code != 0; break;
      case EventType::remove_face:
        if (ev.code < story.faces_removed.size()) ++story.faces_removed[ev.code];
        break;
      case EventType::remove_vertex:
        story.removed = StepStory::Removal{ev.ids[0], star_at_start(log, story.first_event, e + 1, ev.ids[0])};
        break;
      case EventType::point_selected:
        story.selected = StepStory::Selected{
            ev.code, {ev.ids[0], ev.ids[1], ev.ids[2]}, ev.point, {ev.points.begin(), ev.points.end()}, false};
        story.selected->chose_circumcenter = ev.code < replay::kFirstSampleChoice &&
                                             is_circumcenter_of(log, story.selected->bad, ev.point, ev.points);
        break;
      case EventType::lepp_path: story.lepp = StepStory::Lepp{triples(ev.list), ev.ids[0], ev.ids[1], ev.ids[2]}; break;
      case EventType::encroached:
        story.encroached = StepStory::Encroachment{ev.ids[0], ev.ids[1], ev.ids[2], ev.point, kNone};
        break;
      case EventType::criterion_test:
        if (!(ev.code & replay::kCriterionPassed))
          story.failed.push_back({static_cast<std::uint8_t>(ev.code & ~replay::kCriterionPassed),
                                  {ev.ids[0], ev.ids[1], ev.ids[2]},
                                  ev.value});
        break;
      default: break;
    }
    for (const replay::SlotWrite& w : log.writes(e)) {
      story.written.push_back(w.slot);
      // The face found, as the walk found it: the first write to its slot after the locate
      // replaced it.
      if (w.slot == located_slot && !located_captured && story.located) {
        story.located->face = w.before;
        located_captured = true;
      }
    }
  }
  // Not written since: the slot still holds it.
  if (story.located && !located_captured && located_slot < cursor.slots().size())
    story.located->face = cursor.slots()[located_slot];

  std::sort(story.written.begin(), story.written.end());
  story.written.erase(std::unique(story.written.begin(), story.written.end()), story.written.end());
  return story;
}

double encroachment_angle(const replay::LogReader& log) {
  if (log.run().encroachment != Encroachment::lens) return 90.0;
  return log.run().lens_angle.value_or(120.0);
}

std::string chosen_point_name(const StepStory::Selected& selected, const std::optional<StepStory::Lepp>& lepp) {
  if (selected.strategy >= replay::kFirstSampleChoice) {
    switch (static_cast<replay::SampleChoice>(selected.strategy)) {
      case replay::SampleChoice::worst_sample: return "sample of largest error";
      case replay::SampleChoice::terminal_worst: return "terminal triangle's worst sample";
      case replay::SampleChoice::terminal_point:
        return lepp && lepp->terminal_triangles == 1 ? "sample nearest the terminal triangle's centroid"
                                                     : "sample nearest the terminal point";
      case replay::SampleChoice::own_worst: return "bad triangle's own worst sample";
      default: return "sample";
    }
  }
  // Every strategy weighs its point against the circumcenter and records the circumcenter
  // as the alternative, unless it chose the circumcenter itself; the off-center selection
  // then records the off-center it did not take.
  if (selected.chose_circumcenter) return "circumcenter";
  const SelectionInfo* info = nullptr;
  for (const SelectionInfo& s : selections())
    if (static_cast<std::uint8_t>(s.selection) == selected.strategy) info = &s;
  if (!info) return "circumcenter";  // (a strategy no selection has: a damaged log)
  // On the boundary the terminal edge has one triangle: a Lepp centroid takes its midpoint.
  if (!info->boundary_point_name.empty() && lepp && lepp->terminal_triangles == 1)
    return std::string(info->boundary_point_name);
  return std::string(info->point_name);
}

// "22.4° < 30°": the measured value against the run's bound (from the log's parameters;
// a regional or old-mesh area bound varies from place to place and is not in them).
std::string criterion_text(const StepStory::Criterion& f, const replay::LogReader& log) {
  using replay::Criterion;
  const auto criterion = static_cast<Criterion>(f.criterion);
  const replay::RunHeader& run = log.run();
  const std::optional<double> recorded = criterion == Criterion::min_angle        ? run.min_angle
                                         : criterion == Criterion::max_angle      ? run.max_angle
                                         : criterion == Criterion::max_aspect     ? run.max_aspect
                                         : criterion == Criterion::max_area       ? run.max_area
                                         : criterion == Criterion::size           ? run.size
                                         : criterion == Criterion::vertical_error ? run.max_error
                                                                                  : std::nullopt;
  const double bound = recorded.value_or(0.0);
  const bool numeric = bound > 0.0;
  const auto number = [](double v) { return printed("%.3g", v); };
  // One decimal, or as many more as it takes not to print 29.96 as "30.0° < 30°".
  const auto degrees = [&](double v) {
    std::string text = printed("%.1f", v);
    for (int decimals = 2; numeric && decimals <= 4 && std::strtod(text.c_str(), nullptr) == bound; ++decimals)
      text = printed(("%." + std::to_string(decimals) + "f").c_str(), v);
    return text + "\u00B0";
  };
  // A bound as given: "30°", "20.7°".
  const auto bound_degrees = [](double v) { return printed("%g", v) + "\u00B0"; };
  switch (criterion) {
    case Criterion::min_angle: return degrees(f.value) + (numeric ? " < " + bound_degrees(bound) : " too small");
    case Criterion::max_angle: return degrees(f.value) + (numeric ? " > " + bound_degrees(bound) : " too large");
    case Criterion::max_aspect:
      return "aspect " + number(f.value) + (numeric ? " > " + printed("%g", bound) : " too large");
    case Criterion::max_area:
      return "area " + number(f.value) + (numeric ? " > " + printed("%g", bound) : " too large");
    case Criterion::local_max_area: return "area " + number(f.value) + " > the local bound";
    case Criterion::size: return "edge " + number(f.value) + (numeric ? " > " + printed("%g", bound) : " too long");
    case Criterion::vertical_error:
      return "vertical error " + number(f.value) + (numeric ? " > " + printed("%.3g", bound) : " too large");
    default: return "criterion " + std::to_string(f.criterion) + ": " + number(f.value);
  }
}

}  // namespace meshstep::scene::detail
