// The viewer's state as JSON, for scripted tests: one field per line, so that a test (or a
// person) can read it without a JSON library.
#pragma once

#include <string>

namespace meshstep::viewer {

class Viewer;

std::string state_json(Viewer& viewer);

}  // namespace meshstep::viewer
