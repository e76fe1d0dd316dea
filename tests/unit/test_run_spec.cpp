// The run description: parsing the command line's words and printing them back are each
// other's inverse, over every algorithm and every option of the registry; bad words are
// refused in the command line's terms; refine_options() runs what the words say.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "meshstep/refine/registry.hpp"
#include "meshstep/refine/run_spec.hpp"

namespace meshstep {
namespace {

// A value of the parameter other than its default, for each word it may take.
std::vector<std::string> values_of(const ParameterInfo& p) {
  switch (p.kind) {
    case ParameterKind::flag: return {""};
    case ParameterKind::count: return {"1", "250000"};
    case ParameterKind::number: return {"25", "0.125", "2e-05", "179.5"};
    case ParameterKind::text: return {"0.5", "sizes.asc"};
    case ParameterKind::choice: {
      std::vector<std::string> words;
      for (const std::string& w : choices(p))
        if (w != p.default_text) words.push_back(w);
      return words;
    }
  }
  return {};
}

void expect_round_trip(const std::string& text) {
  SCOPED_TRACE(text);
  const Operation op = parse_operation(text);
  EXPECT_EQ(print_operation(op), text);
  EXPECT_EQ(parse_operation(print_operation(op)), op);
}

TEST(RunSpec, EveryAlgorithmPrintsAsItParses) {
  for (const AlgorithmInfo& a : algorithms()) {
    Operation op;
    op.algorithm = std::string(a.name);
    const std::string text = print_operation(op);
    EXPECT_EQ(parse_operation(text), op) << text;
    if (a.name != kDefaultAlgorithm) expect_round_trip("refine --algorithm " + std::string(a.name));
  }
  expect_round_trip("refine");
}

TEST(RunSpec, EveryOptionPrintsAsItParses) {
  for (const ParameterInfo& p : refine_parameters()) {
    const std::vector<std::string> values = values_of(p);
    ASSERT_FALSE(values.empty()) << p.name;
    for (const std::string& v : values) expect_round_trip("refine --" + std::string(p.name) + (v.empty() ? "" : " " + v));
  }
}

TEST(RunSpec, AllOptionsTogetherInTheRegistrysOrder) {
  std::string text = "refine";
  for (const ParameterInfo& p : refine_parameters()) {
    if (p.name == "keep-free") continue;  // (contradicts delete-free only when run, not when read)
    text += " --" + std::string(p.name);
    if (p.kind != ParameterKind::flag) text += " " + values_of(p).back();
  }
  expect_round_trip(text);
  expect_round_trip("refine --algorithm lepp-centroid --min-angle 25 --max-area 2e-05");
  expect_round_trip("triangulate --insertion cavity --ds dcel --convex-hull");
}

TEST(RunSpec, ReadsTheCommandLinesOtherSpellings) {
  EXPECT_EQ(print_operation(parse_operation("refine -a lepp-midpoint -c --min-angle=30 --max-area 2e-5")),
            "refine --algorithm lepp-midpoint --min-angle 30 --max-area 2e-05 --convex-hull");
  EXPECT_EQ(print_operation(parse_operation("refine --algorithm offcenter --insertion flip")), "refine");
}

std::string refusal(const std::string& text) {
  try {
    parse_operation(text);
  } catch (const RunSpecError& e) {
    return e.what();
  }
  return "(accepted)";
}

// --region and --region-poly are the operation's like the registry's options.
TEST(RunSpec, TheRegionPrintsAsItParses) {
  expect_round_trip("refine --algorithm midpoint-area --max-area 2e-05 --region 0.2,-0.8,0.45,-0.5");
  expect_round_trip("refine --min-angle 25 --region-poly l.poly");
  const Operation op = parse_operation("refine --region=1,2,3.5,4");
  ASSERT_TRUE(op.region && op.region->box);
  EXPECT_EQ(op.region->box->first, (Point{1, 2}));
  EXPECT_EQ(op.region->box->second, (Point{3.5, 4}));
  const std::optional<RefineRegion> region = region_of(op);
  ASSERT_TRUE(region);
  EXPECT_EQ(region->text(), "box:1,2,3.5,4");
  EXPECT_FALSE(region_of(parse_operation("refine --min-angle 20")));
  EXPECT_EQ(refusal("refine --region 3,1,1,3"),
            "--region: the region box 3,1,1,3 is empty: X0 must be below X1 and Y0 below Y1");
  EXPECT_EQ(refusal("refine --region 1,2,3"),
            "--region: a region box is X0,Y0,X1,Y1 (four numbers separated by commas), not '1,2,3'");
  EXPECT_EQ(refusal("refine --region 0,0,1,1 --region-poly l.poly"),
            "more than one of --region, --region-polygon and --region-poly names a region: give one");
  EXPECT_EQ(refusal("triangulate --region 0,0,1,1"), "--region: does not apply to triangulate");
  EXPECT_EQ(refusal("refine --region"), "--region: needs a value");
}

// --region-polygon: the polygon written out in the recipe's line, its vertices as given
// (either way round), checked simple when read.
TEST(RunSpec, AnInlinePolygonPrintsAsItParses) {
  expect_round_trip("refine --max-area 0.05 --region-polygon 0,0,4,0,4,1,1,1,1,4,0,4");
  expect_round_trip("refine --min-angle 25 --region-polygon 0.1,0.30000000000000004,-2e-05,7,3.5,1e+300");
  // Clockwise as given: printed clockwise, and the region the same as counterclockwise.
  const Operation cw = parse_operation("refine --region-polygon=0,0,0,4,4,4,4,0");
  EXPECT_EQ(print_operation(cw), "refine --region-polygon 0,0,0,4,4,4,4,0");
  ASSERT_TRUE(cw.region);
  EXPECT_EQ(cw.region->polygon, (std::vector<Point>{{0, 0}, {0, 4}, {4, 4}, {4, 0}}));
  const std::optional<RefineRegion> region = region_of(cw);
  ASSERT_TRUE(region);
  EXPECT_EQ(region->kind(), RefineRegion::Kind::polygon);
  EXPECT_EQ(region->text(), "polygon:4,0;4,4;0,4;0,0");
  // An L: its notch is outside; its border, exactly, inside.
  const std::optional<RefineRegion> ell = region_of(parse_operation("refine --region-polygon 0,0,4,0,4,1,1,1,1,4,0,4"));
  ASSERT_TRUE(ell);
  EXPECT_TRUE(ell->contains({0.5, 3}));
  EXPECT_TRUE(ell->contains({1, 2.5}));
  EXPECT_FALSE(ell->contains({2, 2}));
  EXPECT_FALSE(ell->contains({std::nextafter(1.0, 2.0), 2}));
}

TEST(RunSpec, AnInlinePolygonThatIsNotSimpleIsRefusedByName) {
  // A bow tie: edges 1 and 3 cross at (1, 1).
  EXPECT_EQ(refusal("refine --region-polygon 0,0,2,2,2,0,0,2"),
            "--region-polygon: a region polygon's edge 1 (0,0 to 2,2) and edge 3 (2,0 to 0,2) touch or cross: "
            "the polygon is not simple");
  // A vertex on another edge (touching, not crossing) is refused; 1e-16 above it, it is not:
  // decided exactly, by orientation, where a tolerance would call both the same.
  EXPECT_EQ(refusal("refine --region-polygon 0,0,4,0,4,4,2,0.0000000000000001,0,4"), "(accepted)");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,4,0,4,4,2,0,0,4"),
            "--region-polygon: a region polygon's edge 1 (0,0 to 4,0) and edge 4 (2,0 to 0,4) touch or cross: "
            "the polygon is not simple");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,1,0,2,0"),
            "--region-polygon: a region polygon's edge 3 (2,0 to 0,0) and edge 1 (0,0 to 1,0) overlap: "
            "the polygon is not simple");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,1,0,1,0,0,1"),
            "--region-polygon: a region polygon's edge 2 (1,0 to 1,0) has length zero");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,1,0"),
            "--region-polygon: a region polygon is X0,Y0,X1,Y1,X2,Y2,... (at least 3 vertices), not '0,0,1,0'");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,1,0,1"),
            "--region-polygon: a region polygon is X0,Y0,X1,Y1,X2,Y2,... (an odd count of numbers: every vertex is "
            "two), not '0,0,1,0,1'");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,1,x,1,1"),
            "--region-polygon: a region polygon is X0,Y0,X1,Y1,X2,Y2,... (numbers separated by commas, two for "
            "each vertex), not '0,0,1,x,1,1'");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,,1,1,1"),
            "--region-polygon: a region polygon is X0,Y0,X1,Y1,X2,Y2,... (numbers separated by commas, two for "
            "each vertex), not '0,0,,1,1,1'");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,1,nan,1,1"),
            "--region-polygon: a region polygon's coordinates must be finite numbers, not 'nan'");
  EXPECT_EQ(refusal("refine --region-polygon 0,0,1,0,1,1 --region 0,0,1,1"),
            "more than one of --region, --region-polygon and --region-poly names a region: give one");
  EXPECT_EQ(refusal("refine --region-polygon"), "--region-polygon: needs a value");
  EXPECT_EQ(refusal("triangulate --region-polygon 0,0,1,0,1,1"), "--region-polygon: does not apply to triangulate");
}

