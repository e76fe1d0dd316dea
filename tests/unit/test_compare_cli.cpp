// `meshstep compare`: logs side by side (the numbers each run's `refine --stats json` gives),
// the matrix of algorithms x inputs (rows equal to separate `refine` runs, whatever order the
// runs end in), its summary and plot, and the errors for bad input. Through the real binary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "meshstep/scene/image.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::json_field;
using testing::slurp;
using testing::stats_line;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string asset(const std::string& name) { return std::string(MESHSTEP_ASSETS) + "/examples/" + name; }
std::string shared_poly(const std::string& name) { return std::string(MESHSTEP_SHARED_DATA) + "/pslg/" + name; }

// The objects of a JSON array whose every object starts with `first_key`, as raw text.
std::vector<std::string> objects_starting(const std::string& json, const std::string& first_key) {
  std::vector<std::string> parts;
  const std::string start = "{\"" + first_key + "\":";
  for (std::size_t at = json.find(start); at != std::string::npos;) {
    const std::size_t next = json.find(start, at + 1);
    parts.push_back(json.substr(at, next == std::string::npos ? std::string::npos : next - at));
    at = next;
  }
  return parts;
}

std::string unquoted(const std::string& s) {
  return s.size() >= 2 && s.front() == '"' ? s.substr(1, s.size() - 2) : s;
}

class CompareCli : public testing::CliTest {
 protected:
  CompareCli() : CliTest("meshstep_compare_cli_") {}
  // Records `algorithm` on `input` at `min_angle`; returns the log and the run's --stats json.
  std::pair<std::string, std::string> record(const std::string& input, const std::string& algorithm,
                                             const std::string& min_angle, const std::string& name) const {
    const std::string log = dir_.file(name + ".mslog");
    const CommandResult r = meshstep("refine " + input + " --algorithm " + algorithm + " --min-angle " + min_angle +
                                     " --record " + log + " --no-output --stats json -q");
    EXPECT_EQ(r.status, 0) << r.err;
    return {log, stats_line(r.out)};
  }
};

// The test: circumcenter and off-center logs of guitar.poly at 30 degrees; compare's
// numbers are each run's own.
TEST_F(CompareCli, GuitarLogsReportWhatEachRunsStatsJsonSaid) {
  const std::string guitar = shared_poly("guitar.poly");
  if (!fs::exists(guitar)) GTEST_SKIP() << guitar << " is absent: skipped";
  const auto [circ_log, circ_stats] = record(guitar, "circumcenter", "30", "circ");
  const auto [off_log, off_stats] = record(guitar, "offcenter", "30", "off");
  // Different runs, or the test would not tell the columns apart.
  ASSERT_NE(json_field(circ_stats, "steiner"), json_field(off_stats, "steiner"));

  const CommandResult r = meshstep("compare " + circ_log + " " + off_log + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");  // same input: no warning
  const std::vector<std::string> runs = objects_starting(r.out, "log");
  ASSERT_EQ(runs.size(), 2u) << r.out;
  const std::pair<std::string, std::string> expected[] = {{runs[0], circ_stats}, {runs[1], off_stats}};
  for (const auto& [run, stats] : expected) {
    SCOPED_TRACE(run);
    for (const char* key : {"steiner", "triangles", "min_angle", "max_angle", "vertices"})
      EXPECT_EQ(json_field(run, key), json_field(stats, key)) << key;
    EXPECT_EQ(json_field(run, "algorithm"), json_field(stats, "algorithm"));
    EXPECT_NE(json_field(run, "steps"), "0");
  }
  EXPECT_TRUE(contains(r.out, "\"same_input\":true")) << r.out;

  // The text: a column per run, captioned by its description, with the same counts.
  const CommandResult text = meshstep("compare " + circ_log + " " + off_log);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_TRUE(contains(text.out, "circumcenter, min angle 30")) << text.out;
  EXPECT_TRUE(contains(text.out, "offcenter, min angle 30")) << text.out;
  std::string steiner_row;
  for (std::size_t at = 0, end; (end = text.out.find('\n', at)) != std::string::npos; at = end + 1)
    if (text.out.compare(at, 14, "Steiner points") == 0) steiner_row = text.out.substr(at, end - at);
  EXPECT_TRUE(contains(steiner_row, " " + json_field(circ_stats, "steiner") + " ")) << steiner_row;
  EXPECT_TRUE(steiner_row.ends_with(" " + json_field(off_stats, "steiner"))) << steiner_row;
}

// Logs of different inputs are compared, with a warning naming both.
TEST_F(CompareCli, LogsOfDifferentInputsAreComparedWithAWarning) {
  const auto [lesson_log, lesson_stats] = record(asset("lesson.poly"), "offcenter", "25", "lesson");
  const auto [plate_log, plate_stats] = record(asset("plate.poly"), "offcenter", "25", "plate");
  const CommandResult r = meshstep("compare " + lesson_log + " " + plate_log + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "meshstep: warning:")) << r.err;
  EXPECT_TRUE(contains(r.err, "different inputs")) << r.err;
  EXPECT_TRUE(contains(r.err, "lesson.poly") && contains(r.err, "plate.poly")) << r.err;
  EXPECT_TRUE(contains(r.out, "\"same_input\":false")) << r.out;
  const std::vector<std::string> runs = objects_starting(r.out, "log");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(json_field(runs[1], "steiner"), json_field(plate_stats, "steiner"));
}

