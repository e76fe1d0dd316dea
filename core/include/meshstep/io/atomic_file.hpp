// Whole files written atomically: a temporary file beside the target, renamed into place,
// so a reader never sees half a file and a failure leaves the target as it was.
#pragma once

#include <string>
#include <string_view>

namespace meshstep::io {

// Throws InputError("PATH: why") when the file cannot be written.
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace meshstep::io
