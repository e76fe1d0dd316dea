// make_points N OUT.node [SEED]
//
// Writes N uniform random points of the unit square (the same points the benchmark
// programs use for that seed) as a Triangle .node file: header "N 2 0 0", then one line
// "index x y" per vertex, numbered from 1, coordinates as the shortest decimal strings
// that read back to the same doubles. Used to time and measure the whole
//   meshstep triangulate OUT.node --no-output
// process (see docs/benchmarks.md).
//
// Exit status: 0 written, 1 cannot write, 2 usage error.
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "bench_args.hpp"
#include "random_points.hpp"

namespace {

int usage(const char* message) {
  std::fprintf(stderr, "make_points: error: %s\nusage: make_points N OUT.node [SEED]\n", message);
  return 2;
}

using meshstep::bench::parse_whole;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) return usage("expected 2 or 3 arguments");
  std::uint64_t n = 0;
  if (!parse_whole(argv[1], n) || n == 0 || n > 0xFFFFFFFEull) {
    return usage("N must be an integer between 1 and 4294967294");
  }
  std::uint64_t seed = meshstep::bench::kDefaultSeed;
  if (argc == 4 && !parse_whole(argv[3], seed)) return usage("SEED must be an unsigned integer");
  const char* path = argv[2];

  const std::vector<meshstep::Point> points =
      meshstep::bench::uniform_points(static_cast<std::size_t>(n), seed);

  std::FILE* out = std::fopen(path, "wb");
  if (!out) {
    std::fprintf(stderr, "make_points: error: %s: %s\n", path, std::strerror(errno));
    return 1;
  }
  std::fprintf(out, "# %llu uniform random points in [0,1)^2, seed %llu (meshstep make_points)\n",
               static_cast<unsigned long long>(n), static_cast<unsigned long long>(seed));
  std::fprintf(out, "%llu 2 0 0\n", static_cast<unsigned long long>(n));

  // Lines are assembled in a large buffer and written in blocks.
  std::string buffer;
  buffer.reserve(1 << 20);
  char field[64];
  bool ok = true;
  for (std::size_t i = 0; i < points.size() && ok; ++i) {
    auto put = [&](auto value) {
      const auto result = std::to_chars(field, field + sizeof field, value);
      buffer.append(field, result.ptr);
    };
    put(i + 1);
    buffer.push_back(' ');
    put(points[i].x);
    buffer.push_back(' ');
    put(points[i].y);
    buffer.push_back('\n');
    if (buffer.size() > (1u << 20) - 128) {
      ok = std::fwrite(buffer.data(), 1, buffer.size(), out) == buffer.size();
      buffer.clear();
    }
  }
  if (ok && !buffer.empty()) ok = std::fwrite(buffer.data(), 1, buffer.size(), out) == buffer.size();
  if (std::fclose(out) != 0) ok = false;
  if (!ok) {
    std::fprintf(stderr, "make_points: error: %s: write failed\n", path);
    return 1;
  }
  return 0;
}
