#include "settings.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string_view>
#include <system_error>

#include "meshstep/error.hpp"
#include "meshstep/io/atomic_file.hpp"
#include "ui_look.hpp"

namespace meshstep::viewer {
namespace {

// A settings file is a few hundred bytes; anything this large is something else.
constexpr std::size_t kMaxFileBytes = std::size_t{1} << 20;
// A file of junk could have thousands of bad lines: the first ones say enough.
constexpr std::size_t kMaxLineWarnings = 20;
constexpr const char* kUseDefault = "; using the default";

constexpr std::string_view kBlanks = " \t\r\v\f";

std::string_view trim(std::string_view s) {
  const std::size_t begin = s.find_first_not_of(kBlanks);
  if (begin == std::string_view::npos) return {};
  const std::size_t end = s.find_last_not_of(kBlanks);
  return s.substr(begin, end - begin + 1);
}

// The length of the UTF-8 sequence starting at s[i], or 0 when it is not a valid one.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  std::size_t n = 0;
  unsigned min = 0;
  if (c < 0x80) return 1;
  if (c >= 0xc2 && c <= 0xdf) {
    n = 2, min = 0x80;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 3, min = 0x800;
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4, min = 0x10000;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  unsigned code = c & (0x7fu >> n);
  for (std::size_t k = 1; k < n; ++k) {
    const auto d = static_cast<unsigned char>(s[i + k]);
    if ((d & 0xc0) != 0x80) return 0;
    code = code << 6 | (d & 0x3fu);
  }
  if (code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff)) return 0;
  return n;
}

// Text from the file, made safe to print in a warning: control bytes and bytes that are not
// UTF-8 escaped as \xHH, cut short after kMaxShown bytes of it.
std::string shown(std::string_view s) {
  constexpr std::size_t kMaxShown = 40;
  constexpr const char* kHex = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (i >= kMaxShown) {
      out += "...";
      break;
    }
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = utf8_length(s, i);
    if (n == 0 || c < 0x20 || c == 0x7f) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
      ++i;
    } else {
      out.append(s, i, n);
      i += n;
    }
  }
  return out;
}

// The word the file (and the viewer's scripts) use for a unit.
const char* file_name(Unit unit) {
  switch (unit) {
    case Unit::event: return "event";
    case Unit::step: return "step";
    case Unit::phase: return "phase";
  }
  return "step";
}

// --- Values ---------------------------------------------------------------------------

// Each parser returns what is wrong, or nothing.
using Problem = std::optional<std::string>;

Problem parse_bool(std::string_view key, std::string_view text, bool& out) {
  if (text == "true") {
    out = true;
  } else if (text == "false") {
    out = false;
  } else {
    return std::string(key) + ": '" + shown(text) + "' is not true or false";
  }
  return std::nullopt;
}

Problem parse_int(std::string_view key, std::string_view text, int lo, int hi, int& out) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec == std::errc::result_out_of_range)
    return std::string(key) + ": " + shown(text) + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")";
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    return std::string(key) + ": '" + shown(text) + "' is not a whole number";
  if (v < lo || v > hi)
    return std::string(key) + ": " + std::to_string(v) + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")";
  out = v;
  return std::nullopt;
}

template <class Real>
std::string format_real(Real v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

template <class Real>
Problem parse_real(std::string_view key, std::string_view text, Real lo, Real hi, Real& out) {
  Real v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  const std::string range = " (" + format_real(lo) + ".." + format_real(hi) + ")";
  if (ec == std::errc::result_out_of_range) return std::string(key) + ": " + shown(text) + " is out of range" + range;
  if (ec != std::errc() || end != text.data() + text.size() || text.empty() || !std::isfinite(v))
    return std::string(key) + ": '" + shown(text) + "' is not a number";
  if (v < lo || v > hi) return std::string(key) + ": " + shown(text) + " is out of range" + range;
  out = v;
  return std::nullopt;
}

Problem parse_layers(std::string_view text, scene::LayerSet& out) {
  scene::LayerSet layers = scene::LayerSet::none();
  if (!text.empty()) {
    while (true) {
      const std::size_t comma = text.find(',');
      const std::string_view item = trim(text.substr(0, comma));
      const std::optional<scene::Layer> layer = scene::parse_layer(item);
      if (!layer) return item.empty() ? std::string("layers: an empty layer name") : "layers: unknown layer '" + shown(item) + "'";
      layers.set(*layer);
      if (comma == std::string_view::npos) break;
      text.remove_prefix(comma + 1);
    }
  }
  out = layers;
  return std::nullopt;
}

std::string format_layers(scene::LayerSet layers) {
  std::string out;
  for (std::size_t i = 0; i < scene::kLayerCount; ++i) {
    const auto layer = static_cast<scene::Layer>(i);
    if (!layers.has(layer)) continue;
    if (!out.empty()) out += ", ";
    out += scene::name(layer);
  }
  return out;
}

// A path written as it is unless the trimming would change it or a line cannot hold it.
bool needs_quotes(std::string_view s) {
  if (s.empty() || s.front() == '"' || kBlanks.find(s.front()) != std::string_view::npos ||
      kBlanks.find(s.back()) != std::string_view::npos)
    return true;
  return std::any_of(s.begin(), s.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c < 0x20 || c == 0x7f;
  });
}

