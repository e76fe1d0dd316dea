// Large arrays on huge pages. On the virtual machines this project runs on, the first
// touch of a 4 KiB page of fresh memory costs about 7 us (133 MB took 0.98 s to zero);
// asked for transparent huge pages (2 MiB), the same took 0.055 s. Arrays that grow to
// tens of megabytes (a log's vertices, a scene's triangles) reserve through here.
#pragma once

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <type_traits>
#include <cstdint>
#include <vector>

namespace meshstep {

// Asks the kernel for huge pages under [data, data + bytes) (the whole 2 MiB pages inside
// it; smaller ranges are left alone). Only advice: nothing changes if it is refused.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < 2 * kHuge) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// Makes room for at least `n` elements, growing geometrically, new storage advised to use
// huge pages before anything touches it. Call before the elements are added.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  if (n <= v.capacity()) return;
  std::vector<T> bigger;
  bigger.reserve(std::max(n, 2 * v.capacity()));
  advise_huge_pages(bigger.data(), bigger.capacity() * sizeof(T));
  bigger.insert(bigger.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(bigger);
}

// v.resize(n, value), the new storage advised (reserve_huge) before resize touches it.
template <class T>
void resize_huge(std::vector<T>& v, std::size_t n, const std::type_identity_t<T>& value = T()) {
  reserve_huge(v, n);
  v.resize(n, value);
}

// Room for `extra` more elements, as reserve_huge grows: call before push_back on arrays
// that grow to tens of megabytes while an algorithm runs (a refinement's faces and
// points), where each doubling would otherwise fault in fresh 4 KiB pages one by one.
template <class T>
void grow_huge(std::vector<T>& v, std::size_t extra = 1) {
  if (v.capacity() - v.size() < extra) reserve_huge(v, v.size() + extra);
}

}  // namespace meshstep
