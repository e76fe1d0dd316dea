// A video file made by piping raw RGBA frames to ffmpeg (Debian package ffmpeg; optional).
// The container and codec follow the name: .mp4 (H.264), .webm (VP9), .gif (a palette
// made from the frames). ffmpeg writes to a temporary file beside the target, renamed
// into place when it succeeds, so a failed export leaves nothing behind. A frame's time
// is its index over the frame rate, never the wall clock.
#pragma once

#include <string>
#include <sys/types.h>

#include "meshstep/scene/image.hpp"

namespace meshstep::app {

class VideoPipe {
 public:
  // Throws InputError(path: why): an unknown extension, no ffmpeg (naming the package), or
  // ffmpeg failing to start.
  VideoPipe(std::string path, int width, int height, double fps);
  ~VideoPipe();  // without finish(): stops ffmpeg and removes the temporary file
  VideoPipe(const VideoPipe&) = delete;
  VideoPipe& operator=(const VideoPipe&) = delete;

  void add(const scene::Image& frame);  // throws InputError when ffmpeg has failed
  void finish();                        // waits for ffmpeg; renames into place

  // The ffmpeg program to run: $MESHSTEP_FFMPEG, else "ffmpeg" found on PATH; empty if none.
  static std::string find_ffmpeg();

 private:
  [[noreturn]] void fail(const std::string& why);
  void abandon() noexcept;

  std::string path_, temp_path_, log_path_;
  int width_, height_;
  int stdin_fd_ = -1;
  pid_t pid_ = -1;
};

}  // namespace meshstep::app