std::string quote_path(std::string_view s) {
  constexpr const char* kHex = "0123456789abcdef";
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20 || c == 0x7f) {
          out += "\\x";
          out += kHex[c >> 4];
          out += kHex[c & 15];
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

Problem parse_path(std::string_view text, std::string& out) {
  if (text.empty()) return std::string("recent: an empty path");
  if (text.front() != '"') {
    out = std::string(text);
    return std::nullopt;
  }
  std::string path;
  std::size_t i = 1;
  for (;; ++i) {
    if (i >= text.size()) return std::string("recent: a quoted path without its closing quote");
    const char c = text[i];
    if (c == '"') break;
    if (c != '\\') {
      path += c;
      continue;
    }
    if (++i >= text.size()) return std::string("recent: a quoted path without its closing quote");
    switch (text[i]) {
      case '"': path += '"'; break;
      case '\\': path += '\\'; break;
      case 'n': path += '\n'; break;
      case 'r': path += '\r'; break;
      case 't': path += '\t'; break;
      case 'x': {
        const int hi = i + 1 < text.size() ? hex_digit(text[i + 1]) : -1;
        const int lo = i + 2 < text.size() ? hex_digit(text[i + 2]) : -1;
        if (hi < 0 || lo < 0) return std::string("recent: a bad \\x escape in a quoted path");
        path += static_cast<char>(hi * 16 + lo);
        i += 2;
        break;
      }
      default: return "recent: an unknown escape '\\" + shown(text.substr(i, 1)) + "' in a quoted path";
    }
  }
  if (i + 1 != text.size()) return std::string("recent: text after the closing quote of a path");
  if (path.empty()) return std::string("recent: an empty path");
  out = std::move(path);
  return std::nullopt;
}

// --- Lines ----------------------------------------------------------------------------

// Applies one `key = value`: what is wrong (a bad value, an unknown key), or nothing.
Problem apply(Settings& s, std::string_view key, std::string_view value) {
  if (key == "window_width") return parse_int(key, value, Settings::kMinWindow, Settings::kMaxWindow, s.window_width);
  if (key == "window_height") return parse_int(key, value, Settings::kMinWindow, Settings::kMaxWindow, s.window_height);
  if (key == "side_panel_width")
    return parse_real(key, value, Settings::kMinSidePanel, Settings::kMaxSidePanel, s.side_panel_width);
  if (key == "explain_open") return parse_bool(key, value, s.explain_open);
  if (key == "layers_open") return parse_bool(key, value, s.layers_open);
  if (key == "stats_open") return parse_bool(key, value, s.stats_open);
  if (key == "code_open") return parse_bool(key, value, s.code_open);
  if (key == "plots_open") return parse_bool(key, value, s.plots_open);
  if (key == "follow") return parse_bool(key, value, s.follow);
  if (key == "view_3d") return parse_bool(key, value, s.view_3d);
  if (key == "azimuth") return parse_real(key, value, -180.0, 180.0, s.orbit.azimuth_deg);
  if (key == "elevation") return parse_real(key, value, -90.0, 90.0, s.orbit.elevation_deg);
  if (key == "z_scale") return parse_real(key, value, Orbit::kMinZScale, Orbit::kMaxZScale, s.orbit.z_scale);
  if (key == "speed") return parse_real(key, value, Playback::kMinSpeed, Playback::kMaxSpeed, s.speed);
  if (key == "layers") return parse_layers(value, s.layers);
  if (key == "timeline_marks") {
    std::string bad;
    const std::optional<MarkSet> marks = parse_marks(value, bad);
    if (!marks) {
      std::string known;
      for (std::size_t i = 0; i < kMarkCount; ++i) known.append(i ? ", " : "").append(name(static_cast<Mark>(i)));
      if (bad.empty()) return std::string("timeline_marks: an empty kind");
      return std::string("timeline_marks: unknown kind '").append(shown(bad)).append("' (").append(known).append(")");
    }
    s.timeline_marks = *marks;
    return std::nullopt;
  }
  if (key == "color_by") {
    const std::optional<scene::ColorBy> c = scene::parse_color_by(value);
    if (!c) {
      std::string known;
      for (std::size_t i = 0; i < static_cast<std::size_t>(scene::ColorBy::count_); ++i)
        known += std::string(i ? ", " : "") + scene::name(static_cast<scene::ColorBy>(i));
      return "color_by: unknown colouring '" + shown(value) + "' (" + known + ")";
    }
    s.color_by = *c;
    return std::nullopt;
  }
  if (key == "theme") {
    const std::optional<scene::Theme> theme = parse_theme(value);
    if (!theme) return "theme: unknown theme '" + shown(value) + "' (light, dark, high-contrast)";
    s.theme = *theme;
    return std::nullopt;
  }
  if (key == "ui_scale") {
    const std::optional<float> scale = parse_ui_scale(value);
    if (!scale) return "ui_scale: '" + shown(value) + "' is not a UI scale (0.75 to 3, in steps of 0.25)";
    s.ui_scale = *scale;
    return std::nullopt;
  }
  if (key == "unit") {
    if (value == "event" || value == "events") {
      s.unit = Unit::event;
    } else if (value == "step" || value == "steps") {
      s.unit = Unit::step;
    } else if (value == "phase" || value == "phases") {
      s.unit = Unit::phase;
    } else {
      return "unit: unknown unit '" + shown(value) + "' (event, step, phase)";
    }
    return std::nullopt;
  }
  if (key == "recent") {
    std::string path;
    if (Problem p = parse_path(value, path)) return p;
    // The file lists them most recent first: keep the first of duplicates, and the first ten.
    if (s.recent_files.size() < Settings::kMaxRecent &&
        std::find(s.recent_files.begin(), s.recent_files.end(), path) == s.recent_files.end())
      s.recent_files.push_back(std::move(path));
    return std::nullopt;
  }
  return "unknown key '" + shown(key) + "'";
}

// The whole file, or what is wrong with it; nullopt with an empty `problem` when it is missing.
std::optional<std::string> read_whole_file(const std::string& path, std::string& problem) {
  problem.clear();
  // O_NONBLOCK: opening a FIFO must not wait for a writer.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    if (errno != ENOENT) problem = std::string("cannot read: ") + std::strerror(errno);
    return std::nullopt;
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    problem = std::string("cannot read: ") + std::strerror(errno);
    return std::nullopt;
  }
  if (S_ISDIR(st.st_mode)) {
    problem = "cannot read: it is a folder";
    return std::nullopt;
  }
  if (!S_ISREG(st.st_mode)) {
    problem = "cannot read: not a regular file";
    return std::nullopt;
  }
  std::string text;
  char buffer[4096];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0) {
      if (errno == EINTR) continue;
      problem = std::string("cannot read: ") + std::strerror(errno);
      return std::nullopt;
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > kMaxFileBytes) {
      problem = "larger than " + std::to_string(kMaxFileBytes >> 20) + " MiB: not a settings file";
      return std::nullopt;
    }
  }
  return text;
}

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

