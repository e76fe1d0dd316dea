// The replay log: open it, then replay it to its end, back to the start, and to its
// middle by steps; read every event; then verify it as `log verify` does. Whatever the
// bytes, a log either opens and replays or is refused with an InputError, and the
// verifier reports on it without throwing anything (a damaged log is a report, never an
// internal error). The checksums are remade before the bytes are read (log_bytes.hpp), so
// mutations reach the decoder; the seeds store their payloads raw for the same reason.
#include "fuzz_support.hpp"
#include "log_bytes.hpp"
#include "meshstep/replay/log_reader.hpp"
#include "meshstep/replay/replay.hpp"
#include "meshstep/replay/verify.hpp"

using namespace meshstep;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> bytes(data, data + size);
  fuzz::fix_checksums(bytes);
  fuzz::refusals_allowed([&] {
    const replay::LogReader log(fuzz::write_input(bytes.data(), bytes.size(), ".mslog"));
    for (std::uint64_t e = 0; e < log.event_count() && e < 10000; ++e) (void)log.event(e);
    replay::Replay cursor(log);
    cursor.seek_event(log.event_count());
    (void)cursor.mesh();
    (void)cursor.output_mesh();  // what `log mesh` writes: markers, regions, header fields
    cursor.seek_event(0);
    cursor.seek_step(log.step_count() / 2);
    while (cursor.prev_event()) {
    }
    cursor.walk_to(log.event_count());
    (void)cursor.hash();
  });
  // A log that opens is verified; verify() reports, and throws nothing, not even an InputError.
  try {
    const replay::LogReader log(fuzz::write_input(bytes.data(), bytes.size(), ".mslog"));
    try {
      (void)replay::verify(log);
    } catch (const std::exception& e) {
      fuzz::finding(std::string("log verify threw: ") + e.what());
    }
  } catch (const InputError&) {
  }
  return 0;
}
