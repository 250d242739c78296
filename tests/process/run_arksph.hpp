// Running the arksph binary from a test.
#pragma once
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace arksph::testing {

// The binary under test: ARKSPH_TEST_BINARY if set (to run the process tests against another
// build, e.g. an older release), else the one built with the tests.
inline std::string arksph_binary() {
  const char* b = std::getenv("ARKSPH_TEST_BINARY");
  return b && *b ? std::string(b) : std::string(ARKSPH_BINARY);
}

// Runs the binary with `args`; returns its exit code (-1 if it did not exit normally). stdout and
// stderr go to `log` (appended). One OpenMP thread: these runs are tiny, and spinning threads on a
// loaded machine made them 50 times slower (results do not depend on the thread count).
inline int run_arksph(const std::string& args, const std::string& log) {
  const std::string cmd = "OMP_NUM_THREADS=1 " + arksph_binary() + " " + args + " >>" + log + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct RunOutcome {
  int code = -1;    // exit code; 128 + N if killed by signal N (as a shell reports it)
  std::string out, err;
};

// Runs the shell command `command` with stdout and stderr captured through files under `scratch`.
// max_file_bytes >= 0: the child's RLIMIT_FSIZE, with SIGXFSZ ignored, so that a write beyond it
// fails with EFBIG like a write to a full disk (a test cannot mount a small tmpfs).
inline RunOutcome run_command_captured(const std::string& command, const std::string& scratch, long max_file_bytes = -1) {
  static int calls = 0;
  const std::string tag = scratch + "/.run_" + std::to_string(::getpid()) + "_" + std::to_string(calls++);
  const std::string cmd = "OMP_NUM_THREADS=1 exec " + command + " >" + tag + ".out 2>" + tag + ".err";
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (max_file_bytes >= 0) {
      ::signal(SIGXFSZ, SIG_IGN);
      const rlimit lim{static_cast<rlim_t>(max_file_bytes), static_cast<rlim_t>(max_file_bytes)};
      ::setrlimit(RLIMIT_FSIZE, &lim);
    }
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  RunOutcome o;
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  const auto read = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  o.out = read(tag + ".out");
  o.err = read(tag + ".err");
  std::remove((tag + ".out").c_str());
  std::remove((tag + ".err").c_str());
  return o;
}

// The same for the binary under test with `args`.
inline RunOutcome run_arksph_captured(const std::string& args, const std::string& scratch, long max_file_bytes = -1) {
  return run_command_captured(arksph_binary() + " " + args, scratch, max_file_bytes);
}

}  // namespace arksph::testing
