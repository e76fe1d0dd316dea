// terrain_table [DIR] [--grids volcano,jacksboro_fault] [--bounds 1,0.5,0.2,0.1] [--repeat 3]
//               [--meshstep PATH] [--hmm PATH | --hmm-source DIR | --no-hmm]
//               [--synthetic N] [--work DIR]
//
// docs/terrain.md's comparison with Michael Fogleman's hmm, as Markdown on standard output.
// For each grid DIR/NAME.png (a 16-bit heightmap; DIR/NAME.asc gives its metres) and each
// bound (percent of the height range) it runs, as whole processes,
//     meshstep terrain NAME.png -a lepp-surface | -a greedy --png-cell 1 --z-scale Z ...
//     hmm NAME.png OUT.stl -z Z -e BOUND
// so that both read the same pixels and build the same 3D geometry (x, y in pixels, z =
// raw / 65535 * Z). Z is the ASC's height range over its mean cell side: true to life.
//
// Every output is read back from its STL file and measured here by one code: triangles, the
// share whose smallest 3D angle is under 20 degrees (meshstep's definition), and the largest
// vertical error at every pixel, by linear interpolation inside each triangle against the
// PNG's heights. Time is wall clock of the whole process (median of --repeat runs, the
// programs taking turns), peak memory its ru_maxrss from wait4.
//
// --synthetic N: instead of (or, with DIR, after) the grids, a smooth random N x N 16-bit PNG
// (a sum of plane waves, fixed seed), greedy and hmm at 0.1%, one run each (N = 4096: seconds
// a run, and a large file), peak memory against 3x the grid as float32 (N * N * 12 bytes).
//
// hmm is built on first use into hmm/ beside this program, from a copy of --hmm-source
// (the shared peers folder is read-only); when that folder is absent hmm is skipped.
//
// Exit status: 0 ok, 1 a run failed or a meshstep output missed its bound by our measure,
// 2 usage error or unreadable input.
#include <zlib.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bench_args.hpp"
#include "whole_process.hpp"
#include "meshstep/io/surface_io.hpp"
#include "meshstep/terrain/height_grid.hpp"

#ifndef MESHSTEP_HMM_SOURCE
#define MESHSTEP_HMM_SOURCE "/work/shared/peers/hmm"
#endif

