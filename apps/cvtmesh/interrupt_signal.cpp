#include "interrupt_signal.hpp"

#include <atomic>
#include <csignal>

namespace cvtmesh::cli {

namespace {

// Lock-free, hence safe to set from a signal handler.
std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int signal) {
  requested.store(true, std::memory_order_relaxed);
  std::signal(signal, SIG_DFL);  // the next one is not caught
}

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

bool interrupt_requested() {
  return requested.load(std::memory_order_relaxed);
}

}  // namespace cvtmesh::cli
