// Default output names, as Triangle chooses them: "box.poly" -> "box.1", "box.1.node" -> "box.2".
#pragma once

#include <cctype>
#include <string>

namespace meshstep::app {

inline std::string strip_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
  return path.substr(0, dot);
}

inline std::string default_output_prefix(const std::string& input) {
  const std::string stem = strip_extension(input);
  const std::size_t dot = stem.find_last_of('.');
  const std::size_t slash = stem.find_last_of('/');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash) && dot + 1 < stem.size()) {
    const std::string tail = stem.substr(dot + 1);
    bool digits = tail.size() < 9;
    for (const char c : tail) digits = digits && std::isdigit(static_cast<unsigned char>(c));
    if (digits) return stem.substr(0, dot + 1) + std::to_string(std::stoi(tail) + 1);
  }
  return stem + ".1";
}

}  // namespace meshstep::app
