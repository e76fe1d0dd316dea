// meshstep render and meshstep export as a user runs them: pictures of a log, a mesh and an
// input; frames and videos of a run; every bad option or file refused with a message, and
// nothing half-written left behind. PNG cases skip, saying why, where no OpenGL can be had.
#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <string>
#include <vector>

#include "meshstep/scene/image.hpp"
#include "run_cli.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using meshstep::testing::CommandResult;
using meshstep::testing::ffmpeg_works;
using meshstep::testing::run_meshstep;
using meshstep::testing::slurp;
using meshstep::testing::TempDir;

std::string lesson() { return std::string(MESHSTEP_ASSETS) + "/examples/lesson.poly"; }

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    log_ = (dir_.path() / "lesson.mslog").string();
    const CommandResult r =
        run_meshstep("refine " + lesson() + " --algorithm offcenter --min-angle 30 --record " + log_ + " -o " +
                         (dir_.path() / "lesson").string() + " -q",
                     dir_.path());
    ASSERT_EQ(r.status, 0) << r.err;
  }
  // Skips the test when this machine has no OpenGL (render says so and exits 1).
  bool gl_available() {
    const CommandResult r = run_meshstep("render " + log_ + " -o " + (dir_.path() / "probe.png").string() + " -q",
                                         dir_.path());
    if (r.status == 0) return true;
    EXPECT_NE(r.err.find("OpenGL"), std::string::npos) << r.err;
    return false;
  }
  fs::path file(const std::string& name) const { return dir_.path() / name; }

  TempDir dir_;
  std::string log_;
};

TEST_F(RenderCli, PngOfAStepHasTheAskedSizeAndSaysWhatItShows) {
  if (!gl_available()) GTEST_SKIP() << "no OpenGL on this machine";
  const CommandResult r =
      run_meshstep("render " + log_ + " --step 40 --size 320x200 -o " + file("s.png").string(), dir_.path());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("at step 40 of"), std::string::npos) << r.out;
  const meshstep::scene::Image image = meshstep::scene::read_png(file("s.png").string());
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 200);
}

TEST_F(RenderCli, SvgNeedsNoOpenGLAndDrawsTheMesh) {
  // A context that cannot exist: SVG must not care.
  const std::string command = "render " + log_ + " -o " + file("end.svg").string() + " --gl osmesa";
  const CommandResult r = run_meshstep(command, dir_.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = slurp(file("end.svg"));
  ASSERT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_EQ(svg.find("<svg", svg.find("<svg") + 1), std::string::npos) << "one document";
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("width=\"1280\""), std::string::npos) << "the default size";
  EXPECT_NE(svg.find("segments"), std::string::npos) << "the segments' group";
}

// The Voronoi layer is off unless --layers asks for it: +voronoi adds it to the default
// set, a plain list with it draws it, 'all' includes it; step 0 draws the input.
TEST_F(RenderCli, VoronoiOnlyWhenAskedAndStepZeroDrawsTheInput) {
  const auto svg_with = [&](const std::string& options) {
    const CommandResult r = run_meshstep("render " + log_ + " " + options + " -o " + file("v.svg").string(), dir_.path());
    EXPECT_EQ(r.status, 0) << options << ": " << r.err;
    return slurp(file("v.svg"));
  };
  EXPECT_EQ(svg_with("").find("voronoi_edges"), std::string::npos);
  EXPECT_EQ(svg_with("--layers -caption").find("voronoi_edges"), std::string::npos);
  for (const char* on : {"--layers +voronoi", "--layers fill,edges,voronoi", "--layers all"}) {
    const std::string svg = svg_with(on);
    EXPECT_NE(svg.find("class=\"voronoi_edges\""), std::string::npos) << on;
    EXPECT_NE(svg.find("class=\"voronoi_vertices\""), std::string::npos) << on;
  }
  const std::string input = svg_with("--step 0");
  EXPECT_NE(input.find("input: 14 vertices, 12 segments, 1 hole"), std::string::npos);
  EXPECT_NE(input.find("class=\"segments\""), std::string::npos);
  EXPECT_NE(input.find(">14</text>"), std::string::npos) << "vertex 14 named";
}

