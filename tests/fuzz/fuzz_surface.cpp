// 3D surfaces (.off, .obj, .ply, .stl): the first byte picks the reader. What reads must
// report without throwing, write, and read back the same; and edge flips (the first byte's
// high bits pick the dihedral bound) must refuse it or leave a surface as clean as it was,
// with the same triangle count and a smallest angle no lower, on either mesh structure, and
// recorded, with a log that replays forward and backward.
#include <filesystem>

#include "fuzz_support.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/verify.hpp"
#include "meshstep/surface/surface_flips.hpp"

using namespace meshstep;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".off", ".obj", ".ply", ".stl"};
  const std::string extension = kExtensions[data[0] % 4];
  fuzz::refusals_allowed([&] {
    const io::Surface s = io::read_surface(fuzz::write_input(data + 1, size - 1, extension));
    (void)io::describe(io::report_surface(s));
    const std::string again = (std::filesystem::temp_directory_path() / "fuzz_surface_again.ply").string();
    io::write_surface(again, s, io::SurfaceFormat::ply_binary);
    const io::Surface back = io::read_surface(again);
    if (back.vertices != s.vertices || back.triangles != s.triangles) fuzz::finding("a PLY round trip changed the surface");
    surface::FlipReport report;
    const io::Surface flipped = surface::flip_surface(s, {static_cast<double>(data[0] >> 2) * 3.0}, &report);
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
      surface::FlipOptions options{static_cast<double>(data[0] >> 2) * 3.0};
      options.data_structure = DataStructure::dcel;
      options.record = &writer;
      const io::Surface on_dcel = surface::flip_surface(s, options);
      writer.finish();
      if (on_dcel.triangles != flipped.triangles) fuzz::finding("tds and dcel flip differently");
    }
    const replay::VerifyReport verified = replay::verify(replay::LogReader(path));
    if (!verified.ok) fuzz::finding("a surface run's log does not replay: " + verified.problem);
  });
  return 0;
}
