// A cursor over a text file, for the readers written by hand (JSON for GeoJSON, WKT): where
// it stands and on which line, white space, single characters, numbers, and errors as
// FILE:LINE. The readers differ in their grammars; what they share is here, once.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace meshstep::io::detail {

class TextScanner {
 public:
  TextScanner(const std::string& file, std::string_view text) : file_(file), text_(text) {}

 protected:
  // Throws InputError(file, the current line, message).
  [[noreturn]] void fail(const std::string& message) const;

  // What stands at the cursor, for a message: "end of file", "'x'" for a printable
  // character, "byte 0xNN" otherwise. With `whole_token`, a word or number is quoted whole
  // (up to 24 characters: "'1.5e'"), not only its first character.
  std::string describe_here(bool whole_token = false) const;

  // Past spaces, tabs and line breaks ("\n", "\r\n"), counting the lines.
  void skip_space();
  // After white space: whether `c` is next, and if so past it.
  bool take(char c);

  bool digit_at(std::size_t i) const { return i < text_.size() && text_[i] >= '0' && text_[i] <= '9'; }

  // A number in JSON's grammar (RFC 8259 section 6) at the cursor: no '+', no leading zeros,
  // digits after '.' and in an exponent. An underflow reads as 0; an overflow, as any
  // departure from the grammar, fails.
  double json_number();
  // A number as WKT writers print them, after white space: the run of letters, digits, '.',
  // '+' and '-' at the cursor, read whole as a decimal number (a leading '+' allowed). An
  // underflow reads as 0; anything else that is not a finite number fails with
  // "unexpected 'TOKEN': expected a finite number".
  double decimal_token();

  const std::string& file_;
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;

 private:
  // The decimal number text_[start, end) holds (from_chars' syntax, no '+'); false when it
  // does not hold one, or it is too large for a double. An underflow is 0.
  bool convert(std::size_t start, std::size_t end, double& value) const;
};

}  // namespace meshstep::io::detail