TEST_F(RenderCli, VertexMarkersOnlyWhereThePictureHasRoomForThem) {
  // The refined lesson has 54 vertices: marked at 1280x720 (room for 1,024), left out at
  // 160x100 (room for 17), where they would hide the mesh.
  for (const auto& [size, marked] : {std::pair{"1280x720", true}, std::pair{"160x100", false}}) {
    const CommandResult r =
        run_meshstep("render " + log_ + " --size " + size + " -o " + file("v.svg").string(), dir_.path());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(file("v.svg")).find("steiner_vertices") != std::string::npos, marked) << size;
  }
}

TEST_F(RenderCli, MeshPrefixAndInputRenderToo) {
  for (const std::string& input : {(dir_.path() / "lesson").string(), lesson()}) {
    const CommandResult r = run_meshstep("render " + input + " -o " + file("x.svg").string(), dir_.path());
    EXPECT_EQ(r.status, 0) << input << ": " << r.err;
    EXPECT_TRUE(fs::exists(file("x.svg")));
    fs::remove(file("x.svg"));
  }
}

TEST_F(RenderCli, BadOptionsAreUsageErrorsNamingTheOption) {
  const struct {
    const char* options;
    const char* says;
  } cases[] = {
      {"--size 12x9000000", "--size"},          {"--size big", "--size"},
      {"--view 1,2,3", "--view"},               {"--view 3,0,1,1", "X1 > X0"},
      {"--color-by beauty", "--color-by"},      {"--layers fill,sparkles", "sparkles"},
      {"--theme sepia", "--theme"},             {"--gl vulkan", "--gl"},
      {"--step 9999", "outside the run"},          {"--step 3 --event 4", "not both"},
      {"--samples 3", "--samples"},
  };
  for (const auto& c : cases) {
    const CommandResult r =
        run_meshstep("render " + log_ + " " + c.options + " -o " + file("bad.svg").string(), dir_.path());
    EXPECT_EQ(r.status, 2) << c.options << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.options << ": " << r.err;
    EXPECT_FALSE(fs::exists(file("bad.svg"))) << c.options;
  }
  const CommandResult wrong = run_meshstep("render " + log_ + " -o " + file("x.jpg").string(), dir_.path());
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find(".png or .svg"), std::string::npos) << wrong.err;
}

TEST_F(RenderCli, MissingAndForeignInputsAreBadInput) {
  const CommandResult missing = run_meshstep("render " + file("nothing").string(), dir_.path());
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("nothing"), std::string::npos) << missing.err;
  std::FILE* f = std::fopen(file("junk.mslog").c_str(), "w");
  std::fputs("MSTEPLOG but not really a log", f);
  std::fclose(f);
  const CommandResult junk = run_meshstep("render " + file("junk.mslog").string() + " -o " + file("j.svg").string(),
                                          dir_.path());
  EXPECT_EQ(junk.status, 1) << junk.err;
  EXPECT_FALSE(fs::exists(file("j.svg")));
  const CommandResult not_log =
      run_meshstep("export " + lesson() + " --frames " + file("f").string(), dir_.path());
  EXPECT_EQ(not_log.status, 1);
  EXPECT_NE(not_log.err.find("not a replay log"), std::string::npos) << not_log.err;
}

TEST_F(RenderCli, FramesOnePerStepEventOrPhase) {
  if (!gl_available()) GTEST_SKIP() << "no OpenGL on this machine";
  const CommandResult steps =
      run_meshstep("export " + log_ + " --frames " + file("steps").string() + " --size 160x100 --from 30 --to 39 -q",
                   dir_.path());
  ASSERT_EQ(steps.status, 0) << steps.err;
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(file("steps"))) ++count;
  EXPECT_EQ(count, 10u);
  EXPECT_TRUE(fs::exists(file("steps/frame_000000.png")));
  EXPECT_TRUE(fs::exists(file("steps/frame_000009.png")));
  // A run of a .poly has four phases: insertion, recovery, carving, refinement.
  const CommandResult phases =
      run_meshstep("export " + log_ + " --frames " + file("phases").string() + " --every phase --size 160x100 -q",
                   dir_.path());
  ASSERT_EQ(phases.status, 0) << phases.err;
  count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(file("phases"))) ++count;
  EXPECT_EQ(count, 4u);
  const CommandResult outside =
      run_meshstep("export " + log_ + " --frames " + file("out").string() + " --from 5 --to 2", dir_.path());
  EXPECT_EQ(outside.status, 2);
  EXPECT_NE(outside.err.find("--from 5 comes after --to 2"), std::string::npos) << outside.err;
}

