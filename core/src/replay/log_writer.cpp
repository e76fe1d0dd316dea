// The log writer: a background thread encodes and writes while the algorithm runs.
#include "meshstep/replay/log_writer.hpp"

#include <stdexcept>
#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <exception>
#include <fstream>
#include <mutex>
#include <thread>

#include "format.hpp"
#include "log_encoder.hpp"
#include "meshstep/error.hpp"

namespace meshstep::replay {
namespace {

constexpr std::size_t kBatchWords = 1 << 14;  // 64 KiB of raw events per hand-over
// Batches queued before the algorithm waits: 16 MiB, enough to ride out the time the writer
// spends on a keyframe of a million faces (about 30 ms) without holding up the algorithm.
constexpr std::size_t kMaxPending = 256;

std::string hex16(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

void put_field(std::vector<std::uint8_t>& out, const std::string& key, const std::string& value) {
  format::put_le(out, static_cast<std::uint16_t>(key.size()));
  out.insert(out.end(), key.begin(), key.end());
  format::put_le(out, static_cast<std::uint32_t>(value.size()));
  out.insert(out.end(), value.begin(), value.end());
}

}  // namespace

// Read a buffer at a time: the input of a recorded run is read whole by its own reader
// already, and a second whole copy (45 MB for a million points, zero-filled, then read into,
// page by page) cost the recorded run's thread more than the checksum itself.
std::string file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw InputError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  const std::streamoff size = in.tellg();
  in.seekg(0);
  format::ChecksumStream sum(size > 0 ? static_cast<std::uint64_t>(size) : 0);
  std::vector<std::uint8_t> buffer(std::size_t{1} << 20);  // a multiple of 8 bytes
  for (std::uint64_t left = size > 0 ? static_cast<std::uint64_t>(size) : 0; left > 0;) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(left, buffer.size()));
    if (!in.read(reinterpret_cast<char*>(buffer.data()), static_cast<std::streamsize>(n)))
      throw InputError(path, 0, "cannot read the whole file");
    sum.add({buffer.data(), n});
    left -= n;
  }
  return hex16(sum.value());
}

struct LogWriter::Impl {
  std::string path, partial;
  std::FILE* file = nullptr;
  LogEncoder encoder;
  bool finished = false;

  std::mutex mutex;
  std::condition_variable changed;
  std::deque<EventWords> pending;
  std::vector<EventWords> spare;
  bool closing = false;
  std::exception_ptr failure;
  std::thread worker;

  Impl(std::string p, const LogWriterOptions& options)
      : path(std::move(p)), partial(path + ".partial"),
        encoder(options, [this](const format::BlockHeader& h, std::span<const std::uint8_t> stored) {
          write_block(h, stored);
        }) {}

  void fail_io(const char* what) {
    throw InputError(partial, 0, std::string(what) + ": " + std::strerror(errno));
  }

  void write_bytes(const void* data, std::size_t n) {
    if (std::fwrite(data, 1, n, file) != n) fail_io("cannot write");
  }

  void write_block(const format::BlockHeader& h, std::span<const std::uint8_t> stored) {
    std::uint8_t bytes[format::kBlockHeaderSize];
    format::serialize(h, bytes);
    write_bytes(bytes, sizeof bytes);
    write_bytes(stored.data(), stored.size());
    // Each finished block reaches the operating system at once: a run that dies later
    // leaves every block before it readable.
    if (std::fflush(file) != 0) fail_io("cannot write");
  }

