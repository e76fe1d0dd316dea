// Fingerprints of what the renderer uploads, so that it uploads again only what changed.
//
// The renderer is handed a Scene each frame and cannot know whether the caller changed it in
// place or built a new one at the same address; a content hash can. It costs a few
// milliseconds for a million triangles (one pass over their memory), against the tens it
// would take to upload them again. 64 bits: a collision is not a practical concern.
#pragma once

#include <cstdint>

#include "meshstep/scene/scene.hpp"

namespace meshstep::render {

// The mesh buffers' inputs: points, triangles, fill colours.
std::uint64_t mesh_fingerprint(const scene::MeshLayer& mesh);
// The overlay buffers' inputs: the shapes.
std::uint64_t overlay_fingerprint(const scene::Scene& scene);

}  // namespace meshstep::render
