// Writes a replay log as a stream while the algorithm runs.
//
// The algorithm's Recorder appends raw events to this sink; every few thousand events the
// batch goes to a background thread that encodes them (adding to every face write what the
// slot held before), keeps its own copy of the mesh to do so, compresses blocks with zstd,
// writes keyframes, and appends each block to PATH.partial as soon as it is complete. So a
// run that dies leaves a readable prefix in PATH.partial; finish() writes the end block and
// renames the file to PATH. A writer destroyed without finish() (the run failed) removes
// its partial file: failed runs leave no half-written log behind.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "meshstep/pslg/pslg.hpp"
#include "meshstep/replay/event.hpp"
#include "meshstep/replay/event_sink.hpp"

namespace meshstep::replay {

// What was run on what: the header of the log.
struct LogHeader {
  std::string program_version;  // filled by the writer
  std::string input;            // input file as named on the command line
  std::string input_hash;       // 16 hex digits: checksum of the input file's bytes
  std::string algorithm;        // "triangulate", or a refinement algorithm's name
  std::string parameters;       // "key=value" pairs separated by spaces
  std::string data_structure;   // "tds" or "dcel"
  std::string insertion;        // "flip" or "cavity"
  // A recipe's operations, one a line in the recipe's words (run_spec.hpp: print_operation),
  // when the run had more than one; each runs its phases after the one before.
  std::string operations;
  // What the run's output carries from its input beyond the geometry the events hold, so
  // that a moment's mesh can be written as the run writes it (Replay::output_mesh). In
  // input coordinates (the log's), each number exact to the last bit. Fields (text, one
  // record a line; a log without one reads as an input without it):
  //   "regions"            "x y attribute max_area": the regional attributes' flood
  //   "holes"              "x y"
  //   "vertex_markers"     "marker count": runs of the input vertices' markers
  //   "vertex_attributes"  the count per vertex, then one vertex's attributes a line
  //   "segment_markers"    "1" when the input's segments had markers
  //   "segments"           "a b": the input's segments by 0-based input vertex index, so that
  //                        the moment before the first triangle can show the input (a log
  //                        without it shows the input's vertices, holes and regions only)
  std::vector<Region> regions;
  std::vector<Point> holes;
  std::vector<int> vertex_markers;  // empty: the input had none
  std::size_t attributes_per_vertex = 0;
  std::vector<double> vertex_attributes;
  bool has_segment_markers = false;
  std::vector<Segment> segments;  // markers are not kept (segment_markers says if there were)
};

// Fills the header's description of the input (regions, holes, markers, attributes).
void describe_input(LogHeader& header, const Pslg& in);

// The fields' text and back. The parsers throw std::invalid_argument on a malformed line,
// and on more markers or attribute lines than `vertex_limit`.
std::string regions_field(const std::vector<Region>& regions);
std::vector<Region> parse_regions_field(const std::string& text);
std::string holes_field(const std::vector<Point>& holes);
std::vector<Point> parse_holes_field(const std::string& text);
// Segment indices are checked against the input's vertex count.
std::string segments_field(const std::vector<Segment>& segments);
std::vector<Segment> parse_segments_field(const std::string& text, std::size_t vertex_count);
std::string vertex_markers_field(const std::vector<int>& markers);
std::vector<int> parse_vertex_markers_field(const std::string& text, std::size_t vertex_limit);
std::string vertex_attributes_field(std::size_t per_vertex, const std::vector<double>& values);
std::pair<std::size_t, std::vector<double>> parse_vertex_attributes_field(const std::string& text,
                                                                          std::size_t vertex_limit);

struct LogWriterOptions {
  // Whether event blocks go through zstd. Format 5's events leave its fast levels nothing
  // to find (at -20, a 1e6-point triangulation's events came out 0.02% smaller, for 12% of
  // the writer thread's instructions), so they are stored as they are; a stronger level
  // would shrink them (level 1: about 10%) but cost as much time as the triangulation.
  // Logs of an older format (format_version below) are compressed, as they always were.
  bool compress = false;
  int zstd_level = -20;  // when compressing
  std::size_t block_bytes = 256 * 1024;  // encoded events per block, before compression
  KeyframePolicy keyframes;
  // The file format version to write; 0: the current one. 2 writes what meshstep wrote
  // before version 3 (locate events without their walk), for tests that such logs still
  // read. Any other: std::invalid_argument.
  std::uint32_t format_version = 0;
};

struct LogStats {
  std::uint64_t events = 0, steps = 0, blocks = 0, keyframes = 0, bytes = 0;
  std::uint64_t keyframe_bytes = 0;  // stored (compressed) keyframe payloads
  std::array<std::uint64_t, kEventTypeCount> by_type{};
};

// The 16-hex-digit checksum stored as LogHeader::input_hash. Throws InputError when the
// file cannot be read.
std::string file_hash(const std::string& path);

class LogWriter final : public EventSink {
 public:
  // Creates PATH.partial and writes the header; throws InputError when it cannot.
  LogWriter(std::string path, LogHeader header, LogWriterOptions options = {});
  ~LogWriter() override;
  LogWriter(const LogWriter&) = delete;
  LogWriter& operator=(const LogWriter&) = delete;

  // Writes what is left and the end block, and renames PATH.partial to PATH. Throws
  // InputError on an I/O failure (disk full...).
  void finish();
  const LogStats& stats() const;  // complete after finish()
  const std::string& path() const;

 protected:
  void hand_over(EventWords& words) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace meshstep::replay
