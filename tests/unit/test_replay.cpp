// The replay log ("step engine"), through the core API: a recorded run must replay to the
// very face slots the triangulator went through (by random seeks, step by step, event by
// event, forward and backward), every step boundary must be a valid constrained Delaunay
// triangulation, the final mesh must be the one triangulate() returned, and truncated or
// damaged logs must be reported, never replayed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "meshstep/check/mesh_check.hpp"
#include "meshstep/delaunay/triangulate.hpp"
#include "meshstep/error.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "meshstep/mesh/dcel.hpp"
#include "meshstep/mesh/tds.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/mesh_hash.hpp"
#include "meshstep/replay/recorder.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/verify.hpp"
#include "temp_dir.hpp"
#include "triangulate_support.hpp"

namespace meshstep {
namespace {

namespace fs = std::filesystem;
using replay::FaceRecord;
using Slots = std::vector<FaceRecord>;
using testing::TempDir;

// ---------------------------------------------------------------------------------------
// Inputs: degenerate point sets and a PSLG with every feature segment recovery must handle.

std::vector<Point> uniform(std::size_t n, std::uint64_t seed, Point lo = {0, 0}, Point hi = {1, 1}) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(lo.x, hi.x), uy(lo.y, hi.y);
  std::vector<Point> p(n);
  for (Point& q : p) q = {ux(rng), uy(rng)};
  return p;
}

Pslg point_set(std::vector<Point> p) {
  Pslg in;
  in.points = std::move(p);
  return in;
}

Pslg random_points() { return point_set(uniform(1500, 11)); }

// Every small square of the grid is cocircular: ties everywhere.
Pslg cocircular_grid() {
  std::vector<Point> p;
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) p.push_back({double(i), double(j)});
  return point_set(std::move(p));
}

// Doubles, triples and quadruples, including a point listed before its copies and after.
Pslg many_duplicates() {
  std::vector<Point> p = uniform(300, 5);
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; i += 2) p.push_back(p[i]);
  for (std::size_t i = 1; i < n; i += 7) p.insert(p.end(), {p[i], p[i]});
  p.insert(p.begin() + 10, p[200]);  // an earlier copy of a later point
  return point_set(std::move(p));
}

Pslg collinear_plus_one() {
  std::vector<Point> p;
  for (int i = 0; i < 60; ++i) p.push_back({i * 0.1, i * 0.2});
  p.push_back({0.0, 1.0});
  return point_set(std::move(p));
}

void add_segment(Pslg& in, Point a, Point b, int marker) {
  const auto i = static_cast<std::uint32_t>(in.points.size());
  in.points.insert(in.points.end(), {a, b});
  in.segments.push_back({i, i + 1, marker});
}

void add_loop(Pslg& in, const std::vector<Point>& loop, int marker) {
  const auto base = static_cast<std::uint32_t>(in.points.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    in.points.push_back(loop[i]);
    in.segments.push_back({base + std::uint32_t(i), base + std::uint32_t((i + 1) % loop.size()), marker});
  }
}

// An 8x8 square with a square hole, two diagonals crossing at an exact point, random
// crossing segments (rounded intersections), two T-junctions (a segment ending on the
// interior of the outer boundary and one on the hole's edge) and scattered interior points.
Pslg crossings_hole_and_t_junctions() {
  Pslg in;
  add_loop(in, {{0, 0}, {8, 0}, {8, 8}, {0, 8}}, 1);
  add_loop(in, {{5, 5}, {7, 5}, {7, 7}, {5, 7}}, 2);
  in.holes.push_back({6, 6});
  add_segment(in, {1, 1}, {3, 3}, 3);  // crosses the next one at (2, 2)
  add_segment(in, {1, 3}, {3, 1}, 3);
  add_segment(in, {4, 0}, {4, 4}, 4);  // T on the bottom side
  add_segment(in, {6, 2}, {6, 5}, 5);  // T on the hole's bottom edge
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> ux(0.5, 4.5), uy(4.5, 7.5);
  for (int i = 0; i < 8; ++i) add_segment(in, {ux(rng), uy(rng)}, {ux(rng), uy(rng)}, 6);
  for (const Point& p : uniform(60, 29, {0.2, 0.2}, {7.8, 4.8})) in.points.push_back(p);
  return in;
}

// Far outside the range where incircle's powers are representable: the triangulator
// scales by a power of two and the recorder must store the unscaled coordinates.
Pslg scaled(Pslg in, int exponent) {
  for (Point& p : in.points) p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)};
  for (Point& p : in.holes) p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent)};
  return in;
}
Pslg huge_pslg() { return scaled(crossings_hole_and_t_junctions(), 800); }
Pslg tiny_points() { return scaled(point_set(uniform(400, 13)), -900); }

struct NamedInput {
  std::string name;
  Pslg (*make)();
};
void PrintTo(const NamedInput& c, std::ostream* os) { *os << c.name; }

const std::vector<NamedInput>& generated_inputs() {
  static const std::vector<NamedInput> inputs = {
      {"random_points", random_points},
      {"cocircular_grid", cocircular_grid},
      {"many_duplicates", many_duplicates},
      {"collinear_plus_one", collinear_plus_one},
      {"crossings_hole_and_t_junctions", crossings_hole_and_t_junctions},
      {"huge_pslg", huge_pslg},
      {"tiny_points", tiny_points},
  };
  return inputs;
}

// ---------------------------------------------------------------------------------------
// Slots: comparison (slots beyond either vector's end are dead) and a slot-exact
// fingerprint for the step boundaries whose every slot is not kept.

FaceRecord slot(const Slots& s, std::size_t i) { return i < s.size() ? s[i] : FaceRecord{}; }

std::string text(const FaceRecord& r) {
  if (r.dead()) return "dead";
  std::string out = "(";
  for (const VertexId v : r.v) out += (v == kInfiniteVertex ? std::string("inf") : std::to_string(v)) + " ";
  return out + "c" + std::to_string(r.constrained) + ")";
}

::testing::AssertionResult same_slots(const Slots& replayed, const Slots& expected) {
  const std::size_t n = std::max(replayed.size(), expected.size());
  for (std::size_t i = 0; i < n; ++i)
    if (slot(replayed, i) != slot(expected, i))
      return ::testing::AssertionFailure() << "slot " << i << " holds " << text(slot(replayed, i))
                                           << ", expected " << text(slot(expected, i));
  return ::testing::AssertionSuccess();
}

std::uint64_t mix64(std::uint64_t x) {  // splitmix64's finaliser
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// One slot's share of a slot-exact fingerprint: which slot holds which face, listed from
// which vertex, in which orientation. face_hash is symmetric in the three vertices: it sees
// the vertices and the constrained edges but neither where the face starts nor which way
// round it goes; the first two vertices in their order do.
std::uint64_t slot_term(std::size_t i, const FaceRecord& r, std::uint64_t face_hash) {
  const std::uint64_t order = mix64(std::uint64_t{r.v[0]} << 32 | r.v[1]);
  return mix64(face_hash ^ order) * (2 * std::uint64_t{i} + 1);
}

// Dead slots add nothing, so trailing dead slots do not matter.
std::uint64_t fingerprint(const Slots& slots) {
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < slots.size(); ++i)
    if (!slots[i].dead()) sum += slot_term(i, slots[i], replay::face_hash(slots[i]));
  return sum;
}

::testing::AssertionResult same_points_bitwise(const std::vector<Point>& a, const std::vector<Point>& b) {
  if (a.size() != b.size())
    return ::testing::AssertionFailure() << a.size() << " points instead of " << b.size();
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::bit_cast<std::uint64_t>(a[i].x) != std::bit_cast<std::uint64_t>(b[i].x) ||
        std::bit_cast<std::uint64_t>(a[i].y) != std::bit_cast<std::uint64_t>(b[i].y))
      return ::testing::AssertionFailure() << "point " << i << " is (" << a[i].x << ", " << a[i].y
                                           << "), expected (" << b[i].x << ", " << b[i].y << ")";
  return ::testing::AssertionSuccess();
}

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

