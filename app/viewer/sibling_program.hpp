// The programs built beside the viewer (meshstep, which records and exports runs): found
// in the viewer's own folder, or the one above it, else by name on the PATH.
#pragma once

#include <filesystem>
#include <string>

namespace meshstep::viewer {

inline std::string sibling_program(const char* name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path here = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (!ec)
    for (const fs::path& candidate : {here / name, here.parent_path() / name})
      if (fs::exists(candidate, ec)) return candidate.string();
  return name;
}

}  // namespace meshstep::viewer
