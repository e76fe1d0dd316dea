// The log writer's encoding stage, free of threads and files: takes batches of raw events
// (event_sink.hpp), pairs each change's replaced and new faces by slot, encodes, and emits
// finished blocks (header + stored payload).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "event_codec.hpp"
#include "format.hpp"
#include "meshstep/replay/log_writer.hpp"

namespace meshstep::replay {

class LogEncoder {
 public:
  using BlockOut = std::function<void(const format::BlockHeader&, std::span<const std::uint8_t>)>;

  LogEncoder(const LogWriterOptions& options, BlockOut out);
  void consume(std::span<const std::uint32_t> words);
  // Flushes the last events block and writes the end block.
  void finish();
  const LogStats& stats() const { return stats_; }
  std::uint32_t format_version() const { return version_; }

 private:
  std::span<const std::uint32_t>::iterator parse(std::span<const std::uint32_t>::iterator it,
                                                 std::span<const std::uint32_t>::iterator end);
  std::span<const std::uint32_t>::iterator flip(std::span<const std::uint32_t>::iterator it);
  std::span<const std::uint32_t>::iterator split_face(std::span<const std::uint32_t>::iterator it);
  void finish_event(const Event& e);
  void count_event(EventType type);
  void pair_writes(std::span<const std::uint32_t> before, std::span<const std::uint32_t> after);
  void flush_events();
  std::span<const std::uint32_t>::iterator keyframe(std::span<const std::uint32_t>::iterator it);
  enum class Compression { zstd, none };
  void emit(format::BlockHeader header, std::span<const std::uint8_t> raw, Compression compression = Compression::zstd);

  LogWriterOptions options_;
  std::uint32_t version_;
  BlockOut out_;
  format::Compressor compressor_;
  codec::Encoder encoder_;
  std::vector<std::uint8_t> block_;       // encoded events of the current block: block_used_
  std::size_t block_used_ = 0;            // bytes, the rest is room to write into
  std::vector<std::uint8_t> stored_;      // compression output
  std::vector<std::uint8_t> keyframe_;    // an encoded keyframe
  std::uint64_t block_first_event_ = 0;
  std::uint32_t block_steps_ = 0;
  std::uint64_t hash_ = 0;  // of the last keyframe: at the end, of the final mesh

  // Scratch for the event being parsed.
  std::vector<Point> points_;
  std::vector<SlotWrite> writes_;
  LogStats stats_;
};

}  // namespace meshstep::replay