std::string without_trailing_slashes(std::string dir) {
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  return dir;
}

}  // namespace

void Settings::add_recent(const std::string& path) {
  if (path.empty()) return;
  recent_files.erase(std::remove(recent_files.begin(), recent_files.end(), path), recent_files.end());
  recent_files.insert(recent_files.begin(), path);
  if (recent_files.size() > kMaxRecent) recent_files.resize(kMaxRecent);
}

std::string settings_path() {
  if (std::string p = env("MESHSTEP_VIEWER_CONFIG"); !p.empty()) return p;
  // The XDG base directory spec: a relative XDG_CONFIG_HOME is to be ignored.
  if (std::string xdg = env("XDG_CONFIG_HOME"); !xdg.empty() && xdg.front() == '/')
    return without_trailing_slashes(std::move(xdg)) + "/meshstep/viewer.ini";
  if (std::string home = env("HOME"); !home.empty())
    return without_trailing_slashes(std::move(home)) + "/.config/meshstep/viewer.ini";
  return {};
}

Settings load_settings(const std::string& path, std::vector<std::string>& warnings) {
  Settings s;
  std::string problem;
  const std::optional<std::string> text = read_whole_file(path, problem);
  if (!text) {
    if (!problem.empty()) warnings.push_back(path + ": " + problem + "; using the defaults");
    return s;
  }

  std::size_t reported = 0, unreported = 0;
  auto warn = [&](std::size_t line, const std::string& what) {
    if (reported == kMaxLineWarnings) {
      ++unreported;
      return;
    }
    ++reported;
    warnings.push_back(path + ":" + std::to_string(line) + ": " + what + kUseDefault);
  };

  std::string_view rest = *text;
  for (std::size_t number = 1; !rest.empty(); ++number) {
    const std::size_t newline = rest.find('\n');
    const std::string_view raw = rest.substr(0, newline);
    rest.remove_prefix(newline == std::string_view::npos ? rest.size() : newline + 1);

    const std::string_view line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    const std::size_t equals = line.find('=');
    const std::string_view key = equals == std::string_view::npos ? std::string_view() : trim(line.substr(0, equals));
    if (key.empty()) {
      warn(number, "'" + shown(line) + "' is not a 'key = value' line");
      continue;
    }
    if (Problem p = apply(s, key, trim(line.substr(equals + 1)))) warn(number, *p);
  }
  if (unreported > 0)
    warnings.push_back(path + ": " + std::to_string(unreported) + " more problems" + kUseDefault + " for each");
  return s;
}

