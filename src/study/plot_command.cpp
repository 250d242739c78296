// A study's plot under a time limit (see plot_command.hpp).
#include "study/plot_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

namespace fs = std::filesystem;

namespace arksph {

double plot_timeout_seconds() {
  const char* v = std::getenv("ARKSPH_PLOT_TIMEOUT");
  if (!v || !*v) return kPlotTimeoutSeconds;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  return *end == '\0' && s > 0 && std::isfinite(s) ? s : kPlotTimeoutSeconds;
}

PlotOutcome run_plot_command(const std::vector<std::string>& argv, double seconds) {
  if (argv.empty()) return PlotOutcome::failed;
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return PlotOutcome::failed;
  if (pid == 0) {
    const int null = ::open("/dev/null", O_RDWR);
    if (null >= 0) {
      ::dup2(null, STDIN_FILENO);
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    ::execvp(args[0], args.data());
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (true) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? PlotOutcome::ok : PlotOutcome::failed;
    if (r < 0 && errno != EINTR) return PlotOutcome::failed;
    if (std::chrono::steady_clock::now() >= deadline) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      return PlotOutcome::timed_out;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void run_study_plot(const std::string& study, const std::string& script, const std::vector<std::string>& args,
                    const std::string& png) {
  if (!fs::exists(script)) return;
  const double limit = plot_timeout_seconds();
  for (const char* python : {"/usr/bin/python3", "python3"}) {
    std::vector<std::string> argv = {python, script};
    argv.insert(argv.end(), args.begin(), args.end());
    const PlotOutcome o = run_plot_command(argv, limit);
    if (o == PlotOutcome::timed_out) {
      std::fflush(stdout);
      std::fprintf(stderr,
                   "arksph: study %s: the plot %s did not finish within %g s (ARKSPH_PLOT_TIMEOUT): stopped it, no "
                   "plot written; the study's results stand\n",
                   study.c_str(), script.c_str(), limit);
      return;
    }
    if (o == PlotOutcome::ok && fs::exists(png)) {
      std::printf("plot: %s\n", png.c_str());
      return;
    }
  }
}

}  // namespace arksph
