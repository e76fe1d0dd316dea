// The directed edges of a triangle list, bucketed by origin vertex and sorted by destination
// inside each bucket. The twin of u->v is then a binary search in v's bucket: linear memory
// and O(E log degree) time, with no hashing and no blow-up at vertices of huge degree.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "meshstep/mesh/tri_mesh.hpp"

namespace meshstep::check_detail {

class EdgeTable {
 public:
  // Edge id 3*t + i names the edge of triangle t opposite its corner i; it runs from corner
  // (i+1)%3 to corner (i+2)%3, so a counterclockwise triangle has the interior on its left.
  static constexpr std::uint32_t kBoundary = 0xFFFFFFFFu;     // nothing on the other side
  static constexpr std::uint32_t kNonManifold = 0xFFFFFFFEu;  // not exactly one opposite twin
  // Edge ids must stay below the sentinels.
  static constexpr std::size_t kMaxTriangles = (0xFFFFFFFDu) / 3;

  struct Out {
    std::uint32_t dest;
    std::uint32_t edge;
  };

  // Only triangles with usable[t] != 0 contribute (the others have bad indices); the twins
  // of their edge ids are meaningless.
  EdgeTable(const TriMesh& mesh, const std::vector<std::uint8_t>& usable);

  // Outgoing edges of v, sorted by destination.
  std::span<const Out> out(std::uint32_t v) const {
    return {out_.data() + start_[v], out_.data() + start_[v + 1]};
  }
  // The edges v->dest (more than one only in a broken mesh).
  std::span<const Out> out_to(std::uint32_t v, std::uint32_t dest) const;

  // The opposite edge of the one other triangle using this edge, or a sentinel.
  std::uint32_t twin(std::uint32_t edge) const { return twin_[edge]; }

  std::size_t vertex_count() const { return start_.size() - 1; }

 private:
  std::vector<std::size_t> start_;  // CSR offsets, one per vertex plus one
  std::vector<Out> out_;
  std::vector<std::uint32_t> twin_;
};

}  // namespace meshstep::check_detail
