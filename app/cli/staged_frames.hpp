// A frames folder that shows frames only when all of them are written: they go into a hidden
// folder inside it, and move into place together at commit(). An export that fails part-way
// leaves no frames behind (and no folder, when it made the folder).
#pragma once

#include <string>

namespace meshstep::app {

class StagedFrames {
 public:
  // Makes `dir` if missing and the hidden folder inside it; throws InputError when it cannot.
  explicit StagedFrames(std::string dir);
  // Without commit(): removes the hidden folder and its frames, and `dir` when this made it
  // and it is empty.
  ~StagedFrames();
  StagedFrames(const StagedFrames&) = delete;
  StagedFrames& operator=(const StagedFrames&) = delete;

  // Where the frames are written until commit().
  const std::string& staging() const { return staging_; }
  // Moves every file of the hidden folder into `dir` and removes the hidden folder. A move
  // that fails takes back the ones made before it and throws InputError.
  void commit();

 private:
  std::string dir_, staging_;
  bool made_dir_ = false, committed_ = false;
};

}  // namespace meshstep::app
