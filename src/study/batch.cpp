// The batch runner (see batch.hpp): fork/exec of the arksph binary per run, a job limit, resume.
#include "study/batch.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

#include "core/file_text.hpp"
#include "run/interrupt.hpp"
#include "study/batch_ranks.hpp"
#include "run/output_folder.hpp"
#include "core/errors.hpp"
#include "io/input_file.hpp"
#include "io/json_reader.hpp"
#include "io/scene_reader.hpp"

namespace fs = std::filesystem;

namespace arksph {

namespace {
using clock = std::chrono::steady_clock;

std::vector<std::string> child_args(const Sweep& sw, const SweepRun& run, const std::string& dir) {
  std::vector<std::string> a = {"arksph", "run", sw.scene, "--out", dir, "--quiet"};
  for (const auto& s : run.sets) a.insert(a.end(), {"--set", s});
  return a;
}

// The command that continues a stopped run from the checkpoint in its folder. The checkpoint holds
// the run's resolved scene; its --set values are given again so that the keys a restart may change
// (the end time among them) are the run's whatever the checkpoint says.
std::vector<std::string> resume_args(const SweepRun& run, const std::string& dir) {
  std::vector<std::string> a = {"arksph", "run", "--restart", (fs::path(dir) / "checkpoint.h5").string(),
                                "--out", dir, "--quiet"};
  for (const auto& s : run.sets) a.insert(a.end(), {"--set", s});
  return a;
}

std::string joined(const std::vector<std::string>& args) {
  std::string s;
  for (const auto& a : args) s += a + "\n";
  return s;
}

// Fills status, wall time, steps and metrics from the run's summary.json (if readable).
bool read_summary(BatchRunResult& r) {
  const fs::path p = fs::path(r.dir) / "summary.json";
  if (!fs::exists(p)) return false;
  try {
    const JsonValue j = read_json_file(p.string());
    if (const JsonValue* s = j.find("status")) r.status = s->text;
    if (const JsonValue* w = j.find("wall_seconds")) r.wall_seconds = w->number;
    if (const JsonValue* s = j.find("steps")) r.steps = static_cast<long>(s->number);
    if (const JsonValue* s = j.find("rhs_evals")) r.rhs_evals = static_cast<long>(s->number);
    r.metrics.clear();
    if (const JsonValue* m = j.find("metrics"))
      for (const auto& [k, v] : m->members) {
        if (v.kind == JsonValue::Kind::number) r.metrics.emplace_back(k, v.text);
        if (v.kind == JsonValue::Kind::null) r.metrics.emplace_back(k, "nan");  // summary.json writes NaN as null
      }
    return true;
  } catch (const InputError&) {
    return false;  // truncated by a crash: treated as missing
  }
}

// Starts one child with stdout and stderr into DIR/run.log (appended to when `append`: the log of a
// resumed run keeps what the run wrote before it stopped).
// The child gets SIGTERM when the batch dies (also by SIGKILL): it writes its checkpoint and stops,
// instead of running on as an orphan that a resumed batch would race for the same folder.
pid_t launch(const std::string& exe, const std::vector<std::string>& args, const std::string& dir, bool append) {
  const std::string log = (fs::path(dir) / "run.log").string();
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(128 + SIGTERM);  // the batch died before prctl took effect
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | (append ? O_APPEND : O_TRUNC), 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      close(fd);
    }
    setenv("OMP_NUM_THREADS", "1", 0);  // parallelism comes from the jobs; keep a user's setting
    forget_launcher_ranks();            // the child is one process, not a rank of the launch
    execv(exe.c_str(), argv.data());
    std::perror("arksph batch: exec");
    _exit(127);
  }
  return pid;
}

// How long the ranks of a launch wait for each other to appear (not for their runs to finish).
constexpr double kJoinTimeoutSeconds = 120;

std::string rank_tag(const LauncherRanks& ranks) {
  return ranks.size > 1 ? " rank " + std::to_string(ranks.rank) + "/" + std::to_string(ranks.size) : std::string();
}

