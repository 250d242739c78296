// Signal handlers for a clean interruption. The flag is the one piece of process-wide state: a
// POSIX signal handler cannot reach anything else (async-signal-safe calls only).
#include "run/interrupt.hpp"

#include <csignal>
#include <initializer_list>
#include <string>

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

constexpr int kSignals[] = {SIGHUP, SIGINT, SIGQUIT, SIGTERM};

void install_interrupt_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // interrupted system calls (file writes) resume
  sigset_t handled;
  sigemptyset(&handled);
  for (int sig : kSignals) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. SIGINT of a background job, SIGHUP under nohup: stays ignored
    sigaction(sig, &sa, nullptr);
    sigaddset(&handled, sig);
  }
  pthread_sigmask(SIG_UNBLOCK, &handled, nullptr);
}

int pending_interrupt() { return g_signal; }

const char* interrupt_name(int signal) {
  switch (signal) {
    case SIGHUP: return "SIGHUP";
    case SIGINT: return "SIGINT";
    case SIGQUIT: return "SIGQUIT";
    case SIGTERM: return "SIGTERM";
    default: return "signal";
  }
}

InterruptedDuringSetup::InterruptedDuringSetup(int sig)
    : std::runtime_error(std::string("interrupted by ") + interrupt_name(sig) +
                         " during set-up, before the first step: no checkpoint written (nothing to continue from)"),
      signal(sig) {}

void poll_setup_interrupt() {
  if (const int sig = g_signal) throw InterruptedDuringSetup(sig);
}

}  // namespace arksph
