// The viewer's model without GL: moving through a run, playing it, bookmarks, the scene
// rebuilt only when something changed, the timeline's phases and the explain panel's words.
#include <gtest/gtest.h>

#include <algorithm>

#include "golden_runs.hpp"
#include "meshstep/scene/explain.hpp"
#include "session.hpp"

namespace meshstep::viewer {
namespace {

using replay::StepKind;

constexpr const char* kOffcenter = "--algorithm offcenter --min-angle 30";

std::unique_ptr<Session> lesson(const char* args = kOffcenter) {
  const replay::LogReader* log = golden::lesson_run(args);
  if (!log) return nullptr;
  return Session::open_log(log->path());
}

bool contains(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

TEST(ViewerSession, OpensAtTheEndAndMovesByEventStepAndPhase) {
  auto s = lesson();
  ASSERT_TRUE(s);
  const replay::LogReader& log = *s->log();
  EXPECT_EQ(s->cursor_info().position, log.event_count());
  EXPECT_EQ(s->cursor_info().step, log.step_count());

  s->seek_step(10);
  EXPECT_EQ(s->cursor_info().step, 10u);
  EXPECT_EQ(s->cursor_info().position, log.step_start(10));
  s->move(Unit::event, +1);
  EXPECT_EQ(s->cursor_info().position, log.step_start(10) + 1);
  s->move(Unit::event, -1);
  s->move(Unit::step, +1);
  EXPECT_EQ(s->cursor_info().step, 11u);
  s->move(Unit::step, -1);
  EXPECT_EQ(s->cursor_info().step, 10u);

  // Phase moves land on phase boundaries, in order, and reach the end.
  s->to_start();
  std::vector<std::uint64_t> boundaries;
  for (const replay::PhaseSpan& p : log.phases()) boundaries.insert(boundaries.end(), {p.begin, p.end});
  std::uint64_t last = 0;
  for (int i = 0; i < 20 && s->cursor_info().position < log.event_count(); ++i) {
    s->move(Unit::phase, +1);
    const std::uint64_t at = s->cursor_info().position;
    EXPECT_GT(at, last);
    EXPECT_TRUE(at == log.event_count() || std::count(boundaries.begin(), boundaries.end(), at)) << at;
    last = at;
  }
  EXPECT_EQ(s->cursor_info().position, log.event_count());
  s->move(Unit::phase, -1);
  EXPECT_LT(s->cursor_info().position, log.event_count());
}

TEST(ViewerSession, PhasesAreTheRunsInOrder) {
  auto s = lesson();
  ASSERT_TRUE(s);
  const auto& phases = s->log()->phases();
  ASSERT_GE(phases.size(), 3u);
  EXPECT_EQ(phases.front().phase, replay::Phase::insert_vertices);
  EXPECT_TRUE(std::any_of(phases.begin(), phases.end(), [](const auto& p) { return p.phase == replay::Phase::refine; }));
  for (std::size_t i = 0; i < phases.size(); ++i) {
    EXPECT_LT(phases[i].begin, phases[i].end);
    EXPECT_LE(phases[i].end, s->log()->event_count());
    if (i) {
      EXPECT_GE(phases[i].begin, phases[i - 1].begin);
    }
    // A step's kind matches the phase that holds it.
    if (phases[i].phase != replay::Phase::recover_segments) continue;
    for (std::uint64_t k = 0; k < s->log()->step_count(); ++k) {
      if (s->log()->step_start(k) > phases[i].begin && s->log()->step_start(k) < phases[i].end) {
        EXPECT_EQ(s->log()->step_kind(k), StepKind::recover_segment) << "step " << k;
      }
    }
  }
  s->seek(phases.back().begin + 1);
  ASSERT_TRUE(s->cursor_info().phase);
  EXPECT_EQ(*s->cursor_info().phase, phases.back().phase);
}

TEST(ViewerSession, FindsTheNextAndPreviousStepOfAKind) {
  auto s = lesson();
  ASSERT_TRUE(s);
  const replay::LogReader& log = *s->log();
  s->to_start();
  ASSERT_TRUE(s->find_step(StepKind::split_segment, +1));
  const std::uint64_t first = s->cursor_info().step;
  EXPECT_EQ(log.step_kind(first - 1), StepKind::split_segment);
  for (std::uint64_t k = 0; k + 1 < first; ++k) EXPECT_NE(log.step_kind(k), StepKind::split_segment) << k;
  ASSERT_TRUE(s->find_step(StepKind::split_segment, +1));
  const std::uint64_t second = s->cursor_info().step;
  EXPECT_GT(second, first);
  ASSERT_TRUE(s->find_step(StepKind::split_segment, -1));
  EXPECT_EQ(s->cursor_info().step, first);
  EXPECT_FALSE(s->find_step(StepKind::split_segment, -1));
  EXPECT_FALSE(s->find_step(StepKind::bisect, +1)) << "an off-center run bisects nothing";
}

TEST(ViewerSession, FindsRejectedPointsAndBigCavities) {
  auto s = lesson();
  ASSERT_TRUE(s);
  const replay::LogReader& log = *s->log();
  // Every rejected point and big cavity of the run, found by a plain scan.
  std::vector<std::uint64_t> rejected, cavities;
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    if (is_rejected_point(log.event(e))) rejected.push_back(e + 1);
    if (is_big_cavity(log.event(e))) cavities.push_back(e + 1);
  }
  ASSERT_GE(rejected.size(), 2u) << "the teaching example rejects points near its segments";
  s->to_start();
  for (const std::uint64_t at : rejected) {
    ASSERT_TRUE(s->find_event(is_rejected_point, +1));
    EXPECT_EQ(s->cursor_info().position, at);
  }
  EXPECT_FALSE(s->find_event(is_rejected_point, +1));
  ASSERT_TRUE(s->find_event(is_rejected_point, -1));
  EXPECT_EQ(s->cursor_info().position, rejected[rejected.size() - 2]);
  // An off-center run by flips has no cavity at all; a cavity run's big ones are found.
  EXPECT_TRUE(cavities.empty());
  s->to_start();
  EXPECT_FALSE(s->find_event(is_big_cavity, +1));
  auto bw = lesson("--algorithm circumcenter --insertion cavity --min-angle 30");
  ASSERT_TRUE(bw);
  std::size_t big = 0, any = 0;
  for (std::uint64_t e = 0; e < bw->log()->event_count(); ++e) {
    const replay::Event ev = bw->log()->event(e);
    any += ev.type == replay::EventType::cavity;
    big += is_big_cavity(ev);
  }
  EXPECT_GT(any, 0u);
  bw->to_start();
  EXPECT_EQ(bw->find_event(is_big_cavity, +1), big > 0);
}

TEST(ViewerSession, PlaysAtItsSpeedAndStopsAtTheEnd) {
  auto s = lesson();
  ASSERT_TRUE(s);
  s->seek_step(5);
  s->playback().speed = 4.0;
  s->playback().unit = Unit::step;
  s->toggle_play();
  EXPECT_TRUE(s->playback().playing);
  s->advance(0.5);  // two steps
  EXPECT_EQ(s->cursor_info().step, 7u);
  s->advance(0.125);  // half a step: owed, not moved
  EXPECT_EQ(s->cursor_info().step, 7u);
  s->advance(0.125);
  EXPECT_EQ(s->cursor_info().step, 8u);
  s->playback().unit = Unit::event;
  const std::uint64_t at = s->cursor_info().position;
  s->advance(1.0);
  EXPECT_EQ(s->cursor_info().position, at + 4);
  s->playback().speed = 1000.0;
  for (int i = 0; i < 100 && s->playback().playing; ++i) s->advance(1.0);
  EXPECT_FALSE(s->playback().playing);
  EXPECT_EQ(s->cursor_info().position, s->log()->event_count());
  s->toggle_play();  // at the end, play starts again from the start
  EXPECT_EQ(s->cursor_info().position, 0u);
  s->scale_speed(1e9);
  EXPECT_EQ(s->playback().speed, Playback::kMaxSpeed);
  s->scale_speed(1e-9);
  EXPECT_EQ(s->playback().speed, Playback::kMinSpeed);
}

TEST(ViewerSession, BookmarksRememberPositions) {
  auto s = lesson();
  ASSERT_TRUE(s);
  s->seek(123);
  s->set_bookmark(3);
  s->seek(7);
  EXPECT_FALSE(s->go_to_bookmark(4));
  EXPECT_EQ(s->cursor_info().position, 7u);
  EXPECT_TRUE(s->go_to_bookmark(3));
  EXPECT_EQ(s->cursor_info().position, 123u);
  EXPECT_FALSE(s->bookmark(0));
  EXPECT_FALSE(s->bookmark(10));
}

TEST(ViewerSession, BuildsTheSceneOnlyWhenSomethingChanged) {
  auto s = lesson();
  ASSERT_TRUE(s);
  s->seek_step(30);
  const std::size_t before = s->scene_builds();
  s->scene();
  s->scene();
  EXPECT_EQ(s->scene_builds(), before + 1);
  s->set_layer(scene::Layer::edges, false);  // a layer needs no new scene
  EXPECT_FALSE(s->scene().visible.has(scene::Layer::edges));
  EXPECT_EQ(s->scene_builds(), before + 1);
  s->seek_step(30);  // where it is already
  s->scene();
  EXPECT_EQ(s->scene_builds(), before + 1);
  s->move(Unit::event, +1);
  s->scene();
  EXPECT_EQ(s->scene_builds(), before + 2);
  s->set_color_by(scene::ColorBy::age);
  EXPECT_TRUE(s->scene().legend.has_value());
  EXPECT_EQ(s->scene_builds(), before + 3);
  // The mesh is the cursor's, exactly.
  EXPECT_EQ(s->scene().mesh.triangles.size(), s->cursor()->mesh().triangles.size());
}

TEST(ViewerExplain, SaysWhyEachPointWentWhereItDid) {
  auto s = lesson();
  ASSERT_TRUE(s);
  // A refinement step: the bad triangle against the bound, the point chosen and the other
  // considered, how it went in, the new triangles.
  s->to_start();
  ASSERT_TRUE(s->find_step(StepKind::refine, +1));
  scene::Explanation e = s->explanation();
  EXPECT_NE(e.heading.find("refine"), std::string::npos) << e.heading;
  EXPECT_TRUE(contains(e.lines, "bad triangle")) << ::testing::PrintToString(e.lines);
  EXPECT_TRUE(contains(e.lines, "< 30\u00B0")) << ::testing::PrintToString(e.lines);
  EXPECT_TRUE(contains(e.lines, "chosen: the ")) << ::testing::PrintToString(e.lines);
  EXPECT_TRUE(contains(e.lines, "also considered")) << ::testing::PrintToString(e.lines);
  EXPECT_TRUE(contains(e.lines, "new triangles: ")) << ::testing::PrintToString(e.lines);

  // A segment split: the encroachment and where the segment was split.
  s->to_start();
  ASSERT_TRUE(s->find_step(StepKind::split_segment, +1));
  e = s->explanation();
  EXPECT_TRUE(contains(e.lines, "encroache")) << ::testing::PrintToString(e.lines);
  EXPECT_TRUE(contains(e.lines, "split by vertex")) << ::testing::PrintToString(e.lines);

  // Before the run, and a cavity run's insertion.
  s->to_start();
  EXPECT_EQ(s->explanation().heading, "before the run");
  auto bw = lesson("--algorithm circumcenter --insertion cavity --min-angle 30");
  ASSERT_TRUE(bw);
  bw->to_start();
  ASSERT_TRUE(bw->find_step(StepKind::refine, +1));
  EXPECT_TRUE(contains(bw->explanation().lines, "Bowyer-Watson cavity")) << ::testing::PrintToString(bw->explanation().lines);
}

}  // namespace
}  // namespace meshstep::viewer
