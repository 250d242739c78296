#include "run/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <system_error>

#include "core/errors.hpp"
#include "core/file_text.hpp"
#include "io/json_reader.hpp"

namespace fs = std::filesystem;

namespace arksph {

namespace {

constexpr const char* kLockName = ".arksph.lock";

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
bool all_digits(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

// Written by the batch runner into the run's folder before the run starts: kept by the run.
bool is_batch_file(const std::string& name) { return name == "run.log" || name == "batch_run.txt"; }

// A file the run itself writes (without temporaries).
bool is_run_file(const std::string& name) {
  static const char* const fixed[] = {"particles.pvd",       "walls.pvd",       "timeseries.csv",          "summary.json",
                                      "nn_histogram.csv",    "ghia_u.csv",              "ghia_v.csv",
                                      "poiseuille_profile.csv", "profile_1d.csv",       "timeseries_before_restart.csv", "checkpoint.h5",
                                      kLockName};
  for (const char* f : fixed)
    if (name == f) return true;
  const auto numbered = [&](const char* prefix, const char* ext) {
    return starts_with(name, prefix) && ends_with(name, ext) &&
           all_digits(name.substr(std::strlen(prefix), name.size() - std::strlen(prefix) - std::strlen(ext)));
  };
  if (numbered("particles_", ".vtp") || numbered("particles_", ".pvtp") || numbered("interface_", ".csv")) return true;
  if (numbered("walls_", ".vtp") || numbered("walls_", ".pvtp")) return true;  // output.walls
  for (const std::string prefix : {"particles_", "walls_"}) {
    if (!starts_with(name, prefix.c_str()) || !ends_with(name, ".vtp")) continue;  // a rank's piece PREFIX_NNNNNN_rR.vtp
    const std::string mid = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    const auto r = mid.find("_r");
    if (r != std::string::npos && r > 0 && r + 2 < mid.size() && all_digits(mid.substr(0, r)) &&
        all_digits(mid.substr(r + 2)))
      return true;
  }
  return false;
}

std::string linked_output_message(const std::string& source, const std::string& dir, const std::string& name) {
  return source + ": output.directory: " + dir + "/" + echo_value(name, 60) +
         " is a symbolic link; arksph writes its files only inside the folder and never through a link "
         "(remove the link or choose another --out)";
}

}  // namespace

bool is_run_output(const std::string& name) {
  if (is_batch_file(name) || is_run_file(name)) return true;
  // Temporaries: NAME.tmp.PID (and NAME.tmp of older runs).
  const auto t = name.rfind(".tmp");
  if (t == std::string::npos || t == 0) return false;
  const std::string rest = name.substr(t + 4);
  return is_run_file(name.substr(0, t)) && (rest.empty() || (rest[0] == '.' && all_digits(rest.substr(1))));
}

std::string new_run_id() {
  std::random_device rd;
  const auto now = static_cast<unsigned long long>(std::chrono::system_clock::now().time_since_epoch().count());
  std::seed_seq seq{rd(), rd(), static_cast<unsigned>(now), static_cast<unsigned>(now >> 32),
                    static_cast<unsigned>(::getpid())};
  std::mt19937_64 gen(seq);
  char id[17];
  std::snprintf(id, sizeof id, "%016llx", static_cast<unsigned long long>(gen()));
  return id;
}

OutputFolder::OutputFolder(const std::string& dir, const std::string& source, const std::string& key)
    : dir_(dir), source_(source), key_(key) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw OutputError("cannot write " + dir + ": cannot create the folder (" + key + " of " + source +
                      "): " + (ec ? ec.message() : "not a directory"));
  const std::string lock = (fs::path(dir) / kLockName).string();
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (lock_fd_ < 0 && errno == ELOOP) throw InputError(linked_output_message(source, dir, kLockName));
  if (lock_fd_ < 0) throw OutputError("cannot write " + lock + ": " + std::strerror(errno));
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(lock_fd_);
    lock_fd_ = -1;
    if (err != EWOULDBLOCK) throw OutputError("cannot write " + lock + ": flock: " + std::strerror(err));
    std::string pid = file_text(lock);
    while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
    throw InputError(source + ": " + key + ": " + dir + " is in use by another arksph run (pid " +
                     (all_digits(pid) ? pid : std::string("unknown")) +
                     "); wait for it to finish or choose another --out");
  }
  const std::string text = std::to_string(::getpid()) + "\n";
  if (::ftruncate(lock_fd_, 0) != 0 || ::pwrite(lock_fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
    const int err = errno ? errno : EIO;
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw OutputError("cannot write " + lock + ": " + std::strerror(err));
  }
  for (const auto& e : fs::directory_iterator(dir_)) {
    const std::string name = e.path().filename().string();
    if (e.is_symlink() && is_run_output(name)) throw InputError(linked_output_message(source, dir, name));
  }
}

OutputFolder::~OutputFolder() {
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the lock; the file stays (removing it would race)
}

void OutputFolder::refuse_foreign_files() const {
  std::vector<std::string> foreign;
  std::size_t count = 0;
  for (const auto& e : fs::directory_iterator(dir_)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && is_run_output(name)) continue;
    if (++count <= 3) foreign.push_back(echo_value(name, 60));
  }
  if (count == 0) return;
  std::string list;
  for (const auto& f : foreign) list += (list.empty() ? "" : ", ") + f;
  if (count > foreign.size()) list += ", ... (" + std::to_string(count) + " in all)";
  throw InputError(source_ + ": " + key_ + ": " + dir_ + " holds files that are not arksph run outputs (" + list +
                   "); choose an empty or new folder, or give --overwrite to write beside them");
}

OutputFolder::Removed OutputFolder::remove_run_outputs() const {
  Removed removed;
  for (const auto& e : fs::directory_iterator(dir_)) {
    const std::string name = e.path().filename().string();
    if (!e.is_regular_file() || !is_run_output(name) || is_batch_file(name) || name == kLockName) continue;
    std::error_code ec;
    fs::remove(e.path(), ec);
    if (ec) throw OutputError("cannot write " + e.path().string() + ": cannot remove the earlier run's file: " + ec.message());
    ++removed.files;
    if (name.find(".tmp") == std::string::npos && starts_with(name, "particles_") &&
        (ends_with(name, ".pvtp") || (ends_with(name, ".vtp") && name.find("_r") == std::string::npos)))
      ++removed.frames;
  }
  return removed;
}

std::string OutputFolder::run_id(bool* unidentified) const {
  bool readable_without_id = false;
  const fs::path summary = fs::path(dir_) / "summary.json";
  if (fs::exists(summary)) {
    try {
      const JsonValue j = read_json_file(summary.string());
      if (const JsonValue* id = j.find("run_id"); id && id->kind == JsonValue::Kind::string) return id->text;
      readable_without_id = true;
    } catch (const InputError&) {
      // unreadable summary: try the collection
    }
  }
  const std::string pvd = file_text(fs::path(dir_) / "particles.pvd");
  const std::string key = "<!-- arksph run_id=\"";
  const auto b = pvd.find(key);
  const auto e = b == std::string::npos ? b : pvd.find('"', b + key.size());
  if (e != std::string::npos) return pvd.substr(b + key.size(), e - b - key.size());
  if (pvd.find("<Collection") != std::string::npos) readable_without_id = true;
  if (unidentified) *unidentified = readable_without_id;
  return {};
}

}  // namespace arksph
