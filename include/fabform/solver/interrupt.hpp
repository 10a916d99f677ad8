#pragma once
// A request to stop a run at the end of its current iteration. Signals (SIGINT, SIGTERM) are
// process-wide, and so is this request: a signal handler makes it, every solver's
// record_iteration honours it, and the run then writes its state marked "interrupted".

namespace fabform {

/// Asks every running solver to stop after its current iteration. Async-signal-safe.
void request_interrupt(int signal) noexcept;

/// The signal that asked for the stop, or 0 when none did.
int interrupt_signal() noexcept;

/// Withdraws the request (a new run in the same process starts clean).
void clear_interrupt() noexcept;

}  // namespace fabform
