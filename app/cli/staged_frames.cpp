#include "staged_frames.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

#include "meshstep/error.hpp"

namespace meshstep::app {

namespace fs = std::filesystem;

StagedFrames::StagedFrames(std::string dir) : dir_(std::move(dir)) {
  std::error_code ec;
  made_dir_ = fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_)) throw InputError(dir_, 0, "cannot make the frames folder (" + ec.message() + ")");
  // In the frames folder itself, so that commit()'s moves are renames on one file system.
  staging_ = (fs::path(dir_) / (".frames." + std::to_string(::getpid()) + ".partial")).string();
  fs::remove_all(staging_, ec);  // left by an earlier process of the same id that was killed
  if (!fs::create_directory(staging_, ec) || ec) {
    if (made_dir_) fs::remove(dir_, ec);
    throw InputError(dir_, 0, "cannot make a folder for the frames in it (" + ec.message() + ")");
  }
}

StagedFrames::~StagedFrames() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (made_dir_ && fs::is_empty(dir_, ec)) fs::remove(dir_, ec);
}

void StagedFrames::commit() {
  std::error_code ec;
  std::vector<fs::path> names;
  for (fs::directory_iterator it(staging_, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename());
  if (ec) throw InputError(staging_, 0, "cannot list the frames written (" + ec.message() + ")");
  std::sort(names.begin(), names.end());
  for (std::size_t k = 0; k < names.size(); ++k) {
    fs::rename(fs::path(staging_) / names[k], fs::path(dir_) / names[k], ec);
    if (!ec) continue;
    const std::string why = ec.message();
    // All or none: the frames already moved go back (the destructor removes them).
    for (std::size_t back = 0; back < k; ++back)
      fs::rename(fs::path(dir_) / names[back], fs::path(staging_) / names[back], ec);
    throw InputError((fs::path(dir_) / names[k]).string(), 0, "cannot move the frame into place (" + why + ")");
  }
  committed_ = true;
  fs::remove_all(staging_, ec);
}

}  // namespace meshstep::app
