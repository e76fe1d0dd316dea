// Turning the fields of a record into numbers, with messages that say which number of which
// record is wrong and why. Every failure throws InputError at the record's line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/record_reader.hpp"

namespace meshstep::io::detail {

// The token in single quotes, non-printable bytes escaped, long tokens cut short.
std::string quote(std::string_view token);

std::int64_t parse_integer(const RecordReader& r, std::size_t field, std::string_view what);
// A finite double.
double parse_real(const RecordReader& r, std::size_t field, std::string_view what);
// A boundary marker: any integer that fits an int.
int parse_marker(const RecordReader& r, std::size_t field, std::string_view what);
// A count from a header line: a non-negative integer.
std::uint64_t parse_count(const RecordReader& r, std::size_t field, std::string_view what);
// A "number of markers" field: 0 or 1.
bool parse_marker_flag(const RecordReader& r, std::size_t field, std::string_view what);

// Fails unless the record has exactly `n` fields; `names` lists them for the message,
// e.g. "vertex number, x, y, marker".
void expect_fields(const RecordReader& r, std::size_t n, std::string_view names);

// Guards allocation against absurd counts: fails when `count` exceeds `limit`, or when the
// rest of the file is too short to hold `count` records of `fields` fields each (every
// field takes at least one byte plus a separator). Returns how many records it is safe to
// reserve room for.
std::size_t check_count(const RecordReader& r, std::uint64_t count, std::uint64_t fields,
                        std::string_view plural, std::uint64_t limit);

// The largest number of fields a record can have (a line is at most kBufferSize bytes).
inline constexpr std::uint64_t kMaxFields = RecordReader::kBufferSize / 2;

// Numbering of a set of files: 0 or 1, or -1 until the first record decides it.
struct Numbering {
  int base = -1;
};

// Checks field 0, the record number of the `index`-th (0-based) record of a section: it
// must be base + index; when the base is not yet known, the record decides it (0 or 1).
void check_record_number(const RecordReader& r, Numbering& numbering, std::uint64_t index,
                         std::string_view singular);

// A reference to an item numbered base..base+count-1 (a vertex, a triangle): returns it
// 0-based. `plural` names the items for the message ("vertices").
std::uint32_t parse_index(const RecordReader& r, std::size_t field, std::string_view what,
                          std::uint64_t count, int base, std::string_view plural);

// Fails with "unexpected end of file" unless the reader found a record.
void require_record(const RecordReader& r, bool found, std::string_view expected);

}  // namespace meshstep::io::detail
