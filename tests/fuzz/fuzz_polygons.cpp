// GeoJSON and WKT polygons (io/polygon_io.hpp): the first byte picks the reader, the rest is
// the file. A polygon read must make a PSLG the triangulator takes or refuses with an
// InputError: its hole points and segments are checked here against its own vertices.
#include "fuzz_support.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/io/polygon_io.hpp"

using namespace meshstep;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const bool wkt = data[0] % 2;
  ++data, --size;
  fuzz::refusals_allowed([&] {
    std::vector<std::string> warnings;
    const Pslg p = wkt ? io::read_wkt(fuzz::write_input(data, size, ".wkt"), &warnings)
                       : io::read_geojson(fuzz::write_input(data, size, ".geojson"), &warnings);
    for (const Segment& s : p.segments)
      if (s.a >= p.points.size() || s.b >= p.points.size() || s.a == s.b) fuzz::finding("a segment out of range");
    if (p.segments.size() < 3) fuzz::finding("a polygon read with fewer than 3 segments");
    // Small ones are meshed too: the hole points must leave a valid triangulation.
    if (p.points.size() <= 2000) triangulate(p);
  });
  return 0;
}
