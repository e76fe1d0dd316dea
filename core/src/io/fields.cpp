#include "io/fields.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <system_error>

namespace meshstep::io::detail {
namespace {

constexpr std::size_t kMaxQuoted = 40;

// from_chars rejects a leading '+', which strtod (and so Triangle) accepts.
std::string_view strip_plus(std::string_view t) {
  if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
  return t;
}

// The common case of an integer field: optional sign, at most 18 digits (so no overflow).
// Several times faster than std::from_chars<long>, which is generic over the base; anything
// else goes to from_chars, which also tells what is wrong.
bool quick_integer(std::string_view t, std::int64_t& out) {
  std::size_t i = 0;
  const bool negative = !t.empty() && t[0] == '-';
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) i = 1;
  if (i == t.size() || t.size() - i > 18) return false;
  std::int64_t v = 0;
  for (; i < t.size(); ++i) {
    const unsigned d = static_cast<unsigned char>(t[i]) - '0';
    if (d > 9) return false;
    v = v * 10 + d;
  }
  out = negative ? -v : v;
  return true;
}

bool is_whole_real(std::string_view t) {
  t = strip_plus(t);
  double v;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ptr == t.data() + t.size() && ec != std::errc::invalid_argument;
}

}  // namespace

std::string quote(std::string_view token) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxQuoted; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7F && c != '\\') {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (token.size() > kMaxQuoted) out += "...";
  out += "'";
  return out;
}

std::int64_t parse_integer(const RecordReader& r, std::size_t field, std::string_view what) {
  const std::string_view raw = r.field(field);
  std::int64_t v = 0;
  if (quick_integer(raw, v)) return v;
  const std::string_view t = strip_plus(raw);
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc() && ptr == t.data() + t.size()) return v;
  if (ec == std::errc::result_out_of_range) {
    r.fail(std::string(what) + " " + quote(raw) + " is out of range");
  }
  if (is_whole_real(raw)) {
    r.fail(std::string(what) + " should be an integer, found " + quote(raw));
  }
  r.fail(std::string(what) + " should be a number, found " + quote(raw));
}

double parse_real(const RecordReader& r, std::size_t field, std::string_view what) {
  const std::string_view raw = r.field(field);
  const std::string_view t = strip_plus(raw);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == t.data() + t.size()) {
    r.fail(std::string(what) + " " + quote(raw) + " is out of the range of a double");
  }
  if (ec != std::errc() || ptr != t.data() + t.size()) {
    r.fail(std::string(what) + " should be a number, found " + quote(raw));
  }
  if (!std::isfinite(v)) {
    r.fail(std::string(what) + " should be a finite number, found " + quote(raw));
  }
  return v;
}

int parse_marker(const RecordReader& r, std::size_t field, std::string_view what) {
  const std::int64_t v = parse_integer(r, field, what);
  if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
    r.fail(std::string(what) + " " + quote(r.field(field)) + " does not fit in an int");
  }
  return static_cast<int>(v);
}

std::uint64_t parse_count(const RecordReader& r, std::size_t field, std::string_view what) {
  const std::int64_t v = parse_integer(r, field, what);
  if (v < 0) r.fail(std::string(what) + " is negative (" + std::to_string(v) + ")");
  return static_cast<std::uint64_t>(v);
}

bool parse_marker_flag(const RecordReader& r, std::size_t field, std::string_view what) {
  const std::int64_t v = parse_integer(r, field, what);
  if (v != 0 && v != 1) {
    r.fail(std::string(what) + " must be 0 or 1, found " + std::to_string(v));
  }
  return v == 1;
}

void expect_fields(const RecordReader& r, std::size_t n, std::string_view names) {
  if (r.field_count() == n) return;
  r.fail("expected " + std::to_string(n) + (n == 1 ? " number (" : " numbers (") +
         std::string(names) + "), found " + std::to_string(r.field_count()));
}

std::size_t check_count(const RecordReader& r, std::uint64_t count, std::uint64_t fields,
                        std::string_view plural, std::uint64_t limit) {
  if (count > limit) {
    r.fail("declares " + std::to_string(count) + " " + std::string(plural) + "; at most " +
           std::to_string(limit) + " are supported");
  }
  // A pipe has no known size: reserve room for a modest number of fields (callers reserve
  // per-field arrays too) and let the vectors grow with what actually arrives.
  constexpr std::uint64_t kBlindReserveFields = 1 << 20;
  const std::uint64_t f = std::max<std::uint64_t>(fields, 1);
  const auto remaining = r.remaining_bytes();
  if (!remaining) return static_cast<std::size_t>(std::min(count, kBlindReserveFields / f));
  // n records of f fields need at least 2*n*f - 1 bytes ("0 0 0\n..." without the last
  // newline); fields <= kMaxFields keeps the product far from overflowing.
  const std::uint64_t capacity = (*remaining + 1) / (2 * f);
  if (count > capacity) {
    r.fail("declares " + std::to_string(count) + " " + std::string(plural) +
           ", but the rest of the file (" + std::to_string(*remaining) +
           " bytes) can hold at most " + std::to_string(capacity) +
           ": the count is wrong or the file is truncated");
  }
  return static_cast<std::size_t>(count);
}

void check_record_number(const RecordReader& r, Numbering& numbering, std::uint64_t index,
                         std::string_view singular) {
  const std::int64_t expected = numbering.base + static_cast<std::int64_t>(index);
  // Fast path for the common case, without building the text of a message.
  if (numbering.base >= 0) {
    std::int64_t v = 0;
    if (quick_integer(r.field(0), v) && v == expected) return;
  }
  const std::int64_t v = parse_integer(r, 0, std::string(singular) + " number");
  if (numbering.base < 0) {
    if (v != 0 && v != 1) {
      r.fail("numbering must start at 0 or 1, but the first " + std::string(singular) +
             " is numbered " + std::to_string(v));
    }
    numbering.base = static_cast<int>(v);
    return;
  }
  if (v == expected) return;
  if (index == 0) {
    r.fail("numbering starts at " + std::to_string(numbering.base) +
           " in this set of files (as decided by the first vertex), but the first " +
           std::string(singular) + " is numbered " + std::to_string(v));
  }
  r.fail(std::string(singular) + " numbers must be consecutive: expected " +
         std::to_string(expected) + ", found " + std::to_string(v));
}

std::uint32_t parse_index(const RecordReader& r, std::size_t field, std::string_view what,
                          std::uint64_t count, int base, std::string_view plural) {
  const std::int64_t v = parse_integer(r, field, what);
  const std::int64_t lo = base < 0 ? 0 : base;
  const std::int64_t hi = lo + static_cast<std::int64_t>(count) - 1;
  if (count == 0 || v < lo || v > hi) {
    const std::string range =
        count == 0 ? "there are no " + std::string(plural)
                   : std::string(plural) + " are numbered " + std::to_string(lo) + ".." +
                         std::to_string(hi);
    r.fail(std::string(what) + " " + std::to_string(v) + " is out of range (" + range + ")");
  }
  return static_cast<std::uint32_t>(v - lo);
}

void require_record(const RecordReader& r, bool found, std::string_view expected) {
  if (!found) r.fail("unexpected end of file: expected " + std::string(expected));
}

}  // namespace meshstep::io::detail
