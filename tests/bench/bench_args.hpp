// Command-line helpers shared by the benchmark programs: whole-argument number parsing and
// the usage error every one of them reports the same way.
#pragma once

#include <charconv>
#include <cstdio>
#include <string>
#include <string_view>
#include <system_error>

namespace meshstep::bench {

// Is all of `text` one number of type T? (std::from_chars: no locale, no leading spaces.)
template <class T>
bool parse_whole(std::string_view text, T& value) {
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value);
  return !text.empty() && ec == std::errc() && end == last;
}

// "PROGRAM: error: MESSAGE" and the usage text on standard error; returns exit status 2.
inline int usage_error(const char* program, const std::string& message, const char* usage) {
  std::fprintf(stderr, "%s: error: %s\n%s", program, message.c_str(), usage);
  return 2;
}

}  // namespace meshstep::bench
