// The triangulate() front door: validation, scaling, insertion order, vertices, segments,
// removal of holes and outside, and conversion to plain arrays.
#include "meshstep/delaunay/triangulate.hpp"

#include "builder.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"

namespace meshstep {
namespace {

using detail::Builder;

template <TriangleMesh Mesh>
TriMesh build(Pslg& input, const TriangulateOptions& options, TriangulateReport& report) {
  if (!options.record) return Builder<Mesh, replay::NullRecorder>(input, options, report, {}).run();
  replay::Recorder recorder(*options.record);
  if (options.observe_steps) recorder.observe_steps(options.observe_steps);
  return Builder<Mesh, replay::Recorder>(input, options, report, std::move(recorder)).run();
}

}  // namespace

TriMesh triangulate(Pslg&& input, const TriangulateOptions& options, TriangulateReport* report) {
  detail::validate(input);
  TriangulateReport local;
  TriangulateReport& r = report ? *report : local;
  switch (options.data_structure) {
    case DataStructure::tds: return build<Tds>(input, options, r);
    case DataStructure::dcel: return build<Dcel>(input, options, r);
  }
  throw std::logic_error("unknown data structure");
}

TriMesh triangulate(const Pslg& input, const TriangulateOptions& options, TriangulateReport* report) {
  Pslg copy = input;
  return triangulate(std::move(copy), options, report);
}

const char* to_string(DataStructure ds) { return ds == DataStructure::tds ? "tds" : "dcel"; }
const char* to_string(Insertion insertion) {
  return insertion == Insertion::flip ? "flip" : "cavity";
}

}  // namespace meshstep
