#include "video_pipe.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "meshstep/error.hpp"

extern char** environ;

namespace meshstep::app {
namespace {

std::string extension_of(const std::string& path) {
  const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return path.substr(dot + 1);
}

std::string ffmpeg_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The encoder's half of the command line, by container.
std::vector<std::string> encoder_arguments(const std::string& ext, double fps) {
  // yuv420p needs even sizes: pad by a pixel where the picture is odd.
  const std::string even = "pad=ceil(iw/2)*2:ceil(ih/2)*2";
  if (ext == "mp4")
    return {"-vf", even, "-c:v", "libx264", "-preset", "superfast", "-crf", "20", "-pix_fmt", "yuv420p",
            "-movflags", "+faststart", "-f", "mp4"};
  if (ext == "webm")
    return {"-vf", even, "-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "34", "-deadline", "realtime", "-cpu-used", "8",
            "-row-mt", "1", "-pix_fmt", "yuv420p", "-f", "webm"};
  if (ext == "gif")
    return {"-vf", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer", "-r", ffmpeg_number(fps),
            "-f", "gif"};
  return {};
}

std::string tail_of_file(const std::string& path, std::size_t max_chars) {
  std::ifstream in(path);
  std::stringstream all;
  all << in.rdbuf();
  std::string text = all.str();
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  if (text.size() > max_chars) text = "..." + text.substr(text.size() - max_chars);
  return text;
}

}  // namespace

std::string VideoPipe::find_ffmpeg() {
  if (const char* own = std::getenv("MESHSTEP_FFMPEG"); own && *own) return own;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string candidate = dirs.substr(start, end - start) + "/ffmpeg";
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return "";
}

VideoPipe::VideoPipe(std::string path, int width, int height, double fps)
    : path_(std::move(path)), width_(width), height_(height) {
  const std::string ext = extension_of(path_);
  const std::vector<std::string> encoder = encoder_arguments(ext, fps);
  if (encoder.empty()) throw InputError(path_, 0, "unknown video format '." + ext + "' (use .mp4, .webm or .gif)");
  const std::string ffmpeg = find_ffmpeg();
  if (ffmpeg.empty())
    throw InputError(path_, 0,
                     "writing a video needs ffmpeg, which is not installed (Debian: apt-get install ffmpeg); "
                     "--frames DIR writes PNG frames without it");
  const std::filesystem::path target(path_);
  const std::string dir = target.has_parent_path() ? target.parent_path().string() : ".";
  temp_path_ = dir + "/." + target.filename().string() + "." + std::to_string(::getpid()) + ".partial";
  log_path_ = temp_path_ + ".log";

  std::vector<std::string> args = {ffmpeg, "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
                                   "-f", "rawvideo", "-pix_fmt", "rgba", "-s",
                                   std::to_string(width) + "x" + std::to_string(height), "-framerate", ffmpeg_number(fps),
                                   "-i", "pipe:0"};
  args.insert(args.end(), encoder.begin(), encoder.end());
  args.push_back(temp_path_);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw InputError(path_, 0, std::string("cannot start ffmpeg: ") + std::strerror(errno));
  const int log_fd = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log_fd < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw InputError(path_, 0, "cannot write beside the video (" + std::string(std::strerror(errno)) + ")");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
  posix_spawn_file_actions_adddup2(&actions, log_fd, 1);
  posix_spawn_file_actions_adddup2(&actions, log_fd, 2);
  const int spawned = ::posix_spawn(&pid_, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  ::close(log_fd);
  if (spawned != 0) {
    ::close(fds[1]);
    pid_ = -1;
    std::filesystem::remove(log_path_);
    throw InputError(path_, 0, "cannot start " + ffmpeg + ": " + std::strerror(spawned));
  }
  stdin_fd_ = fds[1];
  // A frame is megabytes: with the default 64 kB pipe every frame costs ffmpeg and us
  // dozens of wake-ups each. A bigger pipe (where the system allows) lets each side run
  // longer at a time; failing to get one changes nothing else.
  ::fcntl(stdin_fd_, F_SETPIPE_SZ, 1 << 20);
  // A dead ffmpeg must show up as a failed write (EPIPE), not kill this process.
  std::signal(SIGPIPE, SIG_IGN);
}

VideoPipe::~VideoPipe() {
  if (pid_ >= 0 || stdin_fd_ >= 0) abandon();
}

void VideoPipe::add(const scene::Image& frame) {
  if (frame.width != width_ || frame.height != height_) fail("a frame of another size");
  const std::uint8_t* data = frame.rgba.data();
  std::size_t left = frame.rgba.size();
  while (left > 0) {
    const ssize_t n = ::write(stdin_fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("ffmpeg stopped reading");
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

void VideoPipe::finish() {
  ::close(stdin_fd_);
  stdin_fd_ = -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail("ffmpeg failed");
  std::error_code ec;
  std::filesystem::rename(temp_path_, path_, ec);
  if (ec) fail("cannot rename the video into place: " + ec.message());
  std::filesystem::remove(log_path_, ec);
}

void VideoPipe::fail(const std::string& why) {
  std::string detail;
  if (pid_ >= 0 && stdin_fd_ >= 0) {  // let ffmpeg end, to read what it said
    ::close(stdin_fd_);
    stdin_fd_ = -1;
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  detail = tail_of_file(log_path_, 600);
  abandon();
  throw InputError(path_, 0, why + (detail.empty() ? "" : ": " + detail));
}

void VideoPipe::abandon() noexcept {
  if (stdin_fd_ >= 0) ::close(stdin_fd_);
  stdin_fd_ = -1;
  if (pid_ >= 0) {
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  std::error_code ec;
  std::filesystem::remove(temp_path_, ec);
  std::filesystem::remove(log_path_, ec);
}

}  // namespace meshstep::app
