// Runs the arksph binary as a user would and keeps what it said: exit code and stderr.
// ARKSPH_TEST_BINARY=/path/to/arksph runs the tests against another build (e.g. to see a test fail on
// a version without the behaviour it checks); by default the binary of this build.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "minimal_scene.hpp"
#include "run_arksph.hpp"  // arksph_binary()

namespace arksph::testing {

struct CliOutcome {
  int code = -1;    // exit code; 124 when the time limit ended the run; -1 if killed by a signal
  std::string err;  // stderr
  int lines() const {
    int n = 0;
    for (char c : err) n += c == '\n';
    return n;
  }
  bool says(const std::string& text) const { return err.find(text) != std::string::npos; }
};

// `prefix` goes before the binary (environment, `ulimit -v N;`); the run is given `seconds` at most
// (coreutils timeout: exit code 124), so that a version that would never stop fails the test
// instead of hanging it. One OpenMP thread: these runs are tiny.
inline CliOutcome run_cli(const std::string& args, const std::string& prefix = "", int seconds = 300) {
  static int calls = 0;
  const std::string err_file = (std::filesystem::temp_directory_path() /
                                ("arksph_cli_" + std::to_string(getpid()) + "_" + std::to_string(calls++) + ".err"))
                                   .string();
  const std::string cmd = prefix + " OMP_NUM_THREADS=1 timeout " + std::to_string(seconds) + " " + arksph_binary() +
                          " " + args + " >/dev/null 2>" + err_file;
  const int status = std::system(cmd.c_str());
  CliOutcome o;
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  std::stringstream ss;
  ss << in.rdbuf();
  o.err = ss.str();
  std::filesystem::remove(err_file);
  return o;
}

}  // namespace arksph::testing
