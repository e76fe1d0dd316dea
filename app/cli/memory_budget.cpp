#include "memory_budget.hpp"

#include <unistd.h>

#include <cctype>
#include <charconv>
#include <cstdio>

namespace meshstep::app {

std::optional<std::uint64_t> parse_memory(const std::string& text) {
  if (text == "none") return 0;
  std::uint64_t value = 0;
  const char* const end = text.data() + text.size();
  const auto [rest, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || rest == text.data()) return std::nullopt;
  int shift = 0;
  if (rest != end) {
    if (rest + 1 != end && !(rest + 2 == end && (rest[1] == 'B' || rest[1] == 'b'))) return std::nullopt;
    switch (std::toupper(static_cast<unsigned char>(*rest))) {
      case 'K': shift = 10; break;
      case 'M': shift = 20; break;
      case 'G': shift = 30; break;
      case 'T': shift = 40; break;
      default: return std::nullopt;
    }
  }
  if (shift && value > (UINT64_MAX >> shift)) return std::nullopt;
  return value << shift;
}

std::uint64_t default_memory_budget() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return std::uint64_t{4} << 30;
  return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 4;
}

std::string memory_text(std::uint64_t bytes) {
  char buf[32];
  if (bytes >= (std::uint64_t{1} << 30)) std::snprintf(buf, sizeof buf, "%.1f GB", bytes / 1073741824.0);
  else std::snprintf(buf, sizeof buf, "%.0f MB", bytes / 1048576.0);
  return buf;
}

}  // namespace meshstep::app