TEST(RunSpec, RefusesWhatTheCommandLineRefuses) {
  EXPECT_EQ(refusal("refine --min-angle -3"), "--min-angle: must be zero or a positive number, not -3");
  EXPECT_EQ(refusal("refine --max-area 0"), "--max-area: must be a positive number, not 0");
  EXPECT_EQ(refusal("refine --max-area many"), "--max-area: 'many' is not a number");
  EXPECT_EQ(refusal("refine --max-triangles 2.5"), "--max-triangles: '2.5' is not a whole number");
  EXPECT_EQ(refusal("refine --select centroid"),
            "--select: 'centroid' is not one of circumcenter, offcenter, lepp-midpoint, lepp-centroid, "
            "longest-edge-midpoint");
  EXPECT_EQ(refusal("refine --min-angle"), "--min-angle: needs a value");
  EXPECT_EQ(refusal("refine --improve=yes"), "--improve: a flag takes no value, not 'yes'");
  EXPECT_EQ(refusal("refine --colour red"), "unknown option --colour");
  EXPECT_EQ(refusal("refine 30"), "'30' is not an option (--NAME expected)");
  EXPECT_EQ(refusal("smooth --min-angle 30"), "unknown operation 'smooth': refine or triangulate expected");
  EXPECT_EQ(refusal("triangulate --min-angle 30"), "--min-angle: does not apply to triangulate");
  EXPECT_EQ(refusal("triangulate --insertion bisection"), "--insertion: 'bisection' is not one of flip, cavity");
}

