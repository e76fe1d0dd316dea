// What the libFuzzer harnesses share: the fuzzer's bytes as a file (the readers take
// paths), and the rule every harness enforces: a reader may refuse its input with an
// InputError (a clear message), and anything else (another exception, an invalid mesh,
// a crash the sanitizers see) is a finding, reported by aborting.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "meshstep/error.hpp"

namespace meshstep::fuzz {

// A file of this process's own, rewritten for every input: PATH (with the extension the
// reader expects).
inline const std::string& write_input(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  static std::string path;
  path = "/tmp/meshstep_fuzz_" + std::to_string(::getpid()) + extension;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  return path;
}

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "meshstep fuzz finding: %s\n", what.c_str());
  std::abort();
}

// Runs f; an InputError is an answer, any other exception a finding.
template <class F>
void refusals_allowed(F&& f) {
  try {
    f();
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    finding(std::string("not an InputError: ") + e.what());
  }
}

}  // namespace meshstep::fuzz
