// Tours (teach/tour.hpp): a good file is read as written, every bad line is refused as
// TOUR:LINE with what is wrong, and "next KIND" stops land on the first step after the
// previous stop that does KIND, checked against the log's events read here one by one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "meshstep/error.hpp"
#include "meshstep/replay/event.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/scene/layout.hpp"
#include "meshstep/teach/tour.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using teach::Happening;
using teach::Tour;
using teach::TourStop;

constexpr const char* kSquare =
    "4 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n"
    "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "0\n";

class TourFile : public ::testing::Test {
 protected:
  void SetUp() override { dir_.write("square.poly", kSquare); }
  std::string path() const { return dir_.file("t.tour"); }
  Tour parse(const std::string& text) const { return teach::parse_tour(text, path()); }
  // The message parse_tour throws for `text`, or "" when it reads it.
  std::string refusal(const std::string& text) const {
    try {
      parse(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  testing::TempDir dir_{"meshstep_tour_"};
};

const std::string kHead = "input square.poly\nrun refine --algorithm circumcenter --min-angle 25\n";

TEST_F(TourFile, AGoodTourIsReadAsWritten) {
  const Tour t = parse(
      "# a comment\n"
      "title Ruppert on a square\n" + kHead +
      "color-by angle\n"
      "layers -labels\n"
      "hold 3\n"
      "stop step 0\n"
      "caption The input. Four corners and four segments.\n"
      "\n"
      "stop next segment split\n"
      "caption A segment is encroached,\n"
      "caption so it is split at its midpoint.\n"
      "layers fill edges segments\n"
      "camera 0 0 5 5\n"
      "hold 6.5\n"
      "stop end   # the last step\n"
      "caption Every angle is now at least 25 degrees!\n");
  EXPECT_EQ(t.title, "Ruppert on a square");
  EXPECT_EQ(t.input, dir_.file("square.poly"));
  ASSERT_EQ(t.operations.size(), 1u);
  EXPECT_EQ(t.operations[0].algorithm, "circumcenter");
  EXPECT_EQ(t.operations[0].min_angle, 25.0);
  EXPECT_EQ(t.run_line, 4);
  EXPECT_EQ(t.color_by, scene::ColorBy::angle);
  ASSERT_TRUE(t.layers);
  EXPECT_FALSE(t.layers->apply(scene::LayerSet::all()).has(scene::Layer::labels));
  EXPECT_TRUE(t.layers->apply(scene::LayerSet::all()).has(scene::Layer::fill));
  EXPECT_EQ(t.hold_seconds, 3.0);
  ASSERT_EQ(t.stops.size(), 3u);
  EXPECT_EQ(t.stops[0].where, TourStop::Where::step);
  EXPECT_EQ(t.stops[0].step, 0u);
  EXPECT_EQ(t.stops[0].line, 8);
  EXPECT_EQ(t.stops[1].where, TourStop::Where::next);
  EXPECT_EQ(t.stops[1].next, Happening::segment_split);
  EXPECT_EQ(t.stops[1].caption, "A segment is encroached, so it is split at its midpoint.");
  ASSERT_TRUE(t.stops[1].layers);
  const scene::LayerSet exact = t.stops[1].layers->apply(scene::LayerSet::all());
  EXPECT_TRUE(exact.has(scene::Layer::segments));
  EXPECT_FALSE(exact.has(scene::Layer::caption));
  ASSERT_TRUE(t.stops[1].camera);
  EXPECT_EQ(t.stops[1].camera->x1, 5.0);
  EXPECT_EQ(t.stops[1].hold_seconds, 6.5);
  EXPECT_FALSE(t.stops[0].hold_seconds);
  EXPECT_EQ(t.stops[2].where, TourStop::Where::end);
  EXPECT_EQ(t.stops[2].caption, "Every angle is now at least 25 degrees!");
}

TEST_F(TourFile, ARunOfATriangulationAloneHasNoOperation) {
  const Tour t = parse("input square.poly\nrun triangulate\nstop start\ncaption The input.\n");
  EXPECT_TRUE(t.operations.empty());
}

TEST_F(TourFile, ARecipeIsReadRelativeToTheTour) {
  dir_.write("two.recipe", "# two passes\nrefine --min-angle 20\nrefine --max-area 2\n");
  const Tour t = parse("input square.poly\nrecipe two.recipe\nstop end\ncaption Done.\n");
  ASSERT_EQ(t.operations.size(), 2u);
  EXPECT_EQ(t.operations[1].max_area, 2.0);
  EXPECT_EQ(t.recipe, dir_.file("two.recipe"));
  dir_.write("bad.recipe", "refine --min-angle 20\nrefine --min-angle -3\n");
  EXPECT_NE(refusal("input square.poly\nrecipe bad.recipe\nstop end\ncaption Done.\n").find(dir_.file("bad.recipe") + ":2: "),
            std::string::npos);
}

TEST_F(TourFile, EveryBadLineIsRefusedWithItsLineAndWhatIsWrong) {
  const std::string p = path();
  const struct {
    std::string text, starts;  // the message starts with TOUR:LINE:, then says this
  } cases[] = {
      {"input missing.poly\n", ":1: input: "},
      {"input square.poly\nrun refine --min-angle -3\n", ":2: run: --min-angle"},
      {"input square.poly\nrun paint\n", ":2: run: unknown operation"},
      {kHead + "stop step 0\n", ":3: stop: no caption"},
      {kHead + "stop step 0\nstop end\ncaption Done.\n", ":3: stop: no caption"},
      {kHead + "stop step x\ncaption A.\n", ":3: stop step: 'x' is not a step number"},
      {kHead + "stop next wobble\ncaption A.\n", ":3: stop next: unknown kind 'wobble'"},
      {kHead + "stop somewhere\ncaption A.\n", ":3: stop: expected"},
      {kHead + "stop end\ncaption No full stop\n", ":4: caption: end it with"},
      {kHead + "stop end\ncaption One. Two. Three. Four.\n", ":4: caption: 4 sentences"},
      {kHead + "stop end\ncaption " + std::string(401, 'a') + ".\n", ":4: caption: 402 characters"},
      {kHead + "caption Early.\n", ":3: caption: belongs to a stop"},
      {kHead + "stop end\ncaption A.\nlayers +wings\n", ":5: layers: unknown layer '+wings'"},
      {kHead + "stop end\ncaption A.\nlayers +fill edges\n", ":5: layers: either changes"},
      {kHead + "stop end\ncaption A.\ncolor-by taste\n", ":5: color-by: expected"},
      {kHead + "stop end\ncaption A.\ncamera 0 0 1\n", ":5: camera: expected X0 Y0 X1 Y1"},
      {kHead + "stop end\ncaption A.\ncamera 2 0 1 1\n", ":5: camera: the box's second corner"},
      {kHead + "stop end\ncaption A.\nhold 0\n", ":5: hold: expected seconds"},
      {kHead + "stop end\ncaption A.\ninput square.poly\n", ":5: input: given twice"},
      {kHead + "stop end\ncaption A.\ntitle Late\n", ":5: title: belongs before the first stop"},
      {kHead + "wobble 3\n", ":3: unknown line 'wobble'"},
      {"run triangulate\nstop end\ncaption A.\n", ":2: stop: name the input first"},
      {"input square.poly\nstop end\ncaption A.\n", ":2: stop: name the run first"},
      {kHead, ": no stop"},
      {"input square.poly\n", ": no 'run ...'"},
  };
  for (const auto& c : cases) {
    const std::string why = refusal(c.text);
    EXPECT_EQ(why.rfind(p + c.starts, 0), 0u) << "for:\n" << c.text << "said: " << why;
  }
  try {
    teach::read_tour(dir_.file("none.tour"));
    ADD_FAILURE() << "a missing tour was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir_.file("none.tour") + ": cannot be read");
  }
}

TEST(TourCaption, SentencesAreCountedAtTheirLastMark) {
  EXPECT_EQ(teach::count_sentences("One."), 1u);
  EXPECT_EQ(teach::count_sentences("Angle 20.7 degrees. Why?! Look..."), 3u);
  EXPECT_EQ(teach::count_sentences("no mark"), 0u);
}

// The happenings of step K (numbered from 1), read from its events here.
bool step_does(const replay::LogReader& log, std::uint64_t k, Happening h) {
  const std::uint64_t begin = log.step_start(k - 1), end = log.step_start(k);
  if (h == Happening::refine) return log.step_kind(k - 1) == replay::StepKind::refine;
  for (std::uint64_t e = begin; e < end; ++e) {
    const replay::Event ev = log.event(e);
    if (h == Happening::flip && ev.type == replay::EventType::flip && ev.code == 0) return true;
    if (h == Happening::lepp && ev.type == replay::EventType::lepp_path) return true;
    if (h == Happening::segment_split && ev.type == replay::EventType::split_edge &&
        ev.code == static_cast<std::uint8_t>(replay::SplitReason::encroached))
      return true;
  }
  return false;
}

TEST(TourStops, RulesLandOnTheFirstStepAfterThePreviousStopThatDoesTheirKind) {
  testing::TempDir dir("meshstep_tour_stops_");
  const std::string poly = std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly", log_path = dir.file("r.mslog");
  const auto r = testing::run_meshstep("refine " + poly + " --algorithm lepp-centroid --min-angle 28 --record " +
                                           log_path + " --no-output -q",
                                       dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const replay::LogReader log(log_path);
  const std::string tour_path = dir.file("t.tour");
  const Tour t = teach::parse_tour("input " + poly +
                                       "\nrun triangulate\n"
                                       "stop step 3\ncaption A.\n"
                                       "stop next flip\ncaption B.\n"
                                       "stop next lepp\ncaption C.\n"
                                       "stop next lepp\ncaption D.\n"
                                       "stop next segment-split\ncaption E.\n"
                                       "stop end\ncaption F.\n",
                                   tour_path);
  const std::vector<std::uint64_t> steps = teach::resolve_stops(t, log);
  ASSERT_EQ(steps.size(), 6u);
  EXPECT_EQ(steps[0], 3u);
  EXPECT_EQ(steps[5], log.step_count());
  const Happening kinds[] = {Happening::flip, Happening::lepp, Happening::lepp, Happening::segment_split};
  for (std::size_t i = 0; i < 4; ++i) {
    const std::uint64_t from = steps[i], at = steps[i + 1];
    ASSERT_GT(at, from) << "stop " << i + 1;
    EXPECT_TRUE(step_does(log, at, kinds[i])) << "stop " << i + 1 << " at step " << at;
    for (std::uint64_t k = from + 1; k < at; ++k) EXPECT_FALSE(step_does(log, k, kinds[i])) << "skipped step " << k;
  }

  // A step past the end, and a rule that finds nothing, name the stop's line.
  const auto refused = [&](const std::string& stops) -> std::string {
    try {
      teach::resolve_stops(teach::parse_tour("input " + poly + "\nrun triangulate\n" + stops, tour_path), log);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string n = std::to_string(log.step_count());
  EXPECT_EQ(refused("stop step " + std::to_string(log.step_count() + 1) + "\ncaption A.\n"),
            tour_path + ":3: stop step " + std::to_string(log.step_count() + 1) +
                " is outside the run: its steps are numbered 0.." + n + " (0: before the first step, " + n +
                ": after the last)");
  EXPECT_EQ(refused("stop end\ncaption A.\nstop next flip\ncaption B.\n"),
            tour_path + ":5: stop next flip: no Delaunay flip after step " + n + " (the run has " + n + " steps)");
}

}  // namespace
}  // namespace meshstep

namespace meshstep {
namespace {

// `meshstep export --tour`: each shipped tour, as frames (and as a video where ffmpeg is): a
// frame per second of each stop's hold, the same picture through a hold, another at each
// stop.
class TourExport : public ::testing::TestWithParam<std::string> {
 protected:
  testing::TempDir dir_{"meshstep_tour_export_"};
};

TEST_P(TourExport, EveryStopIsHeldForItsSecondsWithItsOwnPicture) {
  const std::string tour_path = std::string(MESHSTEP_ASSETS) + "/tours/" + GetParam() + ".tour";
  const teach::Tour tour = teach::read_tour(tour_path);
  const auto r = testing::run_meshstep("export --tour " + tour_path + " --frames " + dir_.file("frames") +
                                           " --fps 1 --size 640x360 -q",
                                       dir_.path());
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> pictures;  // each frame's bytes, in order
  for (std::size_t i = 0;; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu.png", i);
    const std::filesystem::path p = dir_.path() / "frames" / name;
    if (!std::filesystem::exists(p)) break;
    pictures.push_back(testing::slurp(p));
  }
  std::size_t expected = 0;
  for (const teach::TourStop& s : tour.stops) expected += static_cast<std::size_t>(std::llround(s.hold_seconds.value_or(tour.hold_seconds)));
  ASSERT_EQ(pictures.size(), expected);
  std::size_t at = 0;
  for (std::size_t s = 0; s < tour.stops.size(); ++s) {
    const auto hold = static_cast<std::size_t>(std::llround(tour.stops[s].hold_seconds.value_or(tour.hold_seconds)));
    for (std::size_t h = 1; h < hold; ++h) EXPECT_EQ(pictures[at + h], pictures[at]) << "stop " << s + 1 << " frame " << h;
    if (s > 0) EXPECT_NE(pictures[at], pictures[at - 1]) << "stop " << s + 1 << " looks like the stop before";
    at += hold;
  }
  if (!testing::ffmpeg_works()) GTEST_SKIP() << "ffmpeg or ffprobe missing: the video half is not tested";
  const std::string video = dir_.file("tour.mp4");
  const auto v = testing::run_meshstep("export --tour " + tour_path + " --video " + video + " --fps 2 --size 640x360 -q",
                                       dir_.path());
  ASSERT_EQ(v.status, 0) << v.err;
  const std::string out = dir_.file("probe.txt");
  ASSERT_EQ(std::system(("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width "
                         "-of default=nw=1 " + video + " > " + out).c_str()),
            0);
  const std::string said = testing::slurp(out);
  EXPECT_NE(said.find("width=640"), std::string::npos) << said;
  EXPECT_NE(said.find("nb_read_frames=" + std::to_string(2 * expected)), std::string::npos) << said;
}

INSTANTIATE_TEST_SUITE_P(ShippedTours, TourExport, ::testing::Values("ruppert", "offcenter", "lepp-centroid"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::erase(name, '-');
                           return name;
                         });

TEST(TourExportUsage, ALogBesideATourIsAUsageErrorAndABadTourNamesItsLine) {
  testing::TempDir dir("meshstep_tour_usage_");
  const std::string tour = std::string(MESHSTEP_ASSETS) + "/tours/ruppert.tour";
  auto r = testing::run_meshstep("export some.mslog --tour " + tour + " --frames " + dir.file("f"), dir.path());
  EXPECT_EQ(r.status, 2) << r.err;
  r = testing::run_meshstep("export --tour " + tour + " --frames " + dir.file("f") + " --every event", dir.path());
  EXPECT_EQ(r.status, 2) << r.err;
  const std::string bad = dir.write("bad.tour", "input " + std::string(MESHSTEP_ASSETS) +
                                                    "/examples/lesson.poly\nrun triangulate\nstop step 9999\ncaption A.\n");
  r = testing::run_meshstep("export --tour " + bad + " --frames " + dir.file("f"), dir.path());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find(bad + ":3: stop step 9999 is outside the run"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("f"))) << "a refused export left a frames folder";
}

// The narration's lines fit the picture's width, and the camera's fit leaves their band free.
TEST(Narration, IsWrappedToThePictureAndLeftRoomBelow) {
  const auto lines = scene::wrap_words("one two three four five six seven eight nine ten", 10, 4);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "one two");
  EXPECT_EQ(lines[3], "seven...");
  for (const std::string& l : scene::wrap_words("a long sentence that wraps at twenty columns or fewer", 20, 9))
    EXPECT_LE(l.size(), 20u) << l;
  scene::Scene s;
  s.narration = "A caption of two sentences. It is read from the back of the room.";
  const scene::Layout plain = scene::layout(scene::Scene{}, 1280, 720), told = scene::layout(s, 1280, 720);
  ASSERT_TRUE(told.narration_band);
  EXPECT_EQ(told.narration_band->y + told.narration_band->h, 720.0);
  EXPECT_GT(told.margins.bottom, told.narration_band->h);
  EXPECT_EQ(plain.margins.bottom, 24.0);
  EXPECT_FALSE(plain.narration_band);
}

}  // namespace
}  // namespace meshstep

#include "meshstep/teach/quiz.hpp"

namespace meshstep {
namespace {

// The quiz's grading on a Lepp-centroid run: the terminal edge and the encroached segment of
// the first steps that have them, read here from their events, are right at their midpoints
// and wrong at a corner of the first triangle that is not one of their ends.
TEST(QuizGrading, EdgesAreRightAtTheirMidpointAndWrongElsewhere) {
  testing::TempDir dir("meshstep_quiz_grading_");
  const std::string log_path = dir.file("l.mslog");
  const auto r = testing::run_meshstep("refine " + std::string(MESHSTEP_ASSETS) +
                                           "/examples/lesson.poly --algorithm lepp-centroid --min-angle 30 --record " +
                                           log_path + " --no-output -q",
                                       dir.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const replay::LogReader log(log_path);
  const auto& v = log.vertices();
  std::array<std::uint32_t, 3> first{kNone, kNone, kNone};
  struct Expected {
    replay::EventType type;
    teach::QuestionKind kind;
    std::uint64_t step = 0;
    std::array<std::uint32_t, 2> edge{};
  } expected[] = {{replay::EventType::lepp_path, teach::QuestionKind::terminal_edge},
                  {replay::EventType::encroached, teach::QuestionKind::encroached_segment}};
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const replay::Event ev = log.event(e);
    if (ev.type == replay::EventType::init) first = {ev.ids[0], ev.ids[1], ev.ids[2]};
    for (Expected& x : expected)
      if (!x.step && ev.type == x.type) {
        x.step = log.step_of_event(e) + 1;
        x.edge = {ev.ids[0], ev.ids[1]};
      }
  }
  for (const Expected& x : expected) {
    ASSERT_GT(x.step, 0u) << teach::name(x.kind);
    const auto q = teach::next_question(log, 0, x.kind);
    ASSERT_TRUE(q);
    EXPECT_EQ(q->step, x.step);
    replay::Replay before(log);
    before.seek_step(x.step - 1);
    const Point a = v[x.edge[0]].point, b = v[x.edge[1]].point;
    const teach::Answer right = teach::grade(*q, before, {(a.x + b.x) / 2, (a.y + b.y) / 2});
    EXPECT_TRUE(right.right) << teach::name(x.kind);
    EXPECT_NEAR(right.distance, 0.0, 1e-12);
    std::uint32_t corner = kNone;
    for (const std::uint32_t c : first)
      if (c != x.edge[0] && c != x.edge[1]) corner = c;
    const teach::Answer wrong = teach::grade(*q, before, v[corner].point);
    EXPECT_FALSE(wrong.right) << teach::name(x.kind);
    EXPECT_TRUE(wrong.chosen[0] == corner || wrong.chosen[1] == corner) << teach::name(x.kind);
    teach::QuizScore score;
    score.answers = {{*q, right}, {*q, wrong}};
    EXPECT_EQ(score.right(), 1u);
    EXPECT_NE(score.summary_json(log).find("\"asked\": 2,\n  \"right\": 1,"), std::string::npos);
  }
}

}  // namespace
}  // namespace meshstep
