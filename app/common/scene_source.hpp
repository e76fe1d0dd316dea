// What `render` draws from: a replay log (any moment of the run), a mesh PREFIX, or an
// input .poly/.node (the input itself, before triangulation). Told apart by content and
// name: a log starts with its magic bytes; "x.poly" and "x.node" are inputs; otherwise
// PREFIX.node and PREFIX.ele must exist.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "meshstep/mesh/tri_mesh.hpp"
#include "meshstep/pslg/pslg.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::app {

enum class SourceKind { log, mesh, input };

struct SceneSource {
  SourceKind kind = SourceKind::input;
  std::string path;  // as given (for a mesh: the prefix)
  std::unique_ptr<replay::LogReader> log;
  std::optional<TriMesh> mesh;
  std::optional<Pslg> input;
};

bool is_replay_log(const std::string& path);

// Throws InputError (FILE:LINE where it applies) when INPUT cannot be read.
SceneSource open_scene_source(const std::string& path, std::vector<std::string>* warnings);

}  // namespace meshstep::app
