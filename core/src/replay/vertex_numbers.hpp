// What LogReader keeps of its vertices' names (vertex_names.cpp), worked out once.
#pragma once

#include <cstdint>
#include <mutex>
#include <vector>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay {

struct LogReader::VertexNumbers {
  std::once_flag once;
  std::vector<std::uint32_t> output;   // by vertex id; kNone: removed (or never used)
  std::vector<std::uint32_t> removed;  // by vertex id: 1 for the first removed, 0 for the others
};

}  // namespace meshstep::replay
