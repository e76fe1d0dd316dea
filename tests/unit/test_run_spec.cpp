// The run description: parsing the command line's words and printing them back are each
// other's inverse, over every algorithm and every option of the registry; bad words are
// refused in the command line's terms; refine_options() runs what the words say.
#include <gtest/gtest.h>

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
            "--region and --region-poly both name a region: give one");
  EXPECT_EQ(refusal("triangulate --region 0,0,1,1"), "--region: does not apply to triangulate");
  EXPECT_EQ(refusal("refine --region"), "--region: needs a value");
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
