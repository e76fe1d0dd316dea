// The triangles waiting to be cut, the most oversized first: a bucket queue.
//
// A binary heap of a million targets spent a third of a whole refinement in its sift-downs,
// each a chain of cache misses. Here a target goes to the bucket of its excess's top bits,
// four buckets to a factor of two, and comes out of the highest bucket first, first in,
// first out within a bucket: pushing and popping are a few sequential loads and stores.
// Within a factor of 2^(1/4) the order is by arrival, which the refinement makes the same
// on every data structure (the caller sorts the first targets by their vertex ids).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include "meshstep/huge_pages.hpp"
#include "meshstep/mesh/handles.hpp"

namespace meshstep::surface::detail {

struct Target {
  double excess;  // over 1: how far over its bounds (a squared ratio of sizes)
  FaceId face;
  std::array<VertexId, 3> corners;  // from the smallest id
};

class TargetQueue {
 public:
  void push(const Target& t) {
    const std::size_t b = bucket(t.excess);
    if (b >= buckets_.size()) buckets_.resize(b + 1);
    std::vector<Target>& items = buckets_[b].items;
    grow_huge(items);
    items.push_back(t);
    top_ = std::max(top_, b);
    ++size_;
  }

  bool pop(Target& t) {
    if (size_ == 0) return false;
    // Every target sits at or below top_, and one does since size_ > 0.
    while (buckets_[top_].head == buckets_[top_].items.size()) --top_;
    Bucket& b = buckets_[top_];
    t = b.items[b.head++];
    --size_;
    if (b.head == b.items.size()) {  // emptied: its room serves the next arrivals
      b.items.clear();
      b.head = 0;
    }
    return true;
  }

 private:
  struct Bucket {
    std::vector<Target> items;
    std::size_t head = 0;  // items before it have been popped
  };

  // For doubles over 1 the bit pattern grows with the value: its exponent and the top two
  // bits of its mantissa name a quarter of an octave. An infinite excess (a length whose
  // square overflows) gets the highest bucket.
  static std::size_t bucket(double excess) {
    constexpr std::uint64_t kOne = std::bit_cast<std::uint64_t>(1.0);
    return static_cast<std::size_t>((std::bit_cast<std::uint64_t>(excess) - kOne) >> 50);
  }

  std::vector<Bucket> buckets_;
  std::size_t top_ = 0;
  std::size_t size_ = 0;
};

}  // namespace meshstep::surface::detail