TEST_F(RenderCli, VideoHasTheFramesItWasAskedFor) {
  if (!gl_available()) GTEST_SKIP() << "no OpenGL on this machine";
  if (!ffmpeg_works()) GTEST_SKIP() << "ffmpeg and ffprobe (Debian package ffmpeg) missing or not starting";
  const CommandResult r = run_meshstep(
      "export " + log_ + " --video " + file("v.mp4").string() + " --size 161x101 --fps 12 --duration 2.5 -q",
      dir_.path());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string probe = "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
                            "-of csv=p=0 " + file("v.mp4").string() + " > " + file("frames.txt").string();
  ASSERT_EQ(std::system(probe.c_str()), 0);
  EXPECT_EQ(std::stoi(slurp(file("frames.txt"))), 30) << "12 fps x 2.5 s";
  // Nothing but the video is left beside it.
  for (const auto& entry : fs::directory_iterator(dir_.path()))
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
}

TEST_F(RenderCli, FailedVideoLeavesNothingAndNamesThePackage) {
  const CommandResult unknown = run_meshstep("export " + log_ + " --video " + file("v.avi").string(), dir_.path());
  EXPECT_NE(unknown.status, 0);
  EXPECT_NE(unknown.err.find(".mp4, .webm or .gif"), std::string::npos) << unknown.err;
  if (!gl_available()) GTEST_SKIP() << "no OpenGL on this machine";
  const std::string without = "env PATH=/nonexistent " + std::string(MESHSTEP_BINARY) + " export " + log_ +
                              " --video " + file("w.mp4").string() + " 2> " + file("err.txt").string();
  EXPECT_NE(std::system(without.c_str()), 0);
  EXPECT_NE(slurp(file("err.txt")).find("apt-get install ffmpeg"), std::string::npos) << slurp(file("err.txt"));
  for (const auto& entry : fs::directory_iterator(dir_.path()))
    EXPECT_EQ(entry.path().filename().string().find("w.mp4"), std::string::npos) << entry.path();
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Triangle surfaces in 3D: a TIN made by `meshstep terrain`, drawn from an orbit camera.

class RenderSurfaceCli : public ::testing::Test {
 protected:
  void SetUp() override {
    // A 24 x 18 grid with one hill: a TIN of it, written as OBJ.
    const fs::path grid = file("hill.asc");
    {
      std::ofstream out(grid);
      out << "ncols 24\nnrows 18\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n";
      for (int j = 0; j < 18; ++j) {
        for (int i = 0; i < 24; ++i) out << 100.0 + 40.0 * std::exp(-((i - 12) * (i - 12) + (j - 9) * (j - 9)) / 30.0) << ' ';
        out << '\n';
      }
    }
    tin_ = file("tin.obj").string();
    const CommandResult r = run_meshstep("terrain " + grid.string() + " --max-error 0.5 -o " + tin_ + " -q", dir_.path());
    ASSERT_EQ(r.status, 0) << r.err;
  }
  fs::path file(const std::string& name) const { return dir_.path() / name; }

  TempDir dir_;
  std::string tin_;
};

TEST_F(RenderSurfaceCli, TerrainTinToSvgAndPng) {
  const CommandResult svg =
      run_meshstep("render " + tin_ + " --orbit 30,40 --z-scale 2 -o " + file("tin.svg").string(), dir_.path());
  ASSERT_EQ(svg.status, 0) << svg.err;
  EXPECT_NE(svg.out.find("in 3D"), std::string::npos) << svg.out;
  const std::string text = slurp(file("tin.svg"));
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("azimuth 30"), std::string::npos) << "the caption names the camera";
  EXPECT_NE(text.find("height"), std::string::npos) << "the legend's title";

  const CommandResult png =
      run_meshstep("render " + tin_ + " --size 400x300 --color-by height -o " + file("tin.png").string(), dir_.path());
  if (png.status != 0 && png.err.find("OpenGL") != std::string::npos) GTEST_SKIP() << "no OpenGL on this machine";
  ASSERT_EQ(png.status, 0) << png.err;
  const meshstep::scene::Image image = meshstep::scene::read_png(file("tin.png").string());
  EXPECT_EQ(image.width, 400);
  EXPECT_EQ(image.height, 300);
}

