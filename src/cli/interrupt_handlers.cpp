#include "cli/interrupt_handlers.hpp"

#include "fabform/solver/interrupt.hpp"

namespace fabform::cli {
namespace {

extern "C" void on_stop_signal(int signal) { request_interrupt(signal); }

}  // namespace

InterruptHandlers::InterruptHandlers() {
  clear_interrupt();
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the second signal finds the default action: it kills
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

InterruptHandlers::~InterruptHandlers() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

}  // namespace fabform::cli
