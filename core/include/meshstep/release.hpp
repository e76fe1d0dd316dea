// release(c): empties a container and gives its memory back.
//
// `v = {}` does not: for a std::vector it picks operator=(initializer_list), which clears
// and keeps the capacity. That is how triangulate held its input's points, 16 bytes a
// point, through the whole run.
#pragma once

#include <utility>

namespace meshstep {

template <class Container>
void release(Container& c) {
  Container().swap(c);
}

}  // namespace meshstep