// --select takes exactly the registry's selections, each by its own name.
TEST(RunSpec, SelectTakesEveryRegisteredSelection) {
  const ParameterInfo* select = find_parameter("select");
  ASSERT_NE(select, nullptr);
  std::vector<std::string> names;
  for (const SelectionInfo& s : selections()) names.emplace_back(s.name);
  EXPECT_EQ(choices(*select), names);
  for (const SelectionInfo& s : selections()) {
    EXPECT_EQ(parse_operation("refine --select " + std::string(s.name)).selection, s.selection);
    EXPECT_EQ(parse_selection(s.name), s.selection);
    EXPECT_EQ(default_encroachment(s.selection), s.encroachment);
  }
}

TEST(RunSpec, RefineOptionsRunWhatTheWordsSay) {
  const RefineOptions midpoint = refine_options(parse_operation("refine --algorithm lepp-midpoint"));
  EXPECT_EQ(midpoint.selection, Selection::lepp_midpoint);
  EXPECT_EQ(midpoint.encroachment, Encroachment::circle);
  EXPECT_EQ(midpoint.criteria.min_angle_deg, 20.7);  // no bound given: the algorithm's default

  const RefineOptions chosen = refine_options(
      parse_operation("refine --select offcenter --encroachment circle --order worst --ds dcel --insertion cavity "
                      "--max-area 0.5 --max-steiner 10"));
  EXPECT_EQ(chosen.selection, Selection::offcenter);
  EXPECT_EQ(chosen.encroachment, Encroachment::circle);
  EXPECT_EQ(chosen.order, RefineOrder::worst_first);
  EXPECT_EQ(chosen.triangulate.data_structure, DataStructure::dcel);
  EXPECT_EQ(insertion_name(chosen), "cavity");
  EXPECT_EQ(chosen.criteria.min_angle_deg, 0.0);  // a bound given: no default
  EXPECT_EQ(chosen.criteria.max_area, 0.5);
  EXPECT_EQ(chosen.criteria.max_steiner, 10u);

  const RefineOptions combined = refine_options(parse_operation("refine --algorithm combined --min-angle 25"));
  ASSERT_EQ(combined.phases.size(), 2u);
  EXPECT_EQ(combined.phases[1].criteria.min_angle_deg, 25.0);

  EXPECT_EQ(insertion_name(refine_options(parse_operation("refine --algorithm lepp-bisection --max-area 1"))),
            "bisection");
  EXPECT_THROW(refine_options(parse_operation("refine --delete-free --keep-free")), RunSpecError);
  EXPECT_THROW(refine_options(parse_operation("refine --insertion bisection --improve --max-area 1")), RunSpecError);
  EXPECT_THROW(refine_options(parse_operation("refine --size grid.asc")), RunSpecError);  // no grid reader
  const RefineOptions sized =
      refine_options(parse_operation("refine --size grid.asc"), [](const Point&) { return 3.0; });
  ASSERT_TRUE(sized.criteria.size);
  EXPECT_EQ(sized.criteria.size({0, 0}), 3.0);
  EXPECT_EQ(size_length(parse_operation("refine --size 0.25")), 0.25);
  EXPECT_FALSE(size_length(parse_operation("refine --size grid.asc")));
  EXPECT_FALSE(size_length(parse_operation("refine")));
}

}  // namespace
}  // namespace meshstep
