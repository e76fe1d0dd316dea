#include "disposal.hpp"

namespace meshstep::viewer {

Disposal::~Disposal() {
  if (thread_.joinable()) thread_.join();
}

void Disposal::run(std::function<void()> work) {
  if (thread_.joinable()) thread_.join();
  thread_ = std::thread([work = std::move(work)]() mutable {
    work();
    work = nullptr;  // what it held, freed here too
  });
}

}  // namespace meshstep::viewer
