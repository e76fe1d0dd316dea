// A growable array of plain values for the arrays a mesh grows to tens of megabytes.
//
// std::vector grows by copying into a fresh block and freeing the old one. For a mesh's
// face arrays that costs three ways: the copy itself, the fresh block's first touch (a
// page fault per 4 KiB), and the old blocks, which glibc keeps resident in its heap. A
// refinement to 1.3M triangles peaked at 133 MiB for about 55 MiB of live arrays.
//
// HugeArray keeps small arrays in malloc'd storage and moves an array that passes
// kMapped bytes into its own anonymous mapping, advised to use huge pages. From then on
// it grows with mremap, which moves page tables rather than bytes: no copy, no second
// block resident while growing, and nothing left behind when the array is freed.
//
// Only what the meshes use of std::vector's interface is here. The elements must be
// trivially copyable (they are indices and coordinates): storage moves by memcpy.
#pragma once

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace meshstep {

template <class T>
  requires std::is_trivially_copyable_v<T>
class HugeArray {
 public:
  using value_type = T;
  using size_type = std::size_t;
  using iterator = T*;
  using const_iterator = const T*;

  // Arrays this large live in their own mapping. Below it, a mapping's 4 KiB granularity
  // and the system call would cost more than malloc's copy.
  static constexpr std::size_t kMapped = std::size_t{1} << 20;

  HugeArray() = default;
  HugeArray(std::size_t n, const T& value) { resize(n, value); }
  HugeArray(const HugeArray& other) { *this = other; }
  HugeArray(HugeArray&& other) noexcept { swap(other); }
  HugeArray& operator=(const HugeArray& other) {
    if (this != &other) {
      clear();
      reserve(other.size_);
      if (other.size_ > 0) std::memcpy(data_, other.data_, other.size_ * sizeof(T));
      size_ = other.size_;
    }
    return *this;
  }
  HugeArray& operator=(HugeArray&& other) noexcept {
    HugeArray(std::move(other)).swap(*this);
    return *this;
  }
  ~HugeArray() { free_storage(); }

  void swap(HugeArray& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
  }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

  void push_back(const T& value) {
    if (size_ == capacity_) grow_to(size_ + 1);
    data_[size_++] = value;
  }
  void pop_back() { --size_; }
  void clear() { size_ = 0; }

  void reserve(std::size_t n) {
    if (n > capacity_) reallocate(n);
  }
  // Grows geometrically, like push_back, so that a run of resizes by one stays linear.
  void resize(std::size_t n, const T& value = T()) {
    if (n > capacity_) grow_to(n);
    std::fill(data_ + std::min(size_, n), data_ + n, value);
    size_ = n;
  }
  void assign(std::size_t n, const T& value) {
    clear();
    resize(n, value);
  }

 private:
  void grow_to(std::size_t n) { reallocate(std::max(n, 2 * capacity_)); }

  static bool mapped(std::size_t capacity) { return capacity * sizeof(T) >= kMapped; }

  // Page-rounded length of a mapping holding `capacity` elements.
  static std::size_t mapping_bytes(std::size_t capacity) {
    constexpr std::size_t kPage = 4096;
    return (capacity * sizeof(T) + kPage - 1) & ~(kPage - 1);
  }

  void reallocate(std::size_t capacity) {
    void* storage = nullptr;
    if (!mapped(capacity)) {
      storage = std::realloc(data_, capacity * sizeof(T));
      if (storage == nullptr) throw std::bad_alloc();
    } else if (mapped(capacity_)) {
      storage = ::mremap(data_, mapping_bytes(capacity_), mapping_bytes(capacity), MREMAP_MAYMOVE);
      if (storage == MAP_FAILED) throw std::bad_alloc();
    } else {
      storage = ::mmap(nullptr, mapping_bytes(capacity), PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (storage == MAP_FAILED) throw std::bad_alloc();
      // Advised before the copy touches it, so that the copy faults whole huge pages. The
      // advice covers the whole mapping: advice on part of it would split it in two, and
      // mremap refuses a range that spans two mappings.
      ::madvise(storage, mapping_bytes(capacity), MADV_HUGEPAGE);
      if (size_ > 0) std::memcpy(storage, data_, size_ * sizeof(T));
      std::free(data_);
    }
    // mremap keeps the advice, on the part it added too: one mapping has one set of flags.
    data_ = static_cast<T*>(storage);
    capacity_ = capacity;
  }

  void free_storage() {
    if (mapped(capacity_)) {
      ::munmap(data_, mapping_bytes(capacity_));
    } else {
      std::free(data_);
    }
    data_ = nullptr;
    size_ = capacity_ = 0;
  }

  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace meshstep
