// 3D surfaces (.off, .obj, .ply, .stl). Three bytes of choices, then the file:
//   byte 0: the reader (its two low bits: .off, .obj, .ply, .stl) and the dihedral bound of
//           the flips (its six high bits, times 3 degrees);
//   byte 1: the bounds of the refinement (its two low bits: the area, the longest edge, or
//           both) and whether a triangle cap stops it (the next two: any but 0);
//   byte 2: how small the bounds are, from the surface's own size down to 1/256 of it.
// What reads must report without throwing, write, and read back the same. Edge flips alone
// must refuse it or leave a surface as clean as it was, with the same triangle count and a
// smallest angle no lower, on either mesh structure, and recorded, with a log that replays
// forward and backward. Bisection to the bounds then flips (issue 31) must end with every
// triangle within the bounds unless the cap stopped it (then the flips add no triangle over
// them), count what is over them truly, leave a clean surface, and give the same surface on
// both mesh structures.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <filesystem>

#include "fuzz_support.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/verify.hpp"
#include "meshstep/surface/surface_flips.hpp"
#include "meshstep/surface/surface_refine.hpp"

using namespace meshstep;

namespace {

constexpr std::size_t kChoiceBytes = 3;

Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double norm(const Point3& u) { return std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z); }
double triangle_area(const io::Surface& s, const std::array<std::uint32_t, 3>& t) {
  const Point3 u = minus(s.vertices[t[1]], s.vertices[t[0]]), v = minus(s.vertices[t[2]], s.vertices[t[0]]);
  return 0.5 * norm({u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x});
}
double longest_edge(const io::Surface& s, const std::array<std::uint32_t, 3>& t) {
  double l = 0.0;
  for (int k = 0; k < 3; ++k) l = std::max(l, norm(minus(s.vertices[t[(k + 1) % 3]], s.vertices[t[k]])));
  return l;
}

// Triangles clearly over a bound: measured here again, with a margin for the last bits in
// which this measure and the library's may differ.
std::size_t clearly_over(const io::Surface& s, const surface::BisectionOptions& o) {
  std::size_t over = 0;
  for (const auto& t : s.triangles)
    over += (o.max_area > 0.0 && triangle_area(s, t) > o.max_area * (1 + 1e-9)) ||
            (o.max_edge > 0.0 && longest_edge(s, t) > o.max_edge * (1 + 1e-9));
  return over;
}

void flips_alone(const io::Surface& s, double dihedral) {
  surface::FlipReport report;
  const io::Surface flipped = surface::flip_surface(s, {dihedral}, &report);
  const io::SurfaceReport before = io::report_surface(s), after = io::report_surface(flipped);
  if (flipped.triangles.size() != s.triangles.size()) fuzz::finding("flips changed the number of triangles");
  if (after.boundary_edges != before.boundary_edges || after.non_manifold_edges != 0 || after.inconsistent_edges != 0 ||
      after.degenerate_triangles > before.degenerate_triangles)
    fuzz::finding("flips left a surface less clean than it was: " + io::describe(after));
  if (report.smallest_angle_after_deg < report.smallest_angle_before_deg) fuzz::finding("flips lowered the smallest angle");
  // The other structure, recorded: the same surface, and a log that replays.
  const std::string path = (std::filesystem::temp_directory_path() / "fuzz_surface.mslog").string();
  {
    replay::LogWriter writer(path, replay::LogHeader{});
    surface::FlipOptions options{dihedral};
    options.data_structure = DataStructure::dcel;
    options.record = &writer;
    const io::Surface on_dcel = surface::flip_surface(s, options);
    writer.finish();
    if (on_dcel.triangles != flipped.triangles) fuzz::finding("tds and dcel flip differently");
  }
  const replay::VerifyReport verified = replay::verify(replay::LogReader(path));
  if (!verified.ok) fuzz::finding("a surface run's log does not replay: " + verified.problem);
}