::testing::AssertionResult same_triangles(const Triangles& a, const Triangles& b) {
  for (std::size_t t = 0; t < std::min(a.size(), b.size()); ++t)
    if (a[t] != b[t])
      return ::testing::AssertionFailure() << "triangle " << t << " is (" << a[t][0] << " " << a[t][1] << " "
                                           << a[t][2] << "), expected (" << b[t][0] << " " << b[t][1] << " "
                                           << b[t][2] << ")";
  if (a.size() != b.size()) return ::testing::AssertionFailure() << a.size() << " triangles instead of " << b.size();
  return ::testing::AssertionSuccess();
}

// ---------------------------------------------------------------------------------------
// Recording a run while observing the algorithm's own face slots at every step boundary.

// What the observer saw: the hash and fingerprint of every call, and every slot at a
// sample of calls (all of them for small runs) and at the last two.
class Observation {
 public:
  static std::uint64_t sample_hash(std::uint64_t k) { return (k * 0x9E3779B97F4A7C15ull) >> 40; }

  explicit Observation(std::uint64_t expected_calls) : stride_(std::max<std::uint64_t>(1, expected_calls / 48)) {}

  void add(const Slots& slots) {
    const std::uint64_t k = hashes_.size();
    std::uint64_t hash = 0, print = 0, live = 0;  // one pass: the observer runs at every step
    for (std::size_t i = 0; i < slots.size(); ++i) {
      if (slots[i].dead()) continue;
      const std::uint64_t h = replay::face_hash(slots[i]);
      hash += h;
      print += slot_term(i, slots[i], h);
      ++live;
    }
    hashes_.push_back(hash);
    fingerprints_.push_back(print);
    live_faces_.push_back(live);
    if (k < 4 || sample_hash(k) % stride_ == 0) kept_[k] = slots;
    previous_ = std::move(last_);
    last_ = slots;
  }
  // Call after the run: the last two observations are kept whatever the sample.
  void finish() {
    const std::uint64_t n = hashes_.size();
    if (n >= 1) kept_[n - 1] = last_;
    if (n >= 2) kept_[n - 2] = previous_;
    previous_ = last_ = {};
  }

  std::uint64_t calls() const { return hashes_.size(); }
  std::uint64_t hash(std::uint64_t k) const { return hashes_.at(k); }
  std::uint64_t fingerprint_at(std::uint64_t k) const { return fingerprints_.at(k); }
  std::uint64_t live_faces_at(std::uint64_t k) const { return live_faces_.at(k); }
  const std::vector<std::uint64_t>& hashes() const { return hashes_; }
  const std::map<std::uint64_t, Slots>& kept() const { return kept_; }
  const Slots* kept_at(std::uint64_t k) const {
    const auto it = kept_.find(k);
    return it == kept_.end() ? nullptr : &it->second;
  }

 private:
  std::uint64_t stride_;
  std::vector<std::uint64_t> hashes_, fingerprints_, live_faces_;
  std::map<std::uint64_t, Slots> kept_;
  Slots previous_, last_;
};

replay::LogHeader header_for(const Pslg& in, const TriangulateOptions& options) {
  replay::LogHeader h;
  h.input = "generated";
  h.input_hash = "0000000000000000";
  h.algorithm = "triangulate";
  h.parameters = "convex_hull=" + std::to_string(options.convex_hull) +
                 " input_vertices=" + std::to_string(in.points.size()) +
                 " first_index=" + std::to_string(in.first_index);
  h.data_structure = to_string(options.data_structure);
  h.insertion = to_string(options.insertion);
  return h;
}

struct RecordedRun {
  TriMesh mesh;  // what triangulate() returned
  Observation seen;
  replay::LogStats stats;
};

RecordedRun record_run(const Pslg& in, TriangulateOptions options, const std::string& path,
                       const replay::LogWriterOptions& writer_options = {}) {
  RecordedRun run{{}, Observation(in.points.size() + in.segments.size() + 2), {}};
  replay::LogWriter writer(path, header_for(in, options), writer_options);
  options.record = &writer;
  options.observe_steps = [&run](const Slots& slots) { run.seen.add(slots); };
  run.mesh = triangulate(in, options);
  writer.finish();
  run.seen.finish();
  run.stats = writer.stats();
  return run;
}

// Writer options that make many blocks and keyframes out of a small run.
replay::LogWriterOptions small_blocks() {
  replay::LogWriterOptions o;
  o.block_bytes = 700;
  o.keyframes.factor = 0.5;
  o.keyframes.min_events = 40;
  return o;
}

// Steps whose every event comes before position e, counted from the step starts alone.
std::uint64_t steps_completed_at(const replay::LogReader& log, std::uint64_t e) {
  std::uint64_t done = 0;
  while (done < log.step_count() && log.step_start(done + 1) <= e) ++done;
  return done;
}

// ---------------------------------------------------------------------------------------
// The checks of one recorded run against its log.

void check_log_describes_run(const replay::LogReader& log, const RecordedRun& run,
                             const TriangulateOptions& options) {
  EXPECT_TRUE(log.complete()) << log.incomplete_reason();
  EXPECT_TRUE(log.incomplete_reason().empty()) << log.incomplete_reason();
  // The observer is called at every step_begin and once more at the end of the run.
  EXPECT_EQ(log.step_count() + 1, run.seen.calls());
  EXPECT_EQ(log.step_count(), run.stats.steps);
  EXPECT_EQ(log.event_count(), run.stats.events);
  EXPECT_EQ(log.blocks().size() + log.keyframes().size() + 1, run.stats.blocks);  // + end block
  EXPECT_EQ(log.keyframes().size(), run.stats.keyframes);
  EXPECT_EQ(log.header().data_structure, to_string(options.data_structure));
  EXPECT_EQ(log.header().insertion, to_string(options.insertion));
  EXPECT_FALSE(log.header().program_version.empty());
  EXPECT_EQ(log.final_hash(), run.seen.hash(run.seen.calls() - 1));
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    ASSERT_EQ(log.event(log.step_start(k)).type, replay::EventType::step_begin) << "step " << k;
    ASSERT_EQ(log.step_of_event(log.step_start(k)), k);
  }
}

// The step boundary (observer call) at event e: the k with step_start(k) == e, where
// step_start(step_count()) == event_count() is the end of the run.
std::optional<std::uint64_t> boundary_at(const replay::LogReader& log, std::uint64_t e) {
  std::uint64_t lo = 0, hi = log.step_count();
  while (lo < hi) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    if (log.step_start(mid) < e) lo = mid + 1;
    else hi = mid;
  }
  if (log.step_start(lo) == e) return lo;
  return std::nullopt;
}

