// Events as text: one line for people (log dump, the viewer's event panel) and one JSON
// object per line for programs (log dump --jsonl).
#pragma once

#include <cstdint>
#include <string>

#include "meshstep/replay/event.hpp"

namespace meshstep::replay {

// "flip delaunay a=12 b=40 c=7 d=9; slot 31 (12 40 7) -> (12 9 7); ..."
std::string describe(const Event& e);
// {"event":N,"step":S,"type":"flip","code":"delaunay","a":12,...,"writes":[...]}; step is
// null for events before the first step. Vertex ids: -1 is the vertex at infinity.
std::string to_json(const Event& e, std::uint64_t index, std::uint64_t step, bool in_step);

}  // namespace meshstep::replay
