// Terrain approximation: a triangulated irregular network (TIN) whose vertices are samples
// of a height grid, within a vertical error of every sample.
//
// The planar triangulation is Delaunay in metres (so its angles mean something on a grid
// with unequal cell sides). Every triangle knows the largest vertical error among the
// samples it covers, measured exactly (triangle_scan.hpp): the error of a sample is
// |z - z of the plane through the triangle's three corners| at that sample. An algorithm
// picks the next sample to insert; the triangles that insertion changes are measured
// again, and nothing else is.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/terrain/height_grid.hpp"

namespace meshstep::terrain {

enum class TerrainAlgorithm : std::uint8_t {
  // Coll, Guerrieri, Rivara, Sellares (IMR 2008): the worst triangle's longest-edge
  // propagating path, and the sample nearest the terminal point.
  lepp_surface,
  // Garland and Heckbert's greedy insertion: the sample of largest error.
  greedy,
};

// Where Lepp-surface puts the next point on a terminal edge.
enum class TerminalPoint : std::uint8_t {
  centroid,  // of the terminal triangles (one at the border, two elsewhere)
  midpoint,  // of the terminal edge
};

struct TerrainOptions {
  TerrainAlgorithm algorithm = TerrainAlgorithm::lepp_surface;
  TerminalPoint terminal_point = TerminalPoint::centroid;
  double max_error = 0.0;          // in height units; refine until every sample is within it
  std::size_t max_triangles = 0;   // stop at this many triangles (0: no cap)
  DataStructure data_structure = DataStructure::tds;
  // After the refinement, remove every vertex (not on the border) whose removal keeps every
  // sample within the bound and does not lower the smallest 3D angle of the triangles round
  // it: the improvement step of improvement + refinement (the framework's `improve`, after
  // Coll et al. 2008), here judged by the error as well as the angles. The TIN stays
  // Delaunay in the plane. The CLI does it for lepp-surface unless told not to.
  bool improve = false;
  // At the end, flip every edge whose flip raises the smallest 3D angle of its two
  // triangles and keeps them within the bound (the seed's FlipDelaunay3DSurface).
  bool flips_3d = false;
  // Called now and then (about every 2^16 insertions) with the triangles so far and the
  // current largest error, for progress lines.
  std::function<void(std::size_t triangles, double worst_error)> progress = nullptr;
  // Record every step into this replay log (replay/log_writer.hpp), heights included
  // (elevation events); null: not recorded.
  replay::EventSink* record = nullptr;
};

struct TerrainReport {
  std::size_t vertices = 0, triangles = 0;
  std::size_t insertions = 0;             // samples inserted after the four corners
  // lepp-surface: samples inserted as a terminal triangle's worst, and nearest a terminal
  // point (the rest were the worst triangle's own worst, when the terminal point's sample
  // was taken or had no data).
  std::size_t terminal_worst = 0, terminal_points = 0;
  double worst_error = 0.0;               // the largest error left, by the algorithm's measure
  std::size_t removed = 0;                // vertices removed by the improvement
  std::size_t flips_3d = 0;               // edges flipped for their 3D angles
  bool capped = false;                    // stopped at max_triangles with the bound unmet
  double seconds = 0.0;
};

// A TIN over a grid: its vertices are samples, its triangles counter-clockwise.
struct Tin {
  std::vector<std::uint32_t> samples;                  // i + j * nx, by vertex
  std::vector<float> heights;                          // by vertex: the sample's (a corner
                                                       // without data: its nearest sample's)
  std::vector<std::array<std::uint32_t, 3>> triangles;  // vertex indices
};

// Throws InputError for a grid smaller than 2 x 2 or a negative bound.
Tin approximate(const HeightGrid& grid, const TerrainOptions& options, TerrainReport* report = nullptr);

// The vertices a TIN must have on its grid's rectangle, and only those: a tile's border,
// chosen from the border samples alone so that the neighbouring tile, which shares them,
// chooses the same (terrain/tiles.hpp). The four corners come first, in the order (0, 0),
// (nx - 1, 0), (nx - 1, ny - 1), (0, ny - 1); the others follow in any order. Heights are
// by vertex, as in Tin (a corner without data needs one all the same).
struct BorderVertices {
  std::vector<std::uint32_t> samples;  // i + j * nx, each on the rectangle
  std::vector<float> heights;
};

// As approximate(), but the TIN starts from `border` and no other sample on the rectangle
// is ever inserted: its border edges are exactly the segments between consecutive border
// vertices (they are on the convex hull, which Delaunay insertion inside never changes).
// The samples on the rectangle are the border's business and are not searched: each lies
// on one border edge, where every triangle's plane is the chord between the edge's ends,
// so the caller must have chosen the border vertices within the bound along it.
// Lepp-surface's sample nearest a terminal point, when on the rectangle, gives way to the
// worst triangle's own worst sample. Throws InputError when `border` breaks its rules.
Tin approximate_within_border(const HeightGrid& grid, const BorderVertices& border, const TerrainOptions& options,
                              TerrainReport* report = nullptr);

// The vertical error over every sample with data, measured here independently of the
// algorithm's own bookkeeping, each sample once.
struct ErrorMeasure {
  double max = 0.0;
  double rms = 0.0;
  std::size_t samples = 0;      // with data
  std::size_t uncovered = 0;    // with data but in no triangle (0 for a valid TIN)
};
ErrorMeasure measure_error(const HeightGrid& grid, const Tin& tin);

// Angles of the triangles in 3D (x, y in metres, z in height units).
struct AngleStats {
  double smallest_deg = 0.0;
  std::array<std::size_t, 18> histogram{};  // by 10 degrees: [0, 10), [10, 20), ... [170, 180]
  double share_under_10 = 0.0, share_under_20 = 0.0, share_under_30 = 0.0;  // of triangles
};
AngleStats angle_stats_3d(const HeightGrid& grid, const Tin& tin);

// Vertex v of the TIN in metres, with its height.
std::array<double, 3> vertex_position(const HeightGrid& grid, const Tin& tin, std::uint32_t v);

struct TerrainAlgorithmInfo {
  std::string_view name;
  std::string_view description;
  TerrainAlgorithm algorithm;
};
std::span<const TerrainAlgorithmInfo> terrain_algorithms();
const TerrainAlgorithmInfo* find_terrain_algorithm(std::string_view name);

}  // namespace meshstep::terrain
