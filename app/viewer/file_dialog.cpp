#include "file_dialog.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "meshstep/io/formats.hpp"

namespace meshstep::viewer {

namespace {

namespace fs = std::filesystem;

// Absolute and without "." and ".." parts, nor a trailing '/' (but the root's). Not the
// canonical path: a folder reached through a link keeps the link's name, and going up
// goes back the way it came.
std::string normal(const fs::path& p) {
  std::error_code ec;
  fs::path out = fs::absolute(p, ec);
  if (ec) out = p;
  std::string text = out.lexically_normal().string();
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  return text;
}

std::string current_folder() {
  std::error_code ec;
  const fs::path here = fs::current_path(ec);
  return ec ? std::string("/") : normal(here);
}

// <0, 0 or >0 as a comes before, with or after b, ignoring the case of ASCII letters.
int compare_ignoring_case(const std::string& a, const std::string& b) {
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const int x = std::tolower(static_cast<unsigned char>(a[i])), y = std::tolower(static_cast<unsigned char>(b[i]));
    if (x != y) return x - y;
  }
  return a.size() < b.size() ? -1 : a.size() > b.size() ? 1 : 0;
}

// Folders first, then by name ignoring case (ties by the exact name, so the order is total).
bool listed_before(const FileEntry& a, const FileEntry& b) {
  const bool a_folder = a.kind == FileEntry::Kind::folder, b_folder = b.kind == FileEntry::Kind::folder;
  if (a_folder != b_folder) return a_folder;
  const int order = compare_ignoring_case(a.name, b.name);
  return order != 0 ? order < 0 : a.name < b.name;
}

// "WHAT: PATH" or "WHAT PATH: WHY", built by appending (GCC 12 warns falsely on
// "literal" + std::string).
std::string said(const char* what, const std::string& path, const std::string& why = "") {
  std::string out(what);
  out.append(path);
  if (!why.empty()) out.append(": ").append(why);
  return out;
}

struct Found {
  std::string name;
  bool folder = false, file = false;
  std::uintmax_t bytes = 0;
};

}  // namespace

const char* describe(FileEntry::Kind kind) {
  switch (kind) {
    case FileEntry::Kind::folder: return "folder";
    case FileEntry::Kind::log: return "log";
    case FileEntry::Kind::input: return "input";
    case FileEntry::Kind::mesh: return "mesh (.node + .ele)";
  }
  return "";
}

void format_size(std::uintmax_t bytes, char* out, std::size_t size) {
  if (bytes < 1024) {
    std::snprintf(out, size, "%ju B", bytes);
    return;
  }
  static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB"};
  double value = static_cast<double>(bytes) / 1024.0;
  std::size_t unit = 0;
  while (value >= 1024.0 && unit + 1 < std::size(kUnits)) value /= 1024.0, ++unit;
  std::snprintf(out, size, "%.1f %s", value, kUnits[unit]);
}

FileDialog::FileDialog(const std::string& folder) {
  if (!folder.empty() && list(normal(folder))) return;
  const std::string why = message_;
  if (!list(current_folder())) folder_ = current_folder();
  if (!why.empty()) message_ = why;  // the folder asked for is the one to explain
}

std::string FileDialog::start_folder(const std::string& open_file) {
  if (!open_file.empty()) {
    const fs::path folder = fs::path(normal(open_file)).parent_path();
    std::error_code ec;
    if (fs::is_directory(folder, ec)) return normal(folder);
  }
  return current_folder();
}

