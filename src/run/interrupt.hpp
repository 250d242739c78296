// SIGINT / SIGTERM during a run: the handler only records the signal; the run loop polls it after
// each step, writes a checkpoint and summary.json (status "interrupted") and exits with 128 + signal
// (130 for SIGINT, 143 for SIGTERM). A second signal of the same kind, before the loop has reacted,
// ends the process at once with the default action (no checkpoint).
#pragma once

namespace arksph {

// Installs the handlers (idempotent). Called by `arksph run`; library users that want their own
// signal handling simply do not call it.
void install_interrupt_handlers();

// The signal received since the handlers were installed (SIGINT or SIGTERM), 0 if none.
int pending_interrupt();

// "SIGINT", "SIGTERM" or "signal".
const char* interrupt_name(int signal);

}  // namespace arksph
