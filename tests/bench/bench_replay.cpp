// Google Benchmark: the cost of recording, the size of the log, and seeking in it.
//
//   triangulate/{off,on}/N   triangulate N uniform random points without and with a
//                            recorder writing a replay log (wall time: the log writer
//                            encodes on a second thread). Counters on "on": events,
//                            bytes_per_event (whole file, keyframes included), keyframes.
//   triangulate_discard/N    recording into a sink that drops everything: the cost on the
//                            algorithm's thread alone
//   overhead/N               9 pairs of the two, run back to back in alternating order.
//                            Counters: off_ms, on_ms (medians), ratio (median of the
//                            pairs' on/off), ratio_min, ratio_max. The figure to quote:
//                            each ratio is taken within a pair, so the guest's drift cancels.
//   Every recorded run writes a fresh file: the previous log is deleted untimed.
//   seek/N                   open the log of an N-point run, then 200 seeks to random
//                            events (fixed seed), each timed alone. Counters: open_ms,
//                            first_ms (a cold seek: nothing decoded yet), median_ms,
//                            p90_ms, max_ms over the 200.
//
//   bench_replay --benchmark_filter='/1000000$'
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/replay.hpp"
#include "random_points.hpp"

namespace {

std::string log_path(std::size_t n) {
  return (std::filesystem::temp_directory_path() / ("meshstep_bench_" + std::to_string(n) + ".mslog")).string();
}

// Triangulates `points` with every step recorded into `sink`.
void triangulate_into(meshstep::replay::EventSink& sink, const std::vector<meshstep::Point>& points) {
  meshstep::TriangulateOptions options;
  options.record = &sink;
  meshstep::Pslg input;
  input.points = points;
  const meshstep::TriMesh mesh = meshstep::triangulate(std::move(input), options);
  benchmark::DoNotOptimize(mesh.triangles.data());
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

struct Recorded {
  meshstep::replay::LogStats stats;
  double finish_ms = 0;  // how long the run waited at the end for the writer
};

Recorded record(const std::vector<meshstep::Point>& points, const std::string& path) {
  meshstep::replay::LogHeader header;
  header.algorithm = "triangulate";
  header.parameters = "input_vertices=" + std::to_string(points.size());
  header.data_structure = "tds";
  header.insertion = "flip";
  meshstep::replay::LogWriter writer(path, header);
  triangulate_into(writer, points);
  const auto t0 = std::chrono::steady_clock::now();
  writer.finish();
  return {writer.stats(), ms_since(t0)};
}

// A sink that drops every batch: what recording costs the algorithm's own thread.
class DiscardSink final : public meshstep::replay::EventSink {
 public:
  DiscardSink() : EventSink(1 << 14) {}  // the log writer's batch size
  std::uint64_t words = 0;

 protected:
  void hand_over(meshstep::replay::EventWords& batch) override {
    words += batch.size();
    batch.clear();
  }
};

void bm_triangulate_discard(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<meshstep::Point> points = meshstep::bench::uniform_points(n);
  for (auto _ : state) {
    DiscardSink sink;
    triangulate_into(sink, points);
  }
}

void bm_triangulate(benchmark::State& state, bool recording) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<meshstep::Point> points = meshstep::bench::uniform_points(n);
  Recorded last;
  for (auto _ : state) {
    if (recording) {
      // Replacing the previous iteration's log would time its deletion: rename() over a
      // 124 MB file costs ext4 about 60 ms, freeing the old file's blocks.
      state.PauseTiming();
      std::filesystem::remove(log_path(n));
      state.ResumeTiming();
      last = record(points, log_path(n));
    } else {
      meshstep::Pslg input;
      input.points = points;
      const meshstep::TriMesh mesh = meshstep::triangulate(std::move(input));
      benchmark::DoNotOptimize(mesh.triangles.data());
    }
  }
  if (recording) {
    const meshstep::replay::LogStats& stats = last.stats;
    state.counters["events"] = static_cast<double>(stats.events);
    state.counters["finish_ms"] = last.finish_ms;
    state.counters["bytes_per_event"] = static_cast<double>(stats.bytes) / static_cast<double>(stats.events);
    state.counters["keyframes"] = static_cast<double>(stats.keyframes);
    state.counters["keyframe_bytes_per_event"] =
        static_cast<double>(stats.keyframe_bytes) / static_cast<double>(stats.events);
  }
}


double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The recorded / unrecorded ratio from pairs run back to back, alternating which goes
// first: this guest's speed drifts by tens of percent within minutes, and a ratio taken
// within a pair cancels the drift that separate benchmarks would each see.
void bm_overhead(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::vector<meshstep::Point> points = meshstep::bench::uniform_points(n);
  constexpr int kPairs = 9;
  for (auto _ : state) {
    std::vector<double> off, on, ratio;
    for (int pair = 0; pair < kPairs; ++pair) {
      std::filesystem::remove(log_path(n));  // not timed (see bm_triangulate)
      double times[2];
      for (int k = 0; k < 2; ++k) {
        const bool recording = (pair + k) % 2 == 1;
        const auto t0 = std::chrono::steady_clock::now();
        if (recording) {
          record(points, log_path(n));
        } else {
          meshstep::Pslg input;
          input.points = points;
          const meshstep::TriMesh mesh = meshstep::triangulate(std::move(input));
          benchmark::DoNotOptimize(mesh.triangles.data());
        }
        times[recording] = ms_since(t0);
      }
      off.push_back(times[0]);
      on.push_back(times[1]);
      ratio.push_back(times[1] / times[0]);
    }
    state.counters["off_ms"] = median(off);
    state.counters["on_ms"] = median(on);
    state.counters["ratio"] = median(ratio);
    state.counters["ratio_min"] = *std::min_element(ratio.begin(), ratio.end());
    state.counters["ratio_max"] = *std::max_element(ratio.begin(), ratio.end());
  }
}

void bm_seek(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const std::string path = log_path(n);
  if (!std::filesystem::exists(path)) record(meshstep::bench::uniform_points(n), path);
  for (auto _ : state) {
    auto t0 = std::chrono::steady_clock::now();
    const meshstep::replay::LogReader log(path);
    const double open_ms = ms_since(t0);
    meshstep::replay::Replay replay(log);
    std::mt19937_64 engine(42);
    std::vector<double> ms;
    for (int i = 0; i < 200; ++i) {
      const std::uint64_t target = engine() % (log.event_count() + 1);
      t0 = std::chrono::steady_clock::now();
      replay.seek_event(target);
      benchmark::DoNotOptimize(replay.slots().data());
      ms.push_back(ms_since(t0));
    }
    const double first = ms.front();
    std::sort(ms.begin(), ms.end());
    state.counters["open_ms"] = open_ms;
    state.counters["first_ms"] = first;
    state.counters["median_ms"] = ms[ms.size() / 2];
    state.counters["p90_ms"] = ms[ms.size() * 9 / 10];
    state.counters["max_ms"] = ms.back();
  }
}

}  // namespace

BENCHMARK_CAPTURE(bm_triangulate, off, false)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(bm_triangulate, on, true)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(bm_triangulate_discard)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(bm_overhead)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
BENCHMARK(bm_seek)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

BENCHMARK_MAIN();
