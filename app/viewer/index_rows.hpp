// Rows of a compressed index (the element history's): row r holds entries[offsets[r] ..
// offsets[r + 1]). Made from (row, entry) pairs collected in one pass over a log by a
// counting sort, which keeps the pairs' order within a row (so events stay in log order).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace meshstep::viewer {

template <class T>
struct Rows {
  std::vector<std::uint32_t> offsets;
  std::vector<T> entries;

  std::span<const T> row(std::size_t r) const {
    if (r + 1 >= offsets.size()) return {};
    return {entries.data() + offsets[r], offsets[r + 1] - offsets[r]};
  }
  std::size_t bytes() const { return offsets.size() * sizeof(std::uint32_t) + entries.size() * sizeof(T); }

  static Rows from_pairs(const std::vector<std::pair<std::uint32_t, T>>& pairs, std::size_t rows) {
    Rows out;
    out.offsets.assign(rows + 1, 0);
    for (const auto& p : pairs) ++out.offsets[p.first + 1];
    for (std::size_t r = 0; r < rows; ++r) out.offsets[r + 1] += out.offsets[r];
    out.entries.resize(pairs.size());
    std::vector<std::uint32_t> next(out.offsets.begin(), out.offsets.end() - 1);
    for (const auto& p : pairs) out.entries[next[p.first]++] = p.second;
    return out;
  }
};

}  // namespace meshstep::viewer
