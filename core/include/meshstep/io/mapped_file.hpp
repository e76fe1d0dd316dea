// A whole file's bytes, read only: mapped into memory where the system allows (a regular
// file), else read into a buffer (a pipe, a special file).
//
// Why map: on the virtual machines this project runs on, touching fresh anonymous memory
// costs about 7 us a page, so reading a 133 MB replay log into a vector took 1.4 s, most of
// it page faults; mapping the same file from the page cache took 0.11 s.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace meshstep::io {

class MappedFile {
 public:
  MappedFile() = default;
  // Throws InputError("PATH: cannot read: why").
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const std::uint8_t* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  void release() noexcept;

  const std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
  bool mapped_ = false;
  std::vector<std::uint8_t> buffer_;  // when it could not be mapped
};

}  // namespace meshstep::io
