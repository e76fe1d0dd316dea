// HugeArray: the growable array of the meshes' big arrays (huge_array.hpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "meshstep/huge_array.hpp"
#include "meshstep/release.hpp"

namespace meshstep {
namespace {

constexpr std::size_t kPastMapped = 3 * HugeArray<std::uint32_t>::kMapped / sizeof(std::uint32_t);

HugeArray<std::uint32_t> counting(std::size_t n) {
  HugeArray<std::uint32_t> a;
  for (std::size_t i = 0; i < n; ++i) a.push_back(static_cast<std::uint32_t>(i));
  return a;
}

void expect_counting(const HugeArray<std::uint32_t>& a, std::size_t n) {
  ASSERT_EQ(a.size(), n);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(a[i], i) << "at " << i;
}

// The /proc/self/smaps block of the mapping that holds `p`, or "" when none does.
std::string smaps_block_of(const void* p) {
  std::ifstream smaps("/proc/self/smaps");
  const auto address = reinterpret_cast<std::uintptr_t>(p);
  std::string line, block;
  bool inside = false;
  while (std::getline(smaps, line)) {
    unsigned long long begin = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> begin >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
      if (inside) return block;
      inside = address >= begin && address < end;
      block = line + '\n';
    } else if (inside) {
      block += line + '\n';
    }
  }
  return inside ? block : "";
}

TEST(HugeArray, KeepsItsElementsWhileGrowingIntoItsOwnMapping) {
  const HugeArray<std::uint32_t> a = counting(kPastMapped);
  expect_counting(a, kPastMapped);
  // A malloc'd block starts past malloc's header; a mapping of its own starts on a page.
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % 4096, 0u);
  EXPECT_LE(a.capacity(), 2 * kPastMapped);
}

TEST(HugeArray, ItsMappingIsOneMappingAdvisedForHugePages) {
  // Advice on part of a mapping splits it, and mremap then fails (EFAULT) on the next
  // growth: the whole mapping must carry the advice.
  HugeArray<std::uint32_t> a = counting(kPastMapped);
  const std::string block = smaps_block_of(a.data());
  ASSERT_FALSE(block.empty()) << "no mapping holds the array";
  std::istringstream head(block);
  unsigned long long begin = 0, end = 0;
  char dash = 0;
  head >> std::hex >> begin >> dash >> end;
  // One mapping from the first element to the last of the capacity (the kernel may merge
  // it with a neighbour that has the same flags).
  EXPECT_GE(end, reinterpret_cast<std::uintptr_t>(a.data() + a.capacity()));
  EXPECT_NE(block.find(" hg"), std::string::npos) << "VmFlags lack hg (MADV_HUGEPAGE):\n" << block;
  for (std::size_t i = kPastMapped; i < 4 * kPastMapped; ++i) a.push_back(static_cast<std::uint32_t>(i));
  expect_counting(a, 4 * kPastMapped);
}

TEST(HugeArray, CopiesAreDeepAndMovesTakeTheStorage) {
  for (const std::size_t n : {std::size_t{10}, kPastMapped}) {
    HugeArray<std::uint32_t> a = counting(n);
    HugeArray<std::uint32_t> copy = a;
    copy[0] = 99;
    EXPECT_EQ(a[0], 0u);
    expect_counting(a, n);
    const std::uint32_t* storage = a.data();
    HugeArray<std::uint32_t> moved = std::move(a);
    EXPECT_EQ(moved.data(), storage);
    EXPECT_TRUE(a.empty());
    a = moved;  // the moved-from array is usable again
    expect_counting(a, n);
  }
}

TEST(HugeArray, ResizeFillsOnlyTheNewElements) {
  HugeArray<std::uint32_t> a = counting(5);
  a.resize(8, 7);
  EXPECT_EQ(a[4], 4u);
  EXPECT_EQ(a[5], 7u);
  EXPECT_EQ(a[7], 7u);
  a.resize(2);
  EXPECT_EQ(a.size(), 2u);
  a.resize(4, 1);
  EXPECT_EQ(a[1], 1u);
  EXPECT_EQ(a[2], 1u);  // refilled, not the old 2
  a.assign(3, 5);
  EXPECT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0], 5u);
}

TEST(HugeArray, ResizingOneByOneGrowsGeometrically) {
  HugeArray<std::uint32_t> a;
  std::size_t reallocations = 0;
  for (std::size_t n = 1; n <= 100000; ++n) {
    const std::size_t before = a.capacity();
    a.resize(n, 0);
    reallocations += a.capacity() != before;
  }
  EXPECT_LE(reallocations, 18u);  // about log2(100000) + 1
}

TEST(HugeArray, ReleaseGivesTheStorageBack) {
  HugeArray<std::uint32_t> a = counting(kPastMapped);
  release(a);
  EXPECT_EQ(a.capacity(), 0u);
  EXPECT_EQ(a.data(), nullptr);
  a.push_back(3);
  EXPECT_EQ(a.back(), 3u);
}

}  // namespace
}  // namespace meshstep