// A damaged, cut or missing log is refused with the words `log verify` says of it, exit 1.
TEST_F(CompareCli, DamagedLogsAreRefusedInLogVerifysWords) {
  const auto [good, stats] = record(asset("plate.poly"), "offcenter", "28", "good");
  std::string bytes = slurp(good);
  std::string flipped = bytes;
  flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 0x10);
  const std::string damaged = dir_.write("damaged.mslog", flipped);
  const std::string cut = dir_.write("cut.mslog", bytes.substr(0, bytes.size() - 10));
  const std::string missing = dir_.file("missing.mslog");
  for (const std::string& bad : {damaged, cut, missing}) {
    SCOPED_TRACE(bad);
    const CommandResult verify = meshstep("log verify " + bad);
    ASSERT_EQ(verify.status, 1);
    ASSERT_EQ(verify.err.rfind("meshstep: error: " + bad, 0), 0u) << verify.err;
    const CommandResult r = meshstep("compare " + good + " " + bad);
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_EQ(r.err, verify.err);
    EXPECT_EQ(r.out, "");  // nothing half printed
  }
  const CommandResult one = meshstep("compare " + good);
  EXPECT_EQ(one.status, 2);
  EXPECT_TRUE(contains(one.err, "two logs or more")) << one.err;
}

