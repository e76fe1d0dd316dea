// The registry's tables (see registry.hpp).
#include "meshstep/refine/registry.hpp"

#include <array>
#include <string>

namespace meshstep {
namespace {

constexpr std::array kAlgorithms = {
    AlgorithmInfo{"circumcenter",
                  "Ruppert/Chew Delaunay refinement: the worst triangle's circumcenter, encroached "
                  "segments split on concentric shells",
                  Selection::circumcenter, 20.7},
    AlgorithmInfo{"offcenter",
                  "Ungor's off-centers: on the shortest edge's bisector, only as far as the angle "
                  "bound needs; otherwise as circumcenter",
                  Selection::offcenter, 20.7},
    AlgorithmInfo{"lepp-midpoint",
                  "Rivara's Lepp-Delaunay: follow longest edges from the bad triangle to a terminal "
                  "edge, insert its midpoint, repeat until the triangle is gone",
                  Selection::lepp_midpoint, 20.7},
    AlgorithmInfo{"lepp-centroid",
                  "Lepp-Delaunay inserting the centroid of the two terminal triangles instead "
                  "(the terminal edge's midpoint on the boundary)",
                  Selection::lepp_centroid, 20.7},
};

constexpr std::array kSelections = {
    PartInfo{"circumcenter", "the bad triangle's circumcenter"},
    PartInfo{"offcenter", "the off-center of the bad triangle's shortest edge (Ungor), or its circumcenter if nearer"},
    PartInfo{"lepp-midpoint", "the midpoint of the terminal edge of the bad triangle's longest-edge propagation path"},
    PartInfo{"lepp-centroid", "the centroid of the terminal triangles of that path (on the boundary: the edge's midpoint)"},
};

constexpr std::array kInsertions = {
    PartInfo{"flip", "Lawson: split the face or edge, then flip edges until Delaunay"},
    PartInfo{"cavity", "Bowyer-Watson: remove the faces whose circumcircle holds the point, fan the hole"},
};

constexpr std::array kCriteria = {
    PartInfo{"min-angle", "--min-angle DEG: every angle at least DEG (below 60)"},
    PartInfo{"max-angle", "--max-angle DEG: every angle at most DEG (above 60)"},
    PartInfo{"max-aspect", "--max-aspect R: longest edge / shortest altitude at most R (equilateral: 1.1547)"},
    PartInfo{"max-area", "--max-area A: every triangle's area at most A"},
    PartInfo{"size", "--size VALUE: every edge at most VALUE long"},
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
    PartInfo{".ele", "Triangle's triangles (output; with .node, a mesh to check)"},
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
  return std::nullopt;
}

RefineOptions options_for(const AlgorithmInfo& algorithm) {
  RefineOptions o;
  o.algorithm = std::string(algorithm.name);
  o.selection = algorithm.selection;
  return o;
}

}  // namespace meshstep
