// Every command that writes asks this first (issue 31): an output that is one of its inputs,
// or two outputs that are one file, is a usage error before any work.
#pragma once

#include "command.hpp"
#include "common/file_roles.hpp"
#include "console.hpp"

namespace meshstep::app {

// Prints the clash and returns the usage exit status; 0 when there is none. A command calls
// it once, before it reads or writes anything:
//   if (const int refused = refuse_overwrites(FileRoles().reads(in).writes("-o", out, "output"))) return refused;
inline int refuse_overwrites(const FileRoles& files) {
  const std::optional<std::string> clash = files.clash();
  if (!clash) return kExitOk;
  print_error(*clash);
  return kExitUsage;
}

}  // namespace meshstep::app
