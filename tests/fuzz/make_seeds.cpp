// make_seeds ASSETS_EXAMPLES OUT_DIR: writes the seed corpora of the harnesses into
// OUT_DIR/<harness>/ (seeds.hpp says what they are).
#include <iostream>

#include "seeds.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_seeds ASSETS_EXAMPLES OUT_DIR\n";
    return 2;
  }
  const int logs = meshstep::fuzz::seeds::write_seeds(argv[1], argv[2]);
  std::cout << "seeds written to " << argv[2] << " (" << logs << " logs)\n";
  return 0;
}
