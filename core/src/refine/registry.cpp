// The registry's tables (see registry.hpp).
#include "meshstep/refine/registry.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace meshstep {
namespace {

constexpr std::array kAlgorithms = {
    AlgorithmInfo{"circumcenter",
                  "Ruppert/Chew Delaunay refinement: a bad triangle's circumcenter (shortest edge "
                  "first), encroached segments split on concentric shells where segments meet",
                  Selection::circumcenter, 20.7, RefineInsertion::delaunay, 0.0, false, false, 33.0},
    AlgorithmInfo{"offcenter",
                  "the default: Ungor's off-centers, on the shortest edge's bisector only as far "
                  "as the angle bound needs (as Triangle); otherwise as circumcenter",
                  Selection::offcenter, 20.7},
    AlgorithmInfo{"lepp-midpoint",
                  "Rivara's Lepp-Delaunay: follow longest edges from the bad triangle to a terminal "
                  "edge, insert its midpoint, repeat until the triangle is gone",
                  Selection::lepp_midpoint, 20.7, RefineInsertion::delaunay, 0.0, false, false, 33.0},
    AlgorithmInfo{"lepp-centroid",
                  "Lepp-Delaunay inserting the centroid of the two terminal triangles instead "
                  "(the terminal edge's midpoint on the boundary)",
                  Selection::lepp_centroid, 20.7},
    AlgorithmInfo{"lepp-bisection",
                  "Rivara's Lepp longest-edge bisection to an area or size bound (--max-area, --size): "
                  "bisects the terminal triangles until the target is cut; not Delaunay, conforming, "
                  "angles never below half the starting mesh's smallest",
                  Selection::lepp_midpoint, 0.0, RefineInsertion::bisection, 0.0, false, false, 0.0},
    AlgorithmInfo{"midpoint-area",
                  "Delaunay refinement to an area or size bound (--max-area, --size) inserting the "
                  "midpoint of each too-large triangle's longest edge",
                  Selection::longest_edge_midpoint, 0.0, RefineInsertion::delaunay, 0.0, false, false, 0.0},
    AlgorithmInfo{"lepp-aspect",
                  "Lepp-Delaunay (terminal-triangles centroid) to an aspect-ratio bound "
                  "(--max-aspect, default 2.83 = 1/sin 20.7 degrees)",
                  Selection::lepp_centroid, 0.0, RefineInsertion::delaunay, kDefaultMaxAspect},
    AlgorithmInfo{"improve",
                  "improvement + refinement (Coll et al.): Delaunay refinement (circumcenter; --select "
                  "another), then removal of every free Steiner vertex whose removal raises the smallest "
                  "angle round it and keeps the bounds",
                  Selection::circumcenter, 20.7, RefineInsertion::delaunay, 0.0, false, true, 33.0},
    AlgorithmInfo{"combined",
                  "combined criteria: a Lepp-centroid phase to an aspect-ratio bound (--max-aspect, "
                  "default 2.83), then a phase to the minimum angle (--min-angle, default 20.7)",
                  Selection::lepp_centroid, 20.7, RefineInsertion::delaunay, kDefaultMaxAspect, true},
};

// The lens where its theory holds, for points that make the triangle round them no worse
// than the bound (circumcenters, off-centers, Lepp centroids); the circle for midpoints,
// which sit where the lens lets them crowd a segment (Lepp midpoints at 25 degrees on
// p2t_debug2.poly went past 3M Steiner points with the lens, 540k with the circle).
// The selections' pseudo-code: the lines that choose the point, and the program's title
// and papers (the loop round them is scene/pseudocode.cpp's).
constexpr std::string_view kRuppertReferences =
    "J. Ruppert, \"A Delaunay refinement algorithm for quality 2-dimensional mesh generation\", "
    "J. Algorithms 18(3), 1995; L. P. Chew, Cornell TR 89-983, 1989, and SoCG 1993; concentric shells: "
    "J. R. Shewchuk, CGTA 22, 2002";
constexpr std::string_view kLeppDelaunayReferences =
    "M.-C. Rivara, \"New longest-edge algorithms for the refinement and/or improvement of "
    "unstructured triangulations\", IJNME 40, 1997; M.-C. Rivara, N. Hitschfeld, B. Simpson, "
    "\"Terminal-edge Delaunay (small-angle based) algorithm for the quality triangulation "
    "problem\", Computer-Aided Design 33, 2001";

constexpr std::array<std::string_view, 1> kChooseCircumcenter = {"    c ← circumcenter of t"};
constexpr std::array<std::string_view, 3> kChooseOffcenter = {
    "    c ← off-center of t: on the bisector of t's shortest edge pq,",
    "        the apex of the isosceles triangle on pq with the bound's angle",
    "    if t's circumcenter is nearer to pq: c ← the circumcenter"};
constexpr std::array<std::string_view, 1> kChooseTerminalMidpoint = {"        p ← midpoint of e"};
constexpr std::array<std::string_view, 1> kChooseTerminalCentroid = {
    "        p ← centroid of the two terminal triangles (a segment: e's midpoint)"};
constexpr std::array<std::string_view, 1> kChooseLongestMidpoint = {"    c ← midpoint of t's longest edge"};

constexpr std::array kSelections = {
    SelectionInfo{.name = "circumcenter",
                  .description = "the bad triangle's circumcenter",
                  .selection = Selection::circumcenter,
                  .encroachment = Encroachment::lens,
                  .point_name = "circumcenter",
                  .program = {.title = "Delaunay refinement with circumcenters (Ruppert 1995, Chew 1989/1993)",
                              .reference = kRuppertReferences,
                              .choose_point = kChooseCircumcenter}},
    SelectionInfo{.name = "offcenter",
                  .description = "the off-center of the bad triangle's shortest edge (Ungor), or its circumcenter if nearer",
                  .selection = Selection::offcenter,
                  .encroachment = Encroachment::lens,
                  .point_name = "off-center",
                  .program = {.title = "Off-center refinement (Üngör 2004/2009)",
                              .reference = "A. Üngör, \"Off-centers: a new type of Steiner points for computing "
                                           "size-optimal quality-guaranteed Delaunay triangulations\", LATIN 2004; "
                                           "CGTA 42(2), 2009",
                              .choose_point = kChooseOffcenter}},
    SelectionInfo{.name = "lepp-midpoint",
                  .description = "the midpoint of the terminal edge of the bad triangle's longest-edge propagation path",
                  .selection = Selection::lepp_midpoint,
                  .encroachment = Encroachment::circle,
                  .point_name = "terminal-edge midpoint",
                  .program = {.title = "Lepp-Delaunay, terminal-edge midpoint (Rivara 1997/2001)",
                              .reference = kLeppDelaunayReferences,
                              .lepp = true,
                              .choose_point = kChooseTerminalMidpoint}},
    SelectionInfo{.name = "lepp-centroid",
                  .description = "the centroid of the terminal triangles of that path (on the boundary: the edge's midpoint)",
                  .selection = Selection::lepp_centroid,
                  .encroachment = Encroachment::lens,
                  .point_name = "terminal-triangles centroid",
                  .boundary_point_name = "terminal-edge midpoint",
                  .program = {.title = "Lepp-Delaunay, terminal-triangles centroid (Rivara 2010/2020)",
                              .reference = "M.-C. Rivara, C. Calderon, \"Lepp terminal centroid method for quality "
                                           "triangulation\", Computer-Aided Design 42(1), 2010; M.-C. Rivara, "
                                           "P. Rodriguez-Moreno, \"Terminal triangles centroid algorithms for quality "
                                           "Delaunay triangulation\", CAD 125, 2020",
                              .lepp = true,
                              .choose_point = kChooseTerminalCentroid}},
    SelectionInfo{.name = "longest-edge-midpoint",
                  .description = "the midpoint of the bad triangle's longest edge",
                  .selection = Selection::longest_edge_midpoint,
                  .encroachment = Encroachment::circle,
                  .point_name = "longest-edge midpoint",
                  .program = {.title = "Delaunay refinement with longest-edge midpoints",
                              .reference = "Ruppert's loop (J. Ruppert, J. Algorithms 18(3), 1995) inserting the "
                                           "midpoint of the bad triangle's longest edge: for area and size bounds",
                              .choose_point = kChooseLongestMidpoint}},
};

constexpr std::array<std::string_view, 3> kInsertionWords = {"flip", "cavity", "bisection"};
constexpr std::array<std::string_view, 3> kOrderWords = {"smallest", "worst", "fifo"};
constexpr std::array<std::string_view, 2> kEncroachmentWords = {"circle", "lens"};
// SegmentSplits' modes, in its order (the first is the default), and their words.
constexpr std::array kSegmentSplits = {
    PartInfo{"all", "the default: any segment a point encroaches on is split (conforming Delaunay where the "
                    "bounds are met)"},
    PartInfo{"interior", "never a segment on the domain's boundary, holes' included (Triangle's -Y); those "
                         "with triangles on both sides are split as usual"},
    PartInfo{"none", "never any segment (Triangle's -YY): the mesh's segments are the input's"},
};
constexpr std::array<std::string_view, kSegmentSplits.size()> kSegmentSplitsWords = [] {
  std::array<std::string_view, kSegmentSplits.size()> words{};
  for (std::size_t i = 0; i < words.size(); ++i) words[i] = kSegmentSplits[i].name;
  return words;
}();
constexpr std::array<std::string_view, 2> kDataStructureWords = {"tds", "dcel"};

constexpr std::array kParameters = {
    ParameterInfo{"algorithm", "a", ParameterKind::choice, "", "Refinement algorithm", NumberRange::any, false,
                  kDefaultAlgorithm, ChoiceSource::algorithms},
    ParameterInfo{"select", "", ParameterKind::choice, "S", "Override the algorithm's choice of new vertex",
                  NumberRange::any, false, "", ChoiceSource::selections},
    ParameterInfo{"min-angle", "", ParameterKind::number, "DEG",
                  "Every angle at least DEG (below 60; above about 34-36 refinement\n"
                  "may not end: cap it with --max-steiner or --max-triangles)",
                  NumberRange::non_negative, true},
    ParameterInfo{"max-angle", "", ParameterKind::number, "DEG", "Every angle at most DEG (above 60)",
                  NumberRange::positive, true},
    ParameterInfo{"max-aspect", "", ParameterKind::number, "R",
                  "Longest edge / shortest altitude at most R (equilateral: 1.1547)", NumberRange::positive, true},
    ParameterInfo{"max-area", "", ParameterKind::number, "A", "Every triangle's area at most A", NumberRange::positive,
                  true},
    ParameterInfo{"size", "", ParameterKind::text, "VALUE|GRID.asc",
                  "Every edge at most VALUE long: a positive number, or an ESRI ASCII\n"
                  "grid (.asc) whose cell under a triangle's centroid bounds its longest\n"
                  "edge (no bound outside the grid, on no-data cells, at values <= 0)",
                  NumberRange::positive, true},
    ParameterInfo{"flip-dihedral", "", ParameterKind::number, "DEG",
                  "3D surfaces: afterwards, flip every edge whose flip raises the smallest angle of its\n"
                  "two triangles, where their normals differ by at most DEG degrees (0: coplanar pairs\n"
                  "only, which leaves the surface and its area as they are)",
                  NumberRange::degrees},
    ParameterInfo{"max-triangles", "", ParameterKind::count, "N", "Stop once the mesh has N triangles",
                  NumberRange::positive},
    ParameterInfo{"max-steiner", "", ParameterKind::count, "N",
                  "Stop after inserting N Steiner vertices (default: none; for longest-edge\n"
                  "midpoints against an angle or aspect bound, which need not end: 100000\n"
                  "+ 100 per input vertex)",
                  NumberRange::positive},
    ParameterInfo{"insertion", "", ParameterKind::choice, "",
                  "Point insertion: flip (Lawson) or cavity (Bowyer-Watson), or bisection (Lepp\n"
                  "longest-edge bisection, not Delaunay; --max-area or --size only)",
                  NumberRange::any, false, "flip", ChoiceSource::own, kInsertionWords},
    ParameterInfo{"order", "", ParameterKind::choice, "",
                  "Which bad triangle next: smallest (shortest edge first, as Triangle; keeps\n"
                  "the mesh graded at high bounds), worst (smallest angle first) or fifo",
                  NumberRange::any, false, "smallest", ChoiceSource::own, kOrderWords},
    ParameterInfo{"encroachment", "", ParameterKind::choice, "",
                  "Points that encroach on a segment: those in its diametral circle, or only\n"
                  "those in its diametral lens, seeing it at 180 - 2 x the angle bound degrees or\n"
                  "more (as Triangle; fewer splits). Default: lens, but circle for midpoint\n"
                  "selections (lepp-midpoint, midpoint-area), which crowd segments under a lens",
                  NumberRange::any, false, "", ChoiceSource::own, kEncroachmentWords},
    ParameterInfo{"split-segments", "", ParameterKind::choice, "",
                  "Which segments refinement may split: all; interior (never one on the domain's\n"
                  "boundary, holes' included: Triangle's -Y); none (Triangle's -YY). Kept segments\n"
                  "stay as the input has them, the mesh is constrained Delaunay, and a triangle\n"
                  "whose point would encroach on one is left as it is: bounds may be missed there\n"
                  "(counted in kept_segment_refusals). Not with bisection",
                  NumberRange::any, false, "all", ChoiceSource::own, kSegmentSplitsWords},
    ParameterInfo{"ds", "", ParameterKind::choice, "", "Mesh data structure: tds (triangle-based) or dcel (half-edge)",
                  NumberRange::any, false, "tds", ChoiceSource::own, kDataStructureWords},
    ParameterInfo{"convex-hull", "c", ParameterKind::flag, "",
                  "Mesh the whole convex hull (minus holes), not only what segments enclose"},
    ParameterInfo{"improve", "", ParameterKind::flag, "",
                  "After refining, remove every free Steiner vertex whose removal raises the\n"
                  "smallest angle round it and keeps the bounds (what --algorithm improve does)"},
    ParameterInfo{"delete-free", "", ParameterKind::flag, "",
                  "Before a segment is split away from corners, remove the free Steiner vertices\n"
                  "that face it from inside its diametral circle (Chew's rule, as Triangle;\n"
                  "counted in removed_vertices), even under an area or size bound. The default\n"
                  "does it only without such a bound, which would put them back"},
    ParameterInfo{"keep-free", "", ParameterKind::flag, "",
                  "Never remove free Steiner vertices near a split segment (the rule before 2026-12-03)"},
};

constexpr std::array kInsertions = {
    PartInfo{"flip", "Lawson: split the face or edge, then flip edges until Delaunay"},
    PartInfo{"cavity", "Bowyer-Watson: remove the faces whose circumcircle holds the point, fan the hole"},
    PartInfo{"bisection", "Lepp longest-edge bisection: split the terminal edge at its midpoint, not Delaunay (size criteria only)"},
};


constexpr std::array kDataStructures = {
    PartInfo{"tds", "triangle-based: three vertices and three neighbours per face"},
    PartInfo{"dcel", "half-edge: twin, next and origin per half-edge"},
};


}  // namespace

