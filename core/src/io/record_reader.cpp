#include "io/record_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "meshstep/error.hpp"

namespace meshstep::io::detail {
namespace {

enum CharClass : unsigned char { kText, kSpace, kComment, kBinary };

// Control characters other than whitespace never occur in a text file: they mean the file
// is binary (or corrupt), which deserves a clearer message than "expected a number".
// Bytes >= 0x80 count as text so that UTF-8 comments are accepted.
constexpr std::array<unsigned char, 256> make_classes() {
  std::array<unsigned char, 256> c{};
  for (int i = 0; i < 0x20; ++i) c[i] = kBinary;
  c[0x7F] = kBinary;
  c[' '] = c['\t'] = c['\r'] = c['\v'] = c['\f'] = kSpace;
  c['#'] = kComment;
  return c;
}
constexpr std::array<unsigned char, 256> kClasses = make_classes();

std::string errno_text(int err) { return std::strerror(err); }

// Index of the first byte at or after i that is not kText. Looks at 8 bytes at a time: the
// bit tricks flag bytes below 0x21, equal to '#' or equal to 0x7F; each flags the lowest
// such byte exactly (false positives can only appear above a true one), which is all that
// counting the trailing zero bits needs. Fields of 17-digit numbers are the bulk of a big
// file: this makes reading one about 10% faster than a byte loop.
std::size_t end_of_text(const unsigned char* p, std::size_t i, std::size_t n) {
  constexpr std::uint64_t kOnes = 0x0101010101010101ull;
  constexpr std::uint64_t kHighs = 0x8080808080808080ull;
  // The lowest bits of the word must hold the first byte.
  while (std::endian::native == std::endian::little && i + 8 <= n) {
    std::uint64_t w;
    std::memcpy(&w, p + i, 8);
    const std::uint64_t below = (w - kOnes * 0x21) & ~w & kHighs;
    const std::uint64_t hash = w ^ (kOnes * '#');
    const std::uint64_t del = w ^ (kOnes * 0x7F);
    const std::uint64_t special =
        ((hash - kOnes) & ~hash & kHighs) | ((del - kOnes) & ~del & kHighs);
    const std::uint64_t stop = below | special;
    if (stop != 0) return i + static_cast<std::size_t>(std::countr_zero(stop) / 8);
    i += 8;
  }
  while (i < n && kClasses[p[i]] == kText) ++i;
  return i;
}

}  // namespace

RecordReader::RecordReader(std::string path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw InputError(path_, 0, "cannot open: " + errno_text(errno));
  struct stat st {};
  if (::fstat(fd_, &st) == 0) {
    // A directory opens fine on Linux; say so now rather than at the first read.
    if (S_ISDIR(st.st_mode)) {
      ::close(fd_);
      fd_ = -1;
      throw InputError(path_, 0, "cannot read: " + errno_text(EISDIR));
    }
    // Only a regular file's size bounds what it can hold (pipes report 0).
    if (S_ISREG(st.st_mode)) file_size_ = static_cast<std::uint64_t>(st.st_size);
  }
  // Small files get a small buffer (most inputs are a few kB; allocating and touching 1 MiB
  // for each would dominate); it grows to the full chunk size if a file turns out longer.
  capacity_ = file_size_ ? static_cast<std::size_t>(std::min<std::uint64_t>(
                               kBufferSize, std::max<std::uint64_t>(*file_size_ + 1, 4096)))
                         : kBufferSize;
  buffer_.reset(new char[capacity_]);  // not zeroed: only bytes read are ever looked at
}

RecordReader::~RecordReader() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<std::uint64_t> RecordReader::remaining_bytes() const {
  if (!file_size_) return std::nullopt;
  const std::uint64_t used = consumed_;
  return *file_size_ > used ? *file_size_ - used : 0;
}

void RecordReader::fail(const std::string& message) const {
  throw InputError(path_, line(), message);
}

bool RecordReader::next_line(std::string_view& line) {
  for (;;) {
    const char* start = buffer_.get() + begin_;
    const std::size_t avail = end_ - begin_;
    if (const void* nl = std::memchr(start, '\n', avail)) {
      const std::size_t len = static_cast<const char*>(nl) - start;
      line = std::string_view(start, len);
      begin_ += len + 1;
      consumed_ += len + 1;
      ++line_;
      return true;
    }
    if (at_eof_) {
      if (avail == 0) return false;
      line = std::string_view(start, avail);  // last line without a newline
      begin_ = end_;
      consumed_ += avail;
      ++line_;
      return true;
    }
    // Keep the partial line, moved to the front, and append the next chunk after it.
    if (begin_ > 0) {
      std::memmove(buffer_.get(), start, avail);
      end_ = avail;
      begin_ = 0;
    }
    if (end_ == capacity_) {
      if (capacity_ == kBufferSize) {
        // A binary file need not contain newlines: say "binary" when that is the reason.
        ++line_;
        const auto* bytes = reinterpret_cast<const unsigned char*>(buffer_.get());
        for (std::size_t i = 0; i < end_; ++i) {
          if (kClasses[bytes[i]] == kBinary) fail_binary(bytes[i], i);
        }
        throw InputError(path_, line_,
                         "line is longer than " + std::to_string(kBufferSize) +
                             " bytes; this is not a Triangle file");
      }
      std::unique_ptr<char[]> bigger(new char[kBufferSize]);
      std::memcpy(bigger.get(), buffer_.get(), end_);
      buffer_ = std::move(bigger);
      capacity_ = kBufferSize;
    }
    ssize_t n;
    do {
      n = ::read(fd_, buffer_.get() + end_, capacity_ - end_);
    } while (n < 0 && errno == EINTR);
    if (n < 0) throw InputError(path_, 0, "cannot read: " + errno_text(errno));
    if (n == 0) {
      at_eof_ = true;
    } else {
      end_ += static_cast<std::size_t>(n);
    }
  }
}

void RecordReader::split(std::string_view line) {
  fields_.clear();
  const auto* p = reinterpret_cast<const unsigned char*>(line.data());
  const std::size_t n = line.size();
  std::size_t i = 0;
  // A UTF-8 byte order mark before the first line is an editor artefact, not data.
  if (line_ == 1 && n >= 3 && p[0] == 0xEF && p[1] == 0xBB && p[2] == 0xBF) i = 3;
  // Tight loops over runs of one class: this is the innermost loop of reading a big file.
  for (;;) {
    while (i < n && kClasses[p[i]] == kSpace) ++i;
    if (i == n) return;
    const std::size_t start = i;
    i = end_of_text(p, i, n);
    if (i > start) fields_.emplace_back(line.data() + start, i - start);
    if (i == n) return;
    if (kClasses[p[i]] == kComment) break;
    if (kClasses[p[i]] == kBinary) fail_binary(p[i], i);
  }
  // The comment is ignored, but binary bytes in it still mean this is not a text file.
  for (; i < n; ++i) {
    if (kClasses[p[i]] == kBinary) fail_binary(p[i], i);
  }
}

void RecordReader::fail_binary(unsigned char byte, std::size_t column) const {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(byte));
  fail(std::string("binary data (byte ") + hex + " in column " + std::to_string(column + 1) +
       "); this is not a text file");
}

bool RecordReader::next() {
  std::string_view line;
  while (next_line(line)) {
    split(line);
    if (!fields_.empty()) return true;
  }
  fields_.clear();
  return false;
}

}  // namespace meshstep::io::detail
