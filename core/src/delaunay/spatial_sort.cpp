#include "meshstep/delaunay/spatial_sort.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <utility>

#include "meshstep/huge_pages.hpp"
#include "meshstep/release.hpp"

namespace meshstep {
namespace {

constexpr int kGridBits = 16;
constexpr std::uint32_t kGridMax = (1u << kGridBits) - 1;
constexpr std::size_t kResortRun = 32;  // cells holding more points than this are re-sorted
constexpr int kMaxDepth = 6;
constexpr std::size_t kFirstRound = 64;  // BRIO: the smallest round

// The Hilbert curve, level by level from the top bit: the orientation of the curve inside
// the current cell is one of four states (whether x and y are swapped, whether both are
// reflected). A state and the next bit of x and of y give the key's next two bits and the
// orientation inside the chosen quadrant; the 16 answers are tabulated once.
struct HilbertStep {
  std::uint8_t digit;
  std::uint8_t state;  // bit 0: swapped, bit 1: reflected
};

constexpr std::array<HilbertStep, 16> make_hilbert_table() {
  std::array<HilbertStep, 16> table{};
  for (unsigned state = 0; state < 4; ++state)
    for (unsigned bits = 0; bits < 4; ++bits) {
      unsigned x = (bits >> 1) & 1, y = bits & 1;
      const bool swapped = state & 1, reflected = state & 2;
      if (reflected) x ^= 1, y ^= 1;
      if (swapped) std::swap(x, y);
      unsigned next = state;
      if (y == 0) {
        next ^= 1;              // the lower-left and lower-right quadrants swap the axes...
        if (x == 1) next ^= 2;  // ...and the lower-right one also reflects them
      }
      table[state * 4 + bits] = {static_cast<std::uint8_t>((3 * x) ^ y), static_cast<std::uint8_t>(next)};
    }
  return table;
}

constexpr std::array<HilbertStep, 16> kHilbertTable = make_hilbert_table();

// Position of cell (x, y) along the Hilbert curve of a 2^16 x 2^16 grid, to `levels`
// levels (the key's low bits stay 0 below that: coarser, cheaper keys for small rounds).
std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y, int levels = kGridBits) {
  std::uint32_t key = 0;
  unsigned state = 0;
  for (int level = kGridBits - 1; level >= kGridBits - levels; --level) {
    const unsigned bits = (((x >> level) & 1) << 1) | ((y >> level) & 1);
    const HilbertStep step = kHilbertTable[state * 4 + bits];
    key = (key << 2) | step.digit;
    state = step.state;
  }
  return key << (2 * (kGridBits - levels));
}

std::uint32_t to_grid(double v, double lo, double scale) {
  const double g = (v - lo) * scale;
  return g <= 0.0 ? 0u : g >= kGridMax ? kGridMax : static_cast<std::uint32_t>(g);
}

// Maps points of a box to Hilbert keys, with about 16 grid cells per point.
class KeyGrid {
 public:
  KeyGrid(const BBox& box, std::size_t count) : lo_(box.lo) {
    const double wx = box.hi.x - box.lo.x, wy = box.hi.y - box.lo.y;
    valid_ = wx > 0.0 || wy > 0.0;
    sx_ = wx > 0.0 ? kGridMax / wx : 0.0;
    sy_ = wy > 0.0 ? kGridMax / wy : 0.0;
    while (levels_ < kGridBits && (std::size_t{1} << (2 * levels_)) < 16 * count) ++levels_;
  }
  bool valid() const { return valid_; }
  std::uint32_t key(const Point& p) const {
    return hilbert_key(to_grid(p.x, lo_.x, sx_), to_grid(p.y, lo_.y, sy_), levels_);
  }