std::span<const AlgorithmInfo> algorithms() { return kAlgorithms; }

const AlgorithmInfo* find_algorithm(std::string_view name) {
  for (const AlgorithmInfo& a : kAlgorithms)
    if (a.name == name) return &a;
  return nullptr;
}

std::span<const SelectionInfo> selections() { return kSelections; }

const SelectionInfo* find_selection(std::string_view name) {
  for (const SelectionInfo& s : kSelections)
    if (s.name == name) return &s;
  return nullptr;
}

const SelectionInfo& selection_info(Selection selection) {
  for (const SelectionInfo& s : kSelections)
    if (s.selection == selection) return s;
  throw std::logic_error("a selection without a record in the registry");
}

Encroachment default_encroachment(Selection selection) { return selection_info(selection).encroachment; }

std::span<const ParameterInfo> refine_parameters() { return kParameters; }

const ParameterInfo* find_parameter(std::string_view name) {
  for (const ParameterInfo& p : kParameters)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<std::string> choices(const ParameterInfo& parameter) {
  std::vector<std::string> words;
  if (parameter.choice_source == ChoiceSource::algorithms)
    for (const AlgorithmInfo& a : kAlgorithms) words.emplace_back(a.name);
  else if (parameter.choice_source == ChoiceSource::selections)
    for (const SelectionInfo& s : kSelections) words.emplace_back(s.name);
  else
    for (const std::string_view w : parameter.own_choices) words.emplace_back(w);
  return words;
}

std::string range_problem(const ParameterInfo& parameter, std::string_view text) {
  const bool numeric = parameter.kind == ParameterKind::number || parameter.kind == ParameterKind::count ||
                       parameter.kind == ParameterKind::text;
  if (!numeric || parameter.range == NumberRange::any) return {};
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size()) return {};
  const bool zero_allowed = parameter.range == NumberRange::non_negative || parameter.range == NumberRange::degrees;
  if (std::isfinite(value) && (value > 0.0 || (zero_allowed && value == 0.0)) &&
      (parameter.range != NumberRange::degrees || value <= 180.0))
    return {};
  if (parameter.range == NumberRange::degrees) return "must be between 0 and 180 degrees, not " + std::string(text);
  return std::string(zero_allowed ? "must be zero or a positive number" : "must be a positive number") + ", not " +
         std::string(text);
}
std::span<const PartInfo> insertions() { return kInsertions; }
std::span<const PartInfo> segment_splits_modes() { return kSegmentSplits; }
std::span<const PartInfo> data_structures() { return kDataStructures; }

std::optional<Selection> parse_selection(std::string_view name) {
  if (const SelectionInfo* s = find_selection(name)) return s->selection;
  return std::nullopt;
}

RefineOptions options_for(const AlgorithmInfo& algorithm) {
  RefineOptions o;
  o.algorithm = std::string(algorithm.name);
  o.selection = algorithm.selection;
  o.encroachment = default_encroachment(algorithm.selection);
  o.insertion = algorithm.insertion;
  o.improve = algorithm.improve;
  return o;
}

std::vector<RefinePhase> aspect_then_angle_phases(const RefineCriteria& criteria, const AlgorithmInfo& algorithm) {
  RefinePhase aspect{"aspect", criteria};
  aspect.criteria.min_angle_deg = 0.0;
  if (aspect.criteria.max_aspect <= 0.0) aspect.criteria.max_aspect = kDefaultMaxAspect;
  RefinePhase angle{"min-angle", criteria};
  angle.criteria.max_aspect = 0.0;
  if (angle.criteria.min_angle_deg <= 0.0) angle.criteria.min_angle_deg = algorithm.default_min_angle_deg;
  return {aspect, angle};
}

}  // namespace meshstep
