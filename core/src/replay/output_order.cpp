#include "replay/output_order.hpp"

#include <algorithm>
#include <utility>

namespace meshstep::replay::detail {

std::vector<VertexId> output_order(const std::vector<VertexInfo>& vertices, std::uint64_t position) {
  // Input numbering, with duplicates resolved as the triangulator does: a group of vertices
  // at one place is represented by the copy that comes first in the input.
  std::vector<std::uint32_t> input(vertices.size(), kNone);
  std::vector<VertexId> present;
  for (VertexId v = 0; v < vertices.size(); ++v) {
    if (vertices[v].event == kNone || vertices[v].event >= position) continue;
    if (vertices[v].removed < position) continue;  // removed by then (improvement)
    input[v] = vertices[v].input_index;
    present.push_back(v);
  }
  for (const VertexId v : present) {
    const VertexId r = vertices[v].same_as;
    if (r != kNone && r < input.size() && input[r] != kNone && input[v] < input[r]) std::swap(input[v], input[r]);
  }
  std::sort(present.begin(), present.end(), [&](VertexId a, VertexId b) { return input[a] < input[b]; });
  return present;
}

}  // namespace meshstep::replay::detail