// Events blocks carry no mesh hash; keyframes are copies of the algorithm's own mesh, taken
// at step boundaries where the policy says one is due, and once more at the end of the run.
void check_keyframes(const replay::LogReader& log, const RecordedRun& run, const replay::KeyframePolicy& policy) {
  for (std::size_t b = 0; b < log.blocks().size(); ++b)
    EXPECT_EQ(log.blocks()[b].mesh_hash, 0u) << "events block " << b << " carries a mesh hash";
  const auto& keyframes = log.keyframes();
  ASSERT_FALSE(keyframes.empty()) << "no final keyframe";
  EXPECT_EQ(keyframes.back().event, log.event_count()) << "the last keyframe is not at the end of the run";
  EXPECT_EQ(keyframes.back().mesh_hash, log.final_hash());
  EXPECT_EQ(log.final_hash(), run.seen.hash(run.seen.calls() - 1));

  // The final keyframe is face_records() of the mesh the algorithm ended with: every slot,
  // the same capacity.
  const Slots* final_mesh = run.seen.kept_at(run.seen.calls() - 1);
  ASSERT_NE(final_mesh, nullptr);
  const Slots& final_keyframe = log.keyframe(keyframes.size() - 1);
  EXPECT_EQ(final_keyframe.size(), final_mesh->size());
  EXPECT_TRUE(same_slots(final_keyframe, *final_mesh)) << "final keyframe";

  std::set<std::uint64_t> keyframe_events;
  for (std::size_t j = 0; j < keyframes.size(); ++j) {
    SCOPED_TRACE("keyframe " + std::to_string(j) + " of " + std::to_string(keyframes.size()) + ", after event " +
                 std::to_string(keyframes[j].event));
    if (j > 0) {
      EXPECT_LT(keyframes[j - 1].event, keyframes[j].event);
    }
    keyframe_events.insert(keyframes[j].event);
    const Slots& stored = log.keyframe(j);
    EXPECT_EQ(stored.size(), keyframes[j].slot_count);
    EXPECT_EQ(replay::mesh_hash(stored), keyframes[j].mesh_hash);
    const std::optional<std::uint64_t> k = boundary_at(log, keyframes[j].event);
    ASSERT_TRUE(k.has_value()) << "a keyframe off a step boundary";
    EXPECT_EQ(keyframes[j].mesh_hash, run.seen.hash(*k));
    EXPECT_EQ(fingerprint(stored), run.seen.fingerprint_at(*k));
    if (const Slots* seen = run.seen.kept_at(*k)) {
      EXPECT_EQ(stored.size(), seen->size());
      EXPECT_TRUE(same_slots(stored, *seen));
    }
  }

  // The policy: at the first step boundary where at least max(min_events, factor x live
  // faces) events have passed since the last keyframe (or the start), and nowhere else.
  std::uint64_t last = 0;
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    const std::uint64_t e = log.step_start(k), since = e - last;
    const bool due = since >= policy.min_events &&
                     static_cast<double>(since) >= policy.factor * static_cast<double>(run.seen.live_faces_at(k));
    EXPECT_EQ(keyframe_events.contains(e), due) << "step " << k << " at event " << e << ", " << since
                                                << " events after the last keyframe, "
                                                << run.seen.live_faces_at(k) << " live faces";
    if (due) last = e;
  }
}

// seek_step to random steps (and to every step whose slots were kept), in random order.
void check_random_seeks(const replay::LogReader& log, const RecordedRun& run, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint64_t> targets;
  for (const auto& [k, slots] : run.seen.kept()) targets.push_back(k);
  std::uniform_int_distribution<std::uint64_t> any_step(0, log.step_count());
  for (int i = 0; i < 150; ++i) targets.push_back(any_step(rng));
  std::shuffle(targets.begin(), targets.end(), rng);

  replay::Replay r(log);
  for (const std::uint64_t k : targets) {
    r.seek_step(k);
    ASSERT_EQ(r.position(), log.step_start(k)) << "seek_step(" << k << ")";
    EXPECT_EQ(r.completed_steps(), k);
    EXPECT_EQ(fingerprint(r.slots()), run.seen.fingerprint_at(k)) << "after seek_step(" << k << ")";
    if (const Slots* seen = run.seen.kept_at(k)) {
      EXPECT_TRUE(same_slots(r.slots(), *seen)) << "after seek_step(" << k << ")";
      EXPECT_EQ(r.hash(), run.seen.hash(k));
    }
  }
  // Positions inside steps.
  std::uniform_int_distribution<std::uint64_t> any_event(0, log.event_count());
  for (int i = 0; i < 60; ++i) {
    const std::uint64_t e = any_event(rng);
    r.seek_event(e);
    ASSERT_EQ(r.position(), e);
    EXPECT_EQ(r.completed_steps(), steps_completed_at(log, e)) << "at event " << e;
  }
}

// The step boundaries at which the mesh goes through check_mesh: all of a small run, a
// sample of a large one, always the first and last few.
std::set<std::uint64_t> mesh_sample(std::uint64_t steps) {
  std::set<std::uint64_t> sample;
  const std::uint64_t stride = std::max<std::uint64_t>(1, steps / 40);
  for (std::uint64_t k = 0; k <= steps; k += stride) sample.insert(k);
  for (std::uint64_t k = steps > 3 ? steps - 3 : 0; k <= steps; ++k) sample.insert(k);
  return sample;
}

// The checker's own double-precision predicates overflow or underflow far from unit scale
// (test_triangulate.cpp says so too); scaling by a power of two changes no predicate, so
// check such a mesh brought near 1.
TriMesh near_unit_scale(TriMesh mesh) {
  double largest = 0.0;
  for (const Point& p : mesh.points) largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)});
  const int e = largest > 0.0 ? std::ilogb(largest) : 0;
  if (e > 200 || e < -200)
    for (Point& p : mesh.points) p = {std::ldexp(p.x, -e), std::ldexp(p.y, -e)};
  return mesh;
}

void expect_valid_cdt(const TriMesh& mesh, const std::string& where) {
  const CheckReport check = check_mesh(near_unit_scale(mesh), nullptr, {});
  EXPECT_TRUE(check.ok) << where << ": " << check.problem_count << " problems, first: "
                        << (check.problems.empty() ? std::string() : check.problems.front());
}

// next_step() from the start to the end and prev_step() back: every boundary as observed.
void check_step_walk(const replay::LogReader& log, const RecordedRun& run) {
  const std::uint64_t steps = log.step_count();
  const std::set<std::uint64_t> check_meshes = mesh_sample(steps);
  const std::uint64_t fingerprint_stride = std::max<std::uint64_t>(1, steps / 4000);
  replay::Replay r(log, /*track_hash=*/true);
  std::uint64_t k = log.step_start(0) > 0 ? 0 : 1;  // the first boundary after position 0
  while (r.next_step()) {
    ASSERT_LE(k, steps);
    ASSERT_EQ(r.position(), log.step_start(k)) << "next_step to step " << k;
    ASSERT_EQ(r.completed_steps(), k);
    EXPECT_EQ(r.hash(), run.seen.hash(k)) << "step " << k;
    if (k % fingerprint_stride == 0) {
      EXPECT_EQ(fingerprint(r.slots()), run.seen.fingerprint_at(k)) << "step " << k;
    }
    if (const Slots* seen = run.seen.kept_at(k)) {
      EXPECT_TRUE(same_slots(r.slots(), *seen)) << "step " << k;
    }
    if (check_meshes.contains(k)) expect_valid_cdt(r.mesh(), "mesh after step " + std::to_string(k));
    ++k;
  }
  EXPECT_EQ(k, steps + 1);
  EXPECT_EQ(r.position(), log.event_count());

  for (std::uint64_t j = steps; j-- > 0;) {
    ASSERT_TRUE(r.prev_step()) << "prev_step to step " << j;
    ASSERT_EQ(r.position(), log.step_start(j));
    EXPECT_EQ(r.hash(), run.seen.hash(j)) << "step " << j << ", going back";
  }
  if (log.step_start(0) > 0) {
    ASSERT_TRUE(r.prev_step());  // back over the preamble
  }
  EXPECT_EQ(r.position(), 0u);
  EXPECT_FALSE(r.prev_step());
  EXPECT_EQ(r.live_faces(), 0u);
  EXPECT_EQ(r.hash(), 0u);
}

