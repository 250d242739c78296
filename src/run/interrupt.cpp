// Signal handlers for a clean interruption. The flag is the one piece of process-wide state: a
// POSIX signal handler cannot reach anything else (async-signal-safe calls only).
#include "run/interrupt.hpp"

#include <csignal>
#include <initializer_list>

namespace arksph {

namespace {
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int sig) {
  if (g_signal == sig) {  // second time: the user insists, stop now
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
}
}  // namespace

void install_interrupt_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // interrupted system calls (file writes) resume
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. SIGINT of a background job: stays ignored
    sigaction(sig, &sa, nullptr);
  }
}

int pending_interrupt() { return g_signal; }

const char* interrupt_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "signal";
  }
}

}  // namespace arksph
