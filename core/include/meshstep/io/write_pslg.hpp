// An input (a PSLG) as one self-contained Triangle .poly file: what the viewer's workbench
// saves. (triangle_io.hpp's write_poly writes a mesh's .poly, whose vertices are in the
// .node beside it.)
#pragma once

#include <string>

#include "meshstep/pslg/pslg.hpp"

namespace meshstep::io {

// Its vertices inline, with their attributes and markers when it has them; segments, with
// markers when it has them; holes; regions; numbered from input.first_index. Written to a
// temporary file renamed into place. Read back with read_poly, it gives the same Pslg,
// every number bit for bit (-0.0 included: it is written "-0"; subnormals too). Throws
// InputError ("PATH: cannot write this input: ...") for a number that is not finite or
// arrays that disagree, before the file is touched.
void write_pslg(const std::string& path, const Pslg& input);

}  // namespace meshstep::io
