// A hash of a mesh that does not depend on where its faces are stored: the sum of a hash of
// each live face (rotated to start at its smallest vertex id, constraint flags rotated
// along). Sums update in O(1) per face written, so the log writer and the replay keep it
// current as they go, and a hash computed from a data structure directly can be compared
// with the replayed one.
#pragma once

#include <algorithm>
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

namespace detail {
inline std::uint64_t mix(std::uint64_t x) {  // splitmix64's finaliser
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return x;
}
}  // namespace detail

// A sum over the three vertices and the constrained edges, so that it does not depend on
// which vertex a data structure lists first (and needs no branches to rotate), then mixed.
// It does not see orientation: in a valid mesh three vertices have one orientation, and
// replays compare records exactly besides.
inline std::uint64_t face_hash(const FaceRecord& r) {
  if (r.dead()) return 0;
  constexpr std::uint64_t k1 = 0x9E3779B97F4A7C15ull, k2 = 0xC2B2AE3D27D4EB4Full;
  const auto term = [&](std::uint64_t v) { return (v ^ k2) * k1; };
  std::uint64_t s = term(r.v[0]) + term(r.v[1]) + term(r.v[2]);
  if (r.constrained)
    for (int i = 0; i < 3; ++i)
      if (r.constrained >> i & 1) {
        const std::uint64_t a = r.v[i], b = r.v[(i + 1) % 3];
        s += term(std::min(a, b) << 32 | std::max(a, b)) * k2;
      }
  return detail::mix(s);
}

inline std::uint64_t mesh_hash(std::span<const FaceRecord> slots) {
  std::uint64_t h = 0;
  for (const FaceRecord& r : slots) h += face_hash(r);
  return h;
}

}  // namespace meshstep::replay
