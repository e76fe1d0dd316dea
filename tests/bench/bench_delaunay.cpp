// Google Benchmark: Delaunay triangulation of uniform random points in the unit square,
// for every data structure (tds, dcel) and insertion strategy (flip, cavity), at 1e5, 1e6
// and 4e6 points.
//
// Timed: meshstep::triangulate on a fresh copy of the input (the copy itself, and freeing
// the previous iteration's mesh, happen with the timer paused). Counters: points/s (a rate
// over the timed part), triangles (of the last mesh), mesh_bytes (the data structure's
// largest footprint, as the triangulator reports it).
//
//   bench_delaunay                                   # everything (a few minutes)
//   bench_delaunay --benchmark_filter='/1000000$'    # one size
//   bench_delaunay --benchmark_filter='dcel/cavity'  # one configuration
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "random_points.hpp"

namespace {

using meshstep::DataStructure;
using meshstep::Insertion;

// The points of each size are generated once and shared by every configuration.
const std::vector<meshstep::Point>& points_of_size(std::size_t n) {
  static std::map<std::size_t, std::vector<meshstep::Point>> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, meshstep::bench::uniform_points(n)).first;
  return it->second;
}

void bm_triangulate(benchmark::State& state, DataStructure ds, Insertion insertion) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<meshstep::Point>& points = points_of_size(n);
  meshstep::TriangulateOptions options;
  options.data_structure = ds;
  options.insertion = insertion;

  meshstep::TriMesh mesh;
  meshstep::TriangulateReport report;
  for (auto _ : state) {
    state.PauseTiming();
    { meshstep::TriMesh previous = std::move(mesh); }  // free the last mesh untimed
    meshstep::Pslg input;
    input.points = points;
    report = {};
    state.ResumeTiming();

    mesh = meshstep::triangulate(std::move(input), options, &report);
    benchmark::DoNotOptimize(mesh.triangles.data());
    benchmark::ClobberMemory();
  }
  state.counters["points/s"] = benchmark::Counter(
      static_cast<double>(n) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
  state.counters["mesh_bytes"] = static_cast<double>(report.mesh_bytes);
}

void register_all() {
  const std::pair<DataStructure, Insertion> configurations[] = {
      {DataStructure::tds, Insertion::flip},
      {DataStructure::tds, Insertion::cavity},
      {DataStructure::dcel, Insertion::flip},
      {DataStructure::dcel, Insertion::cavity},
  };
  for (const auto& [ds, insertion] : configurations) {
    const std::string name = std::string("triangulate/") + meshstep::to_string(ds) + "/" +
                             meshstep::to_string(insertion);
    // 1e5: as many iterations as Google Benchmark wants; 1e6: three; 4e6: two (each of
    // those takes seconds, and the spread between runs is small next to it).
    benchmark::RegisterBenchmark(name.c_str(), bm_triangulate, ds, insertion)
        ->Arg(100000)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(name.c_str(), bm_triangulate, ds, insertion)
        ->Arg(1000000)
        ->Iterations(3)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(name.c_str(), bm_triangulate, ds, insertion)
        ->Arg(4000000)
        ->Iterations(2)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