std::string format_settings(const Settings& s) {
  std::string out = "# meshstep viewer settings, written by meshstep-view when it closes.\n";
  auto line = [&](const char* key, const std::string& value) {
    out += key;
    out += value.empty() ? " =" : " = ";
    out += value;
    out += '\n';
  };
  auto boolean = [](bool b) { return std::string(b ? "true" : "false"); };
  line("window_width", std::to_string(s.window_width));
  line("window_height", std::to_string(s.window_height));
  line("side_panel_width", format_real(s.side_panel_width));
  line("ui_scale", format_ui_scale(s.ui_scale));
  line("explain_open", boolean(s.explain_open));
  line("layers_open", boolean(s.layers_open));
  line("stats_open", boolean(s.stats_open));
  line("code_open", boolean(s.code_open));
  line("plots_open", boolean(s.plots_open));
  line("color_by", scene::name(s.color_by));
  line("theme", theme_name(s.theme));
  line("layers", format_layers(s.layers));
  line("speed", format_real(s.speed));
  line("unit", file_name(s.unit));
  line("follow", boolean(s.follow));
  line("timeline_marks", format_marks(s.timeline_marks));
  line("view_3d", boolean(s.view_3d));
  line("azimuth", format_real(s.orbit.azimuth_deg));
  line("elevation", format_real(s.orbit.elevation_deg));
  line("z_scale", format_real(s.orbit.z_scale));
  // As load_settings would keep them: no empty paths, no duplicates, the first ten.
  std::vector<std::string> written;
  for (const std::string& path : s.recent_files) {
    if (written.size() == Settings::kMaxRecent) break;
    if (path.empty() || std::find(written.begin(), written.end(), path) != written.end()) continue;
    written.push_back(path);
    line("recent", needs_quotes(path) ? quote_path(path) : path);
  }
  return out;
}

void save_settings(const Settings& settings, const std::string& path) {
  if (path.empty()) throw InputError("settings: no file to save them to");
  const std::size_t slash = path.find_last_of('/');
  if (slash != std::string::npos && slash > 0) {
    const std::string dir = path.substr(0, slash);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(path, 0, "cannot create the folder " + dir + ": " + ec.message());
  }
  io::write_file_atomically(path, format_settings(settings));
}

}  // namespace meshstep::viewer
