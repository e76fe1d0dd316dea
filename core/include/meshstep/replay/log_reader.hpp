// Opens a replay log, checks all of it, and gives random access to its events.
//
// Opening reads the whole file, verifies the header and every block's checksum, decodes
// every event once (to count them, find the steps and collect the vertices' coordinates)
// and indexes the blocks and keyframes. Errors name the file and where in it the problem
// is: a foreign file, a newer format, a damaged header, a corrupted block. A file that ends
// early (a run that died, a partial copy) opens as the prefix it holds: complete() is then
// false and incomplete_reason() says where it stops.
#pragma once

#include <array>
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "meshstep/io/mapped_file.hpp"
#include "meshstep/replay/decoded_events.hpp"
#include "meshstep/replay/event.hpp"
#include "meshstep/replay/log_writer.hpp"
#include "meshstep/replay/run_header.hpp"

namespace meshstep::replay {

struct BlockInfo {
  std::uint64_t first_event = 0, event_count = 0, mesh_hash = 0;  // hash after the block
  std::uint64_t offset = 0;  // of the block header in the file
  std::uint32_t stored_size = 0, raw_size = 0;
};

struct KeyframeInfo {
  std::uint64_t event = 0;  // the keyframe is the mesh after this many events
  std::uint64_t slot_count = 0, mesh_hash = 0, offset = 0;
  std::uint32_t stored_size = 0, raw_size = 0;
};

// A phase of the run: the events [begin, end), from its phase_begin to its phase_end
// included (end is kNoEnd for a phase the log does not close: a run that died).
struct PhaseSpan {
  Phase phase = Phase::insert_vertices;
  std::uint64_t begin = 0, end = 0;
};
inline constexpr std::uint64_t kNoEnd = UINT64_MAX;

struct VertexInfo {
  Point point;
  std::uint32_t input_index = kNone;  // in the input's numbering (Steiner: its own id)
  std::uint64_t event = 0;            // the event that introduced it
  VertexId same_as = kNone;           // for a duplicate: the vertex standing for it
  std::uint64_t removed = UINT64_MAX;  // the event that removed it (remove_vertex), if any
  double z = 0.0;                      // its height (elevation event; 0 in a planar run)
};

class LogReader {
 public:
  // Throws InputError ("PATH: ...") when the file cannot be read or is not a valid log.
  // keep_writes_bytes: the largest file whose writes all stay decoded (see writes()).
  explicit LogReader(const std::string& path, std::uint64_t keep_writes_bytes = kKeepWritesBytes);
  ~LogReader();

  const std::string& path() const { return path_; }
  const LogHeader& header() const { return header_; }
  std::uint32_t format_version() const { return format_version_; }
  // What the header says of the run, typed (the one reader of its parameters).
  const RunHeader& run() const { return run_; }
  std::uint64_t file_size() const { return file_.size(); }

  bool complete() const { return complete_; }
  const std::string& incomplete_reason() const { return incomplete_reason_; }

  std::uint64_t event_count() const { return event_count_; }
  std::uint64_t step_count() const { return step_starts_.size(); }
  const std::array<std::uint64_t, kEventTypeCount>& counts_by_type() const { return counts_; }
  // Index of the event that begins step k; step_start(step_count()) == event_count().
  std::uint64_t step_start(std::uint64_t k) const;
  // The step an event belongs to, or step_count() for events of the preamble (before the
  // first step).
  std::uint64_t step_of_event(std::uint64_t e) const;
  // Step arithmetic on an event position (the mesh after that many events), without
  // replaying anything: the steps completed there, and the step boundary after (before) it.
  // A Replay cursor's completed_steps(), next_step() and prev_step() are these.
  std::uint64_t completed_steps_at(std::uint64_t position) const;
  std::uint64_t next_step_boundary(std::uint64_t position) const;
  std::uint64_t prev_step_boundary(std::uint64_t position) const;
  // What step k does (its step_begin's kind).
  StepKind step_kind(std::uint64_t k) const { return step_kinds_[k]; }
  // The phases in the order they begin (a timeline's bands).
  const std::vector<PhaseSpan>& phases() const { return phases_; }