namespace {

using namespace meshstep;
namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: terrain_table [DIR] [--grids volcano,jacksboro_fault] [--bounds 1,0.5,0.2,0.1] [--repeat 3]\n"
    "                     [--meshstep PATH] [--hmm PATH | --hmm-source DIR | --no-hmm]\n"
    "                     [--synthetic N] [--work DIR]\n"
    "Compares meshstep terrain (lepp-surface, greedy) with hmm on DIR/NAME.png (DIR/NAME.asc for\n"
    "its units); --synthetic N adds a smooth random N x N grid (greedy and hmm at 0.1%).\n";

int usage_error(const std::string& message) { return meshstep::bench::usage_error("terrain_table", message, kUsage); }

using meshstep::bench::parse_whole;

std::vector<std::string> split(std::string_view text) {
  std::vector<std::string> out;
  std::stringstream ss{std::string(text)};
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// ---------------------------------------------------------------------------------------
// Whole processes.

using meshstep::bench::load_average;
using meshstep::bench::Process;
using meshstep::bench::program_dir;
using meshstep::bench::run_process;

std::optional<fs::path> find_meshstep(const std::string& given) {
  if (!given.empty()) return fs::exists(given) ? std::optional<fs::path>(given) : std::nullopt;
  for (const fs::path& p : {program_dir() / "meshstep", program_dir() / ".." / ".." / "app" / "meshstep"})
    if (fs::exists(p)) return fs::weakly_canonical(p);
  return std::nullopt;
}

// hmm's binary: the one given, else hmm/bin/release/hmm beside this program, built there
// from a writable copy of the source on first use. nullopt (with the reason on stderr) skips it.
std::optional<fs::path> find_or_build_hmm(const std::string& given, const fs::path& source) {
  if (!given.empty()) return fs::exists(given) ? std::optional<fs::path>(given) : std::nullopt;
  if (!fs::exists(source / "Makefile")) {  // the peer is gone: so is the comparison
    std::fprintf(stderr, "terrain_table: hmm skipped: %s is absent\n", source.c_str());
    return std::nullopt;
  }
  const fs::path dest = program_dir() / "hmm", binary = dest / "bin" / "release" / "hmm";
  if (fs::exists(binary)) return binary;
  const fs::path log = program_dir() / "hmm_build.log";
  std::fprintf(stderr, "terrain_table: building hmm from %s into %s (log: %s)\n", source.c_str(), dest.c_str(),
               log.c_str());
  const std::string command = "rm -rf '" + dest.string() + "' && cp -R --no-preserve=mode '" + source.string() +
                              "' '" + dest.string() + "' && make -C '" + dest.string() + "' -j2 > '" + log.string() +
                              "' 2>&1";
  if (std::system(command.c_str()) != 0 || !fs::exists(binary)) {
    std::fprintf(stderr, "terrain_table: hmm skipped: its build failed (see %s)\n", log.c_str());
    return std::nullopt;
  }
  return binary;
}

// ---------------------------------------------------------------------------------------
// The heights both programs read, and the independent measure of a surface against them.

// The PNG's raw 16-bit values, row j = 0 the bottom row of the picture. meshstep's reader puts
// the picture's top row at the largest y, and hmm writes pixel (x, row) at y = height - 1 -
// row: so both place raw(i, j) at (i, j, raw / 65535 * z_scale), and so does this.
struct Truth {
  std::size_t nx = 0, ny = 0;
  std::vector<std::uint16_t> raw;
  double z_scale = 1.0;
  double height(std::size_t i, std::size_t j) const { return raw[j * nx + i] / 65535.0 * z_scale; }
};

// Read with meshstep's reader (stb_image underneath, as in hmm) scaled to 0..65535, so that
// its float values are the raw integers exactly.
Truth read_truth(const fs::path& png, double z_scale) {
  const terrain::HeightGrid g =
      terrain::read_height_grid(png.string(), {.png_cell = 1.0, .png_z_scale = 65535.0, .geographic = std::nullopt});
  Truth t{g.nx, g.ny, std::vector<std::uint16_t>(g.z.size()), z_scale};
  for (std::size_t k = 0; k < g.z.size(); ++k) t.raw[k] = static_cast<std::uint16_t>(std::lround(g.z[k]));
  return t;
}

struct Measured {
  std::size_t triangles = 0;
  double max_error = 0.0;      // largest |surface - height| over every pixel, in z units
  std::size_t uncovered = 0;   // pixels inside no triangle
  std::size_t flat = 0;        // triangles of zero area in the plane
  double share_under_20 = 0.0;
};

// meshstep's definition (terrain::angle_stats_3d): the smallest interior angle, in 3D.
double smallest_angle_deg(const Point3& a, const Point3& b, const Point3& c) {
  const Point3* p[3] = {&a, &b, &c};
  double smallest = 180.0;
  for (int k = 0; k < 3; ++k) {
    const Point3 &o = *p[k], &s = *p[(k + 1) % 3], &t = *p[(k + 2) % 3];
    const double u[3] = {s.x - o.x, s.y - o.y, s.z - o.z}, v[3] = {t.x - o.x, t.y - o.y, t.z - o.z};
    const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    const double cross = std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    smallest = std::min(smallest, std::atan2(cross, dot) * 180.0 / std::numbers::pi);
  }
  return smallest;
}

using I64 = long long;
I64 floor_div(I64 n, I64 d) { return n / d - ((n % d != 0) && ((n < 0) != (d < 0))); }  // d != 0
I64 ceil_div(I64 n, I64 d) { return -floor_div(-n, d); }

struct Pixel {
  I64 x, y;
};
// Twice the signed area of (p, q, r): positive when counter-clockwise. Exact on pixels.
I64 edge(Pixel p, Pixel q, Pixel r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); }

Measured measure(const io::Surface& s, const Truth& t) {
  // Every vertex must sit on a pixel: STL's float32 holds integers below 2^24 exactly.
  std::vector<Pixel> pixel(s.vertices.size());
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    const Point3& p = s.vertices[v];
    pixel[v] = {std::llround(p.x), std::llround(p.y)};
    if (std::abs(p.x - pixel[v].x) > 1e-3 || std::abs(p.y - pixel[v].y) > 1e-3 || pixel[v].x < 0 ||
        pixel[v].y < 0 || pixel[v].x >= static_cast<I64>(t.nx) || pixel[v].y >= static_cast<I64>(t.ny))
      throw std::runtime_error("vertex (" + number(p.x) + ", " + number(p.y) + ") is not on a pixel of the grid");
  }
  Measured m;
  m.triangles = s.triangles.size();
  std::vector<std::uint8_t> covered(t.nx * t.ny, 0);
  std::size_t under20 = 0;
  for (const auto& tri : s.triangles) {
    under20 += smallest_angle_deg(s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]) < 20.0;
    std::array<std::uint32_t, 3> v = tri;
    I64 area = edge(pixel[v[0]], pixel[v[1]], pixel[v[2]]);
    if (area == 0) {
      ++m.flat;
      continue;
    }
    if (area < 0) std::swap(v[1], v[2]), area = -area;  // hmm's triangles face either way
    const Pixel a = pixel[v[0]], b = pixel[v[1]], c = pixel[v[2]];
    const double za = s.vertices[v[0]].z, zb = s.vertices[v[1]].z, zc = s.vertices[v[2]].z;
    // The weight of each corner is the edge function of the opposite side, linear in x
    // along a row: w(x) = A x + B(y). Inside (edges included): all three >= 0.
    const std::array<std::pair<Pixel, Pixel>, 3> sides = {{{b, c}, {c, a}, {a, b}}};
    const I64 x_min = std::min({a.x, b.x, c.x}), x_max = std::max({a.x, b.x, c.x});
    for (I64 y = std::min({a.y, b.y, c.y}); y <= std::max({a.y, b.y, c.y}); ++y) {
      I64 lo = x_min, hi = x_max;
      std::array<I64, 3> A{}, B{};
      for (int k = 0; k < 3; ++k) {
        const auto [p, q] = sides[k];
        A[k] = p.y - q.y;
        B[k] = edge(p, q, {0, y});
        if (A[k] > 0) lo = std::max(lo, ceil_div(-B[k], A[k]));
        else if (A[k] < 0) hi = std::min(hi, floor_div(B[k], -A[k]));
        else if (B[k] < 0) hi = lo - 1;  // the whole row lies outside this side
      }
      for (I64 x = lo; x <= hi; ++x) {
        const double z = (static_cast<double>(A[0] * x + B[0]) * za + static_cast<double>(A[1] * x + B[1]) * zb +
                          static_cast<double>(A[2] * x + B[2]) * zc) /
                         static_cast<double>(area);
        const std::size_t i = static_cast<std::size_t>(x), j = static_cast<std::size_t>(y);
        m.max_error = std::max(m.max_error, std::abs(z - t.height(i, j)));
        covered[j * t.nx + i] = 1;
      }
    }
  }
  m.uncovered = static_cast<std::size_t>(std::count(covered.begin(), covered.end(), 0));
  m.share_under_20 = s.triangles.empty() ? 0.0 : static_cast<double>(under20) / static_cast<double>(s.triangles.size());
  return m;
}

