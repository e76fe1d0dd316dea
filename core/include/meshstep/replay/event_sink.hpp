// Where a Recorder puts events: raw 32-bit words in a buffer that the sink hands over in
// batches (to a log writer's compression thread, or to a test). Appending bumps a pointer;
// the hand-over is one call every few thousand events.
//
// Raw layout of one event (a private contract between Recorder and the log writer):
//   type | code << 8
//   ids                          schema(type).id_count words
//   point                        4 words (two doubles) if schema.has_point
//   value                        2 words if schema.has_value
//   list                         count, then the words, if schema.has_list
//   points                       count, then 4 words per point, if schema.has_points
//   mesh delta                   if schema.has_writes: the faces the change replaces, as
//                                they were (count, then slot, v0, v1, v2, constraint bits
//                                each), then the faces it made, the same way; a slot only
//                                in the first list is dead afterwards, one only in the
//                                second was dead before
// except flips, the bulk of every run, which are packed (kFlipWord):
//   kFlipWord | reason << 8, a, b, c, d (edge a-b, apex c on its left, d on its right),
//   slots of the faces of a->b and b->a before, slots of the faces of c->d and d->c after,
//   then one word: per face, in that order, 2 bits of rotation and 3 constraint bits.
//   The faces are (a, b, c), (b, a, d), (c, d, b), (d, c, a), each listed by the data
//   structure starting at vertex `rotation` of that order.
// and split_face, one per inserted vertex, likewise (kSplitFaceWord):
//   kSplitFaceWord, v, a, b, c (the face split, as the data structure listed it), its slot,
//   the slots of the three faces around v afterwards, then one word: 3 constraint bits of
//   the old face, and per new face (x, y, v) 7 bits: which edge x->y of (a, b, c) it stands
//   on (2 bits: a->b, b->c, c->a), its rotation (2 bits) and its constraint bits (3).
// and a keyframe, when the recorder decides one is due (at a step boundary):
//   kKeyframeWord, slot count, then v0, v1, v2, constraint bits per slot (kNone: dead)
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

#include "meshstep/geometry/point.hpp"

namespace meshstep::replay {

inline constexpr std::uint32_t kKeyframeWord = 0xFFu;
inline constexpr std::uint32_t kFlipWord = 0xFEu;
inline constexpr std::uint32_t kSplitFaceWord = 0xFDu;

// When a keyframe (a copy of every face slot) is due: once at least
// max(min_events, factor * live faces) events have passed since the last one. Seeking then
// replays at most that many events on top of a keyframe, a cost proportional to the mesh
// size, like restoring the keyframe itself.
struct KeyframePolicy {
  double factor = 3.0;
  std::uint64_t min_events = 65536;
};

// An allocator that leaves new elements uninitialised: a batch buffer is written before it
// is read, and zero-filling 64 KiB per batch would cost as much as writing the events.
template <class T> struct UninitializedAllocator : std::allocator<T> {
  template <class U> struct rebind { using other = UninitializedAllocator<U>; };
  UninitializedAllocator() = default;
  template <class U> UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; }
  template <class U, class... Args> void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// A batch of raw event words; its size is the number of words written.
using EventWords = std::vector<std::uint32_t, UninitializedAllocator<std::uint32_t>>;

class EventSink {
 public:
  virtual ~EventSink() = default;
  const KeyframePolicy& keyframe_policy() const { return keyframes_; }

  // Appends n words to be written through the returned pointer (valid until the next
  // append). A bump of a pointer: the recorder calls this several times per flip.
  std::uint32_t* extend(std::size_t n) {
    if (static_cast<std::size_t>(end_ - cursor_) < n) [[unlikely]] grow(n);
    std::uint32_t* out = cursor_;
    cursor_ += n;
    return out;
  }
  void put(std::uint32_t w) { *extend(1) = w; }
  void put(double d) {
    const auto bits = std::bit_cast<std::uint64_t>(d);
    std::uint32_t* out = extend(2);
    out[0] = static_cast<std::uint32_t>(bits);
    out[1] = static_cast<std::uint32_t>(bits >> 32);
  }
  void put(const Point& p) {
    put(p.x);
    put(p.y);
  }
  // Reserves a word to be filled in later (a count not known yet); returns its position.
  std::size_t placeholder() {
    extend(1);
    return size() - 1;
  }
  void fill(std::size_t at, std::uint32_t w) { words_[at] = w; }
  std::size_t size() const { return static_cast<std::size_t>(cursor_ - words_.data()); }

  // Called after each complete event: hands the batch over when it is big enough.
  void end_event() {
    if (cursor_ >= batch_end_) [[unlikely]] hand_over_batch();
  }

 protected:
  explicit EventSink(std::size_t batch_words) : batch_words_(batch_words) { reset_buffer(); }
  // Takes the complete events in `words` and leaves in it an empty buffer to fill next
  // (with its capacity kept, or a fresh one).
  virtual void hand_over(EventWords& words) = 0;
  // Hands over whatever complete events are buffered (the end of a run).
  void flush() {
    if (size() != 0) hand_over_batch();
  }
  KeyframePolicy keyframes_;

 private:
  // Room for the largest ordinary event past the batch size: events never split a batch.
  static constexpr std::size_t kSlack = 1 << 12;

  void hand_over_batch() {
    words_.resize(size());  // shrinking: nothing is written
    hand_over(words_);
    reset_buffer();
  }
  // Makes the whole capacity (at least a batch and its slack) writable.
  void reset_buffer() {
    words_.clear();
    words_.resize(std::max(words_.capacity(), batch_words_ + kSlack));
    point_into_buffer(0);
  }
  // An event bigger than the room left (a keyframe, a huge cavity): a bigger buffer, the
  // words of the events so far kept.
  [[gnu::noinline]] void grow(std::size_t n) {
    const std::size_t used = size();
    words_.resize(std::max(2 * words_.size(), used + n + kSlack));
    point_into_buffer(used);
  }
  // The pointers into words_, after it was (re)sized, with `used` words written.
  void point_into_buffer(std::size_t used) {
    cursor_ = words_.data() + used;
    end_ = words_.data() + words_.size();
    batch_end_ = words_.data() + batch_words_;
  }

  EventWords words_;
  std::uint32_t* cursor_ = nullptr;     // where the next word goes
  std::uint32_t* end_ = nullptr;        // end of the writable buffer
  std::uint32_t* batch_end_ = nullptr;  // a batch this big is handed over
  std::size_t batch_words_;
};

}  // namespace meshstep::replay
