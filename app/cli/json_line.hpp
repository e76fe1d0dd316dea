// A one-line JSON object writer for --stats json: flat fields, nested objects and arrays
// of objects, which is all the statistics need.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace meshstep::app {

class JsonLine {
 public:
  JsonLine& field(const std::string& key, const std::string& value) {
    key_(key);
    text_ += '"';
    for (const char c : value) {
      if (c == '"' || c == '\\') text_ += '\\';
      if (static_cast<unsigned char>(c) < 0x20) continue;
      text_ += c;
    }
    text_ += '"';
    return *this;
  }
  JsonLine& field(const std::string& key, std::size_t value) {
    key_(key);
    text_ += std::to_string(value);
    return *this;
  }
  JsonLine& field(const std::string& key, bool value) {
    key_(key);
    text_ += value ? "true" : "false";
    return *this;
  }
  JsonLine& field(const std::string& key, double value) {
    key_(key);
    if (!std::isfinite(value)) {
      text_ += "null";
      return *this;
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);  // 179.99998 must not read as 180
    text_ += buffer;
    return *this;
  }
  JsonLine& object(const std::string& key, const JsonLine& inner) {
    key_(key);
    text_ += inner.str();
    return *this;
  }
  JsonLine& array(const std::string& key, const std::vector<JsonLine>& items) {
    key_(key);
    text_ += '[';
    for (std::size_t i = 0; i < items.size(); ++i) text_ += (i ? "," : "") + items[i].str();
    text_ += ']';
    return *this;
  }
  std::string str() const { return "{" + text_ + "}"; }

 private:
  void key_(const std::string& key) {
    if (!text_.empty()) text_ += ',';
    text_ += '"' + key + "\":";
  }
  std::string text_;
};

}  // namespace meshstep::app