// The matrix test: three algorithms on two inputs give the rows of six separate
// refine runs; the summary's geometric mean is that of the rows' ratios.
TEST_F(CompareCli, AlgorithmsTimesInputsRowsEqualSeparateRefineRuns) {
  const std::vector<std::string> algorithms = {"offcenter", "circumcenter", "lepp-centroid"};
  const std::vector<std::string> inputs = {asset("lesson.poly"), asset("plate.poly")};
  const CommandResult r = meshstep("compare --algorithms offcenter,circumcenter,lepp-centroid --min-angle 28 " +
                                   inputs[0] + " " + inputs[1] + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> rows = objects_starting(r.out, "algorithm");
  ASSERT_EQ(rows.size(), 6u) << r.out;
  std::map<std::string, double> steiner;  // "algorithm input" -> Steiner points
  std::size_t i = 0;
  for (const std::string& input : inputs)
    for (const std::string& algorithm : algorithms) {
      const std::string& row = rows[i++];
      SCOPED_TRACE(algorithm + " on " + input + ": " + row);
      EXPECT_EQ(unquoted(json_field(row, "algorithm")), algorithm);
      EXPECT_EQ(unquoted(json_field(row, "input")), input);
      const CommandResult one =
          meshstep("refine " + input + " --algorithm " + algorithm + " --min-angle 28 --no-output --stats json -q");
      ASSERT_EQ(one.status, 0) << one.err;
      const std::string stats = stats_line(one.out);
      for (const char* key : {"steiner", "triangles", "vertices", "min_angle", "max_angle", "below_min_angle",
                              "bad_triangles", "bad_near_small_input_angle", "bounds_met", "stopped_by_cap"})
        EXPECT_EQ(json_field(row, key), json_field(stats, key)) << key;
      EXPECT_EQ(std::stoull(json_field(row, "memory_estimate_bytes")), 160 * std::stoull(json_field(stats, "triangles")));
      steiner[algorithm + " " + input] = std::stod(json_field(row, "steiner"));
    }
  for (const std::string& algorithm : algorithms) {
    double log_sum = 0;
    for (const std::string& input : inputs)
      log_sum += std::log(steiner[algorithm + " " + input] / steiner["offcenter " + input]);
    const std::string summary = r.out.substr(r.out.find("\"steiner_ratio_geomean\""));
    EXPECT_NEAR(std::stod(json_field(summary, algorithm)), std::exp(log_sum / 2), 1e-6) << summary;
  }
}

// Two threads or one: the same rows in the same order (the times aside), and the text and
// CSV forms hold the same Steiner counts.
TEST_F(CompareCli, OutputDoesNotDependOnTheOrderRunsEnd) {
  const std::string args = "compare --algorithms circumcenter,offcenter --min-angle 20:30:5 " + asset("lesson.poly") +
                           " " + asset("plate.poly");
  const auto without_times = [](std::string json) {
    // "ms":{...} (to its closing brace) and "peak_rss_bytes":N (to the next , or }).
    for (const std::string key : {"\"ms\":{", "\"peak_rss_bytes\":"})
      for (std::size_t at = json.find(key); at != std::string::npos; at = json.find(key, at)) {
        const std::size_t end = key.back() == '{' ? json.find('}', at) + 1 : json.find_first_of(",}", at);
        if (end == std::string::npos || end == 0) break;
        json.erase(at, end - at);
      }
    return json;
  };
  const CommandResult two = meshstep(args + " --json -j 2");
  const CommandResult one = meshstep(args + " --json -j 1");
  ASSERT_EQ(two.status, 0) << two.err;
  ASSERT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(without_times(two.out), without_times(one.out));
  const std::vector<std::string> rows = objects_starting(two.out, "algorithm");
  ASSERT_EQ(rows.size(), 12u);  // 2 inputs x 3 bounds x 2 algorithms
  EXPECT_EQ(json_field(rows[0], "min_angle_bound"), "20");
  EXPECT_EQ(json_field(rows[5], "min_angle_bound"), "30");
  // A higher bound never leaves a smaller angle than the lower bound's run (same input,
  // same algorithm), and is met on these inputs.
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_GE(std::stod(json_field(rows[k], "min_angle")), std::stod(json_field(rows[k], "min_angle_bound")));
  }

  const CommandResult csv = meshstep(args + " --csv");
  ASSERT_EQ(csv.status, 0) << csv.err;
  std::vector<std::string> lines;
  for (std::size_t at = 0, end; (end = csv.out.find('\n', at)) != std::string::npos; at = end + 1)
    lines.push_back(csv.out.substr(at, end - at));
  ASSERT_EQ(lines.size(), 13u) << csv.out;
  EXPECT_EQ(lines[0].rfind("algorithm,input,min_angle_bound,steiner,triangles,", 0), 0u) << lines[0];
  for (std::size_t k = 0; k < rows.size(); ++k) {
    // The fourth field: the row's Steiner points.
    std::string fields = lines[k + 1];
    for (int skip = 0; skip < 3; ++skip) fields.erase(0, fields.find(',') + 1);
    EXPECT_EQ(fields.substr(0, fields.find(',')), json_field(rows[k], "steiner")) << lines[k + 1];
  }
}

// The plot: a figure with the sweep and the angle distribution, a line per algorithm in each,
// written whole; an existing file is replaced only by a complete one.
TEST_F(CompareCli, PlotHasASeriesPerAlgorithmInEachPanel) {
  const std::string plot = dir_.file("figure.svg");
  const CommandResult r = meshstep("compare --algorithms offcenter,circumcenter --min-angle 20:30:5 " +
                                   asset("lesson.poly") + " --plot " + plot);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = slurp(plot);
  ASSERT_TRUE(svg.ends_with("</svg>\n"));
  std::size_t series = 0;
  for (std::size_t at = svg.find("class=\"series\""); at != std::string::npos; at = svg.find("class=\"series\"", at + 1))
    ++series;
  EXPECT_EQ(series, 4u);
  EXPECT_TRUE(contains(svg, "(a) Steiner points against the angle bound")) << svg.substr(0, 400);
  EXPECT_TRUE(contains(svg, "(b) Smallest angle of each triangle")) << svg.substr(0, 400);
  EXPECT_TRUE(contains(svg, "data-name=\"circumcenter\""));
  // The plot may not replace an input.
  const std::string input = dir_.write("copy.poly", slurp(asset("lesson.poly")));
  const CommandResult clash = meshstep("compare --algorithms offcenter " + input + " --plot " + input);
  EXPECT_EQ(clash.status, 2);
  EXPECT_EQ(slurp(input), slurp(asset("lesson.poly")));
}

