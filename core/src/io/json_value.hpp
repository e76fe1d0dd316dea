// A small JSON reader (RFC 8259) for the GeoJSON reader: the whole text into a tree of
// values, each knowing the line it starts on, so that a reader of the tree can say
// "FILE:LINE: what is wrong". Strict: trailing commas, comments, NaN, leading zeros and
// bad escapes are errors, and nesting deeper than kMaxJsonDepth is refused (no stack
// overflow on hostile input).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace meshstep::io::detail {

inline constexpr std::size_t kMaxJsonDepth = 256;

struct JsonValue {
  enum class Kind { null, boolean, number, string, array, object };
  Kind kind = Kind::null;
  bool boolean = false;
  double number = 0.0;
  std::string text;                                        // a string's value
  std::vector<JsonValue> items;                            // an array's values, unless...
  // ...they are all numbers (a GeoJSON position, [x, y]): then they are here instead, and
  // items is empty. A million positions took 450 bytes each as values, 170 this way.
  std::vector<double> numbers;
  // An object's members, in file order: keys[i] names values[i]. (Two vectors: a vector of
  // pairs of this type, still incomplete here, is refused by clang's library checks.)
  std::vector<std::string> keys;
  std::vector<JsonValue> values;
  std::size_t line = 0;                                    // 1-based, where the value starts

  // The member named `key` (the last one, when a key repeats), or null.
  const JsonValue* member(std::string_view key) const;
};

// "object", "an array", ...: for messages.
const char* json_kind_name(JsonValue::Kind kind);

// Throws InputError(file, line, message) at the first problem.
JsonValue parse_json(const std::string& file, std::string_view text);

}  // namespace meshstep::io::detail
