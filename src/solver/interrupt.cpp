#include "fabform/solver/interrupt.hpp"

#include <atomic>

namespace fabform {
namespace {

std::atomic<int> requested{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

}  // namespace

void request_interrupt(int signal) noexcept { requested.store(signal); }

int interrupt_signal() noexcept { return requested.load(); }

void clear_interrupt() noexcept { requested.store(0); }

}  // namespace fabform
