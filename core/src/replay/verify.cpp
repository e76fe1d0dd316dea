// Forward, backward, forward: every hash the writer stored must come out of the replay.
#include "meshstep/replay/verify.hpp"

#include "meshstep/error.hpp"
#include "meshstep/replay/mesh_hash.hpp"
#include "meshstep/replay/replay.hpp"

namespace meshstep::replay {
namespace {

class Verifier {
 public:
  Verifier(const LogReader& log, const std::function<void(int, double)>& progress)
      : log_(log), replay_(log, /*track_hash=*/true), progress_(progress) {}

  // A problem found (fail) or met on the way (an InputError from the reader or the replay:
  // a damaged or inconsistent file) ends the run as a report, never as an exception.
  VerifyReport run() {
    try {
      check_boundary(0);
      forward(0);
      backward();
      forward(2);
      if (log_.complete() && replay_.hash() != log_.final_hash())
        fail("the mesh at the end differs from the algorithm's final mesh");
      if (!log_.complete()) fail("the log is incomplete: " + log_.incomplete_reason());
    } catch (const Stop&) {
    } catch (const InputError& e) {
      // The log is the file being verified: its path is said once, by the caller.
      report_.ok = false;
      report_.problem = e.file() == log_.path() ? e.message() : e.what();
    }
    report_.events = log_.event_count();
    report_.steps = log_.step_count();
    return report_;
  }

 private:
  // Unwinds from wherever the first problem is found to run(), which catches it alone.
  struct Stop {};

  [[noreturn]] void fail(const std::string& m) {
    report_.ok = false;
    report_.problem = m;
    throw Stop{};
  }

  // At `events`: the keyframes taken there (copies of the algorithm's own mesh) must equal
  // the replayed mesh slot for slot.
  void check_boundary(std::uint64_t events) {
    if (events == 0 && replay_.hash() != 0) fail("the mesh at the start is not empty");
    for (std::size_t j = 0; j < log_.keyframes().size(); ++j) {
      const KeyframeInfo& k = log_.keyframes()[j];
      if (k.event != events) continue;
      ++report_.keyframes_checked;
      const std::vector<FaceRecord>& stored = log_.keyframe(j);
      const auto& slots = replay_.slots();
      bool same = k.mesh_hash == mesh_hash(stored) && k.mesh_hash == replay_.hash();
      for (std::size_t i = 0; same && i < std::max(stored.size(), slots.size()); ++i) {
        const FaceRecord a = i < stored.size() ? stored[i] : FaceRecord{};
        const FaceRecord b2 = i < slots.size() ? slots[i] : FaceRecord{};
        same = a == b2;
      }
      if (!same) fail("the keyframe after event " + std::to_string(events) + " differs from the replayed mesh");
    }
  }

  void forward(int pass) {
    const auto& blocks = log_.blocks();
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      replay_.walk_to(blocks[b].first_event + blocks[b].event_count);
      check_boundary(replay_.position());
      if (progress_ && b % 64 == 0) progress_(pass, static_cast<double>(b) / blocks.size());
    }
  }

  void backward() {
    const auto& blocks = log_.blocks();
    for (std::size_t b = blocks.size(); b-- > 0;) {
      replay_.walk_to(blocks[b].first_event);
      check_boundary(replay_.position());
      if (progress_ && b % 64 == 0) progress_(1, 1.0 - static_cast<double>(b) / blocks.size());
    }
  }

  const LogReader& log_;
  Replay replay_;
  const std::function<void(int, double)>& progress_;
  VerifyReport report_;
};

}  // namespace

VerifyReport verify(const LogReader& log, const std::function<void(int, double)>& progress) {
  return Verifier(log, progress).run();
}

}  // namespace meshstep::replay