TEST_F(RenderSurfaceCli, BadCameraOptionsAreUsageErrors) {
  const struct {
    const char* options;
    const char* says;
  } cases[] = {
      {"--orbit 10", "--orbit"},          {"--orbit 10,95", "-90 to 90"},  {"--orbit 10,-90.5", "-90 to 90"},
      {"--orbit ten,20", "--orbit"},      {"--orbit 10,20,30", "--orbit"}, {"--z-scale 0", "--z-scale"},
      {"--z-scale=-1", "--z-scale"},      {"--z-scale tall", "--z-scale"}, {"--color-by angle", "height"},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_meshstep("render " + tin_ + " " + c.options + " -o " + file("bad.svg").string(), dir_.path());
    EXPECT_EQ(r.status, 2) << c.options << ": " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.options << ": " << r.err;
    EXPECT_FALSE(fs::exists(file("bad.svg"))) << c.options;
  }
  // The camera options need a surface.
  const CommandResult flat = run_meshstep("render " + lesson() + " --orbit 10,20 -o " + file("bad.svg").string(), dir_.path());
  EXPECT_EQ(flat.status, 2) << flat.err;
  EXPECT_NE(flat.err.find("3D surface"), std::string::npos) << flat.err;
  EXPECT_FALSE(fs::exists(file("bad.svg")));
}

namespace {

// The box of the pixels that are not the background (white), left of the legend.
struct PixelBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
PixelBox drawn_box(const meshstep::scene::Image& image, int legend_left) {
  PixelBox b;
  for (int y = 40; y < image.height; ++y)  // below the caption
    for (int x = 0; x < legend_left; ++x) {
      const std::uint8_t* p = image.row(y) + 4 * x;
      if (p[0] > 245 && p[1] > 245 && p[2] > 245) continue;
      b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x), b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
    }
  return b;
}

}  // namespace

// A terrain's run exported in 3D with the camera turning half round: every frame is drawn
// from its own side, and the surface stays in the middle (the camera turns about it). A
// planar run's log has no heights, and --spin needs --orbit: both refused, nothing written.
TEST_F(RenderCli, TerrainRunTurnsIn3D) {
  if (!gl_available()) GTEST_SKIP() << "no OpenGL on this machine";
  const fs::path grid = file("hill.asc");
  {
    std::ofstream out(grid);
    out << "ncols 24\nnrows 18\nxllcorner 0\nyllcorner 0\ncellsize 10\n";
    for (int j = 0; j < 18; ++j) {
      for (int i = 0; i < 24; ++i) out << 20.0 + 15.0 * std::exp(-((i - 12.0) * (i - 12.0) + (j - 9.0) * (j - 9.0)) / 20.0) << ' ';
      out << '\n';
    }
  }
  const std::string log = file("hill.mslog").string();
  ASSERT_EQ(run_meshstep("terrain " + grid.string() + " --max-error 0.5 -q --record " + log, dir_.path()).status, 0);
  const CommandResult spun = run_meshstep("export " + log + " --frames " + file("spun").string() +
                                              " --every 1000 --from 1 --orbit -60,35 --z-scale 3 --spin 180 --size 480x300 -q",
                                          dir_.path());
  ASSERT_EQ(spun.status, 0) << spun.err;
  std::vector<fs::path> frames;
  for (const auto& entry : fs::directory_iterator(file("spun"))) frames.push_back(entry.path());
  std::sort(frames.begin(), frames.end());
  ASSERT_GE(frames.size(), 2u);
  const auto first = meshstep::scene::read_png(frames.front().string());
  const auto last = meshstep::scene::read_png(frames.back().string());
  EXPECT_GT(meshstep::scene::compare_images(first, last, 8).differing_pixels, 1000u);
  // The legend takes the right fifth or so; the surface is centred in what is left of it.
  for (const auto* image : {&first, &last}) {
    const PixelBox b = drawn_box(*image, 360);
    ASSERT_GE(b.x1, b.x0);
    EXPECT_NEAR((b.x0 + b.x1) / 2.0, 190.0, 60.0);
  }

  const CommandResult planar =
      run_meshstep("export " + log_ + " --frames " + file("planar").string() + " --orbit 30,40", dir_.path());
  EXPECT_EQ(planar.status, 2);
  EXPECT_NE(planar.err.find("no heights"), std::string::npos) << planar.err;
  EXPECT_FALSE(fs::exists(file("planar")));
  const CommandResult no_orbit =
      run_meshstep("export " + log + " --frames " + file("no_orbit").string() + " --spin 90", dir_.path());
  EXPECT_EQ(no_orbit.status, 2);
  EXPECT_NE(no_orbit.err.find("--orbit"), std::string::npos) << no_orbit.err;
  EXPECT_FALSE(fs::exists(file("no_orbit")));
}