// Event by event to the end, back to 0 and forward again. At every keyframe position the
// replayed slots are the keyframe's (the algorithm's own mesh) and the tracked hash is the
// keyframe's; at every block boundary the tracked hash has not drifted from the slots.
void check_event_walk(const replay::LogReader& log, const RecordedRun& run) {
  const auto& blocks = log.blocks();
  std::set<std::uint64_t> block_ends;
  for (const replay::BlockInfo& b : blocks) block_ends.insert(b.first_event + b.event_count);
  ASSERT_EQ(block_ends.size(), blocks.size());
  std::map<std::uint64_t, std::size_t> keyframe_at;
  for (std::size_t j = 0; j < log.keyframes().size(); ++j) keyframe_at[log.keyframes()[j].event] = j;
  ASSERT_EQ(keyframe_at.size(), log.keyframes().size());

  replay::Replay r(log, /*track_hash=*/true);
  std::size_t boundaries = 0, keyframes_seen = 0;
  const auto at_boundary = [&](const char* pass) {
    if (block_ends.contains(r.position())) {
      ++boundaries;
      EXPECT_EQ(r.hash(), replay::mesh_hash(r.slots())) << pass << ": tracked hash drifted at event " << r.position();
    }
    if (const auto it = keyframe_at.find(r.position()); it != keyframe_at.end()) {
      ++keyframes_seen;
      const std::size_t j = it->second;
      EXPECT_TRUE(same_slots(r.slots(), log.keyframe(j))) << pass << ": keyframe " << j;
      EXPECT_EQ(r.hash(), log.keyframes()[j].mesh_hash) << pass << ": keyframe " << j;
      EXPECT_EQ(r.hash(), replay::mesh_hash(r.slots())) << pass << ": tracked hash drifted at keyframe " << j;
    }
  };
  at_boundary("start");
  std::uint64_t moves = 0;
  while (r.next_event()) {
    ++moves;
    at_boundary("forward");
  }
  EXPECT_EQ(moves, log.event_count());
  EXPECT_EQ(r.hash(), log.final_hash());
  EXPECT_EQ(r.hash(), log.keyframes().back().mesh_hash);
  EXPECT_EQ(fingerprint(r.slots()), run.seen.fingerprint_at(run.seen.calls() - 1));
  moves = 0;
  while (r.prev_event()) {
    ++moves;
    at_boundary("backward");
  }
  EXPECT_EQ(moves, log.event_count());
  EXPECT_EQ(r.hash(), 0u);
  EXPECT_EQ(r.live_faces(), 0u);
  while (r.next_event()) at_boundary("forward again");
  EXPECT_TRUE(same_slots(r.slots(), *run.seen.kept_at(run.seen.calls() - 1)));
  EXPECT_EQ(r.hash(), log.final_hash());
  EXPECT_EQ(boundaries, 3 * blocks.size() - 1);  // the end is not revisited going back
  // Each keyframe is passed going forward twice and going back once, but the last one
  // (at the end) is not revisited going back (none is at event 0: events come before the
  // first step boundary).
  EXPECT_EQ(keyframes_seen, 3 * log.keyframes().size() - 1);
}

void check_final_mesh(const replay::LogReader& log, const RecordedRun& run) {
  replay::Replay r(log);
  r.seek_step(log.step_count());
  ASSERT_EQ(r.position(), log.event_count());
  const TriMesh replayed = r.mesh();
  EXPECT_TRUE(same_points_bitwise(replayed.points, run.mesh.points));
  EXPECT_EQ(replayed.input_vertex_count, run.mesh.input_vertex_count);
  EXPECT_TRUE(same_triangles(replayed.triangles, run.mesh.triangles));
  // The constrained edges that survive are among the output's segments (which also list
  // the unconstrained edges carving made boundary).
  std::set<std::pair<std::uint32_t, std::uint32_t>> output_segments;
  for (const Segment& s : run.mesh.segments) output_segments.insert(std::minmax(s.a, s.b));
  for (const Segment& s : replayed.segments)
    EXPECT_TRUE(output_segments.contains(std::minmax(s.a, s.b))) << "constrained edge " << s.a << "-" << s.b;
  expect_valid_cdt(replayed, "final replayed mesh");
}

void check_verify(const replay::LogReader& log) {
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_TRUE(report.ok) << report.problem;
  EXPECT_EQ(report.events, log.event_count());
  EXPECT_EQ(report.steps, log.step_count());
  // Hashes are checked only with keyframes now: each one forward, backward and forward
  // again, but the final one is not revisited going back.
  EXPECT_EQ(report.keyframes_checked, 3 * log.keyframes().size() - 1);
}

struct RunSummary {
  std::uint64_t final_hash = 0, steps = 0, events = 0, blocks = 0, keyframes = 0;
  std::vector<std::uint64_t> step_hashes;
};

RunSummary record_and_check(const Pslg& in, const TriangulateOptions& options, const std::string& path,
                            const replay::LogWriterOptions& writer_options) {
  const RecordedRun run = record_run(in, options, path, writer_options);
  const replay::LogReader log(path);
  check_log_describes_run(log, run, options);
  check_keyframes(log, run, writer_options.keyframes);
  check_random_seeks(log, run, 1234);
  check_step_walk(log, run);
  check_event_walk(log, run);
  check_final_mesh(log, run);
  check_verify(log);
  return {log.final_hash(), log.step_count(), log.event_count(), log.blocks().size(),
          log.keyframes().size(), run.seen.hashes()};
}

std::string log_name(const TriangulateOptions& options) {
  std::string name = testing::describe(options);  // "tds/flip"
  std::replace(name.begin(), name.end(), '/', '_');
  return name + ".mslog";
}

// Every data structure x insertion strategy; the data structures must agree on the mesh at
// every step boundary (the hash does not depend on slots), not only at the end.
// Returns the run of the first configuration (tds/flip).
RunSummary record_and_check_everywhere(const Pslg& in, const replay::LogWriterOptions& writer_options,
                                       bool convex_hull = false) {
  TempDir dir("meshstep_replay_");
  std::map<Insertion, std::map<DataStructure, RunSummary>> runs;
  for (const TriangulateOptions& options : testing::all_configurations(convex_hull)) {
    SCOPED_TRACE(testing::describe(options));
    runs[options.insertion][options.data_structure] =
        record_and_check(in, options, dir.file(log_name(options)), writer_options);
  }
  for (auto& [insertion, by_ds] : runs) {
    SCOPED_TRACE(to_string(insertion));
    const RunSummary &tds = by_ds[DataStructure::tds], &dcel = by_ds[DataStructure::dcel];
    EXPECT_EQ(tds.final_hash, dcel.final_hash);
    EXPECT_EQ(tds.steps, dcel.steps);
    EXPECT_EQ(tds.events, dcel.events);
    EXPECT_EQ(tds.step_hashes, dcel.step_hashes) << "the data structures differ at some step boundary";
  }
  return runs[Insertion::flip][DataStructure::tds];
}

// ---------------------------------------------------------------------------------------
// Generated inputs and the shared corpus.

class ReplayRun : public ::testing::TestWithParam<NamedInput> {};

TEST_P(ReplayRun, ReplaysEveryStepEverywhere) {
  const Pslg in = GetParam().make();
  {
    SCOPED_TRACE("default writer options");
    record_and_check_everywhere(in, {});
  }
  {
    SCOPED_TRACE("small blocks, frequent keyframes");
    const RunSummary run = record_and_check_everywhere(in, small_blocks());
    // Seeks and verification went through keyframes and across block boundaries.
    EXPECT_GE(run.blocks, 3u);
    EXPECT_GE(run.keyframes, 1u);
  }
}

// Carving keeps everything inside the convex hull but the hole.
TEST(ReplayConvexHull, ReplaysEveryStepEverywhere) {
  const RunSummary run = record_and_check_everywhere(crossings_hole_and_t_junctions(), small_blocks(), true);
  EXPECT_GE(run.keyframes, 1u);
}

INSTANTIATE_TEST_SUITE_P(ReplayGenerated, ReplayRun, ::testing::ValuesIn(generated_inputs()),
                         [](const ::testing::TestParamInfo<NamedInput>& info) { return info.param.name; });

using testing::corpus_polys;
using testing::corpus_test_name;

class ReplayCorpus : public ::testing::TestWithParam<std::string> {};

// The observer copies every face slot at every step, so a run costs steps x slots: the
// two largest PSLGs of the corpus (p2t_debug2, earcut_water-huge3: 20000 and more vertices
// plus segments) would take over a minute on their own and are skipped.
constexpr std::size_t kMaxCorpusSize = 12000;  // vertices + segments

TEST_P(ReplayCorpus, ReplaysEveryStepEverywhere) {
  const Pslg in = io::read_pslg(GetParam());
  if (in.points.size() + in.segments.size() > kMaxCorpusSize)
    GTEST_SKIP() << GetParam() << ": " << in.points.size() << " vertices and " << in.segments.size()
                 << " segments, more than the " << kMaxCorpusSize << " the replay sample takes";
  replay::LogWriterOptions writer_options;
  writer_options.block_bytes = 16 * 1024;
  writer_options.keyframes.min_events = 2000;
  record_and_check_everywhere(in, writer_options);
}

