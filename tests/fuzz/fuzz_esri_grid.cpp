// ESRI ASCII grids.
#include "fuzz_support.hpp"
#include "meshstep/io/esri_grid.hpp"

using namespace meshstep;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::refusals_allowed([&] {
    const io::EsriGrid grid = io::read_esri_grid(fuzz::write_input(data, size, ".asc"));
    // Divided, not multiplied: a product of the header's counts that wraps is the finding.
    if (grid.values.size() / grid.ncols != grid.nrows || grid.values.size() % grid.ncols != 0)
      fuzz::finding("a grid whose values do not fill it");
    (void)grid.at({grid.x0, grid.y0}, 0.0);
  });
  return 0;
}
