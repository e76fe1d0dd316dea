#include "embedded_files.hpp"

#include <stdexcept>
#include <string>

namespace meshstep::render {

std::string_view embedded_file(std::string_view name) {
  for (std::size_t i = 0; i < kEmbeddedFileCount; ++i)
    if (kEmbeddedFiles[i].name == name) return kEmbeddedFiles[i].bytes;
  throw std::logic_error("no embedded file named " + std::string(name));
}

}  // namespace meshstep::render