std::string status_from_exit(int code, int signal) {
  if (signal) return "crashed";
  switch (code) {
    case 0: return "missing_summary";
    case 2: return "bad_input";
    case 3: return "failed";
    case 129:
    case 130:
    case 131:
    case 143: return "interrupted";
    default: return "failed";
  }
}
}  // namespace

BatchResult run_batch(const Sweep& sw, const BatchOptions& opt) {
  const auto start = clock::now();
  const std::string out = opt.output.empty() ? sw.output : opt.output;
  const std::string exe = opt.executable.empty() ? std::string("/proc/self/exe") : opt.executable;
  const LauncherRanks ranks = opt.launcher_ranks ? launcher_ranks_from_environment() : LauncherRanks{};
  const auto mine = [&](std::size_t i) { return static_cast<int>(i % static_cast<std::size_t>(ranks.size)) == ranks.rank; };
  // Without a job count, the cores of the host shared by the ranks on it.
  int jobs = opt.jobs > 0    ? opt.jobs
             : sw.jobs > 0   ? sw.jobs
                             : static_cast<int>(std::thread::hardware_concurrency()) / ranks.local_size;
  if (jobs < 1) jobs = 1;

  // Every run's scene must read: a bad value is a bad sweep (exit 2) before anything runs. The scene
  // file is read once; a long check says how far it got every opt.progress_every seconds.
  const std::string scene_text = read_input_file(sw.scene, "scene");
  auto reported = clock::now();
  for (std::size_t k = 0; k < sw.runs.size(); ++k) {
    const auto& run = sw.runs[k];
    std::ostringstream warnings;
    try {
      read_scene_text(scene_text, sw.scene, run.sets, warnings);
    } catch (const InputError& e) {
      throw InputError(sw.source + ": run " + run.name + ": " + e.what());
    }
    if (!opt.quiet && ranks.rank == 0 && std::chrono::duration<double>(clock::now() - reported).count() >= opt.progress_every) {
      reported = clock::now();
      std::fprintf(stderr, "batch: checked the scenes of %zu of %zu runs\n", k + 1, sw.runs.size());
    }
  }
  std::error_code ec;
  // One batch per folder at a time (exit 2 naming the pid); the ranks > 0 of a launch join rank 0's.
  std::unique_ptr<OutputFolder> folder;
  if (ranks.rank == 0 && !opt.folder_locked) folder = std::make_unique<OutputFolder>(out, sw.source);
  if (ranks.size > 1 && ranks.rank == 0) publish_batch_group(out, ranks);
  if (ranks.rank > 0) join_batch_group(out, ranks, kJoinTimeoutSeconds);

  BatchResult res;
  res.runs.resize(sw.runs.size());
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < sw.runs.size(); ++i) {
    BatchRunResult& r = res.runs[i];
    r.name = sw.runs[i].name;
    r.dir = (fs::path(out) / r.name).string();
    r.values = sw.runs[i].values;
    if (!mine(i)) continue;  // another rank's run
    const std::string cmd = joined(child_args(sw, sw.runs[i], r.dir));
    const bool same_run = file_text(fs::path(r.dir) / "batch_run.txt") == cmd;
    const bool summary = same_run && read_summary(r);
    if (summary && r.status == "ok") {
      r.skipped = true;
      ++res.skipped;
    } else {
      // The same run stopped by a signal (status "interrupted") or killed before it could write its
      // summary, with a checkpoint in its folder, continues from that checkpoint. A run that
      // failed runs again from the start.
      const bool stopped = !summary || r.status == "interrupted";
      r.resumed = same_run && stopped && fs::exists(fs::path(r.dir) / "checkpoint.h5");
      todo.push_back(i);
    }
  }

  std::size_t total = 0;
  for (std::size_t i = 0; i < sw.runs.size(); ++i) total += mine(i);
  std::size_t done = res.skipped, next = 0;
  std::map<pid_t, std::size_t> running;
  if (!opt.quiet && res.skipped)
    std::fprintf(stderr, "batch%s: %d of %zu runs already finished (skipped), %zu to run, %d at a time\n",
                 rank_tag(ranks).c_str(), res.skipped, total, todo.size(), jobs);
  install_interrupt_handlers();
  while (next < todo.size() || !running.empty()) {
    while (next < todo.size() && static_cast<int>(running.size()) < jobs && !pending_interrupt()) {
      const std::size_t i = todo[next++];
      BatchRunResult& r = res.runs[i];
      fs::create_directories(r.dir);
      fs::remove(fs::path(r.dir) / "summary.json", ec);  // a stale summary must not pass for this run's
      const auto args = child_args(sw, sw.runs[i], r.dir);
      if (r.resumed) {
        running[launch(exe, resume_args(sw.runs[i], r.dir), r.dir, true)] = i;
      } else {
        std::ofstream(fs::path(r.dir) / "batch_run.txt") << joined(args);  // the run's identity
        running[launch(exe, args, r.dir, false)] = i;
      }
    }
    if (running.empty()) break;  // interrupted before launching the rest
    // Wait for a child, polling for a signal to the batch: it goes on to every running child (each
    // writes its checkpoint and stops; the next launch of the batch resumes them).
    int wstatus = 0;
    pid_t pid = 0;
    while ((pid = waitpid(-1, &wstatus, WNOHANG)) == 0) {
      if (const int sig = pending_interrupt(); sig && !res.signal) {
        res.signal = sig;
        if (!opt.quiet)
          std::fprintf(stderr, "batch%s: %s: passing it to the %zu running runs, which write their checkpoints\n",
                       rank_tag(ranks).c_str(), interrupt_name(sig), running.size());
        for (const auto& [child, index] : running) kill(child, sig);
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("waitpid failed");
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;
    BatchRunResult& r = res.runs[it->second];
    running.erase(it);
    const int sig = WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : 0;
    r.exit_code = sig ? 128 + sig : WEXITSTATUS(wstatus);
    const bool have_summary = read_summary(r);  // sets status, wall time, metrics
    if (sig || r.exit_code != 0 || !have_summary) r.status = status_from_exit(r.exit_code, sig);
    if (r.status != "ok") ++res.failed;
    ++done;
    if (!opt.quiet)
      std::fprintf(stderr, "batch%s: [%zu/%zu] %-50s %-9s %6.2f s%s  (failed %d, running %zu)\n", rank_tag(ranks).c_str(),
                   done, total, r.name.c_str(), r.status.c_str(), r.wall_seconds, r.resumed ? " (resumed)" : "",
                   res.failed, running.size());
  }
  for (std::size_t k = next; k < todo.size(); ++k) {  // never launched (interrupt)
    res.runs[todo[k]].status = "not_run";
    ++res.failed;
  }
  if (ranks.rank > 0) {  // rank 0 combines
    write_rank_rows(out, ranks, res);
    res.partial = true;
    return res;
  }
  if (ranks.size > 1) {
    for (const int r : collect_rank_rows(out, ranks, res, kJoinTimeoutSeconds))
      for (std::size_t i = static_cast<std::size_t>(r); i < res.runs.size(); i += static_cast<std::size_t>(ranks.size))
        res.runs[i].status = "not_run";
    res.failed = res.skipped = 0;
    for (const auto& r : res.runs) {
      res.failed += r.status != "ok";
      res.skipped += r.skipped;
    }
    total = res.runs.size();
  }
  res.wall_seconds = std::chrono::duration<double>(clock::now() - start).count();
  write_batch_csv(sw, res, (fs::path(out) / "batch.csv").string());
  write_batch_json(sw, res, (fs::path(out) / "batch.json").string());
  if (!opt.quiet)
    std::fprintf(stderr, "batch: %zu runs (%d skipped, %d not ok) in %.1f s; results in %s/batch.csv\n", total,
                 res.skipped, res.failed, res.wall_seconds, out.c_str());
  return res;
}

}  // namespace arksph