bool FileDialog::list(const std::string& folder) {
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (ec && status.type() != fs::file_type::not_found) {
    message_ = said("cannot read ", folder, ec.message());
    return false;
  }
  if (!fs::exists(status)) {
    message_ = said("no such folder: ", folder);
    return false;
  }
  if (!fs::is_directory(status)) {
    message_ = said("not a folder: ", folder);
    return false;
  }
  std::vector<Found> found;
  fs::directory_iterator it(folder, ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    Found f;
    f.name = it->path().filename().string();
    std::error_code entry_ec;  // a broken link or a vanished file is left out, not an error
    f.folder = it->is_directory(entry_ec);
    f.file = !f.folder && it->is_regular_file(entry_ec);
    if (f.file) f.bytes = it->file_size(entry_ec);
    if (!entry_ec) found.push_back(std::move(f));
  }
  if (ec) {
    message_ = said("cannot read ", folder, ec.message());
    return false;
  }

  const auto file_named = [&](const std::string& name) -> const Found* {
    for (const Found& f : found)
      if (f.file && f.name == name) return &f;
    return nullptr;
  };
  const std::string base = folder == "/" ? std::string() : folder;
  std::vector<FileEntry> entries;
  for (const Found& f : found) {
    if (!show_hidden_ && f.name.starts_with(".")) continue;
    FileEntry e;
    e.name = f.name;
    e.path = base;
    e.path.append("/").append(f.name);
    e.bytes = f.bytes;
    if (f.folder) {
      e.kind = FileEntry::Kind::folder;
      e.bytes = 0;
    } else if (!f.file) {
      continue;
    } else if (const io::FileFormat* format = io::format_of(f.name); !format || !f.name.ends_with(format->extension)) {
      continue;  // (Triangle's files by their own lower-case names only, as the readers take them)
    } else if (format->kind == io::FileKind::log) {
      e.kind = FileEntry::Kind::log;
    } else if (format->kind == io::FileKind::pslg) {
      e.kind = FileEntry::Kind::input;
    } else if (format->kind == io::FileKind::points) {
      const std::string prefix = f.name.substr(0, f.name.size() - format->extension.size());
      if (const Found* ele = file_named(prefix + ".ele")) {
        e.kind = FileEntry::Kind::mesh;
        e.name = prefix;
        e.path.resize(e.path.size() - format->extension.size());
        e.bytes += ele->bytes;
      } else {
        e.kind = FileEntry::Kind::input;
      }
    } else {
      continue;
    }
    entries.push_back(std::move(e));
  }
  std::sort(entries.begin(), entries.end(), listed_before);
  folder_ = folder;
  entries_ = std::move(entries);
  message_.clear();
  return true;
}

std::string FileDialog::resolve(const std::string& typed) const {
  const std::size_t begin = typed.find_first_not_of(" \t"), end = typed.find_last_not_of(" \t\r\n");
  std::string path = begin == std::string::npos ? std::string() : typed.substr(begin, end - begin + 1);
  if (path == "~" || path.starts_with("~/")) {
    const char* home = std::getenv("HOME");
    if (home && *home) path = std::string(home).append(path, 1, std::string::npos);
  }
  if (path.empty()) return folder_;
  return normal(path.front() == '/' ? fs::path(path) : fs::path(folder_) / path);
}

bool FileDialog::go_to(const std::string& folder) { return list(resolve(folder)); }

bool FileDialog::go_up() {
  if (folder_ == "/") return false;
  return list(normal(fs::path(folder_).parent_path()));
}

void FileDialog::refresh() {
  if (!list(folder_)) entries_.clear();
}

void FileDialog::set_show_hidden(bool on) {
  if (on == show_hidden_) return;
  show_hidden_ = on;
  refresh();
}

std::optional<std::string> FileDialog::activate(std::size_t index) {
  if (index >= entries_.size()) return std::nullopt;
  const FileEntry entry = entries_[index];  // a copy: going into a folder replaces the list
  if (entry.kind == FileEntry::Kind::folder) {
    list(entry.path);
    return std::nullopt;
  }
  message_.clear();
  return entry.path;
}

std::optional<std::string> FileDialog::submit(const std::string& typed) {
  if (typed.find_first_not_of(" \t\r\n") == std::string::npos) {
    message_ = "type the path of a file or folder";
    return std::nullopt;
  }
  const std::string path = resolve(typed);
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) {
    list(path);
    return std::nullopt;
  }
  if (fs::exists(status) || io::is_mesh_prefix(path)) {
    message_.clear();
    return path;
  }
  message_ = said("no such file or folder: ", path);
  return std::nullopt;
}

}  // namespace meshstep::viewer