  void write_header(LogHeader header) {
    header.program_version = MESHSTEP_VERSION;
    std::vector<std::uint8_t> fields;
    put_field(fields, "program_version", header.program_version);
    put_field(fields, "input", header.input);
    put_field(fields, "input_hash", header.input_hash);
    put_field(fields, "algorithm", header.algorithm);
    put_field(fields, "parameters", header.parameters);
    put_field(fields, "data_structure", header.data_structure);
    put_field(fields, "insertion", header.insertion);
    if (!header.operations.empty()) {
      // An older reader would read the phases of a chain as one run's.
      if (encoder.format_version() < format::kOperationsVersion)
        throw std::invalid_argument("replay log format version " + std::to_string(encoder.format_version()) +
                                    " cannot name a recipe's operations (" +
                                    std::to_string(format::kOperationsVersion) + " can)");
      put_field(fields, "operations", header.operations);
    }
    if (!header.regions.empty()) put_field(fields, "regions", regions_field(header.regions));
    if (!header.holes.empty()) put_field(fields, "holes", holes_field(header.holes));
    if (!header.vertex_markers.empty()) put_field(fields, "vertex_markers", vertex_markers_field(header.vertex_markers));
    if (header.attributes_per_vertex > 0)
      put_field(fields, "vertex_attributes", vertex_attributes_field(header.attributes_per_vertex, header.vertex_attributes));
    if (header.has_segment_markers) put_field(fields, "segment_markers", "1");
    if (!header.segments.empty()) put_field(fields, "segments", segments_field(header.segments));
    std::vector<std::uint8_t> bytes(format::kFileMagic, format::kFileMagic + 8);
    format::put_le(bytes, encoder.format_version());
    format::put_le(bytes, static_cast<std::uint32_t>(fields.size()));
    bytes.insert(bytes.end(), fields.begin(), fields.end());
    format::put_le(bytes, format::checksum(bytes));
    write_bytes(bytes.data(), bytes.size());
  }

  void run() {
    try {
      for (;;) {
        EventWords batch;
        {
          std::unique_lock lock(mutex);
          changed.wait(lock, [&] { return !pending.empty() || closing; });
          if (pending.empty()) break;
          batch = std::move(pending.front());
          pending.pop_front();
        }
        changed.notify_all();
        encoder.consume(batch);
        batch.clear();
        std::lock_guard lock(mutex);
        spare.push_back(std::move(batch));
      }
      if (finished) encoder.finish();
    } catch (...) {
      std::lock_guard lock(mutex);
      failure = std::current_exception();
      pending.clear();
    }
    changed.notify_all();
  }

  void submit(EventWords& words) {
    std::unique_lock lock(mutex);
    changed.wait(lock, [&] { return pending.size() < kMaxPending || failure; });
    if (failure) std::rethrow_exception(failure);
    pending.push_back(std::move(words));
    if (!spare.empty()) {
      words = std::move(spare.back());
      spare.pop_back();
    } else {
      words = {};  // the sink sizes it
    }
    changed.notify_all();
  }

  void stop() {
    {
      std::lock_guard lock(mutex);
      closing = true;
    }
    changed.notify_all();
    if (worker.joinable()) worker.join();
  }
};

LogWriter::LogWriter(std::string path, LogHeader header, LogWriterOptions options)
    : EventSink(kBatchWords), impl_(std::make_unique<Impl>(std::move(path), options)) {
  keyframes_ = options.keyframes;
  impl_->file = std::fopen(impl_->partial.c_str(), "wb");
  if (!impl_->file) impl_->fail_io("cannot create");
  try {
    impl_->write_header(std::move(header));
  } catch (...) {
    std::fclose(impl_->file);
    std::remove(impl_->partial.c_str());
    throw;
  }
  impl_->worker = std::thread([this] { impl_->run(); });
}

LogWriter::~LogWriter() {
  if (impl_->finished) return;
  impl_->stop();
  std::fclose(impl_->file);
  std::remove(impl_->partial.c_str());
}

void LogWriter::hand_over(EventWords& words) { impl_->submit(words); }

void LogWriter::finish() {
  if (impl_->finished) return;
  flush();
  impl_->finished = true;  // read by the worker only after stop() below wakes it
  impl_->stop();
  const bool closed = std::fclose(impl_->file) == 0;
  impl_->file = nullptr;
  if (impl_->failure) {
    std::remove(impl_->partial.c_str());
    std::rethrow_exception(impl_->failure);
  }
  if (!closed) {
    std::remove(impl_->partial.c_str());
    impl_->fail_io("cannot write");
  }
  if (std::rename(impl_->partial.c_str(), impl_->path.c_str()) != 0) {
    const int err = errno;
    std::remove(impl_->partial.c_str());
    throw InputError(impl_->path, 0, std::string("cannot create: ") + std::strerror(err));
  }
}

const LogStats& LogWriter::stats() const { return impl_->encoder.stats(); }
const std::string& LogWriter::path() const { return impl_->path; }

}  // namespace meshstep::replay
