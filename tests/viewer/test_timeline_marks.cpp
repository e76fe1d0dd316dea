// The timeline's marks: the kinds and their names, the columns' counts checked against an
// independent scan of recorded logs (each kind's columns sum to the number of such steps or
// events in the log, each in the column of its position), counted lazily and once per width,
// the `toggle-marks` script action, and the program's state saying what the bar marks.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "golden_runs.hpp"
#include "meshstep/error.hpp"
#include "script.hpp"
#include "timeline.hpp"
#include "timeline_marks.hpp"

namespace meshstep::viewer {
namespace {

namespace fs = std::filesystem;
using replay::EventType;
using replay::StepKind;

constexpr const char* kOffcenter = "--algorithm offcenter --min-angle 30";
constexpr const char* kCavities = "--algorithm offcenter --min-angle 30 --insertion cavity";

// Each kind's positions (where the bar puts its marks: a step's end, just after an event),
// found from the log's own records without the viewer's code.
std::array<std::vector<std::uint64_t>, kMarkCount> scan(const replay::LogReader& log) {
  std::array<std::vector<std::uint64_t>, kMarkCount> at;
  const auto put = [&](Mark m, std::uint64_t position) { at[static_cast<std::size_t>(m)].push_back(position); };
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    const StepKind kind = log.step_kind(k);
    const std::uint64_t end = log.step_start(k + 1);
    if (kind == StepKind::split_segment) put(Mark::splits, end);
    if (kind == StepKind::refine) put(Mark::refine, end);
    if (kind == StepKind::start || kind == StepKind::insert_vertex || kind == StepKind::recover_segment ||
        kind == StepKind::carve)
      put(Mark::triangulate, end);
  }
  for (std::uint64_t e = 0; e < log.event_count(); ++e) {
    const replay::Event ev = log.event(e);
    if (ev.type == EventType::flip) put(Mark::flips, e + 1);
    if (ev.type == EventType::encroached && ev.ids[2] == kNone) put(Mark::rejected, e + 1);
    if (ev.type == EventType::cavity) {
      std::size_t faces = 0;
      for (const replay::SlotWrite& w : ev.writes) faces += w.before.v[0] != kNone;
      if (faces > 10) put(Mark::cavities, e + 1);
    }
  }
  return at;
}

// A wheel: 24 points round a circle (on three radii a little apart), then one near the
// centre, inserted by Bowyer-Watson: its cavity is nearly every triangle.
// Returns the log of its triangulation, recorded by the meshstep program.
std::string wheel_log(const fs::path& dir) {
  const fs::path node = dir / "wheel.node", log = dir / "wheel.mslog";
  std::ofstream out(node);
  out << "25 2 0 0\n";
  for (int i = 0; i < 24; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * i / 24.0, r = 1.0 + 0.01 * (i % 3);
    char line[96];
    std::snprintf(line, sizeof line, "%d %.17g %.17g\n", i + 1, r * std::cos(a), r * std::sin(a));
    out << line;
  }
  out << "25 0.01 0.02\n";
  out.close();
  const std::string command = std::string(MESHSTEP_BINARY) + " triangulate " + node.string() +
                              " --insertion cavity --no-output -q --record " + log.string();
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return log.string();
}

TEST(TimelineMarks, NamesParseBackAndTheSetFormatsAndParses) {
  for (std::size_t i = 0; i < kMarkCount; ++i) {
    const auto m = static_cast<Mark>(i);
    EXPECT_EQ(parse_mark(name(m)), m);
    EXPECT_STRNE(label(m), "");
  }
  EXPECT_FALSE(parse_mark("Splits"));
  EXPECT_EQ(MarkSet::defaults(), MarkSet::none().set(Mark::splits));  // what the bar showed before
  EXPECT_EQ(format_marks(MarkSet::none().set(Mark::flips).set(Mark::splits)), "splits, flips");
  EXPECT_EQ(format_marks(MarkSet::none()), "");
  std::string bad;
  EXPECT_EQ(parse_marks(" flips ,splits", bad), MarkSet::none().set(Mark::flips).set(Mark::splits));
  EXPECT_EQ(parse_marks("", bad), MarkSet::none());
  EXPECT_EQ(parse_marks(format_marks(MarkSet::all()), bad), MarkSet::all());
  EXPECT_FALSE(parse_marks("flips, sparks", bad));
  EXPECT_EQ(bad, "sparks");
  EXPECT_FALSE(MarkSet::defaults().any_event_kind());
  EXPECT_TRUE(MarkSet::none().set(Mark::cavities).any_event_kind());
  MarkSet s = MarkSet::none();
  EXPECT_TRUE(s.toggle(Mark::rejected).has(Mark::rejected));
  EXPECT_FALSE(s.toggle(Mark::rejected).has(Mark::rejected));
}

// The columns against the independent scan, for each recorded run and a few widths.
TEST(TimelineMarks, ColumnsCountEveryMarkedStepAndEventOnceInItsColumn) {
  const fs::path dir = fs::temp_directory_path() / ("viewer_wheel_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const replay::LogReader wheel(wheel_log(dir));
  std::array<std::uint64_t, kMarkCount> seen{};
  for (const char* args : {kOffcenter, kCavities, "wheel"}) {
    const replay::LogReader* log = std::string(args) == "wheel" ? &wheel : golden::lesson_run(args);
    ASSERT_NE(log, nullptr);
    const auto positions = scan(*log);
    for (const int width : {1, 97, 640, 5000}) {
      TimelineCache cache;
      cache.update(*log, width, MarkSet::all());
      cache.wait_for_scan();
      cache.update(*log, width, MarkSet::all());
      for (std::size_t m = 0; m < kMarkCount; ++m) {
        std::vector<std::uint32_t> expected(static_cast<std::size_t>(width), 0);
        for (const std::uint64_t p : positions[m])
          ++expected[static_cast<std::size_t>(column_of(p, log->event_count(), width))];
        EXPECT_EQ(cache.marks[m], expected) << args << ", width " << width << ", " << name(static_cast<Mark>(m));
        EXPECT_EQ(cache.total_marks[m], positions[m].size()) << args << ", " << name(static_cast<Mark>(m));
        seen[m] += positions[m].size();
      }
    }
  }
  // Not vacuous: the runs have every kind.
  for (std::size_t m = 0; m < kMarkCount; ++m) EXPECT_GT(seen[m], 0u) << name(static_cast<Mark>(m));
  fs::remove_all(dir);
}

// The ticks of a long run as a strip of a pixel per column (TickStrip): the bar's colour
// where no step ends, light grey as strong as the column's share of the fullest one
// elsewhere, and a new stamp whenever the counts are made anew.
TEST(TimelineMarks, TheTickStripShadesEachColumnByItsSteps) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_NE(log, nullptr);
  TimelineCache cache;
  cache.update(*log, 40, MarkSet::none());  // fewer columns than steps: a density
  const std::uint64_t stamp = cache.stamp;
  cache.update(*log, 40, MarkSet::none());
  EXPECT_EQ(cache.stamp, stamp) << "the same counts";
  scene::Image strip;
  tick_strip_pixels(cache, strip);
  ASSERT_EQ(strip.width, 40);
  ASSERT_EQ(strip.height, 1);
  bool some_full = false;
  for (int c = 0; c < 40; ++c) {
    const std::uint8_t* px = strip.rgba.data() + 4 * c;
    const std::uint32_t n = cache.steps[static_cast<std::size_t>(c)];
    EXPECT_EQ(px[3], 255);
    if (n == 0) {
      EXPECT_EQ(px[0], 40);
      EXPECT_EQ(px[2], 46);
      continue;
    }
    some_full = some_full || n == cache.most_steps;
    // The lines' alpha: 0.25 + 0.75 of the share, in 255ths, over (40, 40, 46).
    const double a = std::floor(255.0 * (0.25 + 0.75 * double(n) / double(cache.most_steps))) / 255.0;
    EXPECT_NEAR(px[0], 220.0 * a + 40.0 * (1.0 - a), 0.51) << "column " << c;
    EXPECT_NEAR(px[2], 220.0 * a + 46.0 * (1.0 - a), 0.51) << "column " << c;
    if (n == cache.most_steps) EXPECT_EQ(px[0], 220) << "the fullest column";
  }
  EXPECT_TRUE(some_full);
  cache.update(*log, 41, MarkSet::none());
  EXPECT_NE(cache.stamp, stamp) << "another width: counted anew";
}

TEST(TimelineMarks, EventKindsAreCountedOnlyOnceWantedAndAgainPerWidth) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_NE(log, nullptr);
  TimelineCache cache;
  cache.update(*log, 300, MarkSet::defaults());
  // The step kinds are counted with the steps; the events are not read for the defaults.
  EXPECT_TRUE(cache.counted(Mark::splits));
  EXPECT_TRUE(cache.counted(Mark::refine));
  EXPECT_FALSE(cache.counted(Mark::flips));
  EXPECT_FALSE(cache.events_scanned);
  // Wanted: the pass starts on its own thread; the frame that asked does not wait for it.
  cache.update(*log, 300, MarkSet::none().set(Mark::flips));
  EXPECT_TRUE(cache.scan != nullptr);
  EXPECT_FALSE(cache.events_scanned);
  EXPECT_FALSE(cache.counted(Mark::flips));
  cache.wait_for_scan();
  cache.update(*log, 300, MarkSet::none().set(Mark::flips));  // the same width: counted as it arrives
  EXPECT_TRUE(cache.events_scanned);
  EXPECT_EQ(cache.scan, nullptr);
  ASSERT_TRUE(cache.counted(Mark::flips));
  ASSERT_TRUE(cache.counted(Mark::rejected));  // one pass finds every event kind
  const std::uint64_t flips = cache.total_marks[static_cast<std::size_t>(Mark::flips)];
  EXPECT_EQ(flips, log->counts_by_type()[static_cast<std::size_t>(EventType::flip)]);
  // A new width: the same totals from the positions kept; the same width: nothing to do.
  cache.update(*log, 123, MarkSet::defaults());
  EXPECT_EQ(cache.marks[static_cast<std::size_t>(Mark::flips)].size(), 123u);
  EXPECT_EQ(cache.total_marks[static_cast<std::size_t>(Mark::flips)], flips);
  const std::uint32_t* before = cache.marks[static_cast<std::size_t>(Mark::flips)].data();
  cache.update(*log, 123, MarkSet::all());
  EXPECT_EQ(cache.marks[static_cast<std::size_t>(Mark::flips)].data(), before);
}

