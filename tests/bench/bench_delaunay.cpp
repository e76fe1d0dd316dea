// Google Benchmark: Delaunay triangulation of uniform random points in the unit square,
// for every data structure (tds, dcel) and insertion strategy (flip, cavity), at 1e5, 1e6
// and 4e6 points; and constrained Delaunay triangulations whose time goes into recovering
// segments (cdt/...): a closed random star polygon of 1e5 edges, and a lattice of crossing
// lines over 1e5 random points, whose every crossing splits two constrained edges.
//
// Timed: meshstep::triangulate on a fresh copy of the input (the copy itself, and freeing
// the previous iteration's mesh, happen with the timer paused). Counters: points/s (a rate
// over the timed part), triangles (of the last mesh), mesh_bytes (the data structure's
// largest footprint, as the triangulator reports it).
//
//   bench_delaunay                                   # everything (a few minutes)
//   bench_delaunay --benchmark_filter='/1000000$'    # one size
//   bench_delaunay --benchmark_filter='dcel/cavity'  # one configuration
//   bench_delaunay --benchmark_filter='^cdt/'        # the segment-heavy cases
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
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

// A closed star polygon of n vertices around (0.5, 0.5): angles and radii at random, so
// that most of its edges are not Delaunay edges of its vertices and must be recovered.
meshstep::Pslg star_polygon(std::size_t n) {
  std::mt19937_64 engine(meshstep::bench::kDefaultSeed);
  std::vector<double> angles(n);
  for (double& a : angles) a = 2.0 * std::numbers::pi * meshstep::bench::unit_double(engine);
  std::sort(angles.begin(), angles.end());
  meshstep::Pslg pslg;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = 0.25 + 0.25 * meshstep::bench::unit_double(engine);
    pslg.points.push_back({0.5 + r * std::cos(angles[i]), 0.5 + r * std::sin(angles[i])});
    pslg.segments.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>((i + 1) % n), 0});
  }
  return pslg;
}

// k horizontal and k vertical lines across the unit square over 1e5 random points: k*k
// crossings, each splitting two constrained edges (the segment inserter's bookkeeping).
meshstep::Pslg line_lattice(std::size_t k) {
  meshstep::Pslg pslg;
  pslg.points = meshstep::bench::uniform_points(100000);
  const auto line = [&](meshstep::Point a, meshstep::Point b) {
    const auto i = static_cast<std::uint32_t>(pslg.points.size());
    pslg.points.push_back(a);
    pslg.points.push_back(b);
    pslg.segments.push_back({i, i + 1, 1});
  };
  for (std::size_t i = 0; i < k; ++i) {
    const double c = (static_cast<double>(i) + 0.5) / static_cast<double>(k);
    line({-0.01, c}, {1.01, c});
    line({c, -0.01}, {c, 1.01});
  }
  return pslg;
}

void bm_cdt(benchmark::State& state, const meshstep::Pslg& source, DataStructure ds) {
  meshstep::TriangulateOptions options;
  options.data_structure = ds;
  meshstep::TriMesh mesh;
  meshstep::TriangulateReport report;
  for (auto _ : state) {
    state.PauseTiming();
    { meshstep::TriMesh previous = std::move(mesh); }
    meshstep::Pslg input = source;
    report = {};
    state.ResumeTiming();

    mesh = meshstep::triangulate(std::move(input), options, &report);
    benchmark::DoNotOptimize(mesh.triangles.data());
    benchmark::ClobberMemory();
  }
  state.counters["segments"] = static_cast<double>(source.segments.size());
  state.counters["steiner"] = static_cast<double>(report.steiner_vertices);
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
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
  static const meshstep::Pslg star = star_polygon(100000);
  static const meshstep::Pslg lattice = line_lattice(300);
  for (const DataStructure ds : {DataStructure::tds, DataStructure::dcel}) {
    const std::string suffix = std::string("/") + meshstep::to_string(ds);
    benchmark::RegisterBenchmark(("cdt/star_polygon_100000" + suffix).c_str(), bm_cdt, std::cref(star), ds)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("cdt/line_lattice_300" + suffix).c_str(), bm_cdt, std::cref(lattice), ds)
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
