// The Lepp path belongs to the step that uses it (issue 29): a refinement records it right
// after that step's step_begin, before any change of the mesh, so no moment's caption says
// "next: Lepp path" under the step before.
#include <gtest/gtest.h>

#include <string>

#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/step_numbers.hpp"
#include "meshstep/scene/build.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

using testing::run_meshstep;
using testing::TempDir;

TEST(LeppPathOrder, EachPathOpensTheStepThatUsesIt) {
  TempDir dir;
  const std::string lesson = std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly";
  for (const std::string algorithm : {"lepp-centroid", "lepp-midpoint"}) {
    const std::string log_path = dir.file(algorithm + ".mslog");
    const auto r = run_meshstep("refine " + lesson + " --algorithm " + algorithm + " --min-angle 28 --record " +
                                    log_path + " --no-output -q",
                                dir.path());
    ASSERT_EQ(r.status, 0) << r.err;
    const replay::LogReader log(log_path);
    std::size_t paths = 0;
    for (std::uint64_t e = 0; e < log.event_count(); ++e) {
      if (log.event(e).type != replay::EventType::lepp_path) continue;
      ++paths;
      const std::uint64_t s = log.step_of_event(e);
      ASSERT_LT(s, log.step_count()) << "event " << e << " comes before any step";
      const auto kind = log.step_kind(s);
      EXPECT_TRUE(kind == replay::StepKind::refine || kind == replay::StepKind::split_segment)
          << "event " << e << " is in a step of kind " << replay::name(kind);
      for (std::uint64_t x = log.step_start(s); x < e; ++x)
        EXPECT_FALSE(replay::schema(log.event(x).type).changes_mesh())
            << "event " << x << " changes the mesh before the Lepp path " << e << " of its step";
    }
    EXPECT_GT(paths, 10u) << algorithm;
    // No moment's caption announces the next step's path.
    replay::Replay cursor(log);
    for (std::uint64_t k = 0; k <= log.step_count(); ++k) {
      cursor.seek_event(replay::step_position(log, k));
      const std::string caption = scene::build_scene(cursor, {}).caption;
      EXPECT_EQ(caption.find("next: Lepp path"), std::string::npos) << "step " << k << ": " << caption;
    }
  }
}

}  // namespace
}  // namespace meshstep