TEST(TimelineMarks, ScriptsToggleAKindByName) {
  const fs::path file = fs::temp_directory_path() / ("viewer_marks_" + std::to_string(::getpid()) + ".txt");
  std::ofstream(file) << "toggle-marks flips\n";
  const std::vector<ScriptAction> actions = read_script(file.string());
  ASSERT_EQ(actions.size(), 1u);
  EXPECT_EQ(actions[0].args, std::vector<std::string>{"flips"});
  std::ofstream(file) << "frames 1\ntoggle-marks sparks\n";
  try {
    read_script(file.string());
    ADD_FAILURE() << "accepted an unknown kind";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":2: unknown kind of mark 'sparks' (splits, rejected"),
              std::string::npos)
        << e.what();
  }
  fs::remove(file);
}

// The program: the state names the kinds the bar marks with their counts, and toggling
// changes them.
TEST(TimelineMarksProgram, ToggleMarksChangesWhatTheBarCounts) {
  const replay::LogReader* log = golden::lesson_run(kOffcenter);
  ASSERT_NE(log, nullptr);
  const auto positions = scan(*log);
  const fs::path dir = fs::temp_directory_path() / ("viewer_marks_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path a = dir / "a.json", b = dir / "b.json", script = dir / "s.txt";
  std::ofstream(script) << "frames 1\nstate " << a.string()
                        << "\ntoggle-marks flips\ntoggle-marks rejected\ntoggle-marks splits\nframes 1\nstate "
                        << b.string() << "\nquit\n";
  FILE* pipe = ::popen((std::string(MESHSTEP_VIEW_BINARY) + " " + log->path() +
                        " --offscreen -q --window 1024x640 --script " + script.string() + " 2>&1")
                           .c_str(),
                       "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) output.append(buf, n);
  const int status = ::pclose(pipe);
  if (status != 0 && output.find("cannot open a window or draw") != std::string::npos) GTEST_SKIP() << output;
  ASSERT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0) << output;
  const auto read = [](const fs::path& p) {
    std::stringstream s;
    s << std::ifstream(p).rdbuf();
    return s.str();
  };
  const auto count = [&](Mark m) { return std::to_string(positions[static_cast<std::size_t>(m)].size()); };
  const std::string before = read(a), after = read(b);
  EXPECT_NE(before.find("\n  \"timeline_marks\": {\"splits\": " + count(Mark::splits) + "},\n"), std::string::npos)
      << before;
  EXPECT_NE(after.find("\n  \"timeline_marks\": {\"rejected\": " + count(Mark::rejected) + ", \"flips\": " +
                       count(Mark::flips) + "},\n"),
            std::string::npos)
      << after;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace meshstep::viewer
