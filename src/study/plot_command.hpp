// The plot of a study: a child process (python3 and a plot script) given a time limit, so that a
// plot that hangs cannot keep the study from finishing. The limit is ARKSPH_PLOT_TIMEOUT seconds
// (default kPlotTimeoutSeconds); when it passes, the child is killed and the study says so in one
// line on stderr. The plot is an extra: its outcome never changes the study's results or exit code.
#pragma once
#include <string>
#include <vector>

namespace arksph {

inline constexpr double kPlotTimeoutSeconds = 60;

// ARKSPH_PLOT_TIMEOUT if it is a positive number of seconds, else kPlotTimeoutSeconds.
double plot_timeout_seconds();

enum class PlotOutcome { ok, failed, timed_out };

// Runs argv[0] (looked up in PATH when it has no '/') with the arguments argv[1..], stdout and stderr
// to /dev/null; waits at most `seconds`, then kills it (SIGKILL). `ok` if it exited with status 0.
PlotOutcome run_plot_command(const std::vector<std::string>& argv, double seconds);

// The study's plot: `script` with `args` under /usr/bin/python3, else python3 from PATH (the
// system python has Debian's matplotlib), until one of them writes `png`. Prints "plot: PNG" on
// stdout when it does; when the time limit passes, one line on stderr naming `study` and the limit,
// and no other python is tried. Nothing when the script does not exist.
void run_study_plot(const std::string& study, const std::string& script, const std::vector<std::string>& args,
                    const std::string& png);

}  // namespace arksph
