// Where a Recorder puts events: raw 32-bit words in a buffer that the sink hands over in
// batches (to a log writer's compression thread, or to a test). Appending is a push_back;
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

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
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

class EventSink {
 public:
  virtual ~EventSink() = default;
  const KeyframePolicy& keyframe_policy() const { return keyframes_; }

  void put(std::uint32_t w) { words_.push_back(w); }
  void put(double d) {
    const auto bits = std::bit_cast<std::uint64_t>(d);
    words_.push_back(static_cast<std::uint32_t>(bits));
    words_.push_back(static_cast<std::uint32_t>(bits >> 32));
  }
  void put(const Point& p) {
    put(p.x);
    put(p.y);
  }
  // Reserves a word to be filled in later (a count not known yet); returns its position.
  std::size_t placeholder() {
    words_.push_back(0);
    return words_.size() - 1;
  }
  void fill(std::size_t at, std::uint32_t w) { words_[at] = w; }
  // Appends n words to be written through the returned pointer (valid until the next put).
  std::uint32_t* extend(std::size_t n) {
    words_.resize(words_.size() + n);
    return words_.data() + words_.size() - n;
  }
  std::size_t size() const { return words_.size(); }

  // Called after each complete event: hands the batch over when it is big enough.
  void end_event() {
    if (words_.size() >= batch_words_) hand_over(words_);
  }

 protected:
  explicit EventSink(std::size_t batch_words) : batch_words_(batch_words) {
    words_.reserve(batch_words + batch_words / 4);
  }
  // Takes the complete events in `words` and leaves it empty (capacity kept or restored).
  virtual void hand_over(std::vector<std::uint32_t>& words) = 0;
  std::vector<std::uint32_t> words_;
  KeyframePolicy keyframes_;

 private:
  std::size_t batch_words_;
};

}  // namespace meshstep::replay
