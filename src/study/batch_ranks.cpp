// The batch spread over the processes of an MPI launcher (see batch_ranks.hpp).
#include "study/batch_ranks.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/errors.hpp"
#include "core/file_text.hpp"
#include "io/csv_writer.hpp"  // write_text_atomic
#include "run/interrupt.hpp"
#include "run/launcher_ranks.hpp"

namespace fs = std::filesystem;

namespace arksph {

namespace {
using clock = std::chrono::steady_clock;
constexpr auto kPoll = std::chrono::milliseconds(200);

fs::path group_file(const std::string& folder) { return fs::path(folder) / ".arksph.batch_group"; }
fs::path rows_file(const std::string& folder, int r) { return fs::path(folder) / (".arksph.batch_rank" + std::to_string(r)); }
fs::path pid_file(const std::string& folder, int r) { return rows_file(folder, r).string() + ".pid"; }

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> f;
  std::size_t a = 0;
  for (std::size_t b; (b = line.find(sep, a)) != std::string::npos; a = b + 1) f.push_back(line.substr(a, b - a));
  f.push_back(line.substr(a));
  return f;
}

// The rows of one rank: index, status, exit code, skipped, wall time, steps, rhs evaluations, resumed, then
// metric name and value pairs; tab-separated (no field of a row holds a tab or a newline).
std::string encode(const BatchRunResult& r, std::size_t index) {
  char wall[32];
  std::snprintf(wall, sizeof wall, "%.17g", r.wall_seconds);
  std::ostringstream s;
  s << index << '\t' << r.status << '\t' << r.exit_code << '\t' << (r.skipped ? 1 : 0) << '\t' << wall << '\t' << r.steps
    << '\t' << r.rhs_evals << '\t' << (r.resumed ? 1 : 0);
  for (const auto& [k, v] : r.metrics) s << '\t' << k << '\t' << v;
  return s.str();
}

// False for a malformed row.
bool decode(const std::string& line, BatchResult& res) {
  const auto f = split(line, '\t');
  if (f.size() < 8 || (f.size() - 8) % 2) return false;
  try {
    const std::size_t i = std::stoul(f[0]);
    if (i >= res.runs.size()) return false;
    BatchRunResult& r = res.runs[i];
    r.status = f[1];
    r.exit_code = std::stoi(f[2]);
    r.skipped = f[3] == "1";
    r.wall_seconds = std::stod(f[4]);
    r.steps = std::stol(f[5]);
    r.rhs_evals = std::stol(f[6]);
    r.resumed = f[7] == "1";
    r.metrics.clear();
    for (std::size_t k = 8; k + 1 < f.size(); k += 2) r.metrics.emplace_back(f[k], f[k + 1]);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// True when the pid file names a process on this host that no longer exists.
bool ended_here(const std::string& folder, int r) {
  std::istringstream s(file_text(pid_file(folder, r)));
  std::string host;
  long pid = 0;
  if (!(s >> host >> pid) || host != host_name() || pid <= 0) return false;
  return kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}
}  // namespace

void publish_batch_group(const std::string& folder, const LauncherRanks& ranks) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.path().filename().string().rfind(".arksph.batch_", 0) == 0) fs::remove(e.path(), ec);
  write_text_atomic(group_file(folder).string(), ranks.launch + "\n" + std::to_string(ranks.size) + "\n");
}

void join_batch_group(const std::string& folder, const LauncherRanks& ranks, double timeout_seconds) {
  const std::string expected = ranks.launch + "\n" + std::to_string(ranks.size) + "\n";
  const auto start = clock::now();
  while (file_text(group_file(folder)) != expected) {
    if (std::chrono::duration<double>(clock::now() - start).count() > timeout_seconds)
      throw InputError("batch: rank " + std::to_string(ranks.rank) + " of " + std::to_string(ranks.size) + ": rank 0 of " +
                       ranks.launch + " did not take " + folder + " within " + std::to_string(int(timeout_seconds)) +
                       " s (another batch holds the folder, or rank 0 stopped)");
    if (pending_interrupt()) throw InputError("batch: interrupted while waiting for rank 0");
    std::this_thread::sleep_for(kPoll);
  }
  write_text_atomic(pid_file(folder, ranks.rank).string(), host_name() + " " + std::to_string(getpid()) + "\n");
}

void write_rank_rows(const std::string& folder, const LauncherRanks& ranks, const BatchResult& res) {
  std::string text = ranks.launch + "\n";
  for (std::size_t i = static_cast<std::size_t>(ranks.rank); i < res.runs.size(); i += static_cast<std::size_t>(ranks.size))
    text += encode(res.runs[i], i) + "\n";
  write_text_atomic(rows_file(folder, ranks.rank).string(), text);
}

std::vector<int> collect_rank_rows(const std::string& folder, const LauncherRanks& ranks, BatchResult& res,
                                   double join_timeout_seconds) {
  std::vector<int> missing;
  const auto start = clock::now();
  for (int r = 1; r < ranks.size; ++r) {
    std::string why;
    for (;;) {
      const std::string text = file_text(rows_file(folder, r));
      if (!text.empty() && first_line(text) == ranks.launch) {
        std::istringstream lines(text.substr(text.find('\n') + 1));
        for (std::string line; std::getline(lines, line);)
          if (!line.empty() && !decode(line, res)) why = "a malformed row in " + rows_file(folder, r).string();
        break;
      }
      const bool joined = fs::exists(pid_file(folder, r));
      if (joined && ended_here(folder, r) && first_line(file_text(rows_file(folder, r))) != ranks.launch) {
        why = "it ended without writing its results";
        break;
      }
      if (!joined && std::chrono::duration<double>(clock::now() - start).count() > join_timeout_seconds) {
        why = "it did not join the batch within " + std::to_string(int(join_timeout_seconds)) + " s";
        break;
      }
      if (pending_interrupt()) {
        why = "interrupted while waiting for it";
        break;
      }
      std::this_thread::sleep_for(kPoll);
    }
    if (!why.empty()) {
      missing.push_back(r);
      std::fprintf(stderr, "batch: rank %d of %d: %s; its runs are marked not_run\n", r, ranks.size, why.c_str());
    }
  }
  std::error_code ec;
  for (int r = 1; r < ranks.size; ++r) {
    fs::remove(rows_file(folder, r), ec);
    fs::remove(pid_file(folder, r), ec);
  }
  fs::remove(group_file(folder), ec);
  return missing;
}

}  // namespace arksph
