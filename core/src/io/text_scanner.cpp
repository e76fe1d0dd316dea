// TextScanner (text_scanner.hpp): the cursor the JSON and WKT readers share.
#include "io/text_scanner.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "meshstep/error.hpp"

namespace meshstep::io::detail {
namespace {

bool token_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
}

}  // namespace

void TextScanner::fail(const std::string& message) const { throw InputError(file_, line_, message); }

std::string TextScanner::describe_here(bool whole_token) const {
  if (pos_ >= text_.size()) return "end of file";
  const unsigned char c = static_cast<unsigned char>(text_[pos_]);
  if (c >= 0x21 && c < 0x7F) {
    std::size_t end = pos_ + 1;
    if (whole_token && token_char(static_cast<char>(c)))
      while (end < text_.size() && end - pos_ < 24 && token_char(text_[end])) ++end;
    return "'" + std::string(text_.substr(pos_, end - pos_)) + "'";
  }
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "byte 0x%02X", c);
  return buffer;
}

void TextScanner::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') ++line_;
    else if (c != ' ' && c != '\t' && c != '\r') return;
    ++pos_;
  }
}

bool TextScanner::take(char c) {
  skip_space();
  if (pos_ < text_.size() && text_[pos_] == c) {
    ++pos_;
    return true;
  }
  return false;
}

bool TextScanner::convert(std::size_t start, std::size_t end, double& value) const {
  if (start >= end) return false;
  const char* first = text_.data() + start;
  const char* last = text_.data() + end;
  double v = 0.0;
  const auto [stop, ec] = std::from_chars(first, last, v);
  if (stop != last) return false;
  // Out of range, from_chars leaves v alone: an underflow is 0, an overflow is refused.
  if (ec == std::errc::result_out_of_range) {
    const std::string_view digits(first, end - start);
    const std::size_t e = digits.find_first_of("eE");
    if (e == std::string_view::npos || !digits.substr(e + 1).starts_with('-')) return false;
    v = 0.0;
  } else if (ec != std::errc()) {
    return false;
  }
  value = v;
  return std::isfinite(v);  // "inf" and "nan" are words to from_chars
}

double TextScanner::json_number() {
  std::size_t i = pos_;
  if (i < text_.size() && text_[i] == '-') ++i;
  if (!digit_at(i)) fail("a number needs a digit after its '-'");
  if (text_[i] == '0' && digit_at(i + 1)) fail("a number may not start with 0 followed by digits");
  while (digit_at(i)) ++i;
  if (i < text_.size() && text_[i] == '.') {
    if (!digit_at(++i)) fail("a number needs a digit after its '.'");
    while (digit_at(i)) ++i;
  }
  if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
    ++i;
    if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) ++i;
    if (!digit_at(i)) fail("a number needs a digit in its exponent");
    while (digit_at(i)) ++i;
  }
  double v = 0.0;
  if (!convert(pos_, i, v)) fail("the number " + std::string(text_.substr(pos_, i - pos_)) + " is too large for a double");
  pos_ = i;
  return v;
}

double TextScanner::decimal_token() {
  skip_space();
  std::size_t end = pos_;
  while (end < text_.size() && token_char(text_[end])) ++end;
  const std::size_t first = pos_ < end && text_[pos_] == '+' ? pos_ + 1 : pos_;  // from_chars takes no '+'
  double v = 0.0;
  if (!convert(first, end, v)) fail("unexpected " + describe_here(true) + ": expected a finite number");
  pos_ = end;
  return v;
}

}  // namespace meshstep::io::detail
