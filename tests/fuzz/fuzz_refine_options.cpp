// Refinement under random options: the first kOptionBytes bytes choose them (an algorithm
// of the registry, the data structure, the insertion, the order, the encroachment rule,
// improvement and free-vertex deletion, a minimum angle anywhere in the accepted range,
// a maximum angle, an area and a size bound scaled to the input), the rest is a small
// .poly. Every run is capped at a few Steiner vertices so that any bound ends quickly.
// A refusal (InputError) is an answer; an internal error or a mesh that check_mesh
// rejects is a finding.
#include <algorithm>
#include <cmath>

#include "fuzz_support.hpp"
#include "meshstep/check/mesh_check.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/refine/refine.hpp"
#include "meshstep/refine/registry.hpp"

using namespace meshstep;

namespace {

constexpr std::size_t kOptionBytes = 8;

// The input's bounding box, to scale the area and size bounds to it (a fixed bound would
// mean one triangle or a million, depending on the input's units).
struct Extent {
  double width = 0.0, height = 0.0;
};

Extent extent_of(const Pslg& input) {
  if (input.points.empty()) return {};
  double x0 = input.points[0].x, x1 = x0, y0 = input.points[0].y, y1 = y0;
  for (const Point& p : input.points) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  return {x1 - x0, y1 - y0};
}

// The options that `bytes` (kOptionBytes of them) choose, for `input`.
RefineOptions options_from(const std::uint8_t* bytes, const Pslg& input) {
  const auto registry = algorithms();
  const AlgorithmInfo& algorithm = registry[bytes[0] % registry.size()];
  RefineOptions o = options_for(algorithm);
  const std::uint8_t flags = bytes[1];
  o.triangulate.data_structure = flags & 1 ? DataStructure::dcel : DataStructure::tds;
  o.triangulate.insertion = flags & 2 ? Insertion::cavity : Insertion::flip;
  o.triangulate.convex_hull = (flags & 4) != 0;
  if (flags & 8) o.insertion = RefineInsertion::bisection;
  // Improvement removes vertices from a Delaunay mesh: the command line refuses it with
  // bisection, and so does this harness.
  o.improve = o.insertion == RefineInsertion::delaunay && (o.improve || (flags & 16) != 0);
  switch ((flags >> 5) % 3) {
    case 0: o.encroachment = default_encroachment(o.selection); break;
    case 1: o.encroachment = Encroachment::circle; break;
    default: o.encroachment = Encroachment::lens; break;
  }
  const std::uint8_t order = bytes[2];
  o.order = order % 3 == 0 ? RefineOrder::smallest_first : order % 3 == 1 ? RefineOrder::worst_first : RefineOrder::fifo;
  o.delete_free = (order / 3) % 3 == 0   ? FreeVertexDeletion::unless_sized
                  : (order / 3) % 3 == 1 ? FreeVertexDeletion::always
                                         : FreeVertexDeletion::never;
  if (o.insertion == RefineInsertion::bisection) o.delete_free = FreeVertexDeletion::unless_sized;

  RefineCriteria& c = o.criteria;
  // 0 to just below 60 degrees, the accepted range: past about 34 refinement need not end,
  // which the cap below answers.
  c.min_angle_deg = bytes[3] * (59.9 / 255.0);
  c.max_angle_deg = bytes[4] < 128 ? 180.0 : 60.5 + (bytes[4] - 128) * (119.5 / 127.0);
  const Extent e = extent_of(input);
  const std::uint8_t bounds = bytes[5];
  if (bounds & 0x0f) c.max_area = e.width * e.height / std::ldexp(1.0, bounds & 0x0f);
  if (bounds & 0xf0) {
    const double size = std::hypot(e.width, e.height) / (bounds >> 4);
    if (size > 0.0 && std::isfinite(size)) c.size = [size](const Point&) { return size; };
  }
  if (!(c.max_area > 0.0) || !std::isfinite(c.max_area)) c.max_area = 0.0;
  c.max_steiner = 1 + bytes[6] % 96;  // small, for speed: every bound ends
  if (bytes[7] & 1) c.max_triangles = 4 + bytes[7];
  if (algorithm.aspect_then_angle) o.phases = aspect_then_angle_phases(c, algorithm);
  return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < kOptionBytes) return 0;
  const std::uint8_t* option_bytes = data;
  data += kOptionBytes, size -= kOptionBytes;
  Pslg input;
  try {
    input = io::read_poly(fuzz::write_input(data, size, ".poly"));
  } catch (const InputError&) {
    return 0;
  }
  if (input.points.size() > 200 || input.segments.size() > 200) return 0;  // keep each run short
  fuzz::refusals_allowed([&] {
    const RefineOptions options = options_from(option_bytes, input);
    RefineReport report;
    const TriMesh mesh = refine(input, options, &report);
    // Longest-edge bisection makes a conforming mesh, not a Delaunay one (docs/refinement.md):
    // checking it for the Delaunay property reported a bisection run that got past the bounds
    // bisection refuses (issue 31, regressions/refine_options/bisection_checked_as_delaunay).
    CheckOptions check_options;
    check_options.delaunay = options.insertion == RefineInsertion::delaunay;
    const CheckReport check = check_mesh(mesh, &input, check_options);
    if (!check.ok)
      fuzz::finding(options.algorithm + " (" + to_string(options.selection) + ", " +
                    to_string(options.triangulate.data_structure) + ") wrote an invalid mesh: " +
                    check.problems.front());
  });
  return 0;
}
