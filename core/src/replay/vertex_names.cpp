// The one numbering of a run's vertices in every text: the output's .node numbers
// (log_reader.hpp, vertex_name). The log's own ids are the order the triangulator met the
// vertices in (after its spatial sort), which no input file shows; a lecturer who points at
// vertex 11 of lesson.poly must find vertex 11 in the caption.
#include <algorithm>
#include <numeric>

#include "meshstep/replay/log_reader.hpp"
#include "replay/output_order.hpp"
#include "vertex_numbers.hpp"

namespace meshstep::replay {

const LogReader::VertexNumbers& LogReader::vertex_numbers() const {
  VertexNumbers& n = *vertex_numbers_;
  std::call_once(n.once, [&] {
    n.output.assign(vertices_.size(), kNone);
    n.removed.assign(vertices_.size(), 0);
    const std::uint32_t first = static_cast<std::uint32_t>(std::max(run_.first_index, 0));
    // The survivors at the end of the log, in the order the output writes them.
    const std::vector<VertexId> order = detail::output_order(vertices_, event_count_);
    for (std::size_t i = 0; i < order.size(); ++i) n.output[order[i]] = first + static_cast<std::uint32_t>(i);
    // The removed ones, in the order the run removed them.
    std::vector<VertexId> removed;
    for (VertexId v = 0; v < vertices_.size(); ++v)
      if (vertices_[v].event != kNone && vertices_[v].removed != UINT64_MAX) removed.push_back(v);
    std::sort(removed.begin(), removed.end(),
              [&](VertexId a, VertexId b) { return vertices_[a].removed < vertices_[b].removed; });
    for (std::size_t i = 0; i < removed.size(); ++i) n.removed[removed[i]] = static_cast<std::uint32_t>(i + 1);
  });
  return n;
}

std::uint32_t LogReader::output_number(VertexId v) const {
  const VertexNumbers& n = vertex_numbers();
  return v < n.output.size() ? n.output[v] : kNone;
}

std::string LogReader::vertex_name(VertexId v) const {
  if (v == kInfiniteVertex) return "infinity";
  // Prefixes appended, not `"r" + std::string`: GCC 12 at -O3 warns falsely (-Wrestrict) on that.
  std::string name;
  const VertexNumbers& numbers = vertex_numbers();
  if (v < numbers.removed.size() && numbers.removed[v] != 0) return name.append("r").append(std::to_string(numbers.removed[v]));
  const std::uint32_t n = output_number(v);
  if (n != kNone) return std::to_string(n);
  // A vertex the log never introduced (a damaged log): its id, marked so it is not taken for a number.
  return name.append("#").append(std::to_string(v));
}

}  // namespace meshstep::replay