// "Slow": a minute in Release, left out of the sanitizer pass.
INSTANTIATE_TEST_SUITE_P(ReplaySharedDataSlow, ReplayCorpus, ::testing::ValuesIn(corpus_polys()),
                         corpus_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ReplayCorpus);

// The done-when of the replay log: `log verify` passes on the log of every corpus input,
// the largest included (recorded with the default writer, no observer).
class ReplayCorpusVerify : public ::testing::TestWithParam<std::string> {};

TEST_P(ReplayCorpusVerify, LogOfEveryCorpusInputVerifies) {
  testing::TempDir dir;
  const std::string path = dir.file("run.mslog");
  const Pslg in = io::read_pslg(GetParam());
  TriMesh direct;
  {
    replay::LogWriter writer(path, replay::LogHeader{});
    TriangulateOptions options;
    options.record = &writer;
    direct = triangulate(in, options);
    writer.finish();
  }
  const replay::LogReader log(path);
  ASSERT_TRUE(log.complete());
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_TRUE(report.ok) << report.problem;
  EXPECT_GE(report.keyframes_checked, 2u);
  replay::Replay end(log);
  end.seek_event(log.event_count());
  EXPECT_EQ(end.mesh().triangles, direct.triangles);
}

INSTANTIATE_TEST_SUITE_P(ReplaySharedDataSlow, ReplayCorpusVerify, ::testing::ValuesIn(corpus_polys()),
                         corpus_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(ReplayCorpusVerify);

TEST(ReplayCorpusPresence, SharedDataIsThereOrSkipped) {
  if (corpus_polys().empty())
    GTEST_SKIP() << "no shared corpus at " << testing::shared_data() / "pslg" << ": replay corpus tests skipped";
  EXPECT_GE(corpus_polys().size(), 20u);
}

// ---------------------------------------------------------------------------------------
// Recording is an observer: the result is the same with it and without.

::testing::AssertionResult same_mesh(const TriMesh& a, const TriMesh& b) {
  if (auto points = same_points_bitwise(a.points, b.points); !points) return points;
  if (auto triangles = same_triangles(a.triangles, b.triangles); !triangles) return triangles;
  if (a.neighbors != b.neighbors) return ::testing::AssertionFailure() << "different neighbors";
  if (a.segments.size() != b.segments.size()) return ::testing::AssertionFailure() << "different segment counts";
  for (std::size_t i = 0; i < a.segments.size(); ++i)
    if (a.segments[i].a != b.segments[i].a || a.segments[i].b != b.segments[i].b ||
        a.segments[i].marker != b.segments[i].marker)
      return ::testing::AssertionFailure() << "segment " << i << " differs";
  return ::testing::AssertionSuccess();
}

TEST(ReplayRecording, DoesNotChangeTheResult) {
  TempDir dir("meshstep_replay_");
  for (const NamedInput& input : generated_inputs()) {
    const Pslg in = input.make();
    for (TriangulateOptions options : testing::all_configurations()) {
      SCOPED_TRACE(input.name + " " + testing::describe(options));
      TriangulateReport plain_report, recorded_report;
      const TriMesh plain = triangulate(in, options, &plain_report);
      replay::LogWriter writer(dir.file("run.mslog"), header_for(in, options), small_blocks());
      options.record = &writer;
      const TriMesh recorded = triangulate(in, options, &recorded_report);
      writer.finish();
      EXPECT_TRUE(same_mesh(recorded, plain));
      EXPECT_EQ(recorded_report.duplicate_vertices, plain_report.duplicate_vertices);
      EXPECT_EQ(recorded_report.steiner_vertices, plain_report.steiner_vertices);
      EXPECT_EQ(recorded_report.warnings, plain_report.warnings);
      EXPECT_GT(writer.stats().events, 0u);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Keyframes: the final one is the algorithm's own final mesh; the default policy.

// With the default writer options a small run has no keyframe but the final one, and that
// one holds face_records() of the mesh the algorithm ended with, slot by slot (the
// observer's last call), for every data structure and insertion strategy.
TEST(ReplayFinalKeyframe, IsTheAlgorithmsFinalMeshSlotBySlot) {
  TempDir dir("meshstep_replay_");
  for (const NamedInput& input : generated_inputs()) {
    const Pslg in = input.make();
    for (const TriangulateOptions& options : testing::all_configurations()) {
      SCOPED_TRACE(input.name + " " + testing::describe(options));
      const std::string path = dir.file("run.mslog");
      Slots last;
      std::uint64_t calls = 0;
      {
        TriangulateOptions o = options;
        replay::LogWriter writer(path, header_for(in, o));
        o.record = &writer;
        o.observe_steps = [&](const Slots& slots) {
          last = slots;
          ++calls;
        };
        triangulate(in, o);
        writer.finish();
      }
      const replay::LogReader log(path);
      ASSERT_TRUE(log.complete());
      EXPECT_EQ(calls, log.step_count() + 1);
      ASSERT_LT(log.event_count(), replay::KeyframePolicy{}.min_events) << "the input is no longer small";
      ASSERT_EQ(log.keyframes().size(), 1u);
      const replay::KeyframeInfo& k = log.keyframes().back();
      EXPECT_EQ(k.event, log.event_count());
      const Slots& stored = log.keyframe(0);
      EXPECT_EQ(stored.size(), last.size());  // the data structure's face capacity
      EXPECT_EQ(k.slot_count, last.size());
      EXPECT_TRUE(same_slots(stored, last));
      EXPECT_EQ(k.mesh_hash, replay::mesh_hash(last));
      EXPECT_EQ(log.final_hash(), replay::mesh_hash(last));
      // And the events replay to it.
      replay::Replay r(log);
      r.walk_to(log.event_count());
      EXPECT_TRUE(same_slots(r.slots(), last));
    }
  }
}

// Splits of faces with constrained edges (none happen in a triangulation, where vertices go
// in before segments; refinement splits such faces all the time): the packed split_face
// must carry each new face's constraint bits and rotation, on both data structures, with a
// keyframe taken after each split so that the stored copy is checked as well.
template <class Mesh>
void split_constrained_faces() {
  TempDir dir("meshstep_replay_");
  const std::string path = dir.file("split.mslog");
  Mesh m;
  m.set_vertex_count(6);
  {
    replay::LogWriterOptions options;
    options.keyframes = {.factor = 0.0, .min_events = 1};  // a keyframe at every step boundary
    replay::LogWriter writer(path, replay::LogHeader{}, options);
    replay::Recorder rec(writer);
    rec.step_begin(m, replay::StepKind::start);
    const HalfEdge h = rec.init_sphere(m, 0, 1, 2);
    rec.set_constrained(m, h, true, 1);
    rec.set_constrained(m, m.next(h), true, 2);
    rec.step_begin(m, replay::StepKind::insert_vertex, 3);
    rec.split_face(m, m.face(h), 3);
    // The ghost face across 0-1 (constrained on that edge) and the face holding 1-2 now.
    rec.step_begin(m, replay::StepKind::insert_vertex, 4);
    rec.split_face(m, m.face(m.twin(h)), 4);
    rec.step_begin(m, replay::StepKind::insert_vertex, 5);
    rec.split_face(m, m.face(m.next(h)), 5);
    rec.run_end(m);
    writer.finish();
  }
  const replay::LogReader log(path);
  ASSERT_TRUE(log.complete());
  EXPECT_EQ(log.counts_by_type()[static_cast<std::size_t>(replay::EventType::split_face)], 3u);
  EXPECT_GE(log.keyframes().size(), 4u);
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_TRUE(report.ok) << report.problem;
  replay::Replay r(log);
  r.seek_event(log.event_count());
  const Slots expected = replay::face_records(m);
  EXPECT_TRUE(same_slots(r.slots(), expected));
  std::size_t constrained_records = 0;
  for (const FaceRecord& f : expected) constrained_records += f.constrained != 0;
  EXPECT_GE(constrained_records, 4u) << "the test no longer splits constrained faces";
}

TEST(ReplaySplitFace, CarriesConstraintBitsOnTds) { split_constrained_faces<Tds>(); }
TEST(ReplaySplitFace, CarriesConstraintBitsOnDcel) { split_constrained_faces<Dcel>(); }

TEST(ReplayKeyframePolicy, Defaults) {
  const replay::KeyframePolicy policy;
  EXPECT_EQ(policy.factor, 3.0);
  EXPECT_EQ(policy.min_events, 65536u);
  const replay::LogWriterOptions options;
  EXPECT_EQ(options.keyframes.factor, 3.0);
  EXPECT_EQ(options.keyframes.min_events, 65536u);
}

// A run long enough for the default policy to take a keyframe during it (about seven
// events per point: past 65536 events, while 2 x live faces is still fewer). The observer
// costs steps x slots, so no larger. "Slow": 25 s under the sanitizers, left out of that pass.
TEST(ReplayKeyframePolicy, DefaultPolicyOnALargerRunSlow) {
  TempDir dir("meshstep_replay_");
  const Pslg in = point_set(uniform(10000, 57));
  const TriangulateOptions options;
  const RecordedRun run = record_run(in, options, dir.file("run.mslog"));
  const replay::LogReader log(dir.file("run.mslog"));
  check_log_describes_run(log, run, options);
  check_keyframes(log, run, replay::KeyframePolicy{});
  EXPECT_GE(log.keyframes().size(), 2u) << log.event_count() << " events";
  check_verify(log);
}

// A log too big to keep its writes decoded reads them from its blocks: the same run, the
// same meshes everywhere (keyframes, blocks' ends and middles, forward and backward).
// "Slow": 27 s under the sanitizers, left out of that pass.
TEST(ReplayWritesFromBlocks, ReplaysTheSameMeshesAsWritesKeptInMemorySlow) {
  TempDir dir("meshstep_replay_");
  const Pslg in = point_set(uniform(10000, 58));
  const TriangulateOptions options;
  const RecordedRun run = record_run(in, options, dir.file("run.mslog"));
  const replay::LogReader kept(dir.file("run.mslog"));
  const replay::LogReader from_blocks(dir.file("run.mslog"), 0);
  ASSERT_GE(from_blocks.blocks().size(), 3u);
  check_log_describes_run(from_blocks, run, options);
  replay::Replay a(kept, true), b(from_blocks, true);
  std::vector<std::uint64_t> targets = {from_blocks.event_count(), 0, from_blocks.event_count() / 2, 1};
  for (const replay::BlockInfo& block : from_blocks.blocks())
    targets.insert(targets.end(), {block.first_event + block.event_count, block.first_event + block.event_count / 2});
  for (const replay::KeyframeInfo& k : from_blocks.keyframes()) targets.insert(targets.end(), {k.event + 1, k.event - 1});
  for (const std::uint64_t t : targets) {
    a.seek_event(t);
    b.seek_event(t);
    ASSERT_EQ(b.position(), a.position());
    ASSERT_EQ(b.slots(), a.slots()) << "at event " << t;
    ASSERT_EQ(b.hash(), a.hash()) << "at event " << t;
  }
  b.walk_to(0);
  EXPECT_EQ(b.live_faces(), 0u);
  check_verify(from_blocks);
}

// face_hash is symmetric in the three vertices: it sees neither the rotation nor the
// orientation of a face, only its vertices and which edges are constrained; mesh_hash is
// a sum, blind to slots.
TEST(ReplayMeshHash, FaceHashIsSymmetricInTheVertices) {
  FaceRecord r;
  r.v = {7, 3, 11};
  r.constrained = 0b001;  // the edge 7-3
  FaceRecord rotated;
  rotated.v = {3, 11, 7};
  rotated.constrained = 0b100;  // the edge 7-3 again
  FaceRecord reversed;
  reversed.v = {3, 7, 11};
  reversed.constrained = 0b001;  // 3-7
  EXPECT_EQ(replay::face_hash(r), replay::face_hash(rotated));
  EXPECT_EQ(replay::face_hash(r), replay::face_hash(reversed));
  EXPECT_EQ(replay::face_hash(r), replay::face_hash(replay::canonical(r)));
  EXPECT_EQ(replay::face_hash(rotated), replay::face_hash(replay::canonical(rotated)));
  FaceRecord other_edge = r;
  other_edge.constrained = 0b010;  // 3-11
  EXPECT_NE(replay::face_hash(r), replay::face_hash(other_edge));
  FaceRecord unconstrained = r;
  unconstrained.constrained = 0;
  EXPECT_NE(replay::face_hash(r), replay::face_hash(unconstrained));
  FaceRecord other_vertex = r;
  other_vertex.v[2] = 12;
  EXPECT_NE(replay::face_hash(r), replay::face_hash(other_vertex));
  FaceRecord ghost;
  ghost.v = {3, kInfiniteVertex, 7};
  EXPECT_NE(replay::face_hash(ghost), 0u);
  EXPECT_EQ(replay::face_hash(FaceRecord{}), 0u);

  const Slots a = {r, FaceRecord{}, ghost, other_edge};
  const Slots b = {other_edge, ghost, FaceRecord{}, FaceRecord{}, rotated};
  EXPECT_EQ(replay::mesh_hash(a), replay::mesh_hash(b));
  EXPECT_NE(fingerprint(a), fingerprint(b));  // the test's own slot-exact fingerprint sees slots
  Slots c = a;
  c[0] = reversed;
  EXPECT_EQ(replay::mesh_hash(a), replay::mesh_hash(c));
  EXPECT_NE(fingerprint(a), fingerprint(c));  // and orientation
  c[0] = rotated;
  EXPECT_NE(fingerprint(a), fingerprint(c));  // and rotation
}

// ---------------------------------------------------------------------------------------
// Failed runs leave nothing behind; a run in progress has a readable prefix.

TEST(ReplayFailedRun, ThrowingRunLeavesNeitherLogNorPartial) {
  const Pslg collinear = point_set({{0, 0}, {1, 1}, {2, 2}});
  for (TriangulateOptions options : testing::all_configurations()) {
    SCOPED_TRACE(testing::describe(options));
    TempDir dir("meshstep_replay_");
    const std::string path = dir.file("run.mslog");
    {
      replay::LogWriter writer(path, header_for(collinear, options));
      EXPECT_TRUE(fs::exists(path + ".partial"));
      options.record = &writer;
      EXPECT_THROW(triangulate(collinear, options), InputError);
    }
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".partial"));
    EXPECT_TRUE(dir.entries().empty());
  }
}

struct RunAborted : std::runtime_error {
  RunAborted() : std::runtime_error("aborted by the test") {}
};

// Waits (a bounded time) until the writer's thread has put at least one block after the
// header into the partial file.
bool wait_for_blocks(const std::string& partial) {
  for (int i = 0; i < 500; ++i) {
    std::error_code ec;
    if (fs::file_size(partial, ec) > 1024 && !ec) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// What a reader makes of the partial file of a run still in progress, after `hashes` (the
// mesh hash at every step boundary so far) were observed.
void check_partial_prefix(const std::string& partial, const std::vector<std::uint64_t>& hashes) {
  ASSERT_TRUE(wait_for_blocks(partial)) << "no block reached " << partial;
  const replay::LogReader log(partial);
  EXPECT_FALSE(log.complete());
  EXPECT_FALSE(log.incomplete_reason().empty());
  ASSERT_GT(log.blocks().size(), 0u);
  EXPECT_LT(log.step_count(), hashes.size());
  for (const replay::BlockInfo& b : log.blocks()) EXPECT_EQ(b.mesh_hash, 0u);
  // The prefix replays to the observed mesh at every step boundary it holds.
  replay::Replay r(log, /*track_hash=*/true);
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    r.seek_step(k);
    ASSERT_EQ(r.position(), log.step_start(k));
    EXPECT_EQ(r.hash(), hashes[k]) << "step " << k << " of the prefix";
  }
  r.seek_event(log.event_count());
  EXPECT_EQ(r.position(), log.event_count());
  EXPECT_EQ(r.hash(), replay::mesh_hash(r.slots()));
  // (The prefix ends where a block ended, usually in the middle of a step: the step
  // boundaries above are where it meets the observed meshes.)
  // Its keyframes (whichever the writer's thread has written so far) are the algorithm's
  // mesh at their step boundaries; the end-of-run keyframe is not there.
  replay::Replay walk(log, /*track_hash=*/true);
  for (std::size_t j = 0; j < log.keyframes().size(); ++j) {
    const replay::KeyframeInfo& kf = log.keyframes()[j];
    ASSERT_LE(kf.event, log.event_count());
    const auto k = boundary_at(log, kf.event);
    ASSERT_TRUE(k.has_value()) << "keyframe " << j << " off a step boundary";
    ASSERT_LT(*k, hashes.size());
    EXPECT_EQ(kf.mesh_hash, hashes[*k]) << "keyframe " << j;
    walk.walk_to(kf.event);
    EXPECT_TRUE(same_slots(walk.slots(), log.keyframe(j))) << "keyframe " << j;
    EXPECT_EQ(walk.hash(), kf.mesh_hash) << "keyframe " << j;
  }
  ::testing::Test::RecordProperty("prefix_keyframes", static_cast<int>(log.keyframes().size()));
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_FALSE(report.ok);
  EXPECT_NE(report.problem.find("incomplete"), std::string::npos) << report.problem;
}

// The run dies in the middle: while it runs, the partial file opens as the prefix it holds
// (incomplete, replayable, not verifiable); once the writer is gone, nothing is left.
TEST(ReplayFailedRun, RunDyingMidwayLeavesAReadablePrefixThenNothing) {
  const Pslg in = point_set(uniform(4000, 41));
  TempDir dir("meshstep_replay_");
  const std::string path = dir.file("run.mslog");
  replay::LogWriterOptions writer_options;
  writer_options.block_bytes = 2048;
  writer_options.keyframes.factor = 0.5;  // keyframes in the prefix, when the writer got that far
  writer_options.keyframes.min_events = 1000;
  std::vector<std::uint64_t> hashes;
  {
    TriangulateOptions options;
    replay::LogWriter writer(path, header_for(in, options), writer_options);
    options.record = &writer;
    options.observe_steps = [&](const Slots& slots) {
      hashes.push_back(replay::mesh_hash(slots));
      if (hashes.size() < 3500) return;
      check_partial_prefix(path + ".partial", hashes);
      throw RunAborted();
    };
    EXPECT_THROW(triangulate(in, options), RunAborted);
    EXPECT_TRUE(fs::exists(path + ".partial"));
  }
  EXPECT_EQ(hashes.size(), 3500u);
  EXPECT_TRUE(dir.entries().empty());
}

// ---------------------------------------------------------------------------------------
// Truncated, damaged and foreign files.

std::vector<char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::vector<char>& bytes, std::size_t n) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(n));
}

