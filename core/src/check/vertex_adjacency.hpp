// Who is connected to whom, for following input segments through the mesh.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "check/stages.hpp"

namespace meshstep::check_detail {

// Undirected vertex adjacency of the usable triangles (an interior edge appears twice in a
// list, which costs nothing here).
class Adjacency {
 public:
  explicit Adjacency(const MeshFacts& facts);
  std::span<const std::uint32_t> of(std::uint32_t v) const {
    return {next_.data() + start_[v], next_.data() + start_[v + 1]};
  }

 private:
  std::vector<std::size_t> start_;  // CSR offsets
  std::vector<std::uint32_t> next_;
};

// A segment endpoint that is a duplicate, left unused by the triangulator, stands for the
// used vertex at the same position. The sorted list is built on the first such request.
class Representatives {
 public:
  Representatives(const MeshFacts& facts, const Adjacency& adjacency)
      : facts_(facts), adjacency_(adjacency) {}
  // v itself when a triangle uses it, else a used vertex at the same position, if any.
  std::optional<std::uint32_t> of(std::uint32_t v);

 private:
  const MeshFacts& facts_;
  const Adjacency& adjacency_;
  bool built_ = false;
  std::vector<std::uint32_t> used_;  // used finite vertices in lexicographic order
};

}  // namespace meshstep::check_detail