// ---------------------------------------------------------------------------------------
// One cell of the table: the programs on one PNG at one bound.

enum Who { kLepp, kGreedy, kHmm };
constexpr const char* kWhoName[] = {"lepp-surface", "greedy", "hmm"};

struct Tools {
  fs::path meshstep;
  std::optional<fs::path> hmm;
  fs::path work;
};

struct Setup {
  std::string name;  // for file names and the table
  fs::path png;
  Truth truth;
  double fraction = 0.0;  // the bound as a fraction of full scale (hmm's -e)
  double bound() const { return fraction * truth.z_scale; }
};

struct Result {
  bool ran = false, failed = false;
  std::string failure;
  std::vector<double> ms;
  double peak_mb = 0.0;
  std::string stdout_text;  // of the last run
  Measured m;
  double median_ms() const {
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    return sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  }
};

std::vector<std::string> command(Who who, const Tools& tools, const Setup& s, const fs::path& out) {
  const std::string z = number(s.truth.z_scale);
  if (who == kHmm) return {tools.hmm->string(), s.png.string(), out.string(), "-z", z, "-e", number(s.fraction)};
  return {tools.meshstep.string(), "terrain", s.png.string(), "--max-error", number(s.bound()), "-a", kWhoName[who],
          "--png-cell", "1", "--z-scale", z, "--stats", "json", "-q", "-o", out.string()};
}

fs::path output_of(const Tools& tools, const Setup& s, Who w) {
  return tools.work / (s.name + "_" + number(100 * s.fraction) + "_" + kWhoName[w] + ".stl");
}