void bisection_then_flips(const io::Surface& s, double dihedral, std::uint8_t bounds, std::uint8_t smallness) {
  if (s.triangles.empty()) return;
  double total_area = 0.0, largest_coordinate = 0.0;
  Point3 low = s.vertices[s.triangles[0][0]], high = low;
  for (const auto& t : s.triangles) {
    total_area += triangle_area(s, t);
    for (const std::uint32_t v : t) {
      const Point3& p = s.vertices[v];
      low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
      high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
      largest_coordinate = std::max({largest_coordinate, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
  }
  // 1/2 .. 1/256 of the surface's area, and the square root of that of its box's diagonal.
  const double fraction = std::ldexp(1.0 + (smallness & 31) / 32.0, -1 - (smallness >> 5));
  surface::BisectionOptions options;
  if ((bounds & 3) != 1) options.max_area = total_area * fraction;
  if ((bounds & 3) != 0) options.max_edge = norm(minus(high, low)) * std::sqrt(fraction);
  if (!std::isfinite(options.max_area) || !std::isfinite(options.max_edge) || options.max_area < 0.0) return;
  const bool capped_run = (bounds >> 2 & 3) != 0;
  options.max_triangles = capped_run ? s.triangles.size() + smallness % 64 : 20000;
  options.flip_dihedral_deg = dihedral;

  surface::BisectionReport report;
  const io::Surface out = surface::bisect_surface(s, options, &report);
  const io::SurfaceReport before = io::report_surface(s), after = io::report_surface(out);
  if (after.non_manifold_edges != 0 || after.inconsistent_edges != 0 || after.degenerate_triangles != 0 ||
      after.duplicate_triangles != 0 || after.boundary_loops != before.boundary_loops)
    fuzz::finding("bisection and flips left a surface that is not clean: " + io::describe(after));
  const std::size_t over = clearly_over(out, options);
  if (report.over_bounds < over) fuzz::finding("the report counts fewer triangles over the bounds than there are");
  // Uncapped, a run ends over the bounds only when it refused a cut that doubles cannot make
  // (an edge too short for its midpoint to differ from its ends, or a midpoint rounded onto
  // the line to an apex).
  const double smallest_bound = std::min(options.max_area > 0.0 ? std::sqrt(options.max_area) : INFINITY,
                                         options.max_edge > 0.0 ? options.max_edge : INFINITY);
  if (!report.capped && over > 0 && report.too_fine_to_cut == 0)
    fuzz::finding("a triangle over the bounds at the end of a run that was not capped, and no cut refused");
  // Longest-edge bisection keeps every angle above half the input's smallest (Rivara), so a
  // target's altitude is at least about bound * sin(that half): far above the rounding of the
  // coordinates, a cut is always possible.
  const double half_smallest_angle = report.smallest_angle_before_deg * (3.14159265358979 / 360.0);
  if (report.too_fine_to_cut > 0 && smallest_bound * std::sin(half_smallest_angle) > 1e-6 * largest_coordinate)
    fuzz::finding("a cut refused although the bounds and the angles are far above the coordinates' rounding");
  surface::BisectionOptions unflipped = options;
  unflipped.flip_dihedral_deg = -1.0;
  surface::BisectionReport without;
  (void)surface::bisect_surface(s, unflipped, &without);
  if (report.over_bounds > without.over_bounds) fuzz::finding("the flips made triangles over the bounds");
  surface::BisectionOptions on_dcel = options;
  on_dcel.data_structure = DataStructure::dcel;
  if (surface::bisect_surface(s, on_dcel).triangles != out.triangles)
    fuzz::finding("tds and dcel bisect and flip differently");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < kChoiceBytes) return 0;
  static const char* const kExtensions[] = {".off", ".obj", ".ply", ".stl"};
  const std::string extension = kExtensions[data[0] % 4];
  const double dihedral = static_cast<double>(data[0] >> 2) * 3.0;  // over 180: refused
  io::Surface s;
  fuzz::refusals_allowed([&] {
    s = io::read_surface(fuzz::write_input(data + kChoiceBytes, size - kChoiceBytes, extension));
    (void)io::describe(io::report_surface(s));
    const std::string again = (std::filesystem::temp_directory_path() / "fuzz_surface_again.ply").string();
    io::write_surface(again, s, io::SurfaceFormat::ply_binary);
    const io::Surface back = io::read_surface(again);
    if (back.vertices != s.vertices || back.triangles != s.triangles) fuzz::finding("a PLY round trip changed the surface");
    flips_alone(s, dihedral);
  });
  // Over 180 degrees, the refinement flips coplanar pairs only: the case of issue 31.
  fuzz::refusals_allowed([&] { bisection_then_flips(s, dihedral > 180.0 ? 0.0 : dihedral, data[1], data[2]); });
  return 0;
}
