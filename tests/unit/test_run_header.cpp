// The log header's run description: what each kind of run writes, read_run_header reads
// back typed, and a log whose vertex count is no number is refused when it opens (it was
// read as the digits it starts with, or as 0).
#include <gtest/gtest.h>

#include <string>

#include "meshstep/error.hpp"
#include "meshstep/refine/run_spec.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/run_header.hpp"
#include "temp_dir.hpp"

namespace meshstep {
namespace {

replay::RunHeader read_back(const std::string& parameters) {
  replay::LogHeader h;
  h.insertion = "flip";
  h.parameters = parameters;
  return replay::read_run_header(h, "run.mslog");
}

TEST(RunHeader, ARefinementReadsBackAsItWasRun) {
  const RefineOptions o = refine_options(parse_operation(
      "refine --algorithm lepp-midpoint --min-angle 25 --max-area 2e-05 --insertion cavity --max-steiner 7"));
  const replay::RunHeader run = read_back(replay::refine_parameters(o, "", 12, 1));
  EXPECT_EQ(run.input_vertices, 12u);
  EXPECT_EQ(run.first_index, 1);
  EXPECT_EQ(run.selection, Selection::lepp_midpoint);
  EXPECT_EQ(run.insertion, "cavity");
  EXPECT_EQ(run.encroachment, Encroachment::circle);
  EXPECT_EQ(run.min_angle, 25.0);
  EXPECT_EQ(run.max_area, 2e-05);
  EXPECT_EQ(run.lens_angle, lens_angle_deg(o.criteria));
  EXPECT_FALSE(run.size);  // "size=0": none

  const RefineOptions sized = refine_options(parse_operation("refine --size 0.25"));
  EXPECT_EQ(read_back(replay::refine_parameters(sized, "0.25", 3, 0)).size, 0.25);
  const RefineOptions grid = refine_options(parse_operation("refine --size g.asc"), [](const Point&) { return 1.0; });
  EXPECT_FALSE(read_back(replay::refine_parameters(grid, "g.asc", 3, 0)).size);  // a grid's name: no number
}

// The region= field (RefineRegion::text()) reads back as the region the run was limited to.
TEST(RunHeader, TheRegionReadsBack) {
  const RefineRegion box = RefineRegion::box({0.2, -0.8}, {0.45, -0.5});
  const replay::RunHeader boxed = read_back("input_vertices=3 region=" + box.text());
  ASSERT_TRUE(boxed.region);
  EXPECT_EQ(boxed.region->text(), box.text());
  EXPECT_EQ(boxed.region->kind(), RefineRegion::Kind::box);
  const RefineRegion l = RefineRegion::polygon({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  const replay::RunHeader ell = read_back("region=" + l.text());
  ASSERT_TRUE(ell.region);
  EXPECT_EQ(ell.region->vertices(), l.vertices());
  EXPECT_TRUE(ell.region->contains({0.5, 1.5}));
  EXPECT_FALSE(ell.region->contains({1.5, 1.5}));
  EXPECT_FALSE(read_back("input_vertices=3").region);
  EXPECT_THROW(read_back("region=disc:0,0,1"), InputError);
  EXPECT_THROW(read_back("region=polygon:0,0;1,x;0,1"), InputError);
}

TEST(RunHeader, TriangulationsAndSurfacesReadBack) {
  const replay::RunHeader t = read_back(replay::triangulate_parameters(true, 40, 1));
  EXPECT_EQ(t.input_vertices, 40u);
  EXPECT_EQ(t.first_index, 1);
  EXPECT_EQ(t.insertion, "flip");  // the header's own, without a parameter
  EXPECT_FALSE(t.selection);
  const replay::RunHeader s = read_back(replay::surface_parameters(0.5, 0.0, 8, 100, -1.0));
  EXPECT_EQ(s.input_vertices, 8u);
  EXPECT_EQ(s.insertion, "bisection");
  EXPECT_EQ(s.size, 0.5);
}

// Logs written before the header was typed (hand-made headers in older tests, terrain runs)
// read as they did: missing keys are defaults.
TEST(RunHeader, MissingKeysAreDefaults) {
  const replay::RunHeader run = read_back("max_error=0.5 input_vertices=4");
  EXPECT_EQ(run.input_vertices, 4u);
  EXPECT_EQ(run.first_index, 0);
  EXPECT_EQ(run.max_error, 0.5);
  EXPECT_FALSE(run.min_angle);
  EXPECT_FALSE(run.encroachment);
}

TEST(RunHeader, AVertexCountThatIsNoNumberIsRefusedWhenTheLogOpens) {
  testing::TempDir dir;
  const std::string path = dir.file("bad.mslog");
  replay::LogHeader h;
  h.input = "generated";
  h.input_hash = "0000000000000000";
  h.algorithm = "triangulate";
  h.parameters = "input_vertices=3x first_index=0";
  h.data_structure = "tds";
  h.insertion = "flip";
  {
    replay::LogWriter writer(path, h);
    writer.finish();
  }
  try {
    replay::LogReader log(path);
    FAIL() << "opened";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the header's parameter input_vertices=3x is not a number"), std::string::npos)
        << e.what();
  }
}


// A refinement's header read back as the recipe to run again (the workbench re-runs a log's
// input with it): written again, it gives the header it came from, kept segments, order,
// caps, data structure and convex hull included (the workbench once dropped the kept
// segments and the caps), and the region too.
TEST(RunHeader, ARefinementsHeaderIsTheRecipeToRunItAgain) {
  for (const char* line :
       {"refine --algorithm offcenter --min-angle 30 --split-segments interior --order worst --max-steiner 50 --ds dcel "
        "--insertion cavity",
        "refine --algorithm lepp-bisection --max-area 0.001 --max-triangles 900 -c --region 0.25,0.5,1,2",
        "refine --algorithm lepp-centroid --size 0.125 --split-segments none --order fifo --encroachment circle"}) {
    SCOPED_TRACE(line);
    const Operation op = parse_operation(line);
    const RefineOptions options = refine_options(op);
    replay::LogHeader h;
    h.algorithm = op.algorithm;
    h.data_structure = to_string(op.data_structure);
    h.insertion = to_string(options.triangulate.insertion);
    h.parameters = replay::refine_parameters(options, op.size.value_or(""), 12, 1);
    if (const auto region = region_of(op)) h.parameters += " region=" + region->text();
    const std::vector<Operation> recipe = replay::recorded_recipe(h, replay::read_run_header(h, "run.mslog"));
    ASSERT_EQ(recipe.size(), 1u);
    const Operation& again = recipe.front();
    EXPECT_EQ(again.algorithm, op.algorithm);
    EXPECT_EQ(again.data_structure, op.data_structure);
    EXPECT_EQ(again.region, op.region);
    EXPECT_EQ(replay::refine_parameters(refine_options(again), again.size.value_or(""), 12, 1),
              replay::refine_parameters(options, op.size.value_or(""), 12, 1));
  }
  replay::LogHeader triangulation;
  triangulation.algorithm = "triangulate";
  triangulation.parameters = replay::triangulate_parameters(false, 3, 0);
  EXPECT_TRUE(replay::recorded_recipe(triangulation, replay::read_run_header(triangulation, "t.mslog")).empty());
}

}  // namespace
}  // namespace meshstep
