// The order in which a run writes its vertices to the output's .node, at a moment: input
// vertices by their input number, then Steiner vertices in the order they were inserted;
// a group of duplicates is represented by the copy that comes first in the input. Both the
// replayed mesh (Replay::build_mesh) and the vertices' names in every text (LogReader::
// vertex_name) follow it, so the two can never disagree.
#pragma once

#include <cstdint>
#include <vector>

#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay::detail {

// The vertices present after `position` events (introduced before it, not removed by
// then), in output order.
std::vector<VertexId> output_order(const std::vector<VertexInfo>& vertices, std::uint64_t position);

}  // namespace meshstep::replay::detail
