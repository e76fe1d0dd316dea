// The files built into the program (shaders/*, the DejaVu Sans font): see embed_files.cmake.
#pragma once

#include <cstddef>
#include <string_view>

namespace meshstep::render {

struct EmbeddedFile {
  std::string_view name;  // file name without its folder: "mesh.frag", "DejaVuSans.ttf"
  std::string_view bytes;
};

// Defined in embedded_files_data.cpp, which the build generates.
extern const EmbeddedFile kEmbeddedFiles[];
extern const std::size_t kEmbeddedFileCount;

// The bytes of the embedded file NAME. A missing name is a build mistake, not a user's:
// throws std::logic_error.
std::string_view embedded_file(std::string_view name);

}  // namespace meshstep::render
