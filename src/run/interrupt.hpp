// SIGHUP, SIGINT, SIGQUIT, SIGTERM during a run: the handler only records the signal; the run loop
// polls it after each step, writes a checkpoint and summary.json (status "interrupted") and exits
// with 128 + signal (129 SIGHUP, 130 SIGINT, 131 SIGQUIT, 143 SIGTERM). During set-up, before the
// first step, the set-up loops poll it too (poll_setup_interrupt) and the run stops at once with the
// same exit code and no checkpoint (there is no state to continue from). A second signal of the same
// kind, before the run has reacted, ends the process at once with the default action (no checkpoint).
#pragma once
#include <stdexcept>

namespace arksph {

// Installs the handlers (idempotent) and unblocks these signals (a signal that was blocked, and
// pending, when arksph started is delivered then). Called by `arksph run`; library users that want
// their own signal handling simply do not call it.
void install_interrupt_handlers();

// The signal received since the handlers were installed (one of the four), 0 if none.
int pending_interrupt();

// "SIGHUP", "SIGINT", "SIGQUIT", "SIGTERM" or "signal".
const char* interrupt_name(int signal);

// A signal arrived during set-up: exit code 128 + signal, nothing written to continue from.
struct InterruptedDuringSetup : std::runtime_error {
  explicit InterruptedDuringSetup(int sig);
  int signal;
};

// Throws InterruptedDuringSetup if a signal is pending. Cheap (one load): set-up loops call it
// once per row of particles or per phase.
void poll_setup_interrupt();

}  // namespace arksph