// Runs `who` `repeat` times each, the programs taking turns (starting one later each round);
// their STL files stay in the work folder for measure_outputs.
std::array<Result, 3> run_programs(const Tools& tools, const Setup& s, const std::vector<Who>& who, int repeat) {
  std::array<Result, 3> r;
  const fs::path out_file = tools.work / "stdout.txt", err_file = tools.work / "stderr.txt";
  for (int round = 0; round < repeat; ++round)
    for (std::size_t k = 0; k < who.size(); ++k) {
      const Who w = who[(k + static_cast<std::size_t>(round)) % who.size()];
      Result& res = r[w];
      if (res.failed) continue;
      const Process p = run_process(command(w, tools, s, output_of(tools, s, w)), out_file, err_file);
      res.ran = true;
      if (p.exit_status != 0) {
        res.failed = true;
        res.failure = "exit status " + std::to_string(p.exit_status) + ": " + read_text(err_file);
        continue;
      }
      res.ms.push_back(p.ms);
      res.peak_mb = std::max(res.peak_mb, p.peak_mb);
      res.stdout_text = read_text(out_file);
    }
  return r;
}

// Reads every output back, measures it against s.truth, and removes it.
void measure_outputs(const Tools& tools, const Setup& s, std::array<Result, 3>& r) {
  for (const Who w : {kLepp, kGreedy, kHmm})
    if (r[w].ran && !r[w].failed) {
      r[w].m = measure(io::read_surface(output_of(tools, s, w).string()), s.truth);
      fs::remove(output_of(tools, s, w));
    }
}

// A number after "key" in a program's output ("\"max_error\":" in meshstep's JSON line,
// "error = " in hmm's report).
std::optional<double> number_after(const std::string& text, const std::string& key) {
  const std::size_t at = text.rfind(key);
  if (at == std::string::npos) return std::nullopt;
  return std::strtod(text.c_str() + at + key.size(), nullptr);
}

// Bound met by our measure. STL rounds every coordinate to float32 (heights up to z_scale:
// 6e-8 of it); one 16-bit height step is 1.5e-5 of it, so 1e-6 forgives the rounding and no
// real miss.
bool within(const Measured& m, const Setup& s) {
  return m.uncovered == 0 && m.max_error <= s.bound() + 1e-6 * s.truth.z_scale;
}

// Where the programs' own figures disagree with ours, for the notes under the table.
void cross_check(const Setup& s, Who w, const Result& r, std::vector<std::string>& notes) {
  const std::string where = s.name + " " + number(100 * s.fraction) + "% " + kWhoName[w] + ": ";
  if (r.m.uncovered > 0) notes.push_back(where + std::to_string(r.m.uncovered) + " pixels in no triangle");
  if (r.m.flat > 0) notes.push_back(where + std::to_string(r.m.flat) + " triangles of zero area");
  // Its own figure (found in its output after `key`, times `scale`) against ours.
  const auto compare = [&](const char* what, const std::string& key, double scale, double ours, double tolerance) {
    const auto own = number_after(r.stdout_text, key);
    if (!own) notes.push_back(where + "its output has no " + what);
    else if (std::abs(*own * scale - ours) > tolerance)
      notes.push_back(where + "it reports " + what + " " + number(*own * scale) + ", we measure " + number(ours));
  };
  const double tolerance = 1e-6 * s.truth.z_scale;  // float32 STL coordinates (see within)
  if (w == kHmm) {
    // hmm prints its largest error as a fraction of full scale.
    compare("triangles", "triangles = ", 1.0, static_cast<double>(r.m.triangles), 0.0);
    compare("largest error", "error = ", s.truth.z_scale, r.m.max_error, tolerance);
    return;
  }
  compare("triangles", "\"triangles\":", 1.0, static_cast<double>(r.m.triangles), 0.0);
  compare("largest error", "\"max_error\":", 1.0, r.m.max_error, tolerance);
  // Not quite zero: a triangle within float32 rounding of 20 degrees may fall either side.
  compare("share under 20 degrees", "\"share_under_20\":", 1.0, r.m.share_under_20, 1e-9);
}

