#include "io/atomic_writer.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>

#include "meshstep/error.hpp"

namespace meshstep::io::detail {
namespace {

// Distinguishes temporary files of several writers in one process; O_EXCL guards against
// everything else (other processes, leftovers of a crash).
std::atomic<unsigned> g_temp_counter{0};

std::string temp_name_for(const std::string& path, unsigned attempt) {
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  return dir + "." + base + ".tmp." + std::to_string(::getpid()) + "." +
         std::to_string(g_temp_counter.fetch_add(1)) + "." + std::to_string(attempt);
}

}  // namespace

AtomicWriter::AtomicWriter(std::string path) : path_(std::move(path)) {
  for (unsigned attempt = 0; attempt < 100; ++attempt) {
    temp_path_ = temp_name_for(path_, attempt);
    // Mode 0666 before the umask, like any new file, since the rename gives the target
    // the temporary file's permissions.
    fd_ = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0 || errno != EEXIST) break;
  }
  if (fd_ < 0) {
    const int err = errno;
    temp_path_.clear();
    throw InputError(path_, 0, std::string("cannot write: ") + std::strerror(err));
  }
  buffer_.reset(new char[kBufferSize]);  // not zeroed: only written bytes are flushed
}

AtomicWriter::~AtomicWriter() { discard(); }

void AtomicWriter::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temp_path_.empty()) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
  }
}

void AtomicWriter::fail(const std::string& action, int err) {
  discard();
  throw InputError(path_, 0, action + ": " + std::strerror(err));
}

void AtomicWriter::flush() {
  std::size_t done = 0;
  while (done < used_) {
    const ssize_t n = ::write(fd_, buffer_.get() + done, used_ - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write", errno);
    }
    done += static_cast<std::size_t>(n);
  }
  used_ = 0;
}

void AtomicWriter::text(std::string_view s) {
  while (!s.empty()) {
    if (used_ == kBufferSize) flush();
    const std::size_t n = std::min(s.size(), kBufferSize - used_);
    std::memcpy(buffer_.get() + used_, s.data(), n);
    used_ += n;
    s.remove_prefix(n);
  }
}

void AtomicWriter::integer(std::int64_t v) {
  reserve_number();
  char* out = buffer_.get() + used_;
  used_ += static_cast<std::size_t>(std::to_chars(out, out + kMaxNumberChars, v).ptr - out);
}

void AtomicWriter::real(double v) {
  reserve_number();
  char* out = buffer_.get() + used_;
  used_ += static_cast<std::size_t>(std::to_chars(out, out + kMaxNumberChars, v).ptr - out);
}

void AtomicWriter::commit() {
  flush();
  // close() is where some file systems (NFS) report a failed write.
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("cannot write", errno);
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) fail("cannot replace", errno);
  temp_path_.clear();
}

}  // namespace meshstep::io::detail