TEST_F(CompareCli, BadInputGetsClearErrorsAndExitStatuses) {
  const std::string lesson = asset("lesson.poly");
  struct Case {
    std::string args, words;
    int status;
  };
  const Case cases[] = {
      {"--algorithms offcenter,nosuch " + lesson, "unknown algorithm 'nosuch'", 2},
      {"--algorithms offcenter --min-angle 20:34 " + lesson, "START:END:STEP", 2},
      {"--algorithms offcenter --min-angle 20:x:2 " + lesson, "'x' is not a number", 2},
      {"--algorithms offcenter --min-angle 34:20:2 " + lesson, "the end is below the start", 2},
      {"--algorithms offcenter --min-angle 20:34:0 " + lesson, "the step must be positive", 2},
      {"--algorithms offcenter --min-angle -5 " + lesson, "--min-angle", 2},
      {"--algorithms offcenter " + dir_.file("missing.poly"), dir_.file("missing.poly") + ": cannot be read", 1},
      {"--algorithms offcenter --recipes " + dir_.file("r.recipe") + " " + lesson, "one or the other", 2},
      {"--recipes " + dir_.file("missing.recipe") + " " + lesson, "missing.recipe: cannot be read", 1},
      {"--algorithms offcenter --json --csv " + lesson, "one or the other", 2},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const CommandResult r = meshstep("compare " + c.args);
    EXPECT_EQ(r.status, c.status) << r.err;
    EXPECT_EQ(r.err.rfind("meshstep: error: ", 0), 0u) << r.err;
    EXPECT_TRUE(contains(r.err, c.words)) << r.err;
    EXPECT_EQ(r.out, "");
  }
}

// --recipes: a recipe file's operations per input, its row as `meshstep run` reports it.
TEST_F(CompareCli, RecipesRunAsMeshstepRunRunsThem) {
  const std::string recipe = dir_.write("quality.recipe", "refine --algorithm lepp-centroid --min-angle 25\n");
  const std::string input = asset("plate.poly");
  const CommandResult r = meshstep("compare --recipes " + recipe + " " + input + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> rows = objects_starting(r.out, "algorithm");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(unquoted(json_field(rows[0], "algorithm")), "quality");
  const CommandResult run = meshstep("run " + recipe + " " + input + " -o " + dir_.file("out") + " --stats json -q");
  ASSERT_EQ(run.status, 0) << run.err;
  for (const char* key : {"steiner", "triangles", "min_angle", "max_angle"})
    EXPECT_EQ(json_field(rows[0], key), json_field(stats_line(run.out), key)) << key;
}

}  // namespace
}  // namespace meshstep

namespace meshstep {
namespace {

// --svg: the runs side by side at one moment, each panel captioned with its run and step,
// ids unique in the document; --png the same through OpenGL (skipped without it).
TEST_F(CompareCli, SideBySidePictureAtOneMoment) {
  const auto [circ, circ_stats] = record(asset("lesson.poly"), "circumcenter", "30", "circ");
  const auto [off, off_stats] = record(asset("lesson.poly"), "offcenter", "30", "off");
  const std::string svg_path = dir_.file("side.svg");
  const CommandResult r = meshstep("compare " + circ + " " + off + " --step 10 --svg " + svg_path);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = slurp(svg_path);
  EXPECT_TRUE(contains(svg, "<svg x=\"0\" y=\"0\"")) << svg.substr(0, 300);
  EXPECT_TRUE(contains(svg, "<svg x=\"640\" y=\"0\""));
  EXPECT_TRUE(contains(svg, "circumcenter, min angle 30 \u00b7 ")) << svg.substr(0, 300);
  EXPECT_TRUE(contains(svg, "offcenter, min angle 30 \u00b7 "));
  EXPECT_EQ(svg.find("step 10 of", svg.find("step 10 of") + 1) != std::string::npos, true);  // both panels
  std::vector<std::string> ids;
  for (std::size_t at = svg.find(" id=\""); at != std::string::npos; at = svg.find(" id=\"", at + 1))
    ids.push_back(svg.substr(at + 5, svg.find('"', at + 5) - at - 5));
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end()) << "an id twice";

