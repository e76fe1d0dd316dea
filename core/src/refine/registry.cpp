// The registry's tables (see registry.hpp).
#include "meshstep/refine/registry.hpp"

#include <array>
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

constexpr std::array kSelections = {
    PartInfo{"circumcenter", "the bad triangle's circumcenter"},
    PartInfo{"offcenter", "the off-center of the bad triangle's shortest edge (Ungor), or its circumcenter if nearer"},
    PartInfo{"lepp-midpoint", "the midpoint of the terminal edge of the bad triangle's longest-edge propagation path"},
    PartInfo{"lepp-centroid", "the centroid of the terminal triangles of that path (on the boundary: the edge's midpoint)"},
    PartInfo{"longest-edge-midpoint", "the midpoint of the bad triangle's longest edge"},
};

constexpr std::array kInsertions = {
    PartInfo{"flip", "Lawson: split the face or edge, then flip edges until Delaunay"},
    PartInfo{"cavity", "Bowyer-Watson: remove the faces whose circumcircle holds the point, fan the hole"},
    PartInfo{"bisection", "Lepp longest-edge bisection: split the terminal edge at its midpoint, not Delaunay (size criteria only)"},
};

constexpr std::array kCriteria = {
    PartInfo{"min-angle", "--min-angle DEG: every angle at least DEG (below 60)"},
    PartInfo{"max-angle", "--max-angle DEG: every angle at most DEG (above 60)"},
    PartInfo{"max-aspect", "--max-aspect R: longest edge / shortest altitude at most R (equilateral: 1.1547)"},
    PartInfo{"max-area", "--max-area A: every triangle's area at most A"},
    PartInfo{"size", "--size VALUE|GRID.asc: every edge at most VALUE long, or the value of an ESRI ASCII grid's cell under the triangle's centroid"},
    PartInfo{"max-triangles", "--max-triangles N: stop once the mesh has N triangles"},
    PartInfo{"max-steiner", "--max-steiner N: stop after inserting N vertices"},
};

constexpr std::array kDataStructures = {
    PartInfo{"tds", "triangle-based: three vertices and three neighbours per face"},
    PartInfo{"dcel", "half-edge: twin, next and origin per half-edge"},
};

constexpr std::array kFileFormats = {
    PartInfo{".node", "Triangle's vertices (input: a point set; output)"},
    PartInfo{".poly", "Triangle's PSLG: vertices, segments, holes, regions (input; output)"},
    PartInfo{".ele", "Triangle's triangles (output; with .node, a mesh to check or to refine again)"},
    PartInfo{".area", "Triangle's per-triangle maximum areas (input with a mesh to refine again; output)"},
    PartInfo{".asc", "ESRI ASCII grid (input: refine --size GRID.asc; terrain heights, NODATA kept out)"},
    PartInfo{".png", "8/16-bit greyscale heightmap (input: terrain); also pictures (render, export)"},
    PartInfo{".obj / .off / .ply / .stl", "3D triangle surfaces (output: terrain; PLY and STL ASCII or binary)"},
    PartInfo{".edge / .neigh", "Triangle's edges and neighbours (output, -e / -n)"},
    PartInfo{".mslog", "meshstep replay log (--record; read by meshstep log)"},
};

}  // namespace

std::span<const AlgorithmInfo> algorithms() { return kAlgorithms; }

const AlgorithmInfo* find_algorithm(std::string_view name) {
  for (const AlgorithmInfo& a : kAlgorithms)
    if (a.name == name) return &a;
  return nullptr;
}

std::span<const PartInfo> selections() { return kSelections; }
std::span<const PartInfo> insertions() { return kInsertions; }
std::span<const PartInfo> criteria() { return kCriteria; }
std::span<const PartInfo> data_structures() { return kDataStructures; }
std::span<const PartInfo> file_formats() { return kFileFormats; }

std::optional<Selection> parse_selection(std::string_view name) {
  if (name == "circumcenter") return Selection::circumcenter;
  if (name == "offcenter") return Selection::offcenter;
  if (name == "lepp-midpoint") return Selection::lepp_midpoint;
  if (name == "lepp-centroid") return Selection::lepp_centroid;
  if (name == "longest-edge-midpoint") return Selection::longest_edge_midpoint;
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