// A log with several event blocks, keyframes and an end block.
class ReplayCorrupt : public ::testing::Test {
 protected:
  void SetUp() override {
    Pslg in = crossings_hole_and_t_junctions();
    for (const Point& p : uniform(150, 3, {0.1, 0.1}, {4.9, 4.9})) in.points.push_back(p);
    replay::LogWriterOptions o;
    o.block_bytes = 600;
    o.keyframes.factor = 0.5;
    o.keyframes.min_events = 60;
    original_ = dir_.file("original.mslog");
    replay::LogWriter writer(original_, header_for(in, {}), o);
    TriangulateOptions options;
    options.record = &writer;
    options.observe_steps = [this](const Slots& slots) {
      observed_.push_back(replay::mesh_hash(slots));
      final_slots_ = slots;
    };
    triangulate(in, options);
    writer.finish();
    bytes_ = read_bytes(original_);
    const replay::LogReader log(original_);
    ASSERT_TRUE(log.complete());
    ASSERT_GE(log.blocks().size(), 4u);
    ASSERT_GE(log.keyframes().size(), 3u);  // some during the run, and the final one
    ASSERT_EQ(observed_.size(), log.step_count() + 1);
    first_keyframe_ = log.keyframes().front().offset;
    last_keyframe_ = log.keyframes().back().offset;
    last_keyframe_end_ = last_keyframe_ + 56 + log.keyframes().back().stored_size;
    for (const auto& b : log.blocks()) block_spans_.push_back({b.offset, b.offset + 56 + b.stored_size});
    for (const auto& k : log.keyframes()) block_spans_.push_back({k.offset, k.offset + 56 + k.stored_size});
    std::sort(block_spans_.begin(), block_spans_.end());
    header_end_ = block_spans_.front().first;
    end_block_ = block_spans_.back().second;  // where the end block begins
    ASSERT_EQ(end_block_, last_keyframe_end_);  // the final keyframe comes right before it
    ASSERT_LT(end_block_, bytes_.size());
    // The mesh after each events block, as the original replays it (its keyframes, the
    // algorithm's own mesh, vouch for that replay: OriginalIsValid).
    replay::Replay r(log, /*track_hash=*/true);
    for (const auto& b : log.blocks()) {
      r.walk_to(b.first_event + b.event_count);
      block_end_hash_[b.offset + 56 + b.stored_size] = {r.position(), r.hash()};
    }
    for (const auto& k : log.keyframes()) keyframe_ends_.insert(k.offset + 56 + k.stored_size);
  }

