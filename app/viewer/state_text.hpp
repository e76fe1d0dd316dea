// The words of the scripted mode's `state` JSON, for every file that writes a part of it
// (state_json.cpp, compare_state.cpp, workbench_host.cpp): one spelling of a string and a
// number.
#pragma once

#include <cstdio>
#include <string>

namespace meshstep::viewer {

// A JSON string; control characters are left out (state's texts are one line each).
inline std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + '"';
}

// Nine significant digits: what the tests compare against the logs' own numbers.
inline std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace meshstep::viewer