  // The end of each run: its own step count.
  const CommandResult end = meshstep("compare " + circ + " " + off + " --fraction 1 --svg " + svg_path);
  ASSERT_EQ(end.status, 0) << end.err;
  const std::string last = slurp(svg_path);
  const CommandResult info_c = meshstep("log info " + circ + " --json");
  const CommandResult info_o = meshstep("log info " + off + " --json");
  for (const std::string& info : {info_c.out, info_o.out}) {
    const std::string steps = json_field(info, "steps");
    EXPECT_TRUE(contains(last, "step " + steps + " of " + steps)) << steps;
  }

  const std::string png_path = dir_.file("side.png");
  const CommandResult png = meshstep("compare " + circ + " " + off + " --png " + png_path);
  if (png.status != 0 && contains(png.err, "OpenGL")) GTEST_SKIP() << "no OpenGL: " << png.err;
  ASSERT_EQ(png.status, 0) << png.err;
  const scene::Image image = scene::read_png(png_path);
  EXPECT_EQ(image.width, 1280);
  // As tall as the SVG of the same runs.
  const std::string doc = slurp(svg_path);
  const std::size_t at = doc.find("height=\"") + 8;
  EXPECT_EQ(image.height, std::stoi(doc.substr(at, doc.find('"', at) - at)));
}

TEST_F(CompareCli, PictureOptionsAreChecked) {
  const auto [a, a_stats] = record(asset("lesson.poly"), "offcenter", "25", "a");
  const auto [b, b_stats] = record(asset("lesson.poly"), "circumcenter", "25", "b");
  const std::string logs = a + " " + b + " ";
  struct Case {
    std::string args, words;
  };
  const Case cases[] = {
      {"--fraction 2 --svg " + dir_.file("x.svg"), "--fraction"},
      {"--step 3", "--svg OUT or --png OUT"},
      {"--step 3 --fraction 0.5 --svg " + dir_.file("x.svg"), "one moment or the other"},
      {"--svg " + dir_.file("x.png"), "must end in .svg"},
      {"--svg " + a, "--svg"},  // would replace a log
      {"--algorithms offcenter", "a replay log is compared as it is"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const CommandResult r = meshstep("compare " + logs + c.args);
    EXPECT_NE(r.status, 0);
    EXPECT_TRUE(contains(r.err, c.words)) << r.err;
    EXPECT_FALSE(fs::exists(dir_.file("x.svg")));
  }
  EXPECT_EQ(meshstep("log verify -q " + a).status, 0);  // not replaced by a picture
}

}  // namespace
}  // namespace meshstep

namespace meshstep {
namespace {

// --video: one frame per step of the longer run (ffprobe counts them), as wide as the panels.
TEST_F(CompareCli, SideBySideVideoHasAFramePerStepOfTheLongerRun) {
  if (!testing::ffmpeg_works()) GTEST_SKIP() << "ffmpeg or ffprobe does not start: skipped";
  const auto [circ, circ_stats] = record(asset("lesson.poly"), "circumcenter", "30", "circ");
  const auto [off, off_stats] = record(asset("lesson.poly"), "offcenter", "30", "off");
  long long longest = 0;
  for (const std::string& log : {circ, off})
    longest = std::max(longest, std::stoll(json_field(meshstep("log info " + log + " --json").out, "steps")));
  const std::string video = dir_.file("side.mp4");
  const CommandResult r = meshstep("compare " + circ + " " + off + " --video " + video + " --fps 20");
  if (r.status != 0 && contains(r.err, "OpenGL")) GTEST_SKIP() << "no OpenGL: " << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string frames = dir_.file("frames.txt");
  const std::string probe = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                            "stream=width,nb_read_frames -of csv=p=0 " + video + " > " + frames;
  ASSERT_EQ(std::system(probe.c_str()), 0);
  EXPECT_EQ(slurp(frames), "1280," + std::to_string(longest) + "\n");
  // A moment is a picture's: refused with a video.
  const CommandResult moment = meshstep("compare " + circ + " " + off + " --step 3 --video " + dir_.file("x.mp4"));
  EXPECT_EQ(moment.status, 2);
  EXPECT_FALSE(fs::exists(dir_.file("x.mp4")));
}

}  // namespace
}  // namespace meshstep
