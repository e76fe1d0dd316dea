// Streaming reader of Triangle-style text files: yields one record (the whitespace-separated
// fields of a line, comments and blank lines removed) at a time, reading the file in fixed
// 1 MiB chunks so that memory use does not grow with the file size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meshstep::io::detail {

class RecordReader {
 public:
  // Chunk size; also the longest line accepted (a longer one is not a Triangle file).
  static constexpr std::size_t kBufferSize = std::size_t{1} << 20;

  // Throws InputError(path, 0, reason) when the file cannot be opened.
  explicit RecordReader(std::string path);
  ~RecordReader();
  RecordReader(const RecordReader&) = delete;
  RecordReader& operator=(const RecordReader&) = delete;

  // Advances to the next line holding at least one field; false at the end of the file.
  // The fields stay valid until the next call.
  bool next();

  std::size_t field_count() const { return fields_.size(); }
  std::string_view field(std::size_t i) const { return fields_[i]; }

  // 1-based line of the current record; at the end of the file, the last line (at least 1).
  std::size_t line() const { return line_ == 0 ? 1 : line_; }
  const std::string& path() const { return path_; }

  // Bytes after the current record; empty when the size is unknown (not a regular file).
  std::optional<std::uint64_t> remaining_bytes() const;

  [[noreturn]] void fail(const std::string& message) const;

 private:
  bool next_line(std::string_view& line);
  void split(std::string_view line);
  [[noreturn]] void fail_binary(unsigned char byte, std::size_t column) const;

  std::string path_;
  int fd_ = -1;
  std::optional<std::uint64_t> file_size_;
  std::unique_ptr<char[]> buffer_;
  std::size_t capacity_ = 0;  // kBufferSize, or less for a small file
  std::size_t begin_ = 0;  // unread data is buffer_[begin_, end_)
  std::size_t end_ = 0;
  bool at_eof_ = false;
  std::uint64_t consumed_ = 0;  // bytes of the file before buffer_[begin_]
  std::size_t line_ = 0;
  std::vector<std::string_view> fields_;
};

}  // namespace meshstep::io::detail
