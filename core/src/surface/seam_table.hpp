// Seams: edges of the surface whose two sides the mesh does not join.
//
// The mesh structures can only be built by the concept's operations, which start from a
// sphere and never change its topology, so a torus, or a surface that the loader could not
// close up without pinching, is held cut open along a few edges: each side of such an edge
// is a border of the mesh (twin() is kNone) although the surface goes on across it. This
// table remembers, for each seam, the half-edge on either side, so that a walk can cross it.
//
// Keys are edge_tie_key(a, b) of the edge's vertex ids; the half-edge running from the
// smaller id to the larger is "forward". Open addressing with linear probing over a
// power-of-two array, and deletion by shifting back the entries after the hole: no
// allocation but the occasional doubling, and a lookup that misses (a true border edge)
// costs a probe or two.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "meshstep/mesh/handles.hpp"
#include "meshstep/refine/lepp.hpp"

namespace meshstep::surface::detail {

class SeamTable {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  // Makes the edge a seam (its half-edges unknown until set).
  void add(VertexId a, VertexId b) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    Slot& s = slots_[probe(edge_tie_key(a, b))];
    if (s.key == kEmpty) {
      s = {edge_tie_key(a, b), kNone, kNone};
      ++size_;
    }
  }

  void remove(VertexId a, VertexId b) {
    if (size_ == 0) return;
    std::size_t hole = probe(edge_tie_key(a, b));
    if (slots_[hole].key == kEmpty) return;
    --size_;
    // Move back every later entry of the run that may sit there, so no probe stops early.
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = (hole + 1) & mask; slots_[i].key != kEmpty; i = (i + 1) & mask) {
      const std::size_t home = hash(slots_[i].key);
      // The entry may move to the hole when the hole lies on its way from home to i.
      if (((i - home) & mask) >= ((i - hole) & mask)) {
        slots_[hole] = slots_[i];
        hole = i;
      }
    }
    slots_[hole].key = kEmpty;
  }

  // Records h (from a to b) as the side of seam {a, b} that runs from a to b; nothing when
  // {a, b} is no seam.
  void set_if_seam(VertexId a, VertexId b, HalfEdge h) {
    if (size_ == 0) return;
    Slot& s = slots_[probe(edge_tie_key(a, b))];
    if (s.key == kEmpty) return;
    (a < b ? s.forward : s.backward) = h;
  }

  // The half-edge from b to a on the other side of seam {a, b}; kNone when it is no seam.
  HalfEdge across(VertexId a, VertexId b) const {
    if (size_ == 0) return kNone;
    const Slot& s = slots_[probe(edge_tie_key(a, b))];
    if (s.key == kEmpty) return kNone;
    return a < b ? s.backward : s.forward;
  }

 private:
  // No edge joins a vertex to itself, so key 0 (vertices 0 and 0) never occurs.
  static constexpr std::uint64_t kEmpty = 0;

  struct Slot {
    std::uint64_t key = kEmpty;
    HalfEdge forward = kNone;   // from the smaller vertex id to the larger
    HalfEdge backward = kNone;  // the other way
  };

  // Fibonacci hashing, keeping the product's top bits (the well-mixed ones): vertex ids
  // come in runs, and the multiplication spreads them.
  std::size_t hash(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  // The slot holding key, or the empty slot where it would go. The table is never full.
  std::size_t probe(std::uint64_t key) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = hash(key);
    while (slots_[i].key != kEmpty && slots_[i].key != key) i = (i + 1) & mask;
    return i;
  }

  void grow() {
    std::vector<Slot> old(slots_.empty() ? 16 : 2 * slots_.size());
    old.swap(slots_);
    shift_ = 64 - std::countr_zero(slots_.size());
    for (const Slot& s : old)
      if (s.key != kEmpty) slots_[probe(s.key)] = s;
  }

  std::vector<Slot> slots_;
  std::size_t size_ = 0;
  int shift_ = 64;  // 64 - log2(slots_.size())
};

}  // namespace meshstep::surface::detail