  std::string message_of_open(const std::string& path) {
    try {
      const replay::LogReader log(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  TempDir dir_{"meshstep_replay_"};
  std::string original_;
  std::vector<char> bytes_;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> block_spans_;  // [header, end) of each block
  std::uint64_t header_end_ = 0, end_block_ = 0, first_keyframe_ = 0, last_keyframe_ = 0, last_keyframe_end_ = 0;
  std::map<std::uint64_t, std::pair<std::uint64_t, std::uint64_t>> block_end_hash_;  // file offset -> events, hash
  std::set<std::uint64_t> keyframe_ends_;  // file offsets
  std::vector<std::uint64_t> observed_;    // the mesh hash at every step boundary and at the end
  Slots final_slots_;                      // the algorithm's mesh at the end
};

TEST_F(ReplayCorrupt, OriginalIsValid) {
  const replay::LogReader log(original_);
  const replay::VerifyReport report = replay::verify(log);
  EXPECT_TRUE(report.ok) << report.problem;
  EXPECT_EQ(report.keyframes_checked, 3 * log.keyframes().size() - 1);
  EXPECT_EQ(log.final_hash(), observed_.back());
  EXPECT_TRUE(same_slots(log.keyframe(log.keyframes().size() - 1), final_slots_));
  for (std::uint64_t k = 0; k < log.step_count(); ++k) {
    replay::Replay r(log);
    r.seek_step(k);
    ASSERT_EQ(r.hash(), observed_[k]) << "step " << k;
  }
}

TEST_F(ReplayCorrupt, TruncatedLogsOpenAsTheirPrefixAndNeverVerify) {
  std::set<std::uint64_t> cuts;
  for (std::uint64_t n = 0; n < header_end_; n += 1 + n / 16) cuts.insert(n);
  cuts.insert(header_end_ - 1);
  for (const auto& [begin, end] : block_spans_)
    for (const std::uint64_t n : {begin, begin + 1, begin + 4, begin + 28, begin + 55, begin + 56,
                                  begin + 57, (begin + 56 + end) / 2, end - 1})
      cuts.insert(n);
  for (std::uint64_t n = end_block_; n < bytes_.size(); ++n) cuts.insert(n);  // inside the end block
  std::mt19937_64 rng(77);
  std::uniform_int_distribution<std::uint64_t> anywhere(0, bytes_.size() - 1);
  for (int i = 0; i < 150; ++i) cuts.insert(anywhere(rng));

  const std::string path = dir_.file("cut.mslog");
  for (const std::uint64_t n : cuts) {
    ASSERT_LT(n, bytes_.size());
    SCOPED_TRACE("truncated to " + std::to_string(n) + " of " + std::to_string(bytes_.size()) + " bytes");
    write_bytes(path, bytes_, n);
    if (n < header_end_) {  // no prefix to speak of: the header is incomplete
      const std::string message = message_of_open(path);
      EXPECT_NE(message.find(path), std::string::npos) << message;
      continue;
    }
    std::unique_ptr<replay::LogReader> log;
    try {
      log = std::make_unique<replay::LogReader>(path);
    } catch (const InputError& e) {
      // Allowed by the contract only with the file named; but a cut after the header
      // should give a prefix (log_reader.hpp), so say so.
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      ADD_FAILURE() << "a log cut after its header did not open as a prefix: " << e.what();
      continue;
    }
    EXPECT_FALSE(log->complete());
    EXPECT_FALSE(log->incomplete_reason().empty());
    EXPECT_EQ(log->final_hash(), 0u);  // only an end block has one
    // The prefix holds exactly the event blocks and keyframes that end before the cut.
    std::uint64_t events = 0, hash = 0;
    for (const auto& [end, info] : block_end_hash_)
      if (end <= n) std::tie(events, hash) = info;
    EXPECT_EQ(log->event_count(), events);
    const auto keyframes = static_cast<std::size_t>(
        std::distance(keyframe_ends_.begin(), keyframe_ends_.upper_bound(n)));
    ASSERT_EQ(log->keyframes().size(), keyframes);
    for (const replay::BlockInfo& b : log->blocks()) EXPECT_EQ(b.mesh_hash, 0u);
    // It replays to the mesh the original replays to there, and to the algorithm's mesh at
    // every step boundary it holds (and at each of its keyframes).
    replay::Replay r(*log, /*track_hash=*/true);
    r.seek_event(log->event_count());
    EXPECT_EQ(r.hash(), hash);
    for (std::uint64_t k = 0; k < log->step_count(); ++k) {
      r.seek_step(k);
      ASSERT_EQ(r.hash(), observed_[k]) << "step " << k << " of the prefix";
    }
    for (std::size_t j = 0; j < keyframes; ++j) {
      r.walk_to(log->keyframes()[j].event);  // not seek_event: it could restore that very keyframe
      EXPECT_TRUE(same_slots(r.slots(), log->keyframe(j))) << "keyframe " << j;
      EXPECT_EQ(r.hash(), log->keyframes()[j].mesh_hash) << "keyframe " << j;
    }
    if (n >= last_keyframe_end_) {  // cut inside the end block: every event and keyframe is there
      EXPECT_EQ(r.hash(), observed_.back());
      EXPECT_TRUE(same_slots(log->keyframe(keyframes - 1), final_slots_));
    }
    const replay::VerifyReport report = replay::verify(*log);
    EXPECT_FALSE(report.ok);
    EXPECT_FALSE(report.problem.empty());
  }
}

// A damaged log must either fail to open (an InputError naming the file) or fail
// verification; counts which of the two happened.
void expect_rejected(const std::string& path, std::size_t& rejected_on_open, std::size_t& rejected_by_verify) {
  try {
    const replay::LogReader log(path);
    const replay::VerifyReport report = replay::verify(log);
    EXPECT_FALSE(report.ok) << "a damaged log verified";
    EXPECT_FALSE(report.problem.empty());
    ++rejected_by_verify;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    ++rejected_on_open;
  }
}

TEST_F(ReplayCorrupt, FlippedBytesAreReportedNeverReplayed) {
  std::set<std::uint64_t> positions;
  for (std::uint64_t i = 0; i < header_end_; ++i) positions.insert(i);
  // Every byte of the first and last block headers, of the first keyframe's and of the
  // end block; a random sample of the rest.
  for (const std::uint64_t begin : {block_spans_.front().first, block_spans_.back().first, first_keyframe_})
    for (std::uint64_t i = begin; i < begin + 56; ++i) positions.insert(i);
  for (std::uint64_t i = end_block_; i < bytes_.size(); ++i) positions.insert(i);
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<std::uint64_t> anywhere(0, bytes_.size() - 1);
  for (int i = 0; i < 600; ++i) positions.insert(anywhere(rng));

  const std::string path = dir_.file("flipped.mslog");
  std::size_t rejected_on_open = 0, rejected_by_verify = 0;
  for (const std::uint64_t at : positions) {
    std::vector<char> damaged = bytes_;
    damaged[at] = static_cast<char>(damaged[at] ^ (1 << (rng() % 8)));
    write_bytes(path, damaged, damaged.size());
    SCOPED_TRACE("byte " + std::to_string(at) + " flipped");
    expect_rejected(path, rejected_on_open, rejected_by_verify);
  }
  EXPECT_GT(rejected_on_open, positions.size() / 2);  // checksums catch almost all of it
  RecordProperty("rejected_by_verify", static_cast<int>(rejected_by_verify));
}

// The final keyframe is what the whole replay is checked against at the end: a log whose
// final keyframe was altered on disk (one bit of its payload or of its header, nothing
// recomputed) must not open, or must fail verification.
TEST_F(ReplayCorrupt, AlteredFinalKeyframeIsRejected) {
  const std::string path = dir_.file("altered.mslog");
  std::size_t rejected_on_open = 0, rejected_by_verify = 0;
  // Every byte of its header and the first and last of its payload, a sample of the rest
  // (each try decodes and verifies the whole log); a bit of each.
  std::set<std::uint64_t> positions;
  const std::uint64_t payload = last_keyframe_ + 56;
  for (std::uint64_t at = last_keyframe_; at < std::min(payload + 32, last_keyframe_end_); ++at) positions.insert(at);
  for (std::uint64_t at = std::max(payload, last_keyframe_end_ - 32); at < last_keyframe_end_; ++at) positions.insert(at);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::uint64_t> inside(payload, last_keyframe_end_ - 1);
  for (int i = 0; i < 100; ++i) positions.insert(inside(rng));
  for (const std::uint64_t at : positions) {
    const int bit = static_cast<int>(at % 8);
    SCOPED_TRACE("bit " + std::to_string(bit) + " of byte " + std::to_string(at) + " flipped (final keyframe at " +
                 std::to_string(last_keyframe_) + ", payload from " + std::to_string(payload) + ")");
    std::vector<char> damaged = bytes_;
    damaged[at] = static_cast<char>(damaged[at] ^ (1 << bit));
    write_bytes(path, damaged, damaged.size());
    expect_rejected(path, rejected_on_open, rejected_by_verify);
  }
  EXPECT_EQ(rejected_on_open + rejected_by_verify, positions.size());
  RecordProperty("rejected_by_verify", static_cast<int>(rejected_by_verify));
}

TEST_F(ReplayCorrupt, ForeignFilesAndNewerVersionsAreNamed) {
  const std::string node = dir_.write("points.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n");
  std::string message = message_of_open(node);
  EXPECT_NE(message.find(node), std::string::npos) << message;
  EXPECT_NE(message.find("not a meshstep replay log"), std::string::npos) << message;

  const std::string empty = dir_.write("empty.mslog", "");
  message = message_of_open(empty);
  EXPECT_NE(message.find(empty), std::string::npos) << message;
  EXPECT_NE(message.find("not a meshstep replay log"), std::string::npos) << message;

  std::vector<char> newer = bytes_;
  const std::uint32_t version = 99;
  std::memcpy(newer.data() + 8, &version, 4);
  const std::string newer_path = dir_.file("newer.mslog");
  write_bytes(newer_path, newer, newer.size());
  message = message_of_open(newer_path);
  EXPECT_NE(message.find(newer_path), std::string::npos) << message;
  EXPECT_NE(message.find("format version"), std::string::npos) << message;
  EXPECT_NE(message.find("99"), std::string::npos) << message;

  std::vector<char> longer = bytes_;
  longer.insert(longer.end(), {'x', 'y', 'z'});
  const std::string longer_path = dir_.file("longer.mslog");
  write_bytes(longer_path, longer, longer.size());
  message = message_of_open(longer_path);
  EXPECT_NE(message.find(longer_path), std::string::npos) << message;

  const std::string missing = dir_.file("missing.mslog");
  message = message_of_open(missing);
  EXPECT_NE(message.find(missing), std::string::npos) << message;
}

}  // namespace
}  // namespace meshstep