std::string mb(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

std::string ratio(double ours, double theirs) {
  if (!(theirs > 0)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", ours / theirs);
  return text;
}

// triangles | max error / bound | under 20 | ms
std::string columns(const Result& r, const Setup& s) {
  if (!r.ran) return " - | - | - | - |";
  if (r.failed) return " failed | - | - | - |";
  char text[160];
  std::snprintf(text, sizeof text, " %zu | %.4f%s | %.1f%% | %.1f |", r.m.triangles, r.m.max_error / s.bound(),
                within(r.m, s) ? "" : " (over)", 100.0 * r.m.share_under_20, r.median_ms());
  return text;
}

// ---------------------------------------------------------------------------------------
// The real grids.

struct GridInput {
  std::string name;
  fs::path png;
  Truth truth;
  std::string note;  // how the PNG matches the ASC, and the z-scale chosen
};

// The PNG must be the ASC's heights spread over the full 16-bit range: same size, raw 0 and
// 65535 present, and every sample within rounding of asc_low + raw / 65535 * range. The
// z-scale that makes pixels true to life is the range over the mean cell side (hmm's pixels
// are square: a grid with unequal sides is stretched one way and squeezed the other).
GridInput read_grid(const fs::path& dir, const std::string& name) {
  GridInput in{name, dir / (name + ".png"), {}, {}};
  const terrain::HeightGrid asc = terrain::read_height_grid((dir / (name + ".asc")).string());
  const auto [low, high] = asc.height_range();
  const double range = static_cast<double>(high) - static_cast<double>(low);
  const double cell = std::sqrt(asc.dx * asc.dy);
  in.truth = read_truth(in.png, range / cell);
  if (in.truth.nx != asc.nx || in.truth.ny != asc.ny)
    throw std::runtime_error(name + ": the PNG and the ASC differ in size");
  const auto [raw_low, raw_high] = std::minmax_element(in.truth.raw.begin(), in.truth.raw.end());
  double worst = 0.0;  // metres
  for (std::size_t j = 0; j < asc.ny; ++j)
    for (std::size_t i = 0; i < asc.nx; ++i)
      worst = std::max(worst, std::abs(asc.at(i, j) - (low + in.truth.raw[j * asc.nx + i] / 65535.0 * range)));
  char note[512];
  std::snprintf(note, sizeof note,
                "%s: %zu x %zu, cells %.4g m x %.4g m, heights %g..%g m (range %g m); PNG raw %u..%u, "
                "ASC = low + raw / 65535 * range within %.2g m everywhere (half a 16-bit step is %.2g m); "
                "z-scale %.6g = range / sqrt(dx * dy)",
                name.c_str(), asc.nx, asc.ny, asc.dx, asc.dy, low, high, range, *raw_low, *raw_high, worst,
                range / 65535.0 / 2.0, in.truth.z_scale);
  in.note = note;
  if (*raw_low != 0 || *raw_high != 65535 || worst > range / 65535.0)
    throw std::runtime_error(name + ": the PNG is not the ASC normalised to the full 16-bit range (" + note + ")");
  return in;
}

int grid_tables(const Tools& tools, const std::vector<GridInput>& grids, const std::vector<double>& bounds,
                int repeat) {
  std::vector<Who> who = {kLepp, kGreedy};
  if (tools.hmm) who.push_back(kHmm);
  int status = 0;
  std::vector<std::string> notes, memory;
  for (const GridInput& g : grids) std::printf("- %s\n", g.note.c_str());
  std::printf("\n| grid | bound | lepp-surface triangles | max err / bound | < 20° | ms "
              "| greedy triangles | max err / bound | < 20° | ms "
              "| hmm triangles | max err / bound | < 20° | ms "
              "| triangles lepp / greedy | lepp / hmm | < 20° lepp / greedy | lepp / hmm |\n"
              "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const GridInput& g : grids)
    for (const double percent : bounds) {
      const Setup s{g.name, g.png, g.truth, percent / 100.0};
      std::array<Result, 3> r = run_programs(tools, s, who, repeat);
      measure_outputs(tools, s, r);
      const auto ok = [&](Who w) { return r[w].ran && !r[w].failed; };
      const auto tri = [&](Who w) { return ok(w) ? static_cast<double>(r[w].m.triangles) : 0.0; };
      const auto u20 = [&](Who w) { return ok(w) ? r[w].m.share_under_20 : 0.0; };
      std::printf("| %s | %g%% |%s%s%s %s | %s | %s | %s |\n", g.name.c_str(), percent, columns(r[kLepp], s).c_str(),
                  columns(r[kGreedy], s).c_str(), columns(r[kHmm], s).c_str(),
                  ok(kLepp) ? ratio(tri(kLepp), tri(kGreedy)).c_str() : "-",
                  ok(kLepp) ? ratio(tri(kLepp), tri(kHmm)).c_str() : "-",
                  ok(kLepp) ? ratio(u20(kLepp), u20(kGreedy)).c_str() : "-",
                  ok(kLepp) ? ratio(u20(kLepp), u20(kHmm)).c_str() : "-");
      std::fflush(stdout);
      char line[256];
      std::snprintf(line, sizeof line, "| %s | %g%% | %.1f | %.1f | %s |\n", g.name.c_str(), percent,
                    r[kLepp].peak_mb, r[kGreedy].peak_mb, ok(kHmm) ? mb(r[kHmm].peak_mb).c_str() : "-");
      memory.push_back(line);
      for (const Who w : who) {
        if (r[w].failed) {
          notes.push_back(g.name + " " + number(percent) + "% " + kWhoName[w] + " failed: " + r[w].failure);
          status = 1;
        } else {
          cross_check(s, w, r[w], notes);
          if (w != kHmm && !within(r[w].m, s)) status = 1;  // meshstep missed its bound: a bug
        }
      }
    }
  std::printf("\nPeak resident memory (MB, ru_maxrss of the process):\n\n"
              "| grid | bound | lepp-surface | greedy | hmm |\n|---|--:|--:|--:|--:|\n");
  for (const std::string& line : memory) std::fputs(line.c_str(), stdout);
  if (!notes.empty()) std::printf("\nNotes:\n\n");
  for (const std::string& n : notes) std::printf("- %s\n", n.c_str());
  return status;
}

// ---------------------------------------------------------------------------------------
// The synthetic grid.

void append_u32(std::vector<unsigned char>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

void append_chunk(std::vector<unsigned char>& out, const char* type, const unsigned char* data, std::size_t size) {
  append_u32(out, static_cast<std::uint32_t>(size));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  // The CRC covers the type and the data.
  append_u32(out, static_cast<std::uint32_t>(crc32(0, out.data() + start, static_cast<uInt>(size + 4))));
}

// A 16-bit greyscale PNG, from the specification: the project's writer (scene/image.hpp)
// only does 8-bit RGBA, and hmm and meshstep both read heights from 16-bit grey.
void write_png16(const fs::path& path, std::size_t n, const std::vector<std::uint16_t>& raw) {
  std::vector<unsigned char> rows;  // each row: filter type 0, then big-endian samples
  rows.reserve(n * (1 + 2 * n));
  for (std::size_t y = 0; y < n; ++y) {
    rows.push_back(0);
    for (std::size_t x = 0; x < n; ++x) {
      const std::uint16_t v = raw[y * n + x];
      rows.push_back(static_cast<unsigned char>(v >> 8));
      rows.push_back(static_cast<unsigned char>(v & 0xFF));
    }
  }
  uLongf packed_size = compressBound(rows.size());
  std::vector<unsigned char> packed(packed_size);
  if (compress2(packed.data(), &packed_size, rows.data(), rows.size(), 1) != Z_OK)
    throw std::runtime_error("zlib cannot compress the synthetic grid");
  std::vector<unsigned char> file = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<unsigned char> header;
  append_u32(header, static_cast<std::uint32_t>(n));
  append_u32(header, static_cast<std::uint32_t>(n));
  header.insert(header.end(), {16, 0, 0, 0, 0});  // 16 bits, grey, deflate, filter 0, not interlaced
  append_chunk(file, "IHDR", header.data(), header.size());
  append_chunk(file, "IDAT", packed.data(), packed_size);
  append_chunk(file, "IEND", nullptr, 0);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(file.data()), static_cast<std::streamsize>(file.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// Twelve plane waves in random directions (no grid-aligned features), their wavelengths
// spread evenly in log scale from 32 pixels to the grid's width, each wave's amplitude in
// proportion to its wavelength (as terrain roughly goes): smooth at the pixel scale, and
// detail at every scale, so that a larger grid needs more triangles, as real terrain at a
// finer resolution would. Spread over 0..65535. Each wave is
// sin(a x + b y + phase) = sin(a x) cos(b y + phase) + cos(a x) sin(b y + phase): per-column
// and per-row tables instead of N * N sines.
std::vector<std::uint16_t> synthetic_heights(std::size_t n) {
  std::mt19937_64 rng(20240607);  // the engine's sequence is fixed by the standard
  const auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
  std::vector<double> h(n * n, 0.0);
  std::vector<double> sx(n), cx(n), sy(n), cy(n);
  const double shortest = std::min(32.0, static_cast<double>(n)), longest = static_cast<double>(n);
  for (int wave = 0; wave < 12; ++wave) {
    const double wavelength = shortest * std::pow(longest / shortest, uniform());
    const double direction = 2 * std::numbers::pi * uniform(), phase = 2 * std::numbers::pi * uniform();
    const double amplitude = wavelength;
    const double k = 2 * std::numbers::pi / wavelength;
    for (std::size_t i = 0; i < n; ++i) {
      sx[i] = std::sin(k * std::cos(direction) * static_cast<double>(i));
      cx[i] = std::cos(k * std::cos(direction) * static_cast<double>(i));
      sy[i] = std::sin(k * std::sin(direction) * static_cast<double>(i) + phase);
      cy[i] = std::cos(k * std::sin(direction) * static_cast<double>(i) + phase);
    }
    for (std::size_t y = 0; y < n; ++y)
      for (std::size_t x = 0; x < n; ++x) h[y * n + x] += amplitude * (sx[x] * cy[y] + cx[x] * sy[y]);
  }
  const auto [low, high] = std::minmax_element(h.begin(), h.end());
  std::vector<std::uint16_t> raw(n * n);
  for (std::size_t k = 0; k < n * n; ++k)
    raw[k] = static_cast<std::uint16_t>(std::lround((h[k] - *low) / (*high - *low) * 65535.0));
  return raw;
}

// What the program's own clock says the triangulation took, beside the whole process: with
// one run on a shared machine, the two together tell noise from a real difference.
// meshstep: ms.approximate of --stats json; hmm: its "triangulating... Ss" line (which also
// collects the points and triangles).
double own_triangulation_ms(Who w, const std::string& out) {
  if (w == kHmm) return 1000.0 * number_after(out, "triangulating... ").value_or(0.0);
  return number_after(out, "\"approximate\":").value_or(0.0);
}

int synthetic_table(const Tools& tools, std::size_t n) {
  const fs::path png = tools.work / ("synthetic_" + std::to_string(n) + ".png");
  {  // only the PNG is kept while the programs run
    const std::vector<std::uint16_t> raw = synthetic_heights(n);
    write_png16(png, n, raw);
  }
  const double z_scale = static_cast<double>(n) / 20.0;
  std::vector<Who> who = {kGreedy};
  if (tools.hmm) who.push_back(kHmm);
  // One run each (the grid is large: see the header); the heights are read back afterwards.
  Setup s{"synthetic_" + std::to_string(n), png, Truth{n, n, {}, z_scale}, 0.001};
  const std::string load = load_average();
  std::array<Result, 3> r = run_programs(tools, s, who, 1);
  s.truth = read_truth(png, z_scale);
  measure_outputs(tools, s, r);
  fs::remove(png);
  const double grid_mb = static_cast<double>(n) * static_cast<double>(n) * 4.0 * 3.0 / 1048576.0;
  std::printf("\nSynthetic %zu x %zu grid (twelve plane waves, 16-bit PNG), z-scale %g, bound 0.1%%; one run each "
              "(load average at the start: %s). 3x the grid as float32: %.1f MB.\n\n"
              "| program | triangles | max err / bound | < 20° | wall ms | triangulation ms (own timer) | peak MB "
              "| peak / (3x float32 grid) |\n"
              "|---|--:|--:|--:|--:|--:|--:|--:|\n",
              n, n, z_scale, load.c_str(), grid_mb);
  int status = 0;
  std::vector<std::string> notes;
  for (const Who w : who) {
    const Result& res = r[w];
    if (res.failed) {
      std::printf("| %s | failed | - | - | - | - | - | - |\n", kWhoName[w]);
      notes.push_back(std::string(kWhoName[w]) + " failed: " + res.failure);
      status = 1;
      continue;
    }
    std::printf("| %s | %zu | %.4f%s | %.1f%% | %.0f | %.0f | %.1f | %.2f |\n", kWhoName[w], res.m.triangles,
                res.m.max_error / s.bound(), within(res.m, s) ? "" : " (over)", 100.0 * res.m.share_under_20,
                res.median_ms(), own_triangulation_ms(w, res.stdout_text), res.peak_mb, res.peak_mb / grid_mb);
    cross_check(s, w, res, notes);
    if (w != kHmm && !within(res.m, s)) status = 1;
  }
  if (r[kHmm].ran && !r[kHmm].failed && !r[kGreedy].failed)
    std::printf("\ngreedy / hmm wall time: %s\n", ratio(r[kGreedy].median_ms(), r[kHmm].median_ms()).c_str());
  if (!notes.empty()) std::printf("\nNotes:\n\n");
  for (const std::string& note : notes) std::printf("- %s\n", note.c_str());
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names = {"volcano", "jacksboro_fault"};
  std::vector<double> bounds = {1, 0.5, 0.2, 0.1};
  int repeat = 3;
  std::size_t synthetic = 0;
  std::string dir, meshstep_path, hmm_path, hmm_source = MESHSTEP_HMM_SOURCE, work;
  bool no_hmm = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (arg == "--grids" && has_value) {
      names = split(argv[++i]);
    } else if (arg == "--bounds" && has_value) {
      bounds.clear();
      for (const std::string& b : split(argv[++i])) {
        double value = 0.0;
        if (!parse_whole(b, value) || !(value > 0.0 && value < 100.0))
          return usage_error("--bounds: '" + b + "' is not a percentage in (0, 100)");
        bounds.push_back(value);
      }
    } else if (arg == "--repeat" && has_value) {
      if (!parse_whole(argv[++i], repeat) || repeat < 1)
        return usage_error(std::string("--repeat: '") + argv[i] + "' is not a positive count");
    } else if (arg == "--synthetic" && has_value) {
      if (!parse_whole(argv[++i], synthetic) || synthetic < 2 || synthetic > 16384)
        return usage_error(std::string("--synthetic: '") + argv[i] + "' is not a size in 2..16384");
    } else if (arg == "--meshstep" && has_value) {
      meshstep_path = argv[++i];
    } else if (arg == "--hmm" && has_value) {
      hmm_path = argv[++i];
    } else if (arg == "--hmm-source" && has_value) {
      hmm_source = argv[++i];
    } else if (arg == "--no-hmm") {
      no_hmm = true;
    } else if (arg == "--work" && has_value) {
      work = argv[++i];
    } else if (dir.empty() && !arg.starts_with("-")) {
      dir = arg;
    } else {
      return usage_error(std::string("unexpected argument '") + argv[i] + "'");
    }
  }
  if (dir.empty() && synthetic == 0) return usage_error("no grid folder and no --synthetic");
  if (!dir.empty() && (names.empty() || bounds.empty())) return usage_error("no grids or no bounds");

  Tools tools;
  if (const auto found = find_meshstep(meshstep_path)) {
    tools.meshstep = *found;
  } else {
    std::fprintf(stderr, "terrain_table: error: no meshstep binary (give --meshstep PATH)\n");
    return 2;
  }
  if (no_hmm) std::fprintf(stderr, "terrain_table: hmm skipped (--no-hmm)\n");
  else tools.hmm = find_or_build_hmm(hmm_path, hmm_source);
  const bool temporary = work.empty();
  tools.work = temporary ? fs::temp_directory_path() / ("terrain_table_" + std::to_string(::getpid())) : fs::path(work);
  fs::create_directories(tools.work);

  int status = 0;
  try {
    if (!dir.empty()) {
      std::vector<GridInput> grids;
      try {
        for (const std::string& name : names) grids.push_back(read_grid(dir, name));
      } catch (const std::exception& e) {
        std::fprintf(stderr, "terrain_table: error: %s\n", e.what());
        if (temporary) fs::remove_all(tools.work);
        return 2;
      }
      std::printf("meshstep: %s; hmm: %s; median of %d runs each; load average at the start: %s\n\n",
                  tools.meshstep.c_str(), tools.hmm ? tools.hmm->c_str() : "skipped", repeat, load_average().c_str());
      status = std::max(status, grid_tables(tools, grids, bounds, repeat));
    }
    if (synthetic > 0) status = std::max(status, synthetic_table(tools, synthetic));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "terrain_table: error: %s\n", e.what());
    status = 1;
  }
  if (temporary) fs::remove_all(tools.work);
  return status;
}