  const std::vector<BlockInfo>& blocks() const { return blocks_; }
  const std::vector<KeyframeInfo>& keyframes() const { return keyframes_; }
  std::size_t block_of_event(std::uint64_t e) const;
  // The decoded events of a block (cached: the most recently used blocks stay decoded).
  // The reference stays valid until the next call of block_events or event.
  const DecodedEvents& block_events(std::size_t block) const;
  // Event e; its spans stay valid until the next call of block_events or event.
  Event event(std::uint64_t e) const;
  // The face writes of event e. A log of up to kKeepWritesBytes keeps all its writes
  // decoded in memory from the start (36 bytes a write: moving through it costs a memory
  // copy per write). A bigger log decodes them from its blocks when asked (the recently
  // used blocks stay decoded), valid until the next call of writes, block_events or event:
  // kept decoded, a million-point triangulation's log took 1.1 GB and 7 s to open; read
  // from its blocks, 0.3 GB and 1.2 s, for seeks about 9 times slower.
  std::span<const SlotWrite> writes(std::uint64_t e) const {
    if (write_end_.empty()) return writes_from_blocks(e);
    const std::uint64_t begin = e ? write_end_[e - 1] : 0;
    return {writes_.data() + begin, write_end_[e] - begin};
  }
  static constexpr std::uint64_t kKeepWritesBytes = std::uint64_t{48} << 20;
  // The face records of keyframe j (decoded once, then cached).
  const std::vector<FaceRecord>& keyframe(std::size_t j) const;

  // Every vertex the run introduced, by vertex id (ids never used have event == kNone).
  const std::vector<VertexInfo>& vertices() const { return vertices_; }
  // A vertex's name in every text (captions, explanations, the inspector, `log dump`,
  // labels): its number in the run's output .node, counted from the input's first index
  // (input vertices keep their input file's numbers, Steiner vertices follow in the order
  // they were inserted); "r3" for the third vertex the run removes again, which has no
  // number in the output; "infinity" for the vertex at infinity. (vertex_names.cpp)
  std::string vertex_name(VertexId v) const;
  // Its number in the output's .node (from the first index), or kNone when it has none.
  std::uint32_t output_number(VertexId v) const;
  // A terrain's log: its vertices have heights (elevation events), and it can be seen in 3D.
  bool has_elevation() const { return counts_[static_cast<std::size_t>(EventType::elevation)] > 0; }
  // The final mesh hash from the end block (complete logs only).
  std::uint64_t final_hash() const { return final_hash_; }

  // A location for messages: "PATH: block B (byte N)".
  std::string where(std::size_t block) const;

 private:
  void read_header();
  void scan_blocks();
  void read_input_fields();
 public:
  struct BlockSlot;  // (log_reader.cpp)
  struct Decoded;

 private:
  // Indexes one block (scan_blocks decoded it); true at the end block.
  bool index_block(const BlockSlot& slot, const Decoded& decoded);
  void index_events(std::size_t block, const DecodedEvents& events);
  void read_end_block(const std::uint8_t* payload, std::size_t stored, std::size_t raw);

  std::string path_;
  io::MappedFile file_;
  LogHeader header_;
  RunHeader run_;
  // The raw text of the fields that describe the input, parsed by read_input_fields().
  std::map<std::string, std::string> input_fields_ = {
      {"regions", {}}, {"holes", {}}, {"vertex_markers", {}}, {"vertex_attributes", {}}, {"segment_markers", {}},
      {"segments", {}}};
  std::uint32_t format_version_ = 0;
  std::size_t blocks_start_ = 0;
  bool complete_ = false;
  std::string incomplete_reason_;
  std::uint64_t event_count_ = 0;
  // What a damaged log is held to before its ids are used (index_events): a vertex id
  // below the input's vertices plus the events the blocks declare (each introduces at most
  // one), and face slots made one after the other (a write names a slot already made, or
  // the next one).
  std::uint64_t vertex_bound_ = 0;
  std::uint64_t slot_bound_ = 0;
  std::uint64_t final_hash_ = 0;
  std::array<std::uint64_t, kEventTypeCount> counts_{};
  std::vector<std::uint64_t> step_starts_;
  std::vector<StepKind> step_kinds_;
  std::vector<PhaseSpan> phases_;
  std::vector<BlockInfo> blocks_;
  std::vector<KeyframeInfo> keyframes_;
  std::vector<VertexInfo> vertices_;
  // The names, worked out when first asked for (a sort of every vertex: 0.1-0.3 s for a
  // million, which log info, verify and check need not pay), once, whichever thread asks.
  struct VertexNumbers;
  const VertexNumbers& vertex_numbers() const;
  std::unique_ptr<VertexNumbers> vertex_numbers_;
  std::span<const SlotWrite> writes_from_blocks(std::uint64_t e) const;

  bool keep_writes_ = true;
  std::vector<SlotWrite> writes_;         // all of them, for a log of up to kKeepWritesBytes
  std::vector<std::uint64_t> write_end_;  // per event: end of its writes in writes_
  mutable std::size_t last_block_ = 0;    // the block writes_from_blocks found last

  struct Cache;
  std::unique_ptr<Cache> cache_;
};

}  // namespace meshstep::replay