 private:
  Point lo_;
  double sx_ = 0.0, sy_ = 0.0;
  int levels_ = 2;
  bool valid_ = false;
};

// LSD radix sort of (key << 32 | index) items by their 32-bit key: digits of 11, 11 and 10
// bits, small enough for the bucket heads to stay in cache. Stable, so equal keys stay in
// index order.
void radix_sort_by_key(std::span<std::uint64_t> items, std::vector<std::uint64_t>& scratch) {
  resize_huge(scratch, items.size());
  std::array<std::uint32_t, 2048> count;
  std::span<std::uint64_t> from = items, to{scratch.data(), items.size()};
  for (int shift = 32; shift < 64; shift += 11) {
    count.fill(0);
    for (const std::uint64_t item : from) ++count[(item >> shift) & 0x7FF];
    std::uint32_t offset = 0;
    for (std::uint32_t& c : count) offset += std::exchange(c, offset);
    for (const std::uint64_t item : from) to[count[(item >> shift) & 0x7FF]++] = item;
    std::swap(from, to);
  }
  // Three passes leave the result in scratch.
  std::copy(from.begin(), from.end(), items.begin());
}

void sort_range(std::span<const Point> points, std::span<std::uint64_t> items,
                std::vector<std::uint64_t>& scratch, int depth);

// Items already carry their keys: sort by key, then order again the cells that hold many
// points, each inside its own box.
void sort_by_keys(std::span<const Point> points, std::span<std::uint64_t> items,
                  std::vector<std::uint64_t>& scratch, int depth) {
  radix_sort_by_key(items, scratch);
  if (depth >= kMaxDepth) return;
  for (std::size_t begin = 0; begin < items.size();) {
    std::size_t end = begin + 1;
    while (end < items.size() && (items[end] >> 32) == (items[begin] >> 32)) ++end;
    if (end - begin > kResortRun) sort_range(points, items.subspan(begin, end - begin), scratch, depth + 1);
    begin = end;
  }
}

// Keys of `items` on a grid over their own bounding box, as fine as their number needs.
void sort_range(std::span<const Point> points, std::span<std::uint64_t> items,
                std::vector<std::uint64_t>& scratch, int depth) {
  BBox box;
  for (const std::uint64_t item : items) box.add(points[item & 0xFFFFFFFFu]);
  const KeyGrid grid(box, items.size());
  if (!grid.valid()) return;  // all identical: index order it is
  for (std::uint64_t& item : items)
    item = (std::uint64_t{grid.key(points[item & 0xFFFFFFFFu])} << 32) | (item & 0xFFFFFFFFu);
  sort_by_keys(points, items, scratch, depth);
}

}  // namespace

std::vector<std::uint32_t> hilbert_order(std::span<const Point> points) {
  std::vector<std::uint64_t> items(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) items[i] = i;
  std::vector<std::uint64_t> scratch;
  sort_range(points, items, scratch, 0);
  release(scratch);
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) order[i] = static_cast<std::uint32_t>(items[i]);
  return order;
}

std::vector<std::uint32_t> brio_order(std::span<const Point> points) {
  const std::size_t n = points.size();
  // Rounds: round 0 takes about half the points, round 1 a quarter, ..., the last round
  // (inserted first) the remaining few dozen. A point's round comes from a hash of its
  // index, a reproducible coin-flipping that needs no shuffle of the data.
  int rounds = 1;
  while ((n >> rounds) > kFirstRound) ++rounds;
  std::vector<std::uint32_t> round_size(rounds, 0);
  const auto round_of = [rounds](std::uint64_t i) {
    std::uint64_t z = i * 0x9E3779B97F4A7C15ULL + 0x2545F4914F6CDD1DULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return std::min(std::countr_one(z), rounds - 1);
  };
  // One sequential pass over the points computes every key on the global grid; from here
  // on the sort moves (key, index) pairs and never reads the points in random order.
  BBox box;
  for (const Point& p : points) box.add(p);
  const KeyGrid grid(box, n);
  std::vector<std::uint64_t> keyed;
  resize_huge(keyed, n);
  for (std::size_t i = 0; i < n; ++i) {
    keyed[i] = (std::uint64_t{grid.valid() ? grid.key(points[i]) : 0u} << 32) | i;
    ++round_size[round_of(i)];
  }
  // Bucket by round, last round first, keeping index order inside a round.
  std::vector<std::size_t> start(rounds + 1, 0);
  std::size_t offset = 0;
  for (int r = rounds - 1; r >= 0; --r) {
    start[r] = offset;
    offset += round_size[r];
  }
  std::vector<std::uint64_t> items;
  resize_huge(items, n);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) items[next[round_of(i)]++] = keyed[i];
  }
  release(keyed);
  std::vector<std::uint64_t> scratch;
  for (int r = rounds - 1; r >= 0; --r)
    sort_by_keys(points, std::span(items).subspan(start[r], round_size[r]), scratch, 0);
  release(scratch);
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(items[i]);
  return order;
}

}  // namespace meshstep
