// `meshstep compare A.mslog B.mslog --svg OUT / --png OUT / --video OUT`: the runs side by
// side at one moment (or at every step, as a video), one panel each, with one world scale
// for all (the union of every run's points, so that the same length looks the same in
// every panel) and each panel's caption saying whose run it is and at which step. SVG
// needs no display; PNG and video are drawn by the OpenGL renderer (render/painter.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace meshstep::app {

struct SideBySide {
  std::vector<std::string> logs, captions;  // a caption per log (compare_logs.hpp)
  // The moment: after --step K steps (-1: the end; a run with fewer steps shows its end),
  // or at --fraction F of each run's steps; neither: the end.
  std::optional<long long> step;
  std::optional<double> fraction;
  int panel_width = 640;
  int panel_height = 0;  // 0: as the runs' box needs at that width (200 to 1000 pixels)
};

// Writes OUT (.svg, or .png through OpenGL) whole or not at all. Throws InputError for a
// log that cannot be read, UsageError for a moment out of range, GlUnavailable for a PNG
// without OpenGL. Returns the steps shown, one per log.
std::vector<unsigned long long> write_side_by_side(const SideBySide& picture, const std::string& out);

// The runs side by side as a video through ffmpeg (.mp4, .webm, .gif; video_pipe.hpp): one
// frame per step of the longest run, frame k showing every run after k steps (a shorter
// run stays at its end). Throws as write_side_by_side, and InputError without ffmpeg.
// Returns the frames written.
std::size_t write_side_by_side_video(const SideBySide& picture, const std::string& out, double fps);

}  // namespace meshstep::app
