// Events as text: one line for people (log dump, the viewer's event panel) and one JSON
// object per line for programs (log dump --jsonl).
#pragma once

#include <cstdint>
#include <string>

#include "meshstep/replay/event.hpp"
#include "meshstep/replay/log_reader.hpp"

namespace meshstep::replay {

// Vertices are named by `names`' vertex_name (their numbers in the run's output .node, "r3"
// for a removed one: the numbering of every text) when it is given, else by the log's ids.
//
// "flip delaunay a=12 b=40 c=7 d=9; slot 31 (12 40 7) -> (12 9 7); ..."
std::string describe(const Event& e, const LogReader* names = nullptr);
// {"event":N,"step":S,"type":"flip","code":"delaunay","a":12,...,"writes":[...]}; step is
// null for events before the first step. Vertices: -1 is the vertex at infinity; with
// `names`, a removed vertex is a string ("r3").
std::string to_json(const Event& e, std::uint64_t index, std::uint64_t step, bool in_step,
                    const LogReader* names = nullptr);

}  // namespace meshstep::replay
