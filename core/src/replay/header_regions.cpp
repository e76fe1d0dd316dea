// The log header's "regions" field: one line per region point, "x y attribute max_area",
// each number the shortest text that reads back to the same double.
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include "meshstep/replay/log_writer.hpp"

namespace meshstep::replay {

namespace {

void append_number(std::string& out, double v) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, end);
}

}  // namespace

std::string regions_field(const std::vector<Region>& regions) {
  std::string out;
  for (const Region& r : regions) {
    for (const double v : {r.point.x, r.point.y, r.attribute, r.max_area}) {
      append_number(out, v);
      out += ' ';
    }
    out.back() = '\n';
  }
  return out;
}

std::vector<Region> parse_regions_field(const std::string& text) {
  std::vector<Region> regions;
  const char* p = text.data();
  const char* const end = p + text.size();
  std::size_t line = 1;
  while (p < end) {
    double v[4];
    for (int i = 0; i < 4; ++i) {
      while (p < end && *p == ' ') ++p;
      const auto [next, ec] = std::from_chars(p, end, v[i]);
      if (ec != std::errc() || !std::isfinite(v[i]))
        throw std::invalid_argument("region " + std::to_string(line) + ": expected 4 finite numbers");
      p = next;
    }
    while (p < end && *p == ' ') ++p;
    if (p < end && *p != '\n') throw std::invalid_argument("region " + std::to_string(line) + ": more than 4 numbers");
    if (p < end) ++p;
    regions.push_back({{v[0], v[1]}, v[2], v[3]});
    ++line;
  }
  return regions;
}

}  // namespace meshstep::replay
