#include "scene_fingerprint.hpp"

#include <cstring>
#include <string_view>
#include <type_traits>
#include <vector>

namespace meshstep::render {

namespace {

constexpr std::uint64_t kMultiplier = 0x9e3779b97f4a7c15ull;  // 2^64 / golden ratio, odd
constexpr std::uint64_t kWordMultiplier = 0xc2b2ae3d27d4eb4full;

// One word into a lane: the multiply spreads low bits up, the rotation brings the high bits
// down for the next multiply, so every bit of every word reaches every bit of the lane.
std::uint64_t absorb(std::uint64_t lane, std::uint64_t word) {
  lane += word * kWordMultiplier;
  lane = lane << 31 | lane >> 33;
  return lane * kMultiplier;
}

std::uint64_t mix(std::uint64_t h) {
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 29;
  return h;
}

// Hashes byte ranges into one value. Four independent lanes over 8-byte words keep the
// multiplier's latency out of the way; the tail bytes and the length go into lanes 0 and 1.
class Hasher {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + 32 <= size; i += 32) {
      std::uint64_t w[4];
      std::memcpy(w, p + i, 32);
      for (int k = 0; k < 4; ++k) lanes_[k] = absorb(lanes_[k], w[k]);
    }
    for (; i < size; ++i) lanes_[0] = absorb(lanes_[0], p[i]);
    lanes_[1] = absorb(lanes_[1], size);
  }
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T> && std::has_unique_object_representations_v<T>);
    bytes(&v, sizeof v);
  }
  template <class T>
  void values(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(v.data(), v.size() * sizeof(T));
  }
  void text(std::string_view s) { bytes(s.data(), s.size()); }
  void number(double d) {
    const double same_zero = d == 0.0 ? 0.0 : d;  // -0 and +0 draw alike
    std::uint64_t bits;
    std::memcpy(&bits, &same_zero, sizeof bits);
    value(bits);
  }
  void number(float f) { number(static_cast<double>(f)); }

  std::uint64_t result() const {
    std::uint64_t h = 0;
    for (std::uint64_t lane : lanes_) h = mix(h ^ lane) * kMultiplier;
    return mix(h);
  }

 private:
  std::uint64_t lanes_[4] = {1, 2, 3, 4};
};

}  // namespace

std::uint64_t mesh_fingerprint(const scene::MeshLayer& mesh) {
  static_assert(sizeof(Point) == 2 * sizeof(double), "points are hashed as their bytes");
  Hasher h;
  h.bytes(mesh.points.data(), mesh.points.size() * sizeof(Point));
  h.values(mesh.triangles);
  h.values(mesh.fill);
  return h.result();
}

std::uint64_t overlay_fingerprint(const scene::Scene& scene) {
  Hasher h;
  for (const scene::Shape& s : scene.shapes) {
    h.value(s.layer);
    h.value(s.kind);
    h.value(s.color);
    h.value(s.fill);
    h.number(s.width_px);
    h.value(s.dashed);
    h.number(s.marker_px);
    h.value(s.marker);
    h.bytes(s.points.data(), s.points.size() * sizeof(Point));
    h.bytes(s.radii.data(), s.radii.size() * sizeof(double));
  }
  return h.result();
}

}  // namespace meshstep::render
