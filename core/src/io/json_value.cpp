// parse_json (json_value.hpp): recursive descent over the grammar of RFC 8259, with a
// depth limit.
#include "io/json_value.hpp"

#include "io/text_scanner.hpp"

namespace meshstep::io::detail {
namespace {

class Parser : TextScanner {
 public:
  using TextScanner::TextScanner;

  JsonValue document() {
    JsonValue v = value(0);
    skip_space();
    if (pos_ < text_.size()) fail("unexpected " + describe_here() + " after the JSON value");
    return v;
  }

 private:
  void expect_word(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) fail("unexpected " + describe_here() + ": expected a JSON value");
    pos_ += word.size();
  }

  JsonValue value(std::size_t depth) {
    if (depth > kMaxJsonDepth) fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    skip_space();
    JsonValue v;
    v.line = line_;
    if (pos_ >= text_.size()) fail("unexpected end of file: expected a JSON value");
    const char c = text_[pos_];
    if (c == '{') {
      ++pos_;
      v.kind = JsonValue::Kind::object;
      if (take('}')) return v;
      do {
        skip_space();
        if (pos_ >= text_.size() || text_[pos_] != '"')
          fail("unexpected " + describe_here() + ": expected a member name in quotes");
        std::string key = string();
        if (!take(':')) fail("unexpected " + describe_here() + ": expected ':' after the member name");
        v.keys.push_back(std::move(key));
        v.values.push_back(value(depth + 1));
      } while (take(','));
      if (!take('}')) fail("unexpected " + describe_here() + ": expected ',' or '}' in an object");
    } else if (c == '[') {
      ++pos_;
      v.kind = JsonValue::Kind::array;
      if (take(']')) return v;
      do v.items.push_back(value(depth + 1));
      while (take(','));
      if (!take(']')) fail("unexpected " + describe_here() + ": expected ',' or ']' in an array");
      bool all_numbers = true;
      for (const JsonValue& item : v.items) all_numbers = all_numbers && item.kind == JsonValue::Kind::number;
      if (all_numbers) {
        v.numbers.reserve(v.items.size());
        for (const JsonValue& item : v.items) v.numbers.push_back(item.number);
        std::vector<JsonValue>().swap(v.items);
      }
    } else if (c == '"') {
      v.kind = JsonValue::Kind::string;
      v.text = string();
    } else if (c == 't' || c == 'f') {
      v.kind = JsonValue::Kind::boolean;
      v.boolean = c == 't';
      expect_word(v.boolean ? "true" : "false");
    } else if (c == 'n') {
      expect_word("null");
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      v.kind = JsonValue::Kind::number;
      v.number = json_number();
    } else {
      fail("unexpected " + describe_here() + ": expected a JSON value");
    }
    return v;
  }

  unsigned hex4() {
    if (pos_ + 4 > text_.size()) fail("unexpected end of file in a \\u escape");
    unsigned v = 0;
    for (int k = 0; k < 4; ++k) {
      const char c = text_[pos_++];
      v <<= 4;
      if (c >= '0' && c <= '9') v |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') v |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') v |= static_cast<unsigned>(c - 'A' + 10);
      else fail("a \\u escape needs four hexadecimal digits");
    }
    return v;
  }

  static void append_utf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  // At the opening quote.
  std::string string() {
    ++pos_;
    std::string out;
    while (true) {
      if (pos_ >= text_.size()) fail("unexpected end of file in a string");
      const char c = text_[pos_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("a control character (a line break?) inside a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= text_.size()) fail("unexpected end of file in a string");
      switch (const char e = text_[pos_++]) {
        case '"': case '\\': case '/': out += e; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00) {  // a surrogate pair
            if (pos_ + 2 > text_.size() || text_[pos_] != '\\' || text_[pos_ + 1] != 'u')
              fail("a \\u escape of a high surrogate needs a low one after it");
            pos_ += 2;
            const unsigned low = hex4();
            if (low < 0xDC00 || low >= 0xE000) fail("a \\u escape of a high surrogate needs a low one after it");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          } else if (cp >= 0xDC00 && cp < 0xE000) {
            fail("a \\u escape of a low surrogate without a high one");
          }
          append_utf8(out, cp);
          break;
        }
        default: fail(std::string("unknown escape \\") + (static_cast<unsigned char>(e) >= 0x21 && e != 0x7F ? std::string(1, e) : "?") + " in a string");
      }
    }
  }

};

}  // namespace

const JsonValue* JsonValue::member(std::string_view key) const {
  for (std::size_t i = keys.size(); i-- > 0;)
    if (keys[i] == key) return &values[i];
  return nullptr;
}

const char* json_kind_name(JsonValue::Kind kind) {
  switch (kind) {
    case JsonValue::Kind::null: return "null";
    case JsonValue::Kind::boolean: return "a boolean";
    case JsonValue::Kind::number: return "a number";
    case JsonValue::Kind::string: return "a string";
    case JsonValue::Kind::array: return "an array";
    case JsonValue::Kind::object: return "an object";
  }
  return "?";
}

JsonValue parse_json(const std::string& file, std::string_view text) {
  // A byte-order mark is no JSON, but editors on Windows write one.
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  return Parser(file, text).document();
}

}  // namespace meshstep::io::detail
