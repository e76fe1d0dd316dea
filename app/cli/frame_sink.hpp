// Where an animation's frames go: a frames folder (PNG files, shown only when every one is
// written: staged_frames.hpp) or a video (through ffmpeg: video_pipe.hpp). `export` and the
// tour export write through it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "meshstep/scene/image.hpp"
#include "png_frame_writer.hpp"
#include "staged_frames.hpp"
#include "video_pipe.hpp"

namespace meshstep::app {

class FrameSink {
 public:
  // `frames_dir` given: PNG frames there; otherwise a video at `video`. Throws InputError as
  // StagedFrames and VideoPipe do.
  FrameSink(const std::string& frames_dir, const std::string& video, int width, int height, double fps) {
    if (!frames_dir.empty()) {
      staged_.emplace(frames_dir);
      frames_.emplace(staged_->staging());
    } else {
      video_.emplace(video, width, height, fps);
    }
  }

  void add(std::size_t index, const scene::Image& image) {
    if (frames_) frames_->add(index, image);
    else video_->add(image);
  }
  // Every frame written, then the frames moved into their folder (or the video into place).
  void finish() {
    if (frames_) {
      frames_->finish();
      staged_->commit();
    } else {
      video_->finish();
    }
  }
  bool writes_frames() const { return frames_.has_value(); }

 private:
  // Declared before the writer: on an error, the writer's threads stop before the staged
  // frames are removed. No frame is in the folder until every one is written.
  std::optional<StagedFrames> staged_;
  std::optional<PngFrameWriter> frames_;
  std::optional<VideoPipe> video_;
};

}  // namespace meshstep::app
