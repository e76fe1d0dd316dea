// The one exception type for bad input: it knows where the problem is.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace meshstep {

// what() reads "FILE:LINE: message", "FILE: message" when line is 0, or just the message
// when there is no file (e.g. a point set built in memory).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::size_t line, const std::string& message)
      : std::runtime_error(format(file, line, message)),
        file_(std::move(file)),
        line_(line),
        message_(message) {}
  explicit InputError(const std::string& message) : InputError("", 0, message) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& file, std::size_t line, const std::string& m) {
    if (file.empty()) return m;
    if (line == 0) return file + ": " + m;
    return file + ":" + std::to_string(line) + ": " + m;
  }
  std::string file_;
  std::size_t line_;
  std::string message_;
};

}  // namespace meshstep
