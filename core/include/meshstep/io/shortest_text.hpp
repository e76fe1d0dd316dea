// The shortest decimal text that reads back as exactly the same number (std::to_chars):
// how meshstep writes a coordinate it must not round (messages that name a coordinate, the
// replay log's header fields).
#pragma once

#include <charconv>
#include <string>

namespace meshstep::io {

inline std::string shortest_text(double v) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
}

}  // namespace meshstep::io
