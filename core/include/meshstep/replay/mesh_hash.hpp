// A hash of a mesh that does not depend on where its faces are stored: the sum of a hash of
// each live face (rotated to start at its smallest vertex id, constraint flags rotated
// along). Sums update in O(1) per face written, so the log writer and the replay keep it
// current as they go, and a hash computed from a data structure directly can be compared
// with the replayed one.
#pragma once

#include <bit>
#include <cstdint>
#include <span>

#include "meshstep/mesh/concept.hpp"
#include "meshstep/replay/event.hpp"

namespace meshstep::replay {

inline FaceRecord canonical(const FaceRecord& r) {
  if (r.dead()) return r;
  int k = 0;
  if (r.v[1] < r.v[k]) k = 1;
  if (r.v[2] < r.v[k]) k = 2;
  FaceRecord c;
  for (int j = 0; j < 3; ++j) {
    c.v[j] = r.v[(j + k) % 3];
    c.constrained |= static_cast<std::uint8_t>(((r.constrained >> ((j + k) % 3)) & 1u) << j);
  }
  return c;
}

inline std::uint64_t face_hash(const FaceRecord& r) {
  if (r.dead()) return 0;
  const FaceRecord c = canonical(r);
  std::uint64_t x = c.v[0] * 0x9E3779B97F4A7C15ull;
  x ^= std::rotl(c.v[1] * 0xC2B2AE3D27D4EB4Full, 21);
  x ^= std::rotl(c.v[2] * 0x165667B19E3779F9ull, 42);
  x ^= (std::uint64_t{c.constrained} + 1) * 0xD6E8FEB86659FD93ull;
  // splitmix64 finaliser: every input bit affects every output bit.
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return x;
}

inline std::uint64_t mesh_hash(std::span<const FaceRecord> slots) {
  std::uint64_t h = 0;
  for (const FaceRecord& r : slots) h += face_hash(r);
  return h;
}

}  // namespace meshstep::replay
