#pragma once
// While an InterruptHandlers lives, SIGINT and SIGTERM ask the run to stop at the end of its
// current iteration (fabform/solver/interrupt.hpp) instead of killing it, so its state is
// written; a second signal kills at once, as users expect of a second Ctrl-C.
#include <csignal>

namespace fabform::cli {

class InterruptHandlers {
 public:
  InterruptHandlers();
  ~InterruptHandlers();
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;

 private:
  struct sigaction previous_int_{};
  struct sigaction previous_term_{};
};

}  // namespace fabform::cli
