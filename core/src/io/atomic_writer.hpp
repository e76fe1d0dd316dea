// Buffered output (text, or raw bytes for binary formats) that replaces its target file
// atomically: everything goes to a temporary file in the target's folder, renamed over the
// target by commit(). Until then the target is untouched; on any failure (or without
// commit) the temporary file is removed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace meshstep::io::detail {

class AtomicWriter {
 public:
  // Throws InputError(path, 0, reason) when the temporary file cannot be created.
  explicit AtomicWriter(std::string path);
  ~AtomicWriter();
  AtomicWriter(const AtomicWriter&) = delete;
  AtomicWriter& operator=(const AtomicWriter&) = delete;

  void text(std::string_view s);
  // Raw bytes, for binary formats (text() copies its bytes verbatim too).
  void bytes(const void* data, std::size_t n) { text({static_cast<const char*>(data), n}); }
  void ch(char c) {
    if (used_ == kBufferSize) flush();
    buffer_[used_++] = c;
  }
  void integer(std::int64_t v);
  // Shortest representation that reads back to the same double (std::to_chars).
  void real(double v);

  // Flushes, closes and renames into place. Throws InputError(path, 0, reason).
  void commit();

  const std::string& path() const { return path_; }

 private:
  static constexpr std::size_t kBufferSize = std::size_t{1} << 20;
  static constexpr std::size_t kMaxNumberChars = 32;  // to_chars needs at most 24 for a double

  void flush();
  void reserve_number() {
    if (kBufferSize - used_ < kMaxNumberChars) flush();
  }
  [[noreturn]] void fail(const std::string& action, int err);
  void discard() noexcept;

  std::string path_;
  std::string temp_path_;
  int fd_ = -1;
  std::unique_ptr<char[]> buffer_;
  std::size_t used_ = 0;
};

}  // namespace meshstep::io::detail
