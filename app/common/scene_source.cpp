#include "common/scene_source.hpp"

#include <filesystem>

#include "meshstep/error.hpp"
#include "meshstep/io/formats.hpp"
#include "meshstep/io/triangle_io.hpp"
#include "common/output_prefix.hpp"

namespace meshstep::app {

bool is_replay_log(const std::string& path) { return io::is_replay_log(path); }

SceneSource open_scene_source(const std::string& path, std::vector<std::string>* warnings) {
  namespace fs = std::filesystem;
  SceneSource source;
  source.path = path;
  if (fs::is_regular_file(path) && is_replay_log(path)) {
    source.kind = SourceKind::log;
    source.log = std::make_unique<replay::LogReader>(path);
    if (!source.log->complete() && warnings) warnings->push_back(path + ": " + source.log->incomplete_reason());
    return source;
  }
  if (io::is_planar_input(path)) {
    source.kind = SourceKind::input;
    source.input = io::read_pslg(path, warnings);
    return source;
  }
  const std::string prefix = io::mesh_prefix_of(path);
  if (io::is_mesh_prefix(prefix)) {
    source.kind = SourceKind::mesh;
    source.path = prefix;
    source.mesh = io::read_mesh(prefix, warnings);
    return source;
  }
  if (!fs::exists(path))
    throw InputError(path, 0, "no such file, and no mesh " + prefix + ".node + " + prefix + ".ele");
  throw InputError(path, 0,
                   "not a replay log, a .poly/.node input or a mesh prefix (PREFIX.node + PREFIX.ele)");
}

}  // namespace meshstep::app
