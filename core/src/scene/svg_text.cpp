#include "scene/svg_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace meshstep::scene::detail {

namespace {

constexpr std::string_view kReplacementCharacter = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

// The length of the valid UTF-8 sequence of a character XML allows at the start of `s`,
// or 0 when there is none.
std::size_t valid_xml_char(std::string_view s) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(s[i]); };
  const unsigned char b0 = byte(0);
  if (b0 < 0x80) return (b0 >= 0x20 || b0 == '\t' || b0 == '\n' || b0 == '\r') ? 1 : 0;
  std::size_t length;
  char32_t code;
  if (b0 >= 0xC2 && b0 <= 0xDF) length = 2, code = b0 & 0x1F;
  else if (b0 >= 0xE0 && b0 <= 0xEF) length = 3, code = b0 & 0x0F;
  else if (b0 >= 0xF0 && b0 <= 0xF4) length = 4, code = b0 & 0x07;
  else return 0;
  if (s.size() < length) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    if ((byte(i) & 0xC0) != 0x80) return 0;
    code = code << 6 | (byte(i) & 0x3F);
  }
  const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
  const bool surrogate = code >= 0xD800 && code <= 0xDFFF;
  const bool not_a_char = code == 0xFFFE || code == 0xFFFF || code > 0x10FFFF;
  return overlong || surrogate || not_a_char ? 0 : length;
}

}  // namespace

std::int64_t to_hundredths(double v) {
  // Callers keep coordinates near the picture (see svg_clip.hpp); the clamp only keeps a
  // stray value from overflowing.
  constexpr double kLimit = 1e15;
  return std::llround(std::clamp(v, -kLimit, kLimit) * 100.0);
}

void SvgText::hundredths(std::int64_t v) {
  char buffer[32];
  char* p = buffer;
  if (v < 0) *p++ = '-';
  const std::uint64_t magnitude = v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  p = std::to_chars(p, buffer + sizeof buffer, magnitude / 100).ptr;
  const unsigned cents = static_cast<unsigned>(magnitude % 100);
  if (cents != 0) {
    *p++ = '.';
    *p++ = static_cast<char>('0' + cents / 10);
    if (cents % 10 != 0) *p++ = static_cast<char>('0' + cents % 10);
  }
  append(buffer, p);
}

void SvgText::fine_number(double v) {
  // Thousandths printed as an integer and a fraction without trailing zeros.
  const std::int64_t t = std::llround(std::clamp(v, -1e12, 1e12) * 1000.0);
  char buffer[32];
  char* p = buffer;
  if (t < 0) *p++ = '-';
  const std::uint64_t magnitude = t < 0 ? 0 - static_cast<std::uint64_t>(t) : static_cast<std::uint64_t>(t);
  p = std::to_chars(p, buffer + sizeof buffer, magnitude / 1000).ptr;
  unsigned fraction = static_cast<unsigned>(magnitude % 1000);
  if (fraction != 0) {
    *p++ = '.';
    for (unsigned digit = 100; fraction != 0; digit /= 10) {
      *p++ = static_cast<char>('0' + fraction / digit);
      fraction %= digit;
    }
  }
  append(buffer, p);
}

void SvgText::color(Rgba c) {
  constexpr char kHex[] = "0123456789abcdef";
  const char text[7] = {'#', kHex[c.r >> 4], kHex[c.r & 15], kHex[c.g >> 4], kHex[c.g & 15], kHex[c.b >> 4], kHex[c.b & 15]};
  append(text, text + sizeof text);
}

void SvgText::escaped(std::string_view text) {
  while (!text.empty()) {
    const char c = text.front();
    switch (c) {
      case '&': raw("&amp;"); text.remove_prefix(1); continue;
      case '<': raw("&lt;"); text.remove_prefix(1); continue;
      case '>': raw("&gt;"); text.remove_prefix(1); continue;
      case '"': raw("&quot;"); text.remove_prefix(1); continue;
      case '\'': raw("&apos;"); text.remove_prefix(1); continue;
      default: break;
    }
    const std::size_t n = valid_xml_char(text);
    if (n == 0) {
      raw(kReplacementCharacter);
      text.remove_prefix(1);
    } else {
      raw(text.substr(0, n));
      text.remove_prefix(n);
    }
  }
}

void SvgText::attr(std::string_view name, std::string_view value) {
  ch(' ');
  raw(name);
  raw("=\"");
  raw(value);
  ch('"');
}

void SvgText::attr_escaped(std::string_view name, std::string_view value) {
  ch(' ');
  raw(name);
  raw("=\"");
  escaped(value);
  ch('"');
}

void SvgText::attr_number(std::string_view name, double v) {
  ch(' ');
  raw(name);
  raw("=\"");
  number(v);
  ch('"');
}

void SvgText::attr_fine(std::string_view name, double v) {
  ch(' ');
  raw(name);
  raw("=\"");
  fine_number(v);
  ch('"');
}

void SvgText::attr_color(std::string_view name, Rgba c) {
  ch(' ');
  raw(name);
  raw("=\"");
  color(c);
  ch('"');
}

void SvgText::paint(std::string_view name, Rgba c) {
  if (c.a == 0) {
    attr(name, "none");
    return;
  }
  attr_color(name, c);
  if (c.a == 255) return;
  ch(' ');
  raw(name);
  raw("-opacity=\"");
  fine_number(c.a / 255.0);
  ch('"');
}

void PathData::command(char c) {
  // After 'm', further pairs are implicit 'l's; after 'l', more 'l's need no letter either.
  const bool implied = c == 'l' && (last_ == 'l' || last_ == 'm');
  if (!implied) {
    out_.ch(c);
    after_command_ = true;
  }
  last_ = c;
  empty_ = false;
}

void PathData::value(std::int64_t v) {
  // A minus sign separates numbers by itself.
  if (!after_command_ && v >= 0) out_.ch(' ');
  out_.hundredths(v);
  after_command_ = false;
}

void PathData::pair(std::int64_t x, std::int64_t y) {
  value(x - x_);
  value(y - y_);
  x_ = x;
  y_ = y;
}

void PathData::move_to(Point p) {
  command('m');  // the first 'm' of a path is absolute: relative to (0, 0) it is the same
  pair(to_hundredths(p.x), to_hundredths(p.y));
  start_x_ = x_;
  start_y_ = y_;
}

void PathData::line_to(Point p) {
  command('l');
  pair(to_hundredths(p.x), to_hundredths(p.y));
}

void PathData::close() {
  command('z');
  x_ = start_x_;
  y_ = start_y_;
}

void PathData::circle(Point center, double radius) {
  const std::int64_t r = to_hundredths(radius);
  move_to({center.x - radius, center.y});
  // Two half circles: "a r r 0 1 0 2r 0" then back by -2r (rx ry rotation large sweep dx dy).
  for (const std::int64_t dx : {2 * r, -2 * r}) {
    out_.ch('a');
    after_command_ = true;
    value(r);
    value(r);
    for (int flag : {0, 1, 0}) value(flag * 100);
    value(dx);
    value(0);
    x_ += dx;
  }
  last_ = 'a';
  close();
}

}  // namespace meshstep::scene::detail
